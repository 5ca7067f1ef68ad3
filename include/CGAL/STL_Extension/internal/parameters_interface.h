// Copyright (c) 2026 The Polygon_mesh_processing_ILSA authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Extends CGAL's list of named parameters with the tags of the ILSA smoother, so
// that `CGAL::parameters::number_of_iterations(5).ilsa_quality_floor(0.4)` and
// `CGAL::parameters::ilsa_quality_floor(0.4).number_of_iterations(5)` both chain.
//
// CGAL includes this list several times, each time with another definition of
// `CGAL_add_named_parameter` (enum tags, member functions, free functions), so
// this file must have no include guard. It is found before CGAL's own copy
// because the package's include directory precedes CGAL's (the CMake target
// `CGAL::Polygon_mesh_processing_ILSA` puts it first). It then pulls in CGAL's
// list:
// - by the path in `CGAL_ILSA_CGAL_PARAMETERS_INTERFACE` when it is defined
//   (standard C++, any compiler; the CMake target defines it with the path of
//   the CGAL found at configure time);
// - otherwise with `#include_next`, a GCC/Clang extension.

#if defined(CGAL_ILSA_CGAL_PARAMETERS_INTERFACE)
#include CGAL_ILSA_CGAL_PARAMETERS_INTERFACE
#elif defined(__GNUC__) || defined(__clang__)
#include_next <CGAL/STL_Extension/internal/parameters_interface.h>
#else
#error                                                                                                                 \
    "Define CGAL_ILSA_CGAL_PARAMETERS_INTERFACE as the quoted path of CGAL's CGAL/STL_Extension/internal/parameters_interface.h (the CMake target CGAL::Polygon_mesh_processing_ILSA does)."
#endif

// ILSA parameters (see smooth_surface_mesh_ilsa.h for their meaning)
// clang-format off
CGAL_add_named_parameter(ilsa_feature_angle_t, ilsa_feature_angle, ilsa_feature_angle)
CGAL_add_named_parameter(ilsa_minimum_quality_gain_t, ilsa_minimum_quality_gain, ilsa_minimum_quality_gain)
CGAL_add_named_parameter(ilsa_quality_floor_t, ilsa_quality_floor, ilsa_quality_floor)
CGAL_add_named_parameter(ilsa_fidelity_tolerance_t, ilsa_fidelity_tolerance, ilsa_fidelity_tolerance)
CGAL_add_named_parameter(ilsa_paper_variant_t, ilsa_paper_variant, ilsa_paper_variant)
CGAL_add_named_parameter(ilsa_quality_threshold_t, ilsa_quality_threshold, ilsa_quality_threshold)
CGAL_add_named_parameter(ilsa_compute_hausdorff_distance_t, ilsa_compute_hausdorff_distance, ilsa_compute_hausdorff_distance)
// clang-format on

// Checked by the package's public headers: if CGAL's own list was picked up
// instead of this one, compilation stops with a clear message.
#ifndef CGAL_ILSA_NAMED_PARAMETERS_INTERFACE
#define CGAL_ILSA_NAMED_PARAMETERS_INTERFACE 1
#endif

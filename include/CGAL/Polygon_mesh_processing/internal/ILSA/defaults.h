// Copyright (c) 2026 The Polygon_mesh_processing_ILSA authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The defaults of the named parameters and the constants of the method, in
// one place: the smoother, the classification, the quality and fidelity
// summaries and the ilsa_smooth tool read them from here, and
// test_ilsa_smoothing checks that the reference documentation, the manual's
// parameter table and the tool's usage text state the same values. Why each
// value is what it is: user manual, "Parameters" and "Decisions That Differ
// from the Paper".

#ifndef CGAL_POLYGON_MESH_PROCESSING_INTERNAL_ILSA_DEFAULTS_H
#define CGAL_POLYGON_MESH_PROCESSING_INTERNAL_ILSA_DEFAULTS_H

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace ILSA {
namespace defaults {

// Named parameters.
inline constexpr unsigned int number_of_iterations = 8;
inline constexpr double minimum_quality_gain = 1e-4;
// The angle between face normals above which an edge is sharp (CGAL's
// convention; the paper's dihedral θ_f is 180° minus it).
inline constexpr double feature_angle = 20.;
inline constexpr bool relax_constraints = false;
inline constexpr bool do_project = true;
inline constexpr bool use_safety_constraints = true;
// Raised to the input's minimum aspect ratio when that is higher.
inline constexpr double quality_floor = 0.5;
inline constexpr double fidelity_tolerance = 5e-4; // of the bounding-box diagonal
inline constexpr bool paper_variant = false;
// Quality and fidelity summaries.
inline constexpr double quality_threshold = 0.3; // a face below this aspect ratio counts as poor
inline constexpr bool compute_hausdorff_distance = true;

// Constants of the method (user manual, "Constants").
inline constexpr unsigned int number_of_relaxation_steps = 2; // sweeps of Algo. 2
inline constexpr unsigned int penalty_steps = 8;              // sweeps of Algo. 3 (the paper's variant: 2)
inline constexpr double relaxation = 0.5;                     // relax1
inline constexpr double penalty_relaxation = 0.8;             // relax2
inline constexpr double penalty_mu = 1.;
inline constexpr double length_weight = 1.; // wl
inline constexpr double area_weight = 0.1;  // wa
inline constexpr double crease_contrast = 5.;
inline constexpr unsigned int minimum_open_crease_edges = 20;
inline constexpr double minimum_remaining_gain = 2e-3;
inline constexpr double retry_distance = 0.03;   // of the mean edge length
inline constexpr unsigned int move_halvings = 3; // of a move the safety check rejects, before it is dropped

} // namespace defaults
} // namespace ILSA
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_POLYGON_MESH_PROCESSING_INTERNAL_ILSA_DEFAULTS_H

// Copyright (c) 2026 The Polygon_mesh_processing_ILSA authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The default of every ILSA named parameter, in one place: the smoother, the
// classification, the quality and fidelity summaries and the ilsa_smooth tool
// read them from here, and test_ilsa_smoothing checks that the reference
// documentation, the manual's parameter table and the tool's usage text state
// the same values. Why each default is what it is: user manual, "Parameters
// and Their Defaults".

#ifndef CGAL_POLYGON_MESH_PROCESSING_INTERNAL_ILSA_DEFAULTS_H
#define CGAL_POLYGON_MESH_PROCESSING_INTERNAL_ILSA_DEFAULTS_H

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace ILSA {
namespace defaults {

// Global loop and stops (user manual, "Stopping early").
inline constexpr unsigned int number_of_iterations = 8;
inline constexpr double minimum_quality_gain = 1e-4;
inline constexpr double minimum_remaining_gain = 2e-3;

// ILSA displacement and penalty step (user manual, "Sweeps per Iteration",
// "Fewer, Longer Iterations", "Sweep Order" and "Tangential Sweeps").
inline constexpr unsigned int number_of_relaxation_steps = 2; // sweeps of Algo. 2
inline constexpr unsigned int penalty_steps = 8;              // sweeps of Algo. 3
inline constexpr bool penalty_gauss_seidel = false;           // true: multicolour Gauss-Seidel sweeps of Algo. 3
inline constexpr bool tangential_displacement = true; // false: the paper's displacement, normal component included
inline constexpr bool tangential_sweeps = true;       // false: normal components dropped after the sweeps of Algo. 3
inline constexpr double relaxation = 0.5;             // relax1
inline constexpr double penalty_relaxation = 0.8;     // relax2
inline constexpr double penalty_mu = 1.;
inline constexpr double length_weight = 1.; // wl
inline constexpr double area_weight = 0.1;  // wa

// Classification: the angle between face normals above which an edge is sharp
// (CGAL's convention; the paper's dihedral θ_f is 180° minus it). The crease
// kink angle defaults to the feature angle given.
inline constexpr double feature_angle = 20.;
inline constexpr bool fix_unattached_candidates = false; // true: the paper's rule
inline constexpr double crease_contrast = 5.; // 0: the paper's rule (every feature edge between candidates is sharp)
inline constexpr unsigned int minimum_open_crease_edges = 20; // 0: the paper's rule (no feature edge is dropped)
inline constexpr bool relax_constraints = false;

// Safety check (user manual, "Safety check"). The quality floor is raised to
// the input's minimum aspect ratio when that is higher.
inline constexpr bool do_project = true;
inline constexpr bool use_safety_constraints = true;
inline constexpr double quality_floor = 0.5;
inline constexpr bool quality_monotone = false;
inline constexpr bool reject_worsening_moves = true;
inline constexpr double fidelity_tolerance = 5e-4; // of the bounding-box diagonal
inline constexpr double retry_distance = 0.03;     // of the mean edge length

// Quality summary: the aspect ratio under which a face counts as poor.
inline constexpr double quality_threshold = 0.3;

} // namespace defaults
} // namespace ILSA
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_POLYGON_MESH_PROCESSING_INTERNAL_ILSA_DEFAULTS_H

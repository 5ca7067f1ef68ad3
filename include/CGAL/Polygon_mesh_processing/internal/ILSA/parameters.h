// Copyright (c) 2026 The Polygon_mesh_processing_ILSA authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What the iterations run with: the smoothing parameters, set by
// read_smoothing_parameters() (read_parameters.h) from the named parameters.

#ifndef CGAL_POLYGON_MESH_PROCESSING_INTERNAL_ILSA_PARAMETERS_H
#define CGAL_POLYGON_MESH_PROCESSING_INTERNAL_ILSA_PARAMETERS_H

#include <CGAL/Polygon_mesh_processing/internal/ILSA/defaults.h>

#include <cstddef>
#include <functional>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace ILSA {

// The constants of the method and the named parameters' values; the
// defaults are the package's (defaults.h), read_smoothing_parameters() sets
// what the named parameters and the paper's variant change.
struct Penalty_parameters {
  double relax2 = defaults::penalty_relaxation;
  double mu = defaults::penalty_mu;
  double length_weight = defaults::length_weight; // wl
  double area_weight = defaults::area_weight;     // wa
  std::size_t sweeps = defaults::penalty_steps;
  // Each sweep drops the normal component of the displacements (user manual,
  // "Tangential Displacements"); the paper's variant keeps it.
  bool tangential = true;
  double tolerance = 0; // stop once no displacement changes by more
};

struct Smoothing_parameters {
  std::size_t iterations = defaults::number_of_iterations;   // the paper's max_global_iter_num
  std::size_t sweeps = defaults::number_of_relaxation_steps; // of the ILSA step (Algo. 2)
  double relax1 = defaults::relaxation;
  Penalty_parameters penalty; // relax2, μ, wl, wa, the sweeps of the penalty step (Algo. 3), tangential
  bool do_project = defaults::do_project;
  bool use_safety = defaults::use_safety_constraints;
  // The quality floor; without an explicit one, raised to the input's
  // minimum aspect ratio when that is higher.
  double quality_floor = defaults::quality_floor;
  bool raise_floor_to_input_minimum = true;
  bool reject_worsening = true; // the paper's variant accepts every move the other checks allow
  double fidelity_tolerance = defaults::fidelity_tolerance;
  double minimum_gain = defaults::minimum_quality_gain;
  double minimum_remaining_gain = defaults::minimum_remaining_gain;
  double retry_distance = defaults::retry_distance;
  std::function<bool(double)> callback;

  /// Whether the run may stop before `iterations` (user manual, "Stopping Early").
  bool may_stop() const { return minimum_gain > 0 || minimum_remaining_gain > 0; }
};

} // namespace ILSA
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_POLYGON_MESH_PROCESSING_INTERNAL_ILSA_PARAMETERS_H

// Copyright (c) 2026 The Polygon_mesh_processing_ILSA authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The named parameters of smooth_surface_mesh_ilsa() that drive the
// iterations, read and checked in one place (the classification's are read
// by read_classification_parameters(), set_up.h; the defaults are in
// defaults.h).

#ifndef CGAL_POLYGON_MESH_PROCESSING_INTERNAL_ILSA_SMOOTHING_PARAMETERS_H
#define CGAL_POLYGON_MESH_PROCESSING_INTERNAL_ILSA_SMOOTHING_PARAMETERS_H

#include <CGAL/Polygon_mesh_processing/ilsa_types.h>
#include <CGAL/Polygon_mesh_processing/internal/ILSA/defaults.h>
#include <CGAL/Polygon_mesh_processing/internal/ILSA/core.h>

#include <CGAL/Named_function_parameters.h>

#include <cmath>
#include <cstddef>
#include <functional>
#include <sstream>
#include <string>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace ILSA {

/// Throws `ILSA_error` for a smoothing parameter out of its range; the counts
/// are checked as given, before their conversion to `std::size_t`.
inline void check_smoothing_parameters(const Smoothing_parameters& p, double iterations, double sweeps,
                                       double penalty_sweeps) {
  // The message names the parameter, its range and the value given.
  auto require = [](bool ok, const std::string& what, double value) {
    if (!ok) {
      std::ostringstream message;
      message << what << ", got " << value;
      throw ILSA_error(message.str());
    }
  };
  require(p.quality_floor >= 0 && p.quality_floor < 1, "ilsa_quality_floor must be in [0, 1)", p.quality_floor);
  require(p.fidelity_tolerance > 0, "ilsa_fidelity_tolerance must be positive (infinity disables the bound)",
          p.fidelity_tolerance);
  require(p.minimum_gain >= 0 && std::isfinite(p.minimum_gain),
          "ilsa_minimum_quality_gain must be non-negative and finite (0 disables this stop)", p.minimum_gain);
  require(p.minimum_remaining_gain >= 0 && std::isfinite(p.minimum_remaining_gain),
          "ilsa_minimum_remaining_gain must be non-negative and finite (0 disables this stop)",
          p.minimum_remaining_gain);
  require(p.retry_distance >= 0 && std::isfinite(p.retry_distance),
          "ilsa_retry_distance must be non-negative and finite (0 retries every dropped move at once)",
          p.retry_distance);
  require(iterations >= 0 && iterations <= 100000, "number_of_iterations must be in [0, 100000]", iterations);
  require(sweeps >= 1 && sweeps <= 10000, "number_of_relaxation_steps must be in [1, 10000]", sweeps);
  require(penalty_sweeps >= 1 && penalty_sweeps <= 10000, "ilsa_penalty_steps must be in [1, 10000]", penalty_sweeps);
  require(p.relax1 > 0 && p.relax1 <= 1, "ilsa_relaxation must be in (0, 1]", p.relax1);
  require(p.penalty.relax2 > 0 && p.penalty.relax2 <= 1, "ilsa_penalty_relaxation must be in (0, 1]", p.penalty.relax2);
  require(p.penalty.mu > 0 && std::isfinite(p.penalty.mu), "ilsa_penalty_mu must be positive and finite", p.penalty.mu);
  require(p.penalty.length_weight >= 0 && std::isfinite(p.penalty.length_weight),
          "ilsa_length_weight must be non-negative and finite", p.penalty.length_weight);
  require(p.penalty.area_weight >= 0 && std::isfinite(p.penalty.area_weight),
          "ilsa_area_weight must be non-negative and finite", p.penalty.area_weight);
}

/// Reads the smoothing parameters of `np`; throws `ILSA_error` for a value out of range.
template <class NamedParameters> Smoothing_parameters read_smoothing_parameters(const NamedParameters& np) {
  // The value of the parameter `tag` in `np`, or else `fallback`.
  const auto read = [&np](auto tag, auto fallback) {
    return parameters::choose_parameter(parameters::get_parameter(np, tag), fallback);
  };
  Smoothing_parameters p;
  const auto iterations = read(internal_np::number_of_iterations, defaults::number_of_iterations);
  const auto sweeps = read(internal_np::number_of_relaxation_steps, defaults::number_of_relaxation_steps);
  const auto penalty_sweeps = read(internal_np::ilsa_penalty_steps, defaults::penalty_steps);
  p.tangential = read(internal_np::ilsa_tangential_displacement, defaults::tangential_displacement);
  p.relax1 = read(internal_np::ilsa_relaxation, defaults::relaxation);
  Penalty_parameters& penalty = p.penalty;
  penalty.relax2 = read(internal_np::ilsa_penalty_relaxation, defaults::penalty_relaxation);
  penalty.gauss_seidel = read(internal_np::ilsa_penalty_gauss_seidel, defaults::penalty_gauss_seidel);
  penalty.tangential_sweeps = p.tangential && read(internal_np::ilsa_tangential_sweeps, defaults::tangential_sweeps);
  penalty.mu = read(internal_np::ilsa_penalty_mu, defaults::penalty_mu);
  penalty.length_weight = read(internal_np::ilsa_length_weight, defaults::length_weight);
  penalty.area_weight = read(internal_np::ilsa_area_weight, defaults::area_weight);
  p.do_project = read(internal_np::do_project, defaults::do_project);
  p.use_safety = read(internal_np::use_safety_constraints, defaults::use_safety_constraints);
  p.raise_floor_to_input_minimum =
      parameters::is_default_parameter<NamedParameters, internal_np::ilsa_quality_floor_t>::value;
  p.quality_floor = read(internal_np::ilsa_quality_floor, defaults::quality_floor);
  p.quality_monotone = read(internal_np::ilsa_quality_monotone, defaults::quality_monotone);
  p.reject_worsening = read(internal_np::ilsa_reject_worsening_moves, defaults::reject_worsening_moves);
  p.fidelity_tolerance = read(internal_np::ilsa_fidelity_tolerance, defaults::fidelity_tolerance);
  p.minimum_gain = read(internal_np::ilsa_minimum_quality_gain, defaults::minimum_quality_gain);
  p.minimum_remaining_gain = read(internal_np::ilsa_minimum_remaining_gain, defaults::minimum_remaining_gain);
  p.retry_distance = read(internal_np::ilsa_retry_distance, defaults::retry_distance);
  p.verbose = read(internal_np::verbose, false);
  p.callback = read(internal_np::callback, std::function<bool(double)>());

  check_smoothing_parameters(p, double(iterations), double(sweeps), double(penalty_sweeps));
  p.iterations = std::size_t(iterations);
  p.sweeps = std::size_t(sweeps);
  penalty.sweeps = std::size_t(penalty_sweeps);
  return p;
}

} // namespace ILSA
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_POLYGON_MESH_PROCESSING_INTERNAL_ILSA_SMOOTHING_PARAMETERS_H

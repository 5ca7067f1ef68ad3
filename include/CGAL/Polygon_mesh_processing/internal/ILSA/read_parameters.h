// Copyright (c) 2026 The Polygon_mesh_processing_ILSA authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Every named parameter of the package is read and checked here: those of
// the iterations, of the classification (with the user's constraint maps) and
// of the quality and fidelity summaries. The defaults are in defaults.h.

#ifndef CGAL_POLYGON_MESH_PROCESSING_INTERNAL_ILSA_READ_PARAMETERS_H
#define CGAL_POLYGON_MESH_PROCESSING_INTERNAL_ILSA_READ_PARAMETERS_H

#include <CGAL/Polygon_mesh_processing/ilsa_types.h>
#include <CGAL/Polygon_mesh_processing/internal/ILSA/classification.h>
#include <CGAL/Polygon_mesh_processing/internal/ILSA/defaults.h>
#include <CGAL/Polygon_mesh_processing/internal/ILSA/flat_mesh.h>
#include <CGAL/Polygon_mesh_processing/internal/ILSA/parameters.h>

#include <CGAL/Named_function_parameters.h>
#ifndef CGAL_ILSA_NAMED_PARAMETERS_INTERFACE
#error                                                                                                                 \
    "CGAL's named-parameter list was included without the ILSA tags: put the package's include/ directory before CGAL's in the include path."
#endif
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/property_map.h>

#include <cmath>
#include <cstddef>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace ILSA {

/// Throws `ILSA_error` naming the parameter, its range and the value given, unless `ok`.
inline void require(bool ok, const std::string& what, double value) {
  if (ok) return;
  std::ostringstream message;
  message << what << ", got " << value;
  throw ILSA_error(message.str());
}

/// The value of the named parameter `tag` in `np`, or else `fallback`.
template <class NamedParameters, class Tag, class T> auto read(const NamedParameters& np, Tag tag, const T& fallback) {
  return parameters::choose_parameter(parameters::get_parameter(np, tag), fallback);
}

/// Reads the smoothing parameters of `np`; throws `ILSA_error` for a value out
/// of range. The counts are checked as given, before their conversion to
/// `std::size_t`.
template <class NamedParameters> Smoothing_parameters read_smoothing_parameters(const NamedParameters& np) {
  Smoothing_parameters p;
  const auto iterations = read(np, internal_np::number_of_iterations, defaults::number_of_iterations);
  require(double(iterations) >= 0 && double(iterations) <= 100000, "number_of_iterations must be in [0, 100000]",
          double(iterations));
  p.iterations = std::size_t(iterations);
  p.do_project = read(np, internal_np::do_project, defaults::do_project);
  p.use_safety = read(np, internal_np::use_safety_constraints, defaults::use_safety_constraints);
  p.raise_floor_to_input_minimum =
      parameters::is_default_parameter<NamedParameters, internal_np::ilsa_quality_floor_t>::value;
  p.quality_floor = read(np, internal_np::ilsa_quality_floor, defaults::quality_floor);
  require(p.quality_floor >= 0 && p.quality_floor < 1, "ilsa_quality_floor must be in [0, 1)", p.quality_floor);
  p.fidelity_tolerance = read(np, internal_np::ilsa_fidelity_tolerance, defaults::fidelity_tolerance);
  require(p.fidelity_tolerance > 0, "ilsa_fidelity_tolerance must be positive (infinity disables the bound)",
          p.fidelity_tolerance);
  p.minimum_gain = read(np, internal_np::ilsa_minimum_quality_gain, defaults::minimum_quality_gain);
  require(p.minimum_gain >= 0 && std::isfinite(p.minimum_gain),
          "ilsa_minimum_quality_gain must be non-negative and finite (0 disables the stops)", p.minimum_gain);
  if (p.minimum_gain == 0) p.minimum_remaining_gain = 0; // every iteration runs
  p.callback = read(np, internal_np::callback, std::function<bool(double)>());
  // The paper's variant (user manual, "The Paper's Variant"): its displacement,
  // normal component included; as many sweeps of Algo. 3 as of Algo. 2; every
  // move the other checks allow.
  if (read(np, internal_np::ilsa_paper_variant, defaults::paper_variant)) {
    p.penalty.tangential = false;
    p.penalty.sweeps = p.sweeps;
    p.reject_worsening = false;
  }
  return p;
}

/// Reads the classification rules of `np` (`ilsa_feature_angle`, `ilsa_paper_variant`);
/// throws `ILSA_error` for a feature angle out of range.
template <class NamedParameters> Classification_options read_classification_options(const NamedParameters& np) {
  const double feature_angle = read(np, internal_np::ilsa_feature_angle, defaults::feature_angle);
  require(feature_angle >= 0 && feature_angle < 180,
          "ilsa_feature_angle must be in [0, 180) degrees (the angle between face normals)", feature_angle);
  return Classification_options::rules(feature_angle,
                                       read(np, internal_np::ilsa_paper_variant, defaults::paper_variant));
}

/// Copies the user's constraint maps of `np` (`vertex_is_constrained_map`,
/// `edge_is_constrained_map` with `relax_constraints`) into the flat arrays
/// `vertex_store` and `edge_store`, which `options` then points to.
template <class NamedParameters, class VertexDescriptor, class EdgeDescriptor>
void read_constraint_maps(const Flat_mesh& m, const NamedParameters& np,
                          const std::vector<VertexDescriptor>& vertex_list,
                          const std::vector<EdgeDescriptor>& edge_list, std::vector<unsigned char>& vertex_store,
                          std::vector<unsigned char>& edge_store, Classification_options& options) {
  const auto vcm = read(np, internal_np::vertex_is_constrained, Static_boolean_property_map<VertexDescriptor, false>());
  vertex_store.resize(vertex_list.size());
  for (std::size_t i = 0; i < vertex_list.size(); ++i) vertex_store[i] = get(vcm, vertex_list[i]) ? 1 : 0;
  options.constrained_vertices = &vertex_store;

  if (!parameters::is_default_parameter<NamedParameters, internal_np::edge_is_constrained_t>::value) {
    const auto ecm = read(np, internal_np::edge_is_constrained, Static_boolean_property_map<EdgeDescriptor, false>());
    edge_store.resize(edge_list.size());
    for (std::size_t i = 0; i < edge_list.size(); ++i) edge_store[i] = get(ecm, edge_list[i]) ? 1 : 0;
    options.constrained_edges = &edge_store;
    // CGAL's relax_constraints (user manual, "Constrained Edges"): unless it is
    // true, the ends of the constrained edges do not move, as in CGAL's smoothers.
    if (!read(np, internal_np::relax_constraints, defaults::relax_constraints))
      for (std::size_t i = 0; i < edge_list.size(); ++i)
        if (edge_store[i]) vertex_store[m.edges[i][0]] = vertex_store[m.edges[i][1]] = 1;
  }
}

/// `ilsa_quality_threshold` of `mesh_quality_ilsa()`; throws `ILSA_error` out of [0, 1].
template <class NamedParameters> double read_quality_threshold(const NamedParameters& np) {
  const double threshold = read(np, internal_np::ilsa_quality_threshold, defaults::quality_threshold);
  require(threshold >= 0 && threshold <= 1, "ilsa_quality_threshold must be in [0, 1]", threshold);
  return threshold;
}

/// `ilsa_compute_hausdorff_distance` of `mesh_fidelity_ilsa()`.
template <class NamedParameters> bool read_compute_hausdorff_distance(const NamedParameters& np) {
  return read(np, internal_np::ilsa_compute_hausdorff_distance, defaults::compute_hausdorff_distance);
}

} // namespace ILSA
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_POLYGON_MESH_PROCESSING_INTERNAL_ILSA_READ_PARAMETERS_H

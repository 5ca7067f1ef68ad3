// Copyright (c) 2026 The Polygon_mesh_processing_ILSA authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The set-up that smooth_surface_mesh_ilsa() and classify_vertices_ilsa()
// share: the flat copy of the input and its vertex classification (paper §3),
// with the classification's named parameters.

#ifndef CGAL_POLYGON_MESH_PROCESSING_INTERNAL_ILSA_SET_UP_H
#define CGAL_POLYGON_MESH_PROCESSING_INTERNAL_ILSA_SET_UP_H

#include <CGAL/Polygon_mesh_processing/ilsa_types.h>
#include <CGAL/Polygon_mesh_processing/internal/ILSA/core.h>
#include <CGAL/Polygon_mesh_processing/internal/ILSA/defaults.h>
#include <CGAL/Polygon_mesh_processing/internal/ILSA/flat_mesh.h>
#ifndef CGAL_ILSA_COMPILED_CORE
#include <CGAL/Polygon_mesh_processing/internal/ILSA/vertex_classification.h> // classify()
#endif

#include <CGAL/Named_function_parameters.h>
#ifndef CGAL_ILSA_NAMED_PARAMETERS_INTERFACE
#error                                                                                                                 \
    "CGAL's named-parameter list was included without the ILSA tags: put the package's include/ directory before CGAL's in the include path."
#endif

#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/property_map.h>

#include <cmath>
#include <string>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace ILSA {

/// Copies the user's constraint maps of `np` (`vertex_is_constrained_map`,
/// `edge_is_constrained_map` with `relax_constraints`) into the flat arrays
/// `vertex_store` and `edge_store`, which `options` then points to.
template <class NamedParameters, class VertexDescriptor, class EdgeDescriptor>
void read_constraint_maps(const Flat_mesh& m, const NamedParameters& np,
                          const std::vector<VertexDescriptor>& vertex_list,
                          const std::vector<EdgeDescriptor>& edge_list, std::vector<unsigned char>& vertex_store,
                          std::vector<unsigned char>& edge_store, Classification_options& options) {
  using parameters::choose_parameter;
  using parameters::get_parameter;
  const auto vcm = choose_parameter(get_parameter(np, internal_np::vertex_is_constrained),
                                    Static_boolean_property_map<VertexDescriptor, false>());
  vertex_store.resize(vertex_list.size());
  for (std::size_t i = 0; i < vertex_list.size(); ++i) vertex_store[i] = get(vcm, vertex_list[i]) ? 1 : 0;
  options.constrained_vertices = &vertex_store;

  if (!parameters::is_default_parameter<NamedParameters, internal_np::edge_is_constrained_t>::value) {
    const auto ecm = choose_parameter(get_parameter(np, internal_np::edge_is_constrained),
                                      Static_boolean_property_map<EdgeDescriptor, false>());
    edge_store.resize(edge_list.size());
    for (std::size_t i = 0; i < edge_list.size(); ++i) edge_store[i] = get(ecm, edge_list[i]) ? 1 : 0;
    options.constrained_edges = &edge_store;
    // CGAL's relax_constraints (user manual, "Constrained Edges"): unless it is
    // true, the ends of the constrained edges do not move, as in CGAL's smoothers.
    if (!choose_parameter(get_parameter(np, internal_np::relax_constraints), defaults::relax_constraints))
      for (std::size_t i = 0; i < edge_list.size(); ++i)
        if (edge_store[i]) vertex_store[m.edges[i][0]] = vertex_store[m.edges[i][1]] = 1;
  }
}

/// Reads the classification parameters of `np` (paper §3; user constraints as documented) into
/// `options`; the user's constraint maps are copied into the flat arrays
/// `vertex_store` and `edge_store`, which `options` points to.
template <class TriangleMesh, class NamedParameters>
Classification_options read_classification_parameters(
    const TriangleMesh& tm, const Flat_mesh& m, const NamedParameters& np,
    const std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>& vertex_list,
    const std::vector<typename boost::graph_traits<TriangleMesh>::edge_descriptor>& edge_list,
    std::vector<unsigned char>& vertex_store, std::vector<unsigned char>& edge_store) {
  using parameters::choose_parameter;
  using parameters::get_parameter;
  CGAL_USE(tm);

  Classification_options options;
  const double feature_angle =
      choose_parameter(get_parameter(np, internal_np::ilsa_feature_angle), defaults::feature_angle);
  options.fix_unattached_candidates = choose_parameter(get_parameter(np, internal_np::ilsa_fix_unattached_candidates),
                                                       defaults::fix_unattached_candidates);
  if (!(feature_angle >= 0 && feature_angle < 180))
    throw ILSA_error("ilsa_feature_angle must be in [0, 180) degrees (the angle between face normals), got " +
                     std::to_string(feature_angle));
  options.feature_angle_degrees = feature_angle;
  // By default a crease vertex is a kink when the crease turns there by more
  // than the surface turns across a sharp edge (user manual, "Crease kinks").
  options.kink_angle_degrees = choose_parameter(get_parameter(np, internal_np::ilsa_crease_kink_angle), feature_angle);
  if (!(options.kink_angle_degrees >= 0 && options.kink_angle_degrees <= 180))
    throw ILSA_error("ilsa_crease_kink_angle must be in [0, 180] degrees, got " +
                     std::to_string(options.kink_angle_degrees));

  options.crease_contrast =
      choose_parameter(get_parameter(np, internal_np::ilsa_crease_contrast), defaults::crease_contrast);
  if (!(options.crease_contrast >= 0 && std::isfinite(options.crease_contrast)))
    throw ILSA_error("ilsa_crease_contrast must be non-negative and finite (0: the paper's rule), got " +
                     std::to_string(options.crease_contrast));

  // Any integer type; its value converted to double (negative or huge: an error).
  const auto minimum_edges = choose_parameter(get_parameter(np, internal_np::ilsa_minimum_open_crease_edges),
                                              defaults::minimum_open_crease_edges);
  if (!(double(minimum_edges) >= 0 && double(minimum_edges) <= 1e9))
    throw ILSA_error("ilsa_minimum_open_crease_edges must be in [0, 1e9] (0: the paper's rule), got " +
                     std::to_string(double(minimum_edges)));
  options.minimum_open_crease_edges = std::size_t(minimum_edges);

  read_constraint_maps(m, np, vertex_list, edge_list, vertex_store, edge_store, options);
  return options;
}

inline void count_types(const Vertex_classification& c, ILSA_statistics& s) {
  s.number_of_kink_vertices = c.number_of_kinks;
  std::size_t* count_of[] = {&s.number_of_smooth_vertices, &s.number_of_ridge_vertices, &s.number_of_corner_vertices,
                             &s.number_of_boundary_vertices}; // in the order of ILSA_vertex_type
  for (ILSA_vertex_type t : c.type) ++*count_of[std::size_t(t)];
}

/// The flat copy of a mesh and its classification: what every stage reads, for the whole call.
template <class TriangleMesh> struct Flat_input {
  std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor> vertices; // in flat order
  Flat_mesh mesh;
  Vertex_classification classification;
};

/// Copies `tm` (points of `vpm`, index maps of `np`) and classifies its
/// vertices with the classification parameters of `np`. `incidences`
/// receives what only the set-up reads; the caller frees it once the
/// constructors that read it have run. Throws `ILSA_error` for a non-triangle
/// face, a non-finite coordinate, an index map that is not one to one or an
/// out-of-range parameter; `tm` is only read.
template <class TriangleMesh, class VertexPointMap, class NamedParameters>
Flat_input<TriangleMesh> classified_flat_copy(const TriangleMesh& tm, const VertexPointMap& vpm,
                                              const NamedParameters& np, Set_up_incidences& incidences) {
  Flat_input<TriangleMesh> input;
  // The user's constraint maps as flat arrays, which `options` points to.
  std::vector<unsigned char> constrained_vertices, constrained_edges;
  Classification_options options;
  {
    // (Without a user map, the vertex numbering is a dynamic property of `tm`;
    // it and the edge descriptors are freed before the classification.)
    std::vector<typename boost::graph_traits<TriangleMesh>::edge_descriptor> edge_list;
    Flat_indices<decltype(vertex_index_map_of(tm, np))> vertex_index{vertex_index_map_of(tm, np), {}};
    input.mesh =
        build_flat_mesh(tm, vpm, input.vertices, vertex_index, face_index_map_of(tm, np), edge_list, incidences);
    options = read_classification_parameters(tm, input.mesh, np, input.vertices, edge_list, constrained_vertices,
                                             constrained_edges);
  }
  input.classification = classify(input.mesh, incidences, options);
  return input;
}

} // namespace ILSA
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_POLYGON_MESH_PROCESSING_INTERNAL_ILSA_SET_UP_H

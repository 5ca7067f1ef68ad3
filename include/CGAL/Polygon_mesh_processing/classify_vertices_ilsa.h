// Copyright (c) 2026 The Polygon_mesh_processing_ILSA authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_POLYGON_MESH_PROCESSING_CLASSIFY_VERTICES_ILSA_H
#define CGAL_POLYGON_MESH_PROCESSING_CLASSIFY_VERTICES_ILSA_H

#include <CGAL/Named_function_parameters.h>
#ifndef CGAL_ILSA_NAMED_PARAMETERS_INTERFACE
#error                                                                                                                 \
    "CGAL's named-parameter list was included without the ILSA tags: put the package's include/ directory before CGAL's in the include path."
#endif

#include <CGAL/Polygon_mesh_processing/ilsa_types.h>
#include <CGAL/Polygon_mesh_processing/internal/ILSA/defaults.h>
#include <CGAL/Polygon_mesh_processing/internal/ILSA/flat_mesh.h>
#include <CGAL/Polygon_mesh_processing/internal/ILSA/vertex_classification.h>

#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/property_map.h>

#include <cmath>
#include <string>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace ILSA {

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
  using vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;
  using edge_descriptor = typename boost::graph_traits<TriangleMesh>::edge_descriptor;
  CGAL_USE(tm);

  Classification_options options;
  const double feature_angle =
      choose_parameter(get_parameter(np, internal_np::ilsa_feature_angle), defaults::feature_angle);
  options.fix_unattached_candidates = choose_parameter(get_parameter(np, internal_np::ilsa_fix_unattached_candidates),
                                                       defaults::fix_unattached_candidates);
  if (!(feature_angle >= 0 && feature_angle < 180))
    throw ILSA_error("ilsa_feature_angle must be in [0, 180) degrees (the angle between face normals), got " +
                     std::to_string(feature_angle));
  // The classification works with the paper's dihedral angle θ_f.
  options.feature_angle_degrees = 180. - feature_angle;
  // By default a crease vertex is a kink when the crease turns there by more
  // than the surface turns across a sharp edge (user manual, "Crease kinks").
  options.kink_angle_degrees = choose_parameter(get_parameter(np, internal_np::ilsa_crease_kink_angle), feature_angle);
  if (!(options.kink_angle_degrees >= 0 && options.kink_angle_degrees <= 180))
    throw ILSA_error("ilsa_crease_kink_angle must be in [0, 180] degrees, got " +
                     std::to_string(options.kink_angle_degrees));

  const auto vcm = choose_parameter(get_parameter(np, internal_np::vertex_is_constrained),
                                    Static_boolean_property_map<vertex_descriptor, false>());
  vertex_store.resize(vertex_list.size());
  for (std::size_t i = 0; i < vertex_list.size(); ++i) vertex_store[i] = get(vcm, vertex_list[i]) ? 1 : 0;
  options.constrained_vertices = &vertex_store;

  if (!parameters::is_default_parameter<NamedParameters, internal_np::edge_is_constrained_t>::value) {
    const auto ecm = choose_parameter(get_parameter(np, internal_np::edge_is_constrained),
                                      Static_boolean_property_map<edge_descriptor, false>());
    edge_store.resize(edge_list.size());
    for (std::size_t i = 0; i < edge_list.size(); ++i) edge_store[i] = get(ecm, edge_list[i]) ? 1 : 0;
    options.constrained_edges = &edge_store;
    // CGAL's relax_constraints (user manual, "Constrained Edges"): unless it is
    // true, the ends of the constrained edges do not move, as in CGAL's smoothers.
    if (!choose_parameter(get_parameter(np, internal_np::relax_constraints), defaults::relax_constraints))
      for (std::size_t i = 0; i < edge_list.size(); ++i)
        if (edge_store[i]) vertex_store[m.edges[i][0]] = vertex_store[m.edges[i][1]] = 1;
  }
  return options;
}

inline void count_types(const Vertex_classification& c, ILSA_statistics& s) {
  s.number_of_kink_vertices = c.number_of_kinks;
  for (ILSA_vertex_type t : c.type) {
    switch (t) {
    case ILSA_vertex_type::Smooth:
      ++s.number_of_smooth_vertices;
      break;
    case ILSA_vertex_type::Ridge:
      ++s.number_of_ridge_vertices;
      break;
    case ILSA_vertex_type::Corner:
      ++s.number_of_corner_vertices;
      break;
    case ILSA_vertex_type::Boundary:
      ++s.number_of_boundary_vertices;
      break;
    }
  }
}

} // namespace ILSA
} // namespace internal

/*!
 * \ingroup PkgPMPILSARef
 * classifies the vertices of a triangle mesh into the four ILSA types
 * (Chen et al. 2007, Section 3): `Boundary` (endpoint of a border edge),
 * `Corner` (fixed feature vertex), `Ridge` (on a crease, exactly two sharp
 * edges) and `Smooth`. This is the classification `smooth_surface_mesh_ilsa()`
 * uses with the same named parameters.
 *
 * With `θ` the feature angle (`ilsa_feature_angle`, the angle between face
 * normals; the paper's dihedral angle is `θ_f = 180° − θ`), a vertex is a
 * ridge candidate when the least-squares normal `x` of its star (`A x = 1`,
 * rows of `A` the unit normals of the incident faces) is longer than
 * `1 / cos(θ / 2)`; an edge between two candidates whose face normals make an
 * angle larger than `θ` is sharp; a candidate with two sharp edges is a
 * ridge vertex, with one or more than two a corner, with none a corner or a
 * smooth vertex (`ilsa_fix_unattached_candidates`). A vertex with two sharp
 * edges where the crease turns by more than `ilsa_crease_kink_angle` is a
 * corner too (a kink). Isolated and non-manifold
 * vertices are corners.
 *
 * @tparam TriangleMesh a model of `VertexListGraph`, `EdgeListGraph`, `FaceListGraph` and `HalfedgeGraph`
 * @tparam VertexTypeMap a model of `WritablePropertyMap` with `vertex_descriptor` as key and
 *         `ILSA_vertex_type` as value
 * @tparam NamedParameters a sequence of named parameters
 *
 * @param tm the triangle mesh
 * @param vertex_type_map receives the type of every vertex
 * @param np an optional sequence of named parameters among the ones listed below
 *
 * \cgalNamedParamsBegin
 *   \cgalParamNBegin{vertex_point_map}
 *     \cgalParamDescription{a property map associating points to the vertices of `tm`}
 *     \cgalParamType{a model of `ReadablePropertyMap` with `vertex_descriptor` as key and `%Point_3` as value}
 *     \cgalParamDefault{`boost::get(CGAL::vertex_point, tm)`}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{vertex_index_map, face_index_map}
 *     \cgalParamDescription{as in `smooth_surface_mesh_ilsa()`}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{ilsa_feature_angle}
 *     \cgalParamDescription{an edge is sharp when the normals of its two faces make an angle larger than this, in
 * degrees (CGAL's convention, as in `detect_sharp_edges()`)} \cgalParamType{`double`, in [0, 180)}
 * \cgalParamDefault{`20` (the paper's dihedral θ_f = 8π/9)} \cgalParamNEnd
 *   \cgalParamNBegin{ilsa_fix_unattached_candidates}
 *     \cgalParamDescription{whether a ridge candidate with no sharp edge is a corner (the paper's rule) or a smooth
 * vertex} \cgalParamType{`bool`} \cgalParamDefault{`true`} \cgalParamNEnd
 *   \cgalParamNBegin{ilsa_crease_kink_angle}
 *     \cgalParamDescription{a vertex with two sharp edges where the crease turns by more than this angle (degrees) is a
 * corner, counted in `number_of_kink_vertices`; `180`: the paper's rule}
 *     \cgalParamType{`double`, in [0, 180]} \cgalParamDefault{`ilsa_feature_angle`}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{vertex_is_constrained_map}
 *     \cgalParamDescription{a property map telling which vertices are fixed; they are reported as corners (boundary
 * vertices stay boundary)} \cgalParamType{a model of `ReadablePropertyMap` with `vertex_descriptor` as key and `bool`
 * as value} \cgalParamDefault{no vertex is constrained} \cgalParamNEnd \cgalParamNBegin{edge_is_constrained_map}
 *     \cgalParamDescription{when given, these edges are the sharp edges, replacing the detection: with
 * `relax_constraints(true)`, a vertex with two constrained edges is a ridge vertex, with one or more than two a
 * corner, with none a smooth vertex; by default every end of a constrained edge is a corner}
 *     \cgalParamType{a model of `ReadablePropertyMap` with `edge_descriptor` as key and `bool` as value}
 *     \cgalParamDefault{sharp edges are detected}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{relax_constraints}
 *     \cgalParamDescription{see `smooth_surface_mesh_ilsa()`} \cgalParamType{`bool`} \cgalParamDefault{`false`}
 *   \cgalParamNEnd
 * \cgalNamedParamsEnd
 *
 * @return the number of vertices of each type (the other counters are zero)
 * @throws ILSA_error for a non-triangle face, a non-finite coordinate or an out-of-range parameter
 */
template <class TriangleMesh, class VertexTypeMap, class NamedParameters = parameters::Default_named_parameters>
ILSA_statistics classify_vertices_ilsa(const TriangleMesh& tm, VertexTypeMap vertex_type_map,
                                       const NamedParameters& np = parameters::default_values()) {
  using parameters::choose_parameter;
  using parameters::get_parameter;
  using GT = boost::graph_traits<TriangleMesh>;

  const auto vpm =
      choose_parameter(get_parameter(np, internal_np::vertex_point), get_const_property_map(CGAL::vertex_point, tm));
  std::vector<typename GT::vertex_descriptor> vertex_list;
  internal::ILSA::Flat_indices<decltype(internal::ILSA::vertex_index_map_of(tm, np))> vertex_index{
      internal::ILSA::vertex_index_map_of(tm, np), {}};
  std::vector<typename GT::edge_descriptor> edge_list;
  const internal::ILSA::Flat_mesh m = internal::ILSA::build_flat_mesh(
      tm, vpm, vertex_list, vertex_index, internal::ILSA::face_index_map_of(tm, np), edge_list);

  std::vector<unsigned char> constrained_vertices, constrained_edges;
  const auto options = internal::ILSA::read_classification_parameters(tm, m, np, vertex_list, edge_list,
                                                                      constrained_vertices, constrained_edges);
  const auto c = internal::ILSA::classify(m, options);
  for (std::size_t i = 0; i < vertex_list.size(); ++i) put(vertex_type_map, vertex_list[i], c.type[i]);

  ILSA_statistics s;
  internal::ILSA::count_types(c, s);
  return s;
}

} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif

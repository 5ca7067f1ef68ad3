// Copyright (c) 2026 The Polygon_mesh_processing_ILSA authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_POLYGON_MESH_PROCESSING_CLASSIFY_VERTICES_ILSA_H
#define CGAL_POLYGON_MESH_PROCESSING_CLASSIFY_VERTICES_ILSA_H

#include <CGAL/Polygon_mesh_processing/ilsa_types.h>
#include <CGAL/Polygon_mesh_processing/internal/ILSA/set_up.h>

#include <CGAL/boost/graph/named_params_helper.h>

#include <cmath>
#include <string>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {

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
 * angle larger than `θ` is sharp; a candidate with two sharp edges is a ridge
 * vertex, with one or more than two a corner. Isolated and non-manifold
 * vertices are corners. Where the paper leaves curvature of coarse organic
 * meshes to be taken for creases, three rules of the package apply (user
 * manual, "Decisions That Differ from the Paper"; `ilsa_paper_variant(true)`
 * turns them off):
 * - crease contrast: such an edge is sharp only if its angle is at least 5
 *   times that of the flatter of the two other edges of each of its faces;
 * - open crease lines: a connected set of fewer than 20 such edges that has
 *   an end (a vertex with one of them only) is curvature, not a crease line;
 *   a candidate left with fewer than two sharp edges by these two rules is
 *   a smooth vertex;
 * - a candidate without sharp edge is a smooth vertex (the paper fixes it as
 *   a corner), and a vertex with two sharp edges where the crease turns by
 *   more than `θ` is a corner (a kink, counted in `number_of_kink_vertices`).
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
 *   \cgalParamNBegin{ilsa_feature_angle}
 *     \cgalParamDescription{an edge is sharp when the normals of its two faces make an angle larger than this,
 *       in degrees (CGAL's convention, as in `detect_sharp_edges()`)}
 *     \cgalParamType{`double`, in [0, 180)}
 *     \cgalParamDefault{`20` (the paper's dihedral θ_f = 8π/9)}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{ilsa_paper_variant}
 *     \cgalParamDescription{if `true`, the paper's rules: every edge beyond the feature angle between two
 *       candidates is sharp, a candidate without sharp edge is a corner, no kink rule}
 *     \cgalParamType{`bool`}
 *     \cgalParamDefault{`false`}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{vertex_is_constrained_map}
 *     \cgalParamDescription{a property map telling which vertices are fixed; they are reported as corners
 *       (boundary vertices stay boundary)}
 *     \cgalParamType{a model of `ReadablePropertyMap` with `vertex_descriptor` as key and `bool` as value}
 *     \cgalParamDefault{no vertex is constrained}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{edge_is_constrained_map}
 *     \cgalParamDescription{when given, these edges are the sharp edges, replacing the detection and its rules:
 *       with `relax_constraints(true)`, a vertex with two constrained edges is a ridge vertex, with one or more
 *       than two a corner, with none a smooth vertex; by default every end of a constrained edge is a corner}
 *     \cgalParamType{a model of `ReadablePropertyMap` with `edge_descriptor` as key and `bool` as value}
 *     \cgalParamDefault{sharp edges are detected}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{relax_constraints}
 *     \cgalParamDescription{see `smooth_surface_mesh_ilsa()`}
 *     \cgalParamType{`bool`}
 *     \cgalParamDefault{`false`}
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

  const auto vpm =
      choose_parameter(get_parameter(np, internal_np::vertex_point), get_const_property_map(CGAL::vertex_point, tm));
  internal::ILSA::Set_up_incidences incidences;
  const auto input = internal::ILSA::classified_flat_copy(tm, vpm, np, incidences);
  const auto& c = input.classification;
  for (std::size_t i = 0; i < input.vertices.size(); ++i) put(vertex_type_map, input.vertices[i], c.type[i]);

  ILSA_statistics s;
  internal::ILSA::count_types(c, s);
  return s;
}

} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_POLYGON_MESH_PROCESSING_CLASSIFY_VERTICES_ILSA_H

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
#include <CGAL/Polygon_mesh_processing/internal/ILSA/flat_mesh.h>
#include <CGAL/Polygon_mesh_processing/internal/ILSA/read_parameters.h>
#ifndef CGAL_ILSA_COMPILED_CORE
#include <CGAL/Polygon_mesh_processing/internal/ILSA/vertex_classification.h> // classify()
#endif

#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace ILSA {

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
/// out-of-range parameter; `tm` is only read. `rules`, when given, replaces
/// the classification rules that `np` selects (the tests and the benchmark
/// vary them; the user's constraint maps are still read from `np`).
template <class TriangleMesh, class VertexPointMap, class NamedParameters>
Flat_input<TriangleMesh> classified_flat_copy(const TriangleMesh& tm, const VertexPointMap& vpm,
                                              const NamedParameters& np, Set_up_incidences& incidences,
                                              const Classification_options* rules = nullptr) {
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
    options = rules ? *rules : read_classification_options(np);
    read_constraint_maps(input.mesh, np, input.vertices, edge_list, constrained_vertices, constrained_edges, options);
  }
  input.classification = classify(input.mesh, incidences, options);
  return input;
}

} // namespace ILSA
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_POLYGON_MESH_PROCESSING_INTERNAL_ILSA_SET_UP_H

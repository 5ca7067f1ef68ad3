// Copyright (c) 2026 The Polygon_mesh_processing_ILSA authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What the classification stage (paper §3) hands to the smoothing stages:
// the vertex types, the sharp and feature edges and the crease lines, the
// options it runs with, and which vertices move with which neighbours.

#ifndef CGAL_POLYGON_MESH_PROCESSING_INTERNAL_ILSA_CLASSIFICATION_H
#define CGAL_POLYGON_MESH_PROCESSING_INTERNAL_ILSA_CLASSIFICATION_H

#include <CGAL/Polygon_mesh_processing/ilsa_types.h>
#include <CGAL/Polygon_mesh_processing/internal/ILSA/defaults.h>
#include <CGAL/Polygon_mesh_processing/internal/ILSA/flat_mesh.h>

#include <array>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace ILSA {

/// What the classification stage hands to the smoothing stages (read for the
/// whole call; the intermediate results stay inside classify()).
struct Vertex_classification {
  std::vector<ILSA_vertex_type> type;
  std::vector<Index> crease_of_edge;                // crease polyline of a sharp edge, npos for the other edges
  std::vector<unsigned char> feature_edge;          // sharp, or (without the user's edge map) dihedral angle below θ_f
                                                    // and, with a crease contrast, kept by it
  std::vector<std::array<Index, 2>> attached_edges; // a ridge vertex's two sharp edges
  std::size_t number_of_kinks = 0;                  // vertices with two sharp edges fixed as kinks

  bool is_fixed(std::size_t v) const {
    return type[v] == ILSA_vertex_type::Corner || type[v] == ILSA_vertex_type::Boundary;
  }
  bool is_sharp(std::size_t e) const { return crease_of_edge[e] != npos; }
};

/// The rules of the classification: the package's by default, the paper's
/// with `ilsa_paper_variant(true)` (user manual, "The Paper's Variant").
struct Classification_options {
  // Angle between face normals above which an edge is sharp (CGAL's convention; the paper's θ_f is 180° minus it).
  double feature_angle_degrees = defaults::feature_angle;
  // Candidate without sharp edge: smooth, or a corner (the paper).
  bool fix_unattached_candidates = false;
  // A crease turning by more than this at a vertex makes it a corner (user
  // manual, "Crease Kinks"): the feature angle; 180 in the paper's variant.
  double kink_angle_degrees = defaults::feature_angle;
  // A feature edge between candidates is sharp only if its angle is at least this times the angle of the flatter
  // of the two other edges of each of its faces (user manual, "Crease Contrast"); 0: every one is (the paper).
  double crease_contrast = defaults::crease_contrast;
  // An open set of connected feature edges with fewer edges is curvature (user manual, "Open Crease Lines");
  // 0: none is dropped (the paper).
  std::size_t minimum_open_crease_edges = defaults::minimum_open_crease_edges;
  const std::vector<unsigned char>* constrained_vertices = nullptr; // user's vertex_is_constrained_map
  const std::vector<unsigned char>* constrained_edges = nullptr;    // user's edge_is_constrained_map

  /// The rules for `feature_angle` degrees, the paper's when `paper_variant`.
  static Classification_options rules(double feature_angle, bool paper_variant) {
    Classification_options o;
    o.feature_angle_degrees = o.kink_angle_degrees = feature_angle;
    if (paper_variant) {
      o.fix_unattached_candidates = true;
      o.kink_angle_degrees = 180.;
      o.crease_contrast = 0.;
      o.minimum_open_crease_edges = 0;
    }
    return o;
  }
};

/// Which vertices move and which neighbours drive them (paper's Algo. 2): all one-ring
/// vertices for a smooth node, only its two attached-sharp nodes for a ridge node.
struct ILSA_neighborhoods {
  const Flat_mesh* mesh = nullptr;
  const Vertex_classification* classification = nullptr;
  std::vector<Index> adjustable; // smooth and ridge vertices allowed to move
  std::vector<Index> smooth;     // the smooth ones among them (Algo. 3)

  /// Calls `f(w, e)` for each neighbour `w` driving the adjustable vertex `v`
  /// and the edge `e` between them, in the order of the one ring.
  template <class F> void for_each_neighbor(std::size_t v, F f) const {
    const Vertex_classification& c = *classification;
    if (c.type[v] == ILSA_vertex_type::Ridge) {
      for (std::size_t e : c.attached_edges[v]) {
        const auto& ends = mesh->edges[e];
        f(std::size_t(ends[0] == v ? ends[1] : ends[0]), e); // its attached-sharp node
      }
      return;
    }
    const Index* e = mesh->vertex_edges.first(v);
    for (const Index* w = mesh->vertex_neighbors.first(v); w != mesh->vertex_neighbors.last(v); ++w, ++e)
      f(std::size_t(*w), std::size_t(*e));
  }
};

/// `movable[v]` is false for the vertices outside the user's range. `m` and
/// `c` must outlive the result: it keeps pointers.
inline ILSA_neighborhoods make_neighborhoods(const Flat_mesh& m, const Vertex_classification& c,
                                             const std::vector<unsigned char>& movable) {
  ILSA_neighborhoods nb;
  nb.mesh = &m;
  nb.classification = &c;
  for (std::size_t v = 0; v < m.number_of_vertices(); ++v) {
    if (c.is_fixed(v) || !movable[v]) continue;
    nb.adjustable.push_back(Index(v));
    if (c.type[v] != ILSA_vertex_type::Ridge) nb.smooth.push_back(Index(v));
  }
  nb.adjustable.shrink_to_fit();
  nb.smooth.shrink_to_fit();
  return nb;
}

} // namespace ILSA
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_POLYGON_MESH_PROCESSING_INTERNAL_ILSA_CLASSIFICATION_H

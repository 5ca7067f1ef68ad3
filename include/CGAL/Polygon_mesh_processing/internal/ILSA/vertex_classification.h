// Copyright (c) 2026 The Polygon_mesh_processing_ILSA authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Stage 1 of ILSA (paper §3): discrete normals by least squares, ridge
// candidates, sharp edges, attached-sharp nodes and the four vertex types.

#ifndef CGAL_POLYGON_MESH_PROCESSING_INTERNAL_ILSA_VERTEX_CLASSIFICATION_H
#define CGAL_POLYGON_MESH_PROCESSING_INTERNAL_ILSA_VERTEX_CLASSIFICATION_H

#include <CGAL/Polygon_mesh_processing/ilsa_types.h>
#include <CGAL/Polygon_mesh_processing/internal/ILSA/core.h>
#include <CGAL/Polygon_mesh_processing/internal/ILSA/defaults.h>
#include <CGAL/Polygon_mesh_processing/internal/ILSA/feature_lines.h>
#include <CGAL/Polygon_mesh_processing/internal/ILSA/flat_mesh.h>
#include <CGAL/Polygon_mesh_processing/internal/ILSA/least_squares.h>
#include <CGAL/Polygon_mesh_processing/internal/ILSA/parallel_loops.h>
#include <CGAL/Polygon_mesh_processing/internal/ILSA/union_find.h>

#include <CGAL/number_type_config.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace ILSA {

/// Discrete normal `x` of vertex `v` (paper §3): least-squares solution of
/// `A x = 1`, the rows of `A` being the unit normals of the faces around `v`.
/// Solved through the normal equations `AᵀA x = Aᵀ1` with the SVD; a relative
/// threshold of 1e-12 on the singular values of `AᵀA` (1e-6 on those of `A`)
/// makes a flat star rank 1, giving `x = n` and `|x| = 1`.
/// `face_normal(f)` gives the unit normal of face `f` (zero when degenerate).
template <class FaceNormal> Vec3 discrete_normal(const Flat_mesh& m, std::size_t v, const FaceNormal& face_normal) {
  Eigen::Matrix3d AtA = Eigen::Matrix3d::Zero();
  Vec3 At1 = Vec3::Zero();
  for (const Index* f = m.vertex_faces.first(v); f != m.vertex_faces.last(v); ++f) {
    const Vec3 n = face_normal(std::size_t(*f));
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 3; ++i) AtA(i, j) += n[j] * n[i]; // Eigen's order for AtA += n nᵀ
    At1 += n;
  }
  if (At1.isZero(0)) return Vec3::Zero();
  return solve_by_svd(AtA, At1, 1e-12);
}
/// The same with the unit normals of all faces in `face_normals`.
inline Vec3 discrete_normal(const Flat_mesh& m, const std::vector<Vec3>& face_normals, std::size_t v) {
  return discrete_normal(m, v, [&](std::size_t f) -> const Vec3& { return face_normals[f]; });
}

/// Unit normals of all faces for the positions `pos`.
template <class ConcurrencyTag = CGAL::Sequential_tag>
void compute_face_normals(const Flat_mesh& m, const std::vector<Vec3>& pos, std::vector<Vec3>& normals) {
  normals.resize(m.number_of_faces());
  parallel_for<ConcurrencyTag>(m.number_of_faces(), [&](std::size_t f) { normals[f] = unit_normal(pos, m.faces[f]); });
}

/// The crease contrast (user manual, "Crease Contrast"): keeps a feature edge
/// (and a sharp edge) only if keeps_crease_contrast() says so. A feature edge
/// it drops is curvature, not a crease line: it is no longer a feature edge,
/// so the crease bound of the safety check does not hold it either. `curved`
/// is set for the ends of the sharp edges it drops.
inline void keep_contrasted_creases(const Flat_mesh& m, const Set_up_incidences& incidences,
                                    const std::vector<Vec3>& face_normals, double contrast,
                                    std::vector<unsigned char>& feature_edge, std::vector<unsigned char>& sharp_edge,
                                    std::vector<unsigned char>& curved) {
  const std::size_t ne = m.edges.size();
  auto angle_of = [&](std::size_t e) {
    const auto& fs = incidences.edge_faces[e];
    if (fs[0] == npos || fs[1] == npos) return 0.;
    return normal_angle(face_normals[fs[0]].dot(face_normals[fs[1]]));
  };
  // The edge from `a` to `b` (vertex_neighbors is sorted), or npos.
  auto edge_between = [&](Index a, Index b) {
    const Index* first = m.vertex_neighbors.first(a);
    const Index* last = m.vertex_neighbors.last(a);
    const Index* found = std::lower_bound(first, last, b);
    return found != last && *found == b ? m.vertex_edges.items[m.vertex_edges.begin[a] + std::size_t(found - first)]
                                        : npos;
  };
  // Per face: the angle of the flatter of its two edges other than `e` (the
  // angles are computed where needed: few edges are feature edges, and an
  // array of them would add to the peak memory of large meshes). An edge of a
  // degenerate face, whose normal is zero, counts as flat there.
  auto flat_next_to_degenerate = [&](std::size_t g) {
    const auto& fs = incidences.edge_faces[g];
    if (fs[0] != npos && fs[1] != npos && (face_normals[fs[0]].isZero(0) || face_normals[fs[1]].isZero(0))) return 0.;
    return angle_of(g);
  };
  auto wing = [&](std::size_t f, std::size_t e) {
    double flatter = std::numeric_limits<double>::infinity();
    const auto& t = m.faces[f];
    for (int k = 0; k < 3; ++k) {
      const Index g = edge_between(t[k], t[(k + 1) % 3]);
      if (g != npos && g != e) flatter = (std::min)(flatter, flat_next_to_degenerate(g));
    }
    return flatter == std::numeric_limits<double>::infinity() ? 0. : flatter;
  };
  for (std::size_t e = 0; e < ne; ++e) {
    if (!feature_edge[e] && !sharp_edge[e]) continue;
    const auto& fs = incidences.edge_faces[e];
    if (keeps_crease_contrast(angle_of(e), wing(fs[0], e), wing(fs[1], e), contrast)) continue;
    feature_edge[e] = 0;
    if (sharp_edge[e]) sharp_edge[e] = 0, curved[m.edges[e][0]] = curved[m.edges[e][1]] = 1;
  }
}

/// The intermediate results of classify().
struct Classification_work {
  std::vector<Vec3> face_normals;
  std::vector<unsigned char> ridge_candidate; // per vertex: |x| above the feature threshold
  std::vector<unsigned char> sharp_edge;      // per edge (paper §3 or the user's edge map)
  std::vector<unsigned char> curved;          // per vertex: lost a sharp edge to the contrast or the open-crease rule
};

/// Feature edges: face normals more than the feature angle apart (the
/// paper's dihedral angle below θ_f). Not with the user's edge map, whose
/// edges are the sharp edges (mark_sharp_edges()).
inline void mark_feature_edges(const Flat_mesh& m, const Set_up_incidences& incidences,
                               const Classification_options& opt, Vertex_classification& c,
                               const Classification_work& w) {
  if (opt.constrained_edges) return;
  const double sharp_cosine = feature_cosine(opt.feature_angle_degrees);
  for (std::size_t e = 0; e < m.edges.size(); ++e) {
    const auto& fs = incidences.edge_faces[e];
    if (fs[0] != npos && fs[1] != npos)
      c.feature_edge[e] = w.face_normals[fs[0]].dot(w.face_normals[fs[1]]) < sharp_cosine;
  }
}

/// Boundary vertices, isolated and non-manifold vertices (corners), and the
/// ridge candidates among the others: the discrete normal longer than a fold
/// at the feature angle makes it (user manual, "Feature Angle Convention"). A candidate
/// counts only at the end of a feature edge (a sharp edge joins two; one
/// without sharp edge stays smooth) unless `fix_unattached_candidates` fixes
/// the others: the discrete normal, an SVD, is computed where it counts.
inline void mark_fixed_and_candidates(const Flat_mesh& m, const Set_up_incidences& incidences,
                                      const Classification_options& opt, Vertex_classification& c,
                                      Classification_work& w) {
  const double candidate_length = 1. / std::cos(feature_normal_deviation(opt.feature_angle_degrees) / 2.);
  auto counts = [&](std::size_t v) {
    if (opt.fix_unattached_candidates) return true;
    for (const Index* e = m.vertex_edges.first(v); e != m.vertex_edges.last(v); ++e)
      if (c.feature_edge[*e]) return true;
    return false;
  };
  for (std::size_t v = 0; v < m.number_of_vertices(); ++v) {
    if (incidences.on_border[v])
      c.type[v] = ILSA_vertex_type::Boundary;
    else if (m.vertex_faces.size(v) == 0 || incidences.non_manifold[v])
      c.type[v] = ILSA_vertex_type::Corner;
    else if (!opt.constrained_edges && counts(v))
      w.ridge_candidate[v] = discrete_normal(m, w.face_normals, v).norm() > candidate_length;
  }
}

/// Sharp edges: feature edges between two ridge candidates (paper §3), or the
/// user's constrained edges; the feature edges that the crease contrast or
/// the open-crease rule drops are neither.
inline void mark_sharp_edges(const Flat_mesh& m, const Set_up_incidences& incidences, const Classification_options& opt,
                             Vertex_classification& c, Classification_work& w) {
  for (std::size_t e = 0; e < m.edges.size(); ++e) {
    // Such an edge is sharp (a crease edge) only between two ridge
    // candidates; the others are still feature edges the safety check keeps.
    const auto& ends = m.edges[e];
    w.sharp_edge[e] = opt.constrained_edges
                          ? (*opt.constrained_edges)[e]
                          : c.feature_edge[e] && w.ridge_candidate[ends[0]] && w.ridge_candidate[ends[1]];
  }
  if (!opt.constrained_edges && opt.crease_contrast > 0) {
    w.curved.assign(m.number_of_vertices(), 0);
    keep_contrasted_creases(m, incidences, w.face_normals, opt.crease_contrast, c.feature_edge, w.sharp_edge, w.curved);
  }
  if (!opt.constrained_edges && opt.minimum_open_crease_edges > 1) {
    // The sharp edges are feature edges here: a sharp edge the rule drops
    // makes its ends `curved`, as the contrast does.
    drop_short_open_lines(
        m.number_of_vertices(), [&m](std::size_t e) { return m.edges[e]; },
        [&incidences](std::size_t v) { return incidences.on_border[v] != 0; }, c.feature_edge,
        opt.minimum_open_crease_edges);
    if (w.curved.empty()) w.curved.assign(m.number_of_vertices(), 0);
    for (std::size_t e = 0; e < m.edges.size(); ++e)
      if (w.sharp_edge[e] && !c.feature_edge[e])
        w.sharp_edge[e] = 0, w.curved[m.edges[e][0]] = w.curved[m.edges[e][1]] = 1;
  }
  for (std::size_t e = 0; e < m.edges.size(); ++e) c.feature_edge[e] = c.feature_edge[e] || w.sharp_edge[e];
}

/// The types of the candidates from their sharp edges (paper §3, user edges
/// overriding): two make a ridge vertex, or a corner where the crease turns
/// by more than the kink angle; one or more than two a corner; none a corner
/// or a smooth vertex (`fix_unattached_candidates`).
inline void type_candidates(const Flat_mesh& m, const Classification_options& opt, const Classification_work& w,
                            Vertex_classification& c) {
  // Kink (user manual, "Crease Kinks"): the crease's direction turns at `v`
  // by more than the kink angle, i.e. its two sharp edges meet at less than
  // 180° minus it. A vertex there is the tip of the crease: sliding would cut
  // it off. A zero-length sharp edge has no direction and counts as a kink.
  const double kink_cosine = -std::cos(opt.kink_angle_degrees * CGAL_PI / 180.);
  auto is_kink = [&](const Vec3& v, const Vec3& a, const Vec3& b) {
    if (!(opt.kink_angle_degrees < 180.)) return false;
    const double la = (a - v).norm(), lb = (b - v).norm();
    return la == 0 || lb == 0 || (a - v).dot(b - v) > kink_cosine * la * lb;
  };
  for (std::size_t v = 0; v < m.number_of_vertices(); ++v) {
    if (c.type[v] != ILSA_vertex_type::Smooth) continue;
    std::size_t count = 0;
    std::array<Index, 2> attached_sharp{npos, npos}; // the first two attached-sharp nodes
    const Index* nb = m.vertex_neighbors.first(v);
    for (const Index* e = m.vertex_edges.first(v); e != m.vertex_edges.last(v); ++e, ++nb) {
      if (!w.sharp_edge[*e]) continue;
      if (count < 2) {
        attached_sharp[count] = *nb;
        c.attached_edges[v][count] = *e;
      }
      ++count;
    }
    const bool candidate = opt.constrained_edges ? count > 0 : bool(w.ridge_candidate[v]);
    if (!candidate) continue;
    // Where the crease contrast or the open-crease rule dropped sharp edges,
    // fewer than two left: a vertex of a curved surface (or the end of a
    // crease fading into it).
    if (!w.curved.empty() && w.curved[v] && count < 2) continue;
    if (count == 2 && is_kink(m.points[v], m.points[attached_sharp[0]], m.points[attached_sharp[1]])) {
      c.type[v] = ILSA_vertex_type::Corner;
      ++c.number_of_kinks;
    } else if (count == 2)
      c.type[v] = ILSA_vertex_type::Ridge;
    else if (count != 0 || opt.fix_unattached_candidates)
      c.type[v] = ILSA_vertex_type::Corner;
  }
}

/// Crease polylines: sharp edges chained through ridge vertices (union-find).
inline void chain_creases(const Flat_mesh& m, const Classification_work& w, Vertex_classification& c) {
  const std::size_t ne = m.edges.size();
  Index_union_find<> creases(ne);
  for (std::size_t v = 0; v < m.number_of_vertices(); ++v)
    if (c.type[v] == ILSA_vertex_type::Ridge) creases.unite(c.attached_edges[v][0], c.attached_edges[v][1]);
  for (std::size_t e = 0; e < ne; ++e)
    if (w.sharp_edge[e]) c.crease_of_edge[e] = creases.find(e);
}

inline namespace CGAL_ILSA_CORE_NAMESPACE { // core.h

/// Classifies the vertices of `m` (paper §3), user constraints overriding.
/// `incidences`: those of `m` (read here only).
CGAL_ILSA_CORE_INLINE Vertex_classification classify(const Flat_mesh& m, const Set_up_incidences& incidences,
                                                     const Classification_options& opt) {
  const std::size_t nv = m.number_of_vertices(), ne = m.edges.size();
  Vertex_classification c;
  c.type.assign(nv, ILSA_vertex_type::Smooth);
  c.crease_of_edge.assign(ne, npos);
  c.feature_edge.assign(ne, 0);
  c.attached_edges.assign(nv, {npos, npos});
  Classification_work w;
  w.ridge_candidate.assign(nv, 0);
  w.sharp_edge.assign(ne, 0);
  compute_face_normals(m, m.points, w.face_normals);

  mark_feature_edges(m, incidences, opt, c, w);
  mark_fixed_and_candidates(m, incidences, opt, c, w);
  mark_sharp_edges(m, incidences, opt, c, w);
  type_candidates(m, opt, w, c);
  if (opt.constrained_vertices)
    for (std::size_t v = 0; v < nv; ++v)
      if ((*opt.constrained_vertices)[v] && c.type[v] != ILSA_vertex_type::Boundary)
        c.type[v] = ILSA_vertex_type::Corner;
  for (std::size_t v = 0; v < nv; ++v)
    if (c.type[v] != ILSA_vertex_type::Ridge) c.attached_edges[v] = {npos, npos};
  chain_creases(m, w, c);
  return c;
}

} // namespace CGAL_ILSA_CORE_NAMESPACE

} // namespace ILSA
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_POLYGON_MESH_PROCESSING_INTERNAL_ILSA_VERTEX_CLASSIFICATION_H

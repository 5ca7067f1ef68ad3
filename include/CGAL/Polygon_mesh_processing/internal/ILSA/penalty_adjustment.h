// Copyright (c) 2026 The Polygon_mesh_processing_ILSA authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Stage 3 of ILSA (paper's Algo. 3): the displacement of every smooth
// vertex is corrected toward the minimiser of the quadratic penalty function
//   Q(x; μ) = g(x) + (1/μ) c(x)²,
//   g(x)    = wl (1/n) Σ_j |x − p_j|² + wa Σ_j β_j s(x, p_j, p_j+1)²,
// a "soap film" that keeps the star taut and so non-inverted.

#ifndef CGAL_POLYGON_MESH_PROCESSING_INTERNAL_ILSA_PENALTY_ADJUSTMENT_H
#define CGAL_POLYGON_MESH_PROCESSING_INTERNAL_ILSA_PENALTY_ADJUSTMENT_H

#include <CGAL/Polygon_mesh_processing/internal/ILSA/core.h>
#include <CGAL/Polygon_mesh_processing/internal/ILSA/defaults.h>
#include <CGAL/Polygon_mesh_processing/internal/ILSA/flat_mesh.h>
#include <CGAL/Polygon_mesh_processing/internal/ILSA/ilsa_displacement.h>
#include <CGAL/Polygon_mesh_processing/internal/ILSA/jacobi_sweeps.h>
#include <CGAL/Polygon_mesh_processing/internal/ILSA/least_squares.h>
#include <CGAL/Polygon_mesh_processing/internal/ILSA/vertex_classification.h>

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace ILSA {

/// Plane of the soft constraint c(x) = 0 (user manual, "Plane Constraint Units and Area Weights"), as `a · (x − v) = k`
/// with unit `a`. With no displacement yet it is the tangent plane at `v`, whose normal N(v) (paper §3, normalised)
/// `vertex_normal()` computes; otherwise the plane through `v + d` perpendicular to `d`. The paper's second form, `d ·
/// (x − v) − |d|²`, is this one multiplied by `|d|`: normalising it gives c the unit of a length in both cases, so μ is
/// scale-free. N(v) is only computed for a zero displacement: its least-squares solve is needed for few vertices, if
/// any.
template <class VertexNormal> std::pair<Vec3, double> penalty_plane(const Vec3& d, const VertexNormal& vertex_normal) {
  const double length = d.norm();
  if (length > 0) return {d / length, length};
  return {vertex_normal(), 0.};
}

/// Unit discrete normal N(v) of the smooth vertex `v` (paper §3) at the
/// positions `pos`, or zero. The normals of its faces are computed here: few
/// vertices, if any, need N(v) (see penalty_plane()).
inline Vec3 unit_vertex_normal(const Flat_mesh& m, const std::vector<Vec3>& pos, std::size_t v) {
  const Vec3 n = discrete_normal(m, v, [&](std::size_t f) { return unit_normal(pos, m.faces[f]); });
  return n.norm() > 0 ? Vec3(n.normalized()) : n;
}

/// `displacement` of vertex `v` without its component along the area-weighted
/// normal of its faces at `pos` (user manual, "Fewer, Longer Iterations"): the
/// move stays in the tangent plane, and the projection onto the input only
/// corrects the curvature. Unchanged for a vertex whose faces have no area.
/// The normal is computed at each call rather than stored: the penalty sweeps
/// call this for every smooth vertex, and an array of normals would cost 24
/// bytes per vertex (user manual, "Tangential Displacements").
inline Vec3 without_normal_component(const Flat_mesh& m, const std::vector<Vec3>& pos, std::size_t v,
                                     const Vec3& displacement) {
  Vec3 n = Vec3::Zero();
  for (const Index* f = m.vertex_faces.first(v); f != m.vertex_faces.last(v); ++f) n += area_vector(pos, m.faces[*f]);
  const double length = n.norm();
  if (!(length > 0) || !std::isfinite(length)) return displacement;
  n /= length;
  return displacement - displacement.dot(n) * n;
}

/// Solution of `H x = r` for the symmetric positive definite 3x3 `H` (its lower
/// triangle is read) by its cofactors: x = adj(H) r / det(H), one division
/// (this solve runs for every smooth vertex in every sweep; a Cholesky
/// factorisation takes three square roots and nine divisions in a chain).
/// The caller bounds the condition number of `H` (see
/// minimize_penalty_function()), so that the error is, like Cholesky's, a
/// small multiple of the condition number times the rounding unit
/// (test_ilsa_smoothing compares the two). Returns false when the determinant
/// is not positive and finite.
inline bool solve_by_cofactors(const Eigen::Matrix3d& H, const Vec3& r, Vec3& x) {
  const double a = H(0, 0), b = H(1, 0), c = H(2, 0), e = H(1, 1), f = H(2, 1), g = H(2, 2);
  // The cofactors (adj(H) is symmetric).
  const double A = e * g - f * f, B = c * f - b * g, C = b * f - c * e;
  const double det = a * A + b * B + c * C;
  if (!(det > 0) || !std::isfinite(det)) return false;
  const double E = a * g - c * c, F = b * c - a * f, G = a * e - b * b;
  const double inverse = 1. / det;
  x = Vec3(A * r(0) + B * r(1) + C * r(2), B * r(0) + E * r(1) + F * r(2), C * r(0) + F * r(1) + G * r(2)) * inverse;
  return x.allFinite();
}

/// Minimiser of Q(x; μ) for the smooth vertex `v`, relative to `pos[v]`.
/// Every term is quadratic in x, so ∇Q = 0 is the 3x3 system H x = r. H is
/// symmetric: only its lower triangle is accumulated. `target` holds
/// `pos[w] + d[w]` of each vertex `w`, three coordinates each.
inline Vec3 minimize_penalty_function(const Flat_mesh& m, const std::vector<Vec3>& pos, const std::vector<Vec3>& d,
                                      const std::vector<double>& target, const std::vector<double>& beta, std::size_t v,
                                      const Penalty_parameters& p) {
  const Vec3& x0 = pos[v];
  auto pending = [&](std::size_t w) -> Vec3 { return Vec3(target[3 * w], target[3 * w + 1], target[3 * w + 2]) - x0; };

  // Length term: ∇ = 2 wl (x − mean p_j).
  Eigen::Matrix3d H = 2. * p.length_weight * Eigen::Matrix3d::Identity();
  Vec3 mean = Vec3::Zero();
  for (const Index* w = m.vertex_neighbors.first(v); w != m.vertex_neighbors.last(v); ++w) mean += pending(*w);
  Vec3 r = (2. * p.length_weight / double(m.vertex_neighbors.size(v))) * mean;

  // Area term: 2 s(x, a, b) = |e × x + a × b| with e = b − a, so
  // ∇ (β s²) = (β/2) (|e|² I − e eᵀ) x + (β/2) (a × b) × e.
  for (const Index* f = m.vertex_faces.first(v); f != m.vertex_faces.last(v); ++f) {
    const auto& t = m.faces[*f];
    const std::size_t k = t[0] == v ? 0 : (t[1] == v ? 1 : 2);
    const Vec3 a = pending(t[(k + 1) % 3]), b = pending(t[(k + 2) % 3]);
    const Vec3 e = b - a;
    const double w = 0.5 * p.area_weight * beta[*f];
    const double s = e.squaredNorm();
    for (int j = 0; j < 3; ++j)
      for (int i = j; i < 3; ++i) H(i, j) += w * ((i == j ? s : 0.) - e(i) * e(j));
    r += w * e.cross(a.cross(b));
  }

  // Penalty term (1/μ) (a·x − k)².
  const auto plane = penalty_plane(d[v], [&] { return unit_vertex_normal(m, pos, v); });
  const Vec3 scaled = (2. / p.mu) * plane.first;
  for (int j = 0; j < 3; ++j)
    for (int i = j; i < 3; ++i) H(i, j) += plane.first(j) * scaled(i);
  r += (2. / p.mu) * plane.second * plane.first;

  // Every term is positive semi-definite and the length term adds 2 wl I, so H
  // is positive definite with condition number at most trace(H) / (2 wl):
  // below 1e8, its cofactors solve it about as accurately as Cholesky (see
  // solve_by_cofactors()), at a small fraction of the SVD's cost.
  Vec3 x;
  if (2. * p.length_weight >= 1e-8 * H.trace() && solve_by_cofactors(H, r, x)) return x;
  H(0, 1) = H(1, 0), H(0, 2) = H(2, 0), H(1, 2) = H(2, 1); // the SVD reads the whole matrix
  return solve_by_svd(H, r, 1e-12);
}

/// Algo. 3 on the smooth vertices of `nb`; `d` holds Algo. 2's displacements on
/// entry and the adjusted ones on exit; `buffer` is the sweeps' second buffer,
/// `beta` receives β = 1 / s(v, v_j, v_j+1) per face of the current mesh and
/// `target`, before each sweep, the unprojected target `pos + d` of each
/// vertex, which every neighbour's solve reads up to three times (all three
/// overwritten: the caller lends arrays it does not need meanwhile).
/// With `p.tangential`, each sweep keeps every displacement in the
/// tangent plane of its vertex (see without_normal_component()).
/// Returns the number of sweeps run.
template <class ConcurrencyTag>
std::size_t adjust_displacement_by_penalty(const Flat_mesh& m, const std::vector<Vec3>& pos,
                                           const ILSA_neighborhoods& nb, const Penalty_parameters& p,
                                           std::vector<Vec3>& d, std::vector<double>& beta, std::vector<Vec3>& buffer,
                                           std::vector<double>& target) {
  // β_j from the current faces; a floor at 1e-3 of the mean area keeps a
  // degenerate face from swamping the star.
  beta.resize(m.number_of_faces());
  parallel_for<ConcurrencyTag>(m.number_of_faces(),
                               [&](std::size_t f) { beta[f] = 0.5 * area_vector(pos, m.faces[f]).norm(); });
  double mean_area = 0; // summed in face order, whatever the number of threads
  for (double area : beta) mean_area += area;
  mean_area /= double((std::max)(m.number_of_faces(), std::size_t(1)));
  const double smallest_area = (std::max)(1e-3 * mean_area, 1e-300);
  parallel_for<ConcurrencyTag>(m.number_of_faces(),
                               [&](std::size_t f) { beta[f] = 1. / (std::max)(beta[f], smallest_area); });

  target.resize((std::max)(target.size(), 3 * pos.size()));
  const auto update = [&](std::size_t v) {
    const Vec3 d_new = minimize_penalty_function(m, pos, d, target, beta, v, p);
    const Vec3 mixed = p.relax2 * d_new + (1. - p.relax2) * d[v];
    return p.tangential ? without_normal_component(m, pos, v, mixed) : mixed;
  };
  const auto set_targets = [&] {
    parallel_for<ConcurrencyTag>(pos.size(), [&](std::size_t w) {
      const Vec3 at = pos[w] + d[w];
      for (int i = 0; i < 3; ++i) target[3 * w + i] = at[i];
    });
  };
  return run_jacobi_sweeps<ConcurrencyTag>(nb.smooth, p.sweeps, p.tolerance, d, buffer, update, set_targets);
}

} // namespace ILSA
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_POLYGON_MESH_PROCESSING_INTERNAL_ILSA_PENALTY_ADJUSTMENT_H

// Copyright (c) 2026 The Polygon_mesh_processing_ILSA authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The quality tests of the safety check: the quality floor (user manual,
// "Quality Floor") and the worsening test ("Worsening Moves"), on the star of
// a moved vertex, and the aspect ratio they and the convergence stop compute.

#ifndef CGAL_POLYGON_MESH_PROCESSING_INTERNAL_ILSA_STAR_QUALITY_H
#define CGAL_POLYGON_MESH_PROCESSING_INTERNAL_ILSA_STAR_QUALITY_H

#include <CGAL/Polygon_mesh_processing/triangle_quality_ilsa.h>
#include <CGAL/Polygon_mesh_processing/internal/ILSA/flat_mesh.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace ILSA {

/// Aspect ratio of a triangle from twice its area and its squared edge
/// lengths (opposite to its vertices 0, 1, 2): the edge vectors and lengths of
/// triangle_quality_ilsa() in the same order, hence the same value, bit for
/// bit (test_ilsa_smoothing checks it).
inline double aspect_ratio_from(double double_area, const std::array<double, 3>& squared_length) {
  return aspect_ratio_of_shape(
      double_area, {std::sqrt(squared_length[0]), std::sqrt(squared_length[1]), std::sqrt(squared_length[2])});
}

/// triangle_quality_ilsa(a, b, c), small enough to be inlined where the
/// safety check and the convergence stop compute many.
inline double aspect_ratio(const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 ab = b - a;
  return aspect_ratio_from(ab.cross(c - a).norm(), {(c - b).squaredNorm(), (a - c).squaredNorm(), ab.squaredNorm()});
}

/// The quality floor and the worsening test on the stars of `original`.
class Star_quality_test {
public:
  struct Star_quality {
    double worst = 1., mean = 0.;
  };
  /// What a move did to its star.
  enum class Verdict { pass, floor, floor_from_above, worsening };

  /// `quality_floor`: a move may not lower the minimum aspect ratio of the
  /// vertex's star to below this value (0: no floor). `reject_worsening`: a
  /// move may not lower the mean aspect ratio of the star, the neighbours being
  /// at their new positions. `original` must outlive the test.
  Star_quality_test(const Flat_mesh& original, double quality_floor, bool reject_worsening)
      : m_(original), quality_floor_(quality_floor), reject_worsening_(reject_worsening) {}

  /// Whether a test runs at all.
  bool enabled() const { return quality_floor_ > 0 || reject_worsening_; }
  bool rejects_worsening() const { return reject_worsening_; }

  /// The tests of the move of `v` from `previous` to `next`, whose faces pass
  /// the flip and collapse tests; `quality_now` holds the aspect ratios of
  /// its faces at `next`. The worst triangle of the star may not get worse
  /// and end below the floor (`floor_from_above`: the star was at or above
  /// the floor before the move); then its mean may not drop.
  Verdict test(const std::vector<Vec3>& previous, const std::vector<Vec3>& next, std::size_t v,
               const std::vector<double>& quality_now) const {
    const Star_quality now = now_from(v, quality_now);
    if (quality_floor_ > 0 && now.worst < quality_floor_) {
      const double before = at(previous, v, previous[v]).worst;
      if (now.worst < before) return before < quality_floor_ ? Verdict::floor : Verdict::floor_from_above;
    }
    if (reject_worsening_ && now.mean < at(next, v, previous[v]).mean) return Verdict::worsening;
    return Verdict::pass;
  }

  /// The worsening pre-test (user manual, "Worsening Moves"): whether the
  /// mean aspect ratio of the star of `v`, every vertex at its target
  /// `pos + d`, is lower than with `v` staying at `pos[v]`.
  bool worse_at_targets(const std::vector<Vec3>& pos, const std::vector<Vec3>& d, std::size_t v) const {
    auto target = [&](std::size_t w) -> Vec3 { return pos[w] + d[w]; };
    auto staying = [&](std::size_t w) -> Vec3 { return w == v ? pos[v] : target(w); };
    return at_points(v, target).mean < at_points(v, staying).mean;
  }

private:
  // at(next, v, next[v]) from the aspect ratios of the faces at `next`
  // computed in the current round (`quality_now`), summed in the same order.
  Star_quality now_from(std::size_t v, const std::vector<double>& quality_now) const {
    Star_quality q;
    for (const Index* f = m_.vertex_faces.first(v); f != m_.vertex_faces.last(v); ++f) {
      q.worst = (std::min)(q.worst, quality_now[*f]);
      q.mean += quality_now[*f];
    }
    q.mean /= double((std::max)(m_.vertex_faces.size(v), std::size_t(1)));
    return q;
  }

  // Worst and mean aspect ratio around `v`, with `v` at `point` and the others at `pos`.
  Star_quality at(const std::vector<Vec3>& pos, std::size_t v, const Vec3& point) const {
    return at_points(v, [&](std::size_t w) -> const Vec3& { return w == v ? point : pos[w]; });
  }

  // The same with each vertex `w` of the star at `point(w)`.
  template <class Point> Star_quality at_points(std::size_t v, const Point& point) const {
    Star_quality q;
    for (const Index* f = m_.vertex_faces.first(v); f != m_.vertex_faces.last(v); ++f) {
      const auto& t = m_.faces[*f];
      const double r = aspect_ratio(point(t[0]), point(t[1]), point(t[2]));
      q.worst = (std::min)(q.worst, r);
      q.mean += r;
    }
    q.mean /= double((std::max)(m_.vertex_faces.size(v), std::size_t(1)));
    return q;
  }

  const Flat_mesh& m_;
  double quality_floor_;
  bool reject_worsening_;
};

} // namespace ILSA
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_POLYGON_MESH_PROCESSING_INTERNAL_ILSA_STAR_QUALITY_H

// Copyright (c) 2026 The Polygon_mesh_processing_ILSA authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The crease bound (`ilsa_fidelity_tolerance` along the feature lines; user
// manual, "Fidelity Certificate"): every point of every smoothed feature edge lies
// within the tolerance of its input line, and every point of every input
// feature edge within the tolerance of the smoothed line. The feature lines
// are the crease polylines (the sharp edges, or the user's constrained
// edges) and, each a line of its own, the other feature edges the
// classification keeps. Each edge is bounded as a whole (segment_bound(),
// distance_certificate.h), both ways:
// - a smoothed edge against the input edges of its line around its ends and
//   around their neighbours on the line; it depends on its two ends;
// - an input edge against the smoothed edges of its line at its ends; it
//   depends on their ends.
// As for the surface (fidelity_certificate.h), the smoothing starts where
// every bound is 0 and accepts only certified states.

#ifndef CGAL_POLYGON_MESH_PROCESSING_INTERNAL_ILSA_CREASE_CERTIFICATE_H
#define CGAL_POLYGON_MESH_PROCESSING_INTERNAL_ILSA_CREASE_CERTIFICATE_H

#include <CGAL/Polygon_mesh_processing/internal/ILSA/core.h>
#include <CGAL/Polygon_mesh_processing/internal/ILSA/distance_certificate.h>
#include <CGAL/Polygon_mesh_processing/internal/ILSA/flat_mesh.h>
#include <CGAL/Polygon_mesh_processing/internal/ILSA/parallel_loops.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace ILSA {

class Crease_certificate {
public:
  /// `tolerance` in the normalised units of `mesh` (infinity: no bound).
  /// `mesh` and `classification` must outlive the certificate.
  Crease_certificate(const Flat_mesh& mesh, const Vertex_classification& classification, double tolerance)
      : m_(mesh), c_(classification), tolerance_(tolerance), limit_(tolerance - certificate_margin) {
    if (!std::isfinite(tolerance_)) return;
    for (std::size_t e = 0; e < m_.edges.size(); ++e)
      if (c_.feature_edge[e]) features_.push_back(Index(e));
    stamp_.assign(features_.size(), 0);
  }

  bool enabled() const { return std::isfinite(tolerance_) && !features_.empty(); }

  /// Checks the feature edges whose bounds the moves of `changed` (positions
  /// `pos`) may have changed, and calls `blame(w)` for vertices a failed
  /// edge depends on, in edge order; `blame(w)` returns whether the move of
  /// `w` is shortened.
  template <class ConcurrencyTag, class Blame>
  void check(const std::vector<Vec3>& pos, const std::vector<Index>& changed, const Blame& blame) {
    if (!enabled() || changed.empty()) return;
    if (++round_ == 0) std::fill(stamp_.begin(), stamp_.end(), 0), round_ = 1;
    checked_.clear();
    auto mark = [&](std::size_t e) {
      const std::size_t slot = slot_of(e);
      if (stamp_[slot] != round_) stamp_[slot] = round_, checked_.push_back(Index(e));
    };
    // The edges at a moved vertex and, for the input direction, at its
    // neighbours on its lines.
    for (std::size_t v : changed)
      for_each_feature_edge(v, [&](std::size_t e) {
        mark(e);
        for_each_feature_edge(other_end(e, v), mark);
      });
    failed_.assign(checked_.size(), 0);
    parallel_for<ConcurrencyTag>(checked_.size(), [&](std::size_t i) {
      failed_[i] = !(output_distance(pos, checked_[i], limit_) <= limit_) ||
                   !(input_distance(pos, checked_[i], limit_) <= limit_);
    });
    // A failed edge shortens the moves of its ends first; only when neither
    // can be shortened, those of the other vertices it depends on.
    for (std::size_t i = 0; i < checked_.size(); ++i) {
      if (!failed_[i]) continue;
      const auto& ends = m_.edges[checked_[i]];
      bool blamed = false;
      for (std::size_t w : ends) blamed = blame(w) || blamed;
      if (blamed) continue;
      for (std::size_t w : ends)
        for_each_line_edge(w, line_of(checked_[i]),
                           [&](std::size_t e) { blame(m_.edges[e][0]), blame(m_.edges[e][1]); });
    }
  }

  /// The largest distance between the smoothed feature lines at `pos` and the
  /// input's, both ways, certified (0 without feature edges; infinity without
  /// a tolerance).
  double largest_bound(const std::vector<Vec3>& pos) const {
    if (!std::isfinite(tolerance_)) return std::numeric_limits<double>::infinity();
    double worst = 0;
    const double loose = std::numeric_limits<double>::max();
    for (std::size_t e : features_)
      worst = (std::max)({worst, output_distance(pos, e, limit_, loose), input_distance(pos, e, limit_, loose)});
    return worst;
  }

private:
  // A crease edge belongs to its crease polyline; another feature edge is a line of its own.
  std::size_t line_of(std::size_t e) const { return c_.crease_of_edge[e] != npos ? c_.crease_of_edge[e] : e; }
  std::size_t slot_of(std::size_t e) const {
    return std::size_t(std::lower_bound(features_.begin(), features_.end(), Index(e)) - features_.begin());
  }
  std::size_t other_end(std::size_t e, std::size_t v) const {
    return m_.edges[e][0] == v ? m_.edges[e][1] : m_.edges[e][0];
  }
  template <class F> void for_each_feature_edge(std::size_t w, const F& f) const {
    for (const Index* e = m_.vertex_edges.first(w); e != m_.vertex_edges.last(w); ++e)
      if (c_.feature_edge[*e]) f(*e);
  }
  template <class F> void for_each_line_edge(std::size_t w, std::size_t line, const F& f) const {
    for_each_feature_edge(w, [&](std::size_t e) {
      if (line_of(e) == line) f(e);
    });
  }

  // Edges of a line around an edge, at most `capacity`, `e` first.
  struct Edge_candidates {
    static constexpr std::size_t capacity = 32;
    std::array<Index, capacity> edge;
    std::size_t n = 0;
    void add(std::size_t e) {
      if (n < capacity &&
          std::find(edge.begin(), edge.begin() + std::ptrdiff_t(n), Index(e)) == edge.begin() + std::ptrdiff_t(n))
        edge[n++] = Index(e);
    }
  };

  // Smoothed edge `e` at `pos` against the input edges of its line at its ends
  // and at their neighbours on the line; when `loose` is finite, a bound above
  // `limit` is also returned (for the report), else infinity.
  double output_distance(const std::vector<Vec3>& pos, std::size_t e, double limit,
                         double loose = std::numeric_limits<double>::infinity()) const {
    Edge_candidates candidates;
    candidates.add(e);
    const std::size_t line = line_of(e);
    for (std::size_t w : m_.edges[e])
      for_each_line_edge(w, line, [&](std::size_t x) {
        candidates.add(x);
        for_each_line_edge(other_end(x, w), line, [&](std::size_t y) { candidates.add(y); });
      });
    return bound(pos[m_.edges[e][0]], pos[m_.edges[e][1]], candidates, m_.points, limit, loose);
  }
  // Input edge `e` against the smoothed edges (at `pos`) of its line at its ends.
  double input_distance(const std::vector<Vec3>& pos, std::size_t e, double limit,
                        double loose = std::numeric_limits<double>::infinity()) const {
    Edge_candidates candidates;
    candidates.add(e);
    for (std::size_t w : m_.edges[e]) for_each_line_edge(w, line_of(e), [&](std::size_t x) { candidates.add(x); });
    return bound(m_.points[m_.edges[e][0]], m_.points[m_.edges[e][1]], candidates, pos, limit, loose);
  }
  double bound(const Vec3& p, const Vec3& q, const Edge_candidates& candidates, const std::vector<Vec3>& at,
               double limit, double loose) const {
    auto candidate = [&](std::size_t k) {
      const auto& ends = m_.edges[candidates.edge[k]];
      return std::array<Vec3, 2>{at[ends[0]], at[ends[1]]};
    };
    const double b = segment_bound(p, q, candidates.n, candidate, limit);
    return b <= limit || !(loose < std::numeric_limits<double>::infinity())
               ? b
               : segment_bound(p, q, candidates.n, candidate, loose);
  }

  const Flat_mesh& m_;
  const Vertex_classification& c_;
  double tolerance_, limit_;
  std::vector<Index> features_; // the feature edges, in increasing order
  std::vector<std::uint32_t> stamp_;
  std::uint32_t round_ = 0;
  std::vector<Index> checked_;
  std::vector<unsigned char> failed_;
};

} // namespace ILSA
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_POLYGON_MESH_PROCESSING_INTERNAL_ILSA_CREASE_CERTIFICATE_H

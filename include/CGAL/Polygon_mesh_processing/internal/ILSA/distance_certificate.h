// Copyright (c) 2026 The Polygon_mesh_processing_ILSA authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Certified one-sided distances, without sampling (user manual, "Fidelity Certificate"): an upper bound of the largest
// distance from the points of a triangle (or a segment) to a union of triangles (or segments).
//
// The distance to one convex set is a convex function, so over a convex piece
// of the triangle it is largest at a vertex of the piece. The triangle is cut
// into convex pieces along the footprints of the candidates seen along its
// normal: over the piece under a candidate, that candidate is close, and the
// largest of its distances at the piece's corners bounds the distance of every
// point of the piece. A piece that no footprint covers (a fold, a face seen
// edge-on, a gap left by rounding) is bounded by the best candidate at its
// corners. The cut is only a choice of pieces: every bound stays sound
// whatever the footprints are, since any candidate bounds the distance to the
// union. Rounding: the pieces' corners are rounded to within a few units in
// the last place of the coordinates, so callers compare the bound with the
// tolerance less `certificate_margin`.

#ifndef CGAL_POLYGON_MESH_PROCESSING_INTERNAL_ILSA_DISTANCE_CERTIFICATE_H
#define CGAL_POLYGON_MESH_PROCESSING_INTERNAL_ILSA_DISTANCE_CERTIFICATE_H

#include <CGAL/Polygon_mesh_processing/internal/ILSA/flat_mesh.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <utility>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace ILSA {

/// What a certified bound must stay below the tolerance by, in the normalised
/// units of the flat copy (the bounding-box diagonal is 1): it covers the
/// rounding of the pieces' corners and of the distances, which is of the
/// order of 1e-16 there.
constexpr double certificate_margin = 1e-12;

namespace certificate {
/// Pieces this close to the line they were cut along are left out (their
/// points are within this distance of the pieces kept); far below the margin.
constexpr double on_line_distance = 1e-14;
} // namespace certificate

namespace certificate {

struct Point2 {
  double x, y;
};

/// A convex polygon with at most `capacity` corners (clipping one by a
/// half-plane adds at most one corner; a piece that would need more is not
/// cut further, which only loosens the bound).
struct Polygon2 {
  static constexpr int capacity = 16;
  std::array<Point2, capacity> p;
  int n = 0;
  double lo_x = 0, hi_x = 0, lo_y = 0, hi_y = 0; // bounding box, set by Pieces::push()

  // Copies the corners only (the whole array would be most of the work).
  void assign(const Polygon2& other) {
    n = other.n;
    std::copy(other.p.begin(), other.p.begin() + n, p.begin());
    lo_x = other.lo_x, hi_x = other.hi_x, lo_y = other.lo_y, hi_y = other.hi_y;
  }
  void set_box() {
    lo_x = hi_x = p[0].x, lo_y = hi_y = p[0].y;
    for (int i = 1; i < n; ++i) {
      lo_x = (std::min)(lo_x, p[std::size_t(i)].x), hi_x = (std::max)(hi_x, p[std::size_t(i)].x);
      lo_y = (std::min)(lo_y, p[std::size_t(i)].y), hi_y = (std::max)(hi_y, p[std::size_t(i)].y);
    }
  }
};

inline double cross(const Point2& o, const Point2& a, const Point2& b) {
  return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

/// The part of `in` on the side of the line through `a` and `b` where
/// `sign * cross(a, b, x) >= 0`. Returns false when it has more corners than
/// Polygon2 holds (`out` is then unusable).
inline bool clip(const Polygon2& in, const Point2& a, const Point2& b, double sign, Polygon2& out) {
  out.n = 0;
  if (in.n == 0) return true;
  std::array<double, Polygon2::capacity> side;
  bool all_in = true, all_out = true;
  for (int i = 0; i < in.n; ++i) {
    side[std::size_t(i)] = sign * cross(a, b, in.p[std::size_t(i)]);
    all_in = all_in && side[std::size_t(i)] >= 0;
    all_out = all_out && side[std::size_t(i)] < 0;
  }
  if (all_out) return true;
  if (all_in) {
    out.n = in.n;
    std::copy(in.p.begin(), in.p.begin() + in.n, out.p.begin());
    return true;
  }
  for (int i = 0, j = 1; i < in.n; ++i, j = j + 1 == in.n ? 0 : j + 1) {
    const Point2& p = in.p[std::size_t(i)];
    const Point2& q = in.p[std::size_t(j)];
    const double sp = side[std::size_t(i)], sq = side[std::size_t(j)];
    if (sp >= 0) {
      if (out.n == Polygon2::capacity) return false;
      out.p[std::size_t(out.n++)] = p;
    }
    if ((sp > 0 && sq < 0) || (sp < 0 && sq > 0)) {
      if (out.n == Polygon2::capacity) return false;
      const double t = sp / (sp - sq);
      out.p[std::size_t(out.n++)] = {p.x + t * (q.x - p.x), p.y + t * (q.y - p.y)};
    }
  }
  return true;
}

/// An orthonormal frame of the plane of a triangle, its first corner at the origin.
struct Frame {
  Vec3 origin, u, w, normal; // normal: the unit normal, u x w
  Point2 to2(const Vec3& x) const {
    const Vec3 r = x - origin;
    return {r.dot(u), r.dot(w)};
  }
  Vec3 to3(const Point2& p) const { return origin + p.x * u + p.y * w; }
};

/// The frame of the plane of the triangle `a b c` whose normal (not zero) is
/// `normal`: its origin at `a`, u along `ab`.
inline Frame plane_frame(const Vec3& a, const Vec3& b, const Vec3& normal) {
  Frame frame;
  frame.origin = a;
  frame.u = (b - a) / (b - a).norm();
  frame.normal = normal / normal.norm();
  frame.w = frame.normal.cross(frame.u);
  return frame;
}

/// Pieces not yet bounded; at most `capacity`.
struct Pieces {
  static constexpr int capacity = 32;
  std::array<Polygon2, capacity> piece;
  int n = 0;
  bool push(const Polygon2& p) {
    if (p.n < 3) return true; // no interior: its points lie on the other pieces' sides
    if (n == capacity) return false;
    piece[std::size_t(n)].assign(p);
    piece[std::size_t(n++)].set_box();
    return true;
  }
  // Removes piece `i`, replaced by the last one.
  void remove(int i) {
    if (i != --n) piece[std::size_t(i)].assign(piece[std::size_t(n)]);
  }
};

// Largest squared distance from the corners of `piece` (lifted by `frame`) to
// `candidate`, or more than `limit2` once one corner is farther; `far` is then
// that corner.
template <class Triangle>
double corner_bound(const Polygon2& piece, const Frame& frame, const Triangle& t, double limit2, Vec3* far = nullptr) {
  double worst = 0;
  for (int i = 0; i < piece.n; ++i) {
    const Vec3 x = frame.to3(piece.p[i]);
    worst = (std::max)(worst, squared_distance_to_triangle(x, t[0], t[1], t[2]));
    if (worst > limit2) {
      if (far) *far = x;
      break;
    }
  }
  return worst;
}

// The smallest over the candidates, taken from `first` on (cyclically), of
// corner_bound(), stopping at the first one within `limit2`.
template <class Candidate>
double best_corner_bound(const Polygon2& piece, const Frame& frame, std::size_t n, const Candidate& candidate,
                         std::size_t first, double limit2) {
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t j = 0; j < n && best > limit2; ++j)
    best = (std::min)(best, corner_bound(piece, frame, candidate((first + j) % n), limit2));
  return best;
}

// Whether every corner of `piece` is within `limit` of a candidate (if not,
// no choice of pieces can bound the triangle); `far` is then such a corner.
template <class Candidate>
bool corners_near(const Polygon2& piece, const Frame& frame, std::size_t n, const Candidate& candidate, double limit2,
                  Vec3* far = nullptr) {
  for (int i = 0; i < piece.n; ++i) {
    const Vec3 x = frame.to3(piece.p[std::size_t(i)]);
    bool near = false;
    for (std::size_t k = 0; k < n && !near; ++k) {
      const std::array<Vec3, 3> t = candidate(k);
      near = squared_distance_to_triangle(x, t[0], t[1], t[2]) <= limit2;
    }
    if (!near) {
      if (far) *far = x;
      return false;
    }
  }
  return true;
}

/// A triangle is too thin for a frame of its plane when twice its area is at
/// most this fraction of its longest edge squared. It protects the frames of
/// height_bound() and triangle_bound(), whose normal comes from the cross
/// product of two edges: such a triangle is bounded through its longest edge.
constexpr double thin_ratio = 1e-9;

// Whether a triangle of that double area and longest squared edge is too thin
// for a frame of its plane.
inline bool is_thin(double double_area, double longest_squared) {
  return !(double_area > thin_ratio * longest_squared);
}

/// The clearance of the nearness tests of height_bound(), in the normalised
/// units of the flat copy; far below the margin.
constexpr double clearance = 1e-13;
/// The smallest cosine of the angle between a candidate and the triangle that
/// height_bound() takes (about 84 degrees): its heights grow with the slope.
constexpr double minimum_cosine = 0.1;
/// A candidate's bound from the corners of its footprint or of the triangle,
/// without cutting out the part under it, is kept when it is at most this
/// fraction of the limit.
constexpr double loose_enough = 0.5;

// A counterclockwise triangle for the nearness tests of height_bound(): its
// corners, box and the lengths of its edges (edge i from corner i to i + 1).
struct Clear_triangle {
  Polygon2 t;
  std::array<double, 3> length;
  explicit Clear_triangle(const Polygon2& triangle) : t(triangle) {
    for (std::size_t i = 0; i < 3; ++i) {
      const Point2 &a = t.p[i], &b = t.p[(i + 1) % 3];
      length[i] = std::sqrt((b.x - a.x) * (b.x - a.x) + (b.y - a.y) * (b.y - a.y));
    }
  }
  // Whether the segment `pq` is farther than `clearance` from the triangle:
  // some edge line of the triangle, or the segment's own line, has the
  // triangle on one side and the segment beyond the clearance on the other.
  // (Not finding such a line only costs the quicker bound.)
  bool clear_of(const Point2& p, const Point2& q) const {
    for (std::size_t i = 0; i < 3; ++i) {
      const Point2 &a = t.p[i], &b = t.p[(i + 1) % 3];
      const double gap = -clearance * length[i]; // outside is where cross(a, b, x) < 0
      if (cross(a, b, p) < gap && cross(a, b, q) < gap) return true;
    }
    const double dx = q.x - p.x, dy = q.y - p.y;
    const double gap = clearance * (std::abs(dx) + std::abs(dy)); // at least clearance * |pq|
    if (!(gap > 0)) return false;
    const double s0 = cross(p, q, t.p[0]), s1 = cross(p, q, t.p[1]), s2 = cross(p, q, t.p[2]);
    return (s0 > gap && s1 > gap && s2 > gap) || (s0 < -gap && s1 < -gap && s2 < -gap);
  }
};

} // namespace certificate

/// Segment version of triangle_bound(): an upper bound of the largest distance
/// from the points of the segment `pq` to the union of the segments
/// `candidate(0) .. candidate(n - 1)` (each a `std::array<Vec3, 2>`), or
/// infinity when no bound of at most `limit` is found. The segment is cut at
/// the ends of the candidates' footprints on its line.
template <class Candidate>
double segment_bound(const Vec3& p, const Vec3& q, std::size_t n, const Candidate& candidate, double limit) {
  const double limit2 = limit * limit, inf = std::numeric_limits<double>::infinity();
  const Vec3 pq = q - p;
  const double l2 = pq.squaredNorm();
  auto at = [&](double s) -> Vec3 { return p + s * pq; };
  auto piece_bound = [&](double s0, double s1, const std::array<Vec3, 2>& c) {
    const double d0 = squared_distance_to_segment(at(s0), c[0], c[1]);
    return d0 > limit2 ? d0 : (std::max)(d0, squared_distance_to_segment(at(s1), c[0], c[1]));
  };
  std::array<std::pair<double, double>, 16> open;
  int n_open = 0;
  open[n_open++] = {0., 1.};
  double worst = 0;
  for (std::size_t k = 0; k < n && n_open > 0 && l2 > 0; ++k) {
    const std::array<Vec3, 2> c = candidate(k);
    double lo = (c[0] - p).dot(pq) / l2, hi = (c[1] - p).dot(pq) / l2;
    if (lo > hi) std::swap(lo, hi);
    if (!(hi > lo)) continue;
    for (int i = 0; i < n_open; ++i) {
      const double s0 = (std::max)(open[i].first, lo), s1 = (std::min)(open[i].second, hi);
      if (!(s1 > s0)) continue;
      const double b = piece_bound(s0, s1, c);
      if (b > limit2) continue;
      worst = (std::max)(worst, b);
      const std::pair<double, double> left{open[i].first, s0}, right{s1, open[i].second};
      open[i] = open[--n_open]; // the piece is bounded; what lies outside the footprint stays open
      if (right.second > right.first) {
        if (n_open == int(open.size())) return inf;
        open[n_open++] = right;
      }
      if (left.second > left.first) {
        if (n_open == int(open.size())) return inf;
        open[n_open++] = left;
      }
      --i; // look at the piece moved into slot i
    }
  }
  for (int i = 0; i < n_open; ++i) { // by the best candidate at the ends
    double best = inf;
    for (std::size_t k = 0; k < n && best > limit2; ++k)
      best = (std::min)(best, piece_bound(open[i].first, open[i].second, candidate(k)));
    if (best > limit2) return inf;
    worst = (std::max)(worst, best);
  }
  return std::sqrt(worst);
}

/// A quicker bound for the usual case, where the candidates, seen along the
/// normal of the triangle `abc`, form a height field over it: an upper bound
/// of the largest distance from the points of `abc` to the union of the
/// candidates, or infinity when this way finds none of at most `limit` (then
/// triangle_bound() decides). `candidate(k)` gives the corners of candidate
/// `k` (a `std::array<Vec3, 3>`); `cancelled(k, i)` whether the edge from its
/// corner i to corner i + 1 is cancelled by the reverse edges of the other
/// candidates (false when unsure: it costs only the quicker bound). When it
/// finds a point of the triangle farther than `limit` from every candidate
/// (then no bound exists), `*far` is that point and `*has_far` true.
///
/// The argument (user manual, "Fidelity Certificate"): project the candidates
/// onto the plane of `abc`. For a point x of the plane on none of their
/// edges, the number of candidate footprints containing x, each counted +1 or
/// -1 by its orientation, is the winding number around x of the boundary of
/// the candidates taken as a chain (their directed edges, an edge and its
/// reverse cancelling). When no edge of that boundary comes near the
/// triangle, this number is the same for all its points; if it is at least
/// 1 at one of them, every point x of the triangle lies in the footprint of
/// a positively oriented candidate t: the triangle is covered by the parts
/// under these candidates (points on their edges by continuity). The point
/// of t straight above or below x is at the height z_t(x) of t's plane over
/// x, so the distance from x to t is at most |z_t(x)|, an affine function in
/// absolute value: over the part under t it is largest at a corner of that
/// part, and at most its largest value at the corners of t's footprint or of
/// the triangle (both contain the part). The bound of a part is
/// - the smaller of these two, if it is at most the bound found so far or
///   than `loose_enough` times the limit (the part is not cut out);
/// - else the largest height at the corners of the part;
/// - else, if that exceeds the limit, the largest distance of these corners
///   to t or to another candidate (convexity again).
/// The bound of the triangle is the largest bound of its parts. A steep
/// candidate (its plane at more than about 84 degrees from the triangle's)
/// is left to triangle_bound(), as are thin triangles.
/// Rounding: the nearness tests keep a clearance of `certificate::clearance`,
/// and the corners and heights are exact for positions within a few units in
/// the last place of the given ones, which the margin covers.
template <class Candidate, class Cancelled>
double height_bound(const Vec3& a, const Vec3& b, const Vec3& c, std::size_t n, const Candidate& candidate,
                    const Cancelled& cancelled, double limit, Vec3* far = nullptr, bool* has_far = nullptr) {
  using namespace certificate;
  constexpr std::size_t capacity = 64;
  const double inf = std::numeric_limits<double>::infinity();
  if (n == 0 || n > capacity) return inf;
  const Vec3 normal = (b - a).cross(c - a);
  if (is_thin(normal.norm(), (std::max)({(b - a).squaredNorm(), (c - b).squaredNorm(), (a - c).squaredNorm()})))
    return inf;
  const Frame frame = plane_frame(a, b, normal);
  Polygon2 triangle;
  triangle.n = 3;
  triangle.p[0] = {0., 0.}, triangle.p[1] = frame.to2(b), triangle.p[2] = frame.to2(c); // counterclockwise
  triangle.set_box();
  const Point2 inside{(triangle.p[1].x + triangle.p[2].x) / 3, (triangle.p[1].y + triangle.p[2].y) / 3};

  // The candidates in the frame: corners, heights, orientation.
  std::array<std::array<Point2, 3>, capacity> q;
  std::array<std::array<double, 3>, capacity> h;
  std::array<double, capacity> area;
  std::array<std::array<double, 4>, capacity> box; // of the footprint: lowest x, highest x, lowest y, highest y
  int winding = 0;
  for (std::size_t k = 0; k < n; ++k) {
    const std::array<Vec3, 3> t = candidate(k);
    for (std::size_t i = 0; i < 3; ++i) {
      const Vec3 r = t[i] - a; // (a is the frame's origin)
      q[k][i] = {r.dot(frame.u), r.dot(frame.w)};
      h[k][i] = r.dot(frame.normal);
    }
    const std::array<Point2, 3>& f = q[k];
    box[k] = {(std::min)({f[0].x, f[1].x, f[2].x}), (std::max)({f[0].x, f[1].x, f[2].x}),
              (std::min)({f[0].y, f[1].y, f[2].y}), (std::max)({f[0].y, f[1].y, f[2].y})};
    area[k] = cross(f[0], f[1], f[2]);
    if (area[k] == 0) continue;
    // The winding number at `inside`, if it is clear of the edges.
    if (inside.x + clearance < box[k][0] || inside.x - clearance > box[k][1] || inside.y + clearance < box[k][2] ||
        inside.y - clearance > box[k][3])
      continue;
    const double sign = area[k] > 0 ? 1. : -1.;
    bool in = true;
    for (std::size_t i = 0; i < 3; ++i) {
      const Point2 &p = q[k][i], &r = q[k][(i + 1) % 3];
      const double side = sign * cross(p, r, inside);
      const double length = std::abs(r.x - p.x) + std::abs(r.y - p.y);
      if (std::abs(side) <= clearance * length) return inf; // near the line: undecided
      in = in && side > 0;
    }
    if (in) winding += area[k] > 0 ? 1 : -1;
  }
  if (winding < 1) return inf;

  // No edge of the chain's boundary near the triangle.
  const Clear_triangle clear(triangle);
  const double lo_x = triangle.lo_x - clearance, hi_x = triangle.hi_x + clearance;
  const double lo_y = triangle.lo_y - clearance, hi_y = triangle.hi_y + clearance;
  for (std::size_t k = 0; k < n; ++k)
    for (std::size_t i = 0; i < 3; ++i) {
      if (cancelled(k, i)) continue;
      const Point2 &p = q[k][i], &r = q[k][(i + 1) % 3];
      if ((std::max)(p.x, r.x) < lo_x || (std::min)(p.x, r.x) > hi_x || (std::max)(p.y, r.y) < lo_y ||
          (std::min)(p.y, r.y) > hi_y)
        continue;
      if (!clear.clear_of(p, r)) return inf;
    }

  // The heights over the parts of the triangle under the positive candidates.
  double bound = 0;
  Polygon2 cell, scratch;
  for (std::size_t k = 0; k < n; ++k) {
    if (!(area[k] > 0)) continue;
    // The part under the candidate lies both in its footprint and in the
    // triangle: the heights at the corners of either bound it.
    if (box[k][1] < triangle.lo_x || box[k][0] > triangle.hi_x || box[k][3] < triangle.lo_y ||
        box[k][2] > triangle.hi_y)
      continue;
    const std::array<Point2, 3>& f = q[k];
    const double highest = (std::max)({std::abs(h[k][0]), std::abs(h[k][1]), std::abs(h[k][2])});
    if (highest <= bound) continue;
    // The steepness: the footprint's area against the candidate's, from its
    // corners in the frame (orthonormal: x, y and the height).
    const double ex = f[1].x - f[0].x, ey = f[1].y - f[0].y, fx = f[2].x - f[0].x, fy = f[2].y - f[0].y;
    const double dh1 = h[k][1] - h[k][0], dh2 = h[k][2] - h[k][0];
    if (!(area[k] > minimum_cosine * Vec3(ex, ey, dh1).cross(Vec3(fx, fy, dh2)).norm())) return inf;
    // z(p) = h0 + g . (p - q0), g from the two other corners.
    const double gx = (dh1 * fy - dh2 * ey) / area[k], gy = (ex * dh2 - fx * dh1) / area[k];
    auto z = [&](const Point2& p) { return std::abs(h[k][0] + gx * (p.x - f[0].x) + gy * (p.y - f[0].y)); };
    const double loose = (std::min)(highest, (std::max)({z(triangle.p[0]), z(triangle.p[1]), z(triangle.p[2])}));
    if (loose <= (std::max)(bound, loose_enough * limit)) {
      bound = (std::max)(bound, loose);
      continue;
    }
    if (!clip(triangle, f[0], f[1], 1., cell) || !clip(cell, f[1], f[2], 1., scratch) ||
        !clip(scratch, f[2], f[0], 1., cell))
      return inf;
    if (cell.n < 3) continue;
    double height = 0;
    for (int i = 0; i < cell.n; ++i) height = (std::max)(height, z(cell.p[std::size_t(i)]));
    if (height <= limit) {
      bound = (std::max)(bound, height);
      continue;
    }
    // Too high: the distances from the cell's corners to this candidate, or
    // else to the best of the others, bound the cell as well (convexity).
    const double limit2 = limit * limit;
    const double best = best_corner_bound(cell, frame, n, candidate, k, limit2);
    if (best > limit2) {
      // A corner farther than `limit` from every candidate: no bound exists.
      if (!corners_near(cell, frame, n, candidate, limit2, far) && has_far) *has_far = far != nullptr;
      return inf;
    }
    bound = (std::max)(bound, std::sqrt(best));
  }
  return bound;
}

/// An upper bound of the largest distance from the points of the triangle
/// `abc` to the union of the triangles `candidate(0) .. candidate(n - 1)`
/// (each a `std::array<Vec3, 3>`), or infinity when no bound of at most
/// `limit` is found. Candidates that cover much of the triangle are best
/// given first: each one bounds the piece under its footprint, and a first
/// candidate that bounds the whole triangle at its corners ends the work.
/// When the bound fails because a point of the triangle is farther than
/// `limit` from every candidate, `*far` is that point and `*has_far` true.
template <class Candidate>
double triangle_bound(const Vec3& a, const Vec3& b, const Vec3& c, std::size_t n, const Candidate& candidate,
                      double limit, Vec3* far = nullptr, bool* has_far = nullptr) {
  using namespace certificate;
  const double limit2 = limit * limit, inf = std::numeric_limits<double>::infinity();
  if (n == 0) return inf;
  // A thin triangle: each of its points lies within the distance h of its
  // third corner to its longest edge (convexity again), so the edge's bound
  // plus h bounds the triangle.
  const Vec3 normal = (b - a).cross(c - a);
  const std::array<double, 3> l2{(c - b).squaredNorm(), (a - c).squaredNorm(), (b - a).squaredNorm()};
  const int longest = int(std::max_element(l2.begin(), l2.end()) - l2.begin());
  if (is_thin(normal.norm(), l2[std::size_t(longest)])) {
    const std::array<Vec3, 3> abc{a, b, c};
    const Vec3 &p = abc[std::size_t(longest + 1) % 3], &q = abc[std::size_t(longest + 2) % 3];
    const double h = std::sqrt(squared_distance_to_segment(abc[std::size_t(longest)], p, q));
    if (!(h < limit)) return inf;
    const double edge = segment_bound(
        p, q, 3 * n,
        [&](std::size_t k) {
          const std::array<Vec3, 3> t = candidate(k / 3);
          return std::array<Vec3, 2>{t[k % 3], t[(k + 1) % 3]};
        },
        limit - h);
    // The segment bound against the candidates' edges bounds the distance to
    // the candidates themselves from above.
    return edge + h;
  }
  const Frame frame = plane_frame(a, b, normal);
  // The first candidate, at the corners of the whole triangle.
  Polygon2 whole;
  whole.n = 3;
  whole.p[0] = {0., 0.}, whole.p[1] = frame.to2(b), whole.p[2] = frame.to2(c);
  const std::array<Vec3, 3> first = candidate(0);
  double worst = corner_bound(whole, frame, first, limit2);
  if (worst <= limit2) return std::sqrt(worst);
  worst = 0;
  Pieces open;
  whole.set_box();
  open.push(whole);
  std::size_t last = 0; // the last candidate that bounded a piece
  std::array<Polygon2, 2> buffer;
  std::array<Polygon2, 3> around;
  for (std::size_t k = 0; k < n && open.n > 0; ++k) {
    const std::array<Vec3, 3> t = k == 0 ? first : candidate(k);
    std::array<Point2, 3> f{frame.to2(t[0]), frame.to2(t[1]), frame.to2(t[2])};
    const double area = cross(f[0], f[1], f[2]);
    if (!(std::abs(area) > 0)) continue; // seen edge-on: no footprint
    if (area < 0) std::swap(f[1], f[2]);
    const double lo_x = (std::min)({f[0].x, f[1].x, f[2].x}), hi_x = (std::max)({f[0].x, f[1].x, f[2].x});
    const double lo_y = (std::min)({f[0].y, f[1].y, f[2].y}), hi_y = (std::max)({f[0].y, f[1].y, f[2].y});
    // The pieces open before this candidate (those it adds lie outside its footprint).
    int i = 0, before = open.n;
    while (i < before) {
      const Polygon2& piece = open.piece[std::size_t(i)];
      if (piece.hi_x < lo_x || piece.lo_x > hi_x || piece.hi_y < lo_y || piece.lo_y > hi_y) {
        ++i;
        continue;
      }
      // The piece under the footprint, and the (up to three) pieces around it.
      const Polygon2* inside = &piece;
      bool fits = true;
      for (Polygon2& out : around) out.n = 0;
      for (int e = 0; e < 3 && fits && inside->n >= 3; ++e) {
        const Point2 &p = f[std::size_t(e)], &q = f[std::size_t(e + 1) % 3];
        Polygon2& out = around[std::size_t(e)];
        Polygon2& in = buffer[std::size_t(e % 2)];
        fits = clip(*inside, p, q, -1., out) && clip(*inside, p, q, 1., in);
        inside = &in;
        // A piece within `on_line` of the line is left out: its points lie
        // that close to the rest of the piece (user manual, "Fidelity Certificate").
        const double on_line = on_line_distance * std::sqrt((q.x - p.x) * (q.x - p.x) + (q.y - p.y) * (q.y - p.y));
        bool thin = true;
        for (int j = 0; j < out.n && thin; ++j) thin = std::abs(cross(p, q, out.p[std::size_t(j)])) <= on_line;
        if (thin) out.n = 0;
      }
      if (!fits || inside->n < 3) {
        ++i;
        continue;
      }
      Vec3 far_corner;
      const double bound = corner_bound(*inside, frame, t, limit2, &far_corner);
      if (bound > limit2) {
        // A point of the triangle farther than `limit` from every candidate:
        // no choice of pieces can bound it.
        Polygon2 point;
        point.n = 1, point.p[0] = frame.to2(far_corner);
        if (!corners_near(point, frame, n, candidate, limit2, far)) {
          if (has_far) *has_far = far != nullptr;
          return inf;
        }
        ++i;
        continue;
      }
      worst = (std::max)(worst, bound);
      last = k;
      // The piece is replaced by the pieces around the footprint: the last
      // piece open before this candidate takes its place, and the last piece
      // of all takes that one's.
      const int last_before = --before;
      if (i != last_before) open.piece[std::size_t(i)].assign(open.piece[std::size_t(last_before)]);
      open.remove(last_before);
      for (const Polygon2& rest : around)
        if (!open.push(rest)) return inf;
    }
  }
  // The pieces left: each by the best candidate at its corners, or else cut
  // in two across its longest side, up to `halvings` pieces in all.
  int halvings = 64;
  Polygon2 piece;
  while (open.n > 0) {
    piece.assign(open.piece[std::size_t(--open.n)]);
    const double best = best_corner_bound(piece, frame, n, candidate, last, limit2);
    if (best <= limit2) {
      worst = (std::max)(worst, best);
      continue;
    }
    if (--halvings < 0) return inf;
    if (!corners_near(piece, frame, n, candidate, limit2, far)) {
      if (has_far) *has_far = far != nullptr;
      return inf;
    }
    // The cut: from the middle of the longest side to the middle of the
    // side opposite (or the corner opposite).
    int longest = 0;
    double length = -1;
    for (int j = 0; j < piece.n; ++j) {
      const Point2 &a = piece.p[std::size_t(j)], &b = piece.p[std::size_t(j + 1) % std::size_t(piece.n)];
      const double l = (b.x - a.x) * (b.x - a.x) + (b.y - a.y) * (b.y - a.y);
      if (l > length) length = l, longest = j;
    }
    const Point2 &a = piece.p[std::size_t(longest)], &b = piece.p[std::size_t(longest + 1) % std::size_t(piece.n)];
    const Point2 middle{(a.x + b.x) / 2, (a.y + b.y) / 2};
    const Point2& opposite = piece.p[std::size_t(longest + 1 + piece.n / 2) % std::size_t(piece.n)];
    for (double side : {1., -1.})
      if (!clip(piece, middle, opposite, side, buffer[0]) || !open.push(buffer[0])) return inf;
  }
  return std::sqrt(worst);
}

} // namespace ILSA
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_POLYGON_MESH_PROCESSING_INTERNAL_ILSA_DISTANCE_CERTIFICATE_H

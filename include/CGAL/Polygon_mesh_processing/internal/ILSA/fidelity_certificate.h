// Copyright (c) 2026 The Polygon_mesh_processing_ILSA authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The fidelity certificate (`ilsa_fidelity_tolerance`; user manual,
// "Fidelity Certificate"): every point of every smoothed face lies within the
// tolerance of the input surface, and every point of every input face within
// the tolerance of the smoothed surface. Each face is bounded as a whole
// (distance_certificate.h), in both directions:
// - a smoothed face against the input faces around its vertices' input
//   positions; it depends on its own three vertices;
// - an input face against the smoothed faces around its vertices; it depends
//   on the vertices of these faces.
// The smoothing starts from the input, where every bound is 0, and the safety
// check accepts no position at which a face it changes is not certified, so
// every accepted state is certified.
//
// A bound stays a bound while the vertices move, grown by the largest
// distance its vertices moved (a point of a face moves by at most as much as
// its farthest-moving vertex): a face whose bound at the accepted positions
// plus that distance is within the tolerance is not measured again.

#ifndef CGAL_POLYGON_MESH_PROCESSING_INTERNAL_ILSA_FIDELITY_CERTIFICATE_H
#define CGAL_POLYGON_MESH_PROCESSING_INTERNAL_ILSA_FIDELITY_CERTIFICATE_H

#include <CGAL/assertions.h>
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

/// The faces a certificate bounds a face against: those around the three
/// vertices of face `f`, each once, `f` first (at the input it is the face
/// itself); at most `capacity` (more only tighten the bound).
struct Face_candidates {
  static constexpr std::size_t capacity = 128;
  std::array<Index, capacity> face;
  std::size_t n = 0;
  bool complete = true; // every face around the vertices of `f` is listed

  Face_candidates(const Flat_mesh& m, std::size_t f) : own_(m.faces[f]) {
    const auto& t = own_;
    face[n++] = Index(f);
    // A face around t[k] that has an earlier vertex of `f` was listed with it.
    for (std::size_t k = 0; k < 3; ++k)
      for (const Index* g = m.vertex_faces.first(t[k]); g != m.vertex_faces.last(t[k]); ++g) {
        const auto& s = m.faces[*g];
        bool listed = *g == f;
        for (std::size_t j = 0; j < k && !listed; ++j) listed = s[0] == t[j] || s[1] == t[j] || s[2] == t[j];
        if (listed) continue;
        if (n == capacity) {
          complete = false;
          return;
        }
        face[n++] = *g;
      }
  }

  /// Adds the faces around the neighbours of the vertices of `f`.
  void add_second_ring(const Flat_mesh& m) {
    const auto& t = own_;
    // A face is listed already if it has a vertex of `f` (the first ring) or
    // a neighbour visited before (at most Small_vertex_set::capacity).
    visited_.clear();
    second_ring_closed_ = complete;
    auto seen = [&](Index u) { return u == t[0] || u == t[1] || u == t[2] || visited_.contains(u); };
    for (Index v : t)
      for (const Index* w = m.vertex_neighbors.first(v); w != m.vertex_neighbors.last(v); ++w) {
        if (seen(*w) || visited_.full()) continue;
        for (const Index* g = m.vertex_faces.first(*w); g != m.vertex_faces.last(*w); ++g) {
          const auto& s = m.faces[*g];
          if (seen(s[0]) || seen(s[1]) || seen(s[2])) continue;
          if (n == capacity) {
            second_ring_closed_ = false;
            break;
          }
          face[n++] = *g;
        }
        visited_.insert(*w);
      }
  }

  /// Whether every face around vertex `u` is listed: `u` is a vertex of `f`
  /// (the first ring being complete) or a neighbour of one whose faces the
  /// second ring lists (none left out for the capacity).
  bool lists_every_face_around(Index u) const {
    if (!complete) return false;
    if (u == own_[0] || u == own_[1] || u == own_[2]) return true;
    return second_ring_closed_ && visited_.contains(u);
  }

private:
  // A set of at most `capacity` vertices: open addressing in twice as many
  // slots, a hash of `slot_bits` bits (Index is 32 bits wide).
  struct Small_vertex_set {
    static constexpr unsigned slot_bits = 7;
    static constexpr std::size_t slots = std::size_t(1) << slot_bits, capacity = slots / 2;
    static constexpr Index empty = (std::numeric_limits<Index>::max)();
    std::array<Index, slots> slot;
    std::size_t size = 0;
    void clear() { slot.fill(empty), size = 0; }
    bool full() const { return size == capacity; }
    static std::size_t start(Index u) { return std::size_t(Index(u * 2654435761u) >> (32 - slot_bits)); }
    bool contains(Index u) const {
      for (std::size_t i = start(u);; i = (i + 1) & (slots - 1)) {
        if (slot[i] == u) return true;
        if (slot[i] == empty) return false;
      }
    }
    void insert(Index u) {
      std::size_t i = start(u);
      while (slot[i] != empty) i = (i + 1) & (slots - 1);
      slot[i] = u, ++size;
    }
  };
  std::array<Index, 3> own_;        // the vertices of `f`
  Small_vertex_set visited_;        // the neighbours whose faces the second ring lists (set by add_second_ring())
  bool second_ring_closed_ = false; // the second ring is listed, with every face around the neighbours visited
};

/// Per face of `m`, a bit per edge (from corner i to corner i + 1): whether
/// the edge is balanced, used by the faces of the mesh as often in one
/// direction as in the other (an interior edge between two faces of the same
/// orientation is). A face with a repeated vertex would be listed twice among
/// the candidates of a face: then no edge is taken as balanced.
inline std::vector<unsigned char> balanced_edges(const Flat_mesh& m) {
  std::vector<unsigned char> balanced(m.number_of_faces(), 0);
  for (const auto& t : m.faces)
    if (t[0] == t[1] || t[1] == t[2] || t[2] == t[0]) return balanced;
  for (std::size_t f = 0; f < m.number_of_faces(); ++f)
    for (std::size_t i = 0; i < 3; ++i) {
      const Index u = m.faces[f][i], v = m.faces[f][(i + 1) % 3];
      int net = 0;
      for (const Index* g = m.vertex_faces.first(u); g != m.vertex_faces.last(u); ++g)
        for (std::size_t j = 0; j < 3; ++j) {
          const Index x = m.faces[*g][j], y = m.faces[*g][(j + 1) % 3];
          net += int(x == u && y == v) - int(x == v && y == u);
        }
      if (net == 0) balanced[f] |= static_cast<unsigned char>(1 << i);
    }
  return balanced;
}

/// Per candidate, a bit per edge (from corner i to corner i + 1): whether the
/// edge is cancelled by the reverse edges of the other candidates
/// (height_bound()'s `cancelled`). It is when it is balanced (`balanced`, from
/// balanced_edges()) and has a vertex whose faces are all candidates (a vertex
/// of the face, or one of the second ring's neighbours), so that every face
/// that has the edge is a candidate.
inline void cancelled_edges(const Flat_mesh& m, const std::vector<unsigned char>& balanced,
                            const Face_candidates& candidates,
                            std::array<unsigned char, Face_candidates::capacity>& cancelled) {
  for (std::size_t k = 0; k < candidates.n; ++k) {
    const auto& s = m.faces[candidates.face[k]];
    unsigned corners = 0; // those whose faces are all candidates
    for (std::size_t i = 0; i < 3; ++i) corners |= unsigned(candidates.lists_every_face_around(s[i])) << i;
    const unsigned near = corners | corners >> 1 | (corners & 1) << 2; // edge i: corner i or i + 1
    cancelled[k] = static_cast<unsigned char>(near & balanced[candidates.face[k]]);
  }
}

class Fidelity_certificate {
public:
  /// `tolerance` in the normalised units of `mesh` (infinity: no bound).
  /// `mesh` must outlive the certificate.
  Fidelity_certificate(const Flat_mesh& mesh, double tolerance)
      : m_(mesh), tolerance_(tolerance), limit_(tolerance - certificate_margin) {
    if (!enabled()) return;
    output_.assign(m_.number_of_faces());
    input_.assign(m_.number_of_faces());
    vertex_flags_.assign(m_.number_of_vertices(), 0);
    balanced_ = balanced_edges(m_);
  }

  bool enabled() const { return std::isfinite(tolerance_); }

  /// Checks the faces whose bounds the moves of `changed` (from `previous`,
  /// the accepted positions, to `next`) may have changed, and calls
  /// `blame(w)` for vertices a failed face depends on, in face order (the
  /// result does not depend on the threads); `blame(w)` returns whether the
  /// move of `w` is shortened. The smoothed faces are checked first; an input
  /// face that depends on a vertex they shorten is left to the next call,
  /// which the shortening brings about.
  template <class ConcurrencyTag, class Blame>
  void check(const std::vector<Vec3>& previous, const std::vector<Vec3>& next, const std::vector<Index>& changed,
             const Blame& blame) {
    if (!enabled() || changed.empty()) return;
    for (Side* side : {&output_, &input_}) side->start_check();
    // The smoothed faces around the moved vertices; the input faces whose
    // candidates include one of them, `f`: those with a vertex of `f`, and
    // those bounded against the second ring with a moved vertex among their
    // candidates' (few faces). The vertices of these `f` are touched.
    for (std::size_t v : changed)
      for (const Index* f = m_.vertex_faces.first(v); f != m_.vertex_faces.last(v); ++f) {
        output_.mark(*f);
        for (Index u : m_.faces[*f]) {
          if (vertex_flags_[u] & touched) continue;
          vertex_flags_[u] |= touched;
          for (const Index* t = m_.vertex_faces.first(u); t != m_.vertex_faces.last(u); ++t) input_.mark(*t);
        }
      }
    // (A face around a neighbour w of a vertex of `t` has a moved vertex when
    // w is touched.)
    for (std::size_t t = 0; t < m_.number_of_faces(); ++t) {
      if (!input_.wide(t) || input_.has(t, Side::listed)) continue;
      bool depends = false;
      for (Index v : m_.faces[t])
        for (const Index* w = m_.vertex_neighbors.first(v); w != m_.vertex_neighbors.last(v) && !depends; ++w)
          depends = (vertex_flags_[*w] & touched) != 0;
      if (depends) input_.mark(t);
    }
    for (std::size_t v : changed) {
      for (const Index* f = m_.vertex_faces.first(v); f != m_.vertex_faces.last(v); ++f)
        for (Index u : m_.faces[*f]) vertex_flags_[u] = 0;
    }
    for (Side* side : {&output_, &input_}) side->outcome.assign(side->checked.size(), Side::certified);
    parallel_for<ConcurrencyTag>(output_.checked.size(), [&](std::size_t i) {
      const std::size_t f = output_.checked[i];
      double drift = 0;
      for (Index w : m_.faces[f]) drift = (std::max)(drift, (next[w] - previous[w]).squaredNorm());
      output_.outcome[i] =
          output_.certify(f, std::sqrt(drift), limit_, [&](bool& wide) { return ring_bound(next, m_.points, f, wide); })
              ? Side::certified
              : Side::failed;
    });
    // The smoothed faces that fail shorten the moves of their vertices first.
    // An input face that depends on such a vertex (one of its own or a
    // neighbour of them) is deferred: the shortening changes its candidates,
    // so the next round of the safety check measures it at the new positions
    // (user manual, "Safety Check").
    shortened_.clear();
    for (std::size_t i = 0; i < output_.checked.size(); ++i)
      if (output_.outcome[i] == Side::failed) {
        for (Index w : m_.faces[output_.checked[i]])
          if (blame(w) && !(vertex_flags_[w] & being_shortened)) {
            vertex_flags_[w] |= being_shortened;
            shortened_.push_back(w);
          }
      }
    auto deferred = [&](std::size_t t) {
      if (shortened_.empty()) return false;
      for (Index v : m_.faces[t]) {
        if (vertex_flags_[v] & being_shortened) return true;
        for (const Index* w = m_.vertex_neighbors.first(v); w != m_.vertex_neighbors.last(v); ++w)
          if (vertex_flags_[*w] & being_shortened) return true;
      }
      return false;
    };
    parallel_for<ConcurrencyTag>(input_.checked.size(), [&](std::size_t i) {
      const std::size_t t = input_.checked[i];
      if (deferred(t)) {
        input_.outcome[i] = Side::deferred;
        return;
      }
      // The largest move of a vertex the bound depends on: those of the
      // candidates, the faces around the vertices of `t` (their neighbours),
      // and for a bound found against the second ring, the faces around these.
      double drift = 0;
      auto grow = [&](std::size_t w) { drift = (std::max)(drift, (next[w] - previous[w]).squaredNorm()); };
      if (input_.has(t, Side::accepted_wide)) {
        Face_candidates candidates(m_, t);
        candidates.add_second_ring(m_);
        for_each_dependency(candidates, grow);
      } else {
        for (Index v : m_.faces[t]) {
          grow(v);
          std::for_each(m_.vertex_neighbors.first(v), m_.vertex_neighbors.last(v), grow);
        }
      }
      const bool certified =
          input_.certify(t, std::sqrt(drift), limit_, [&](bool& wide) { return ring_bound(m_.points, next, t, wide); });
      input_.outcome[i] = certified ? Side::certified : Side::failed;
    });
    for (Index w : shortened_) vertex_flags_[w] = 0;
    // An input face that fails shortens the moves of its own vertices first:
    // the smoothed faces around them are its candidates; only when none of them
    // can be shortened, those of the other vertices it depends on.
    for (std::size_t i = 0; i < input_.checked.size(); ++i) {
      if (input_.outcome[i] != Side::failed) continue;
      const std::size_t t = input_.checked[i];
      bool blamed = false;
      for (Index w : m_.faces[t]) blamed = blame(w) || blamed;
      if (blamed) continue;
      Face_candidates candidates(m_, t);
      for_each_dependency(candidates, [&](std::size_t w) { blamed = blame(w) || blamed; });
      if (blamed) continue;
      candidates.add_second_ring(m_);
      for_each_dependency(candidates, blame);
    }
  }

  /// The positions the safety check ends with are accepted: each face checked
  /// since the last call keeps the bound of its last check, which was made
  /// after the last move of its vertices (the check ends with a round in
  /// which no face fails).
  void accept() {
    if (!enabled()) return;
    for (Side* side : {&output_, &input_}) side->accept();
  }

  /// The largest distance between the smoothed surface at the accepted
  /// positions and the input surface, both ways, certified: at most the
  /// tolerance; infinity without a tolerance.
  double largest_bound() const {
    if (!enabled()) return std::numeric_limits<double>::infinity();
    double worst = 0;
    for (const Side* side : {&output_, &input_})
      for (float b : side->accepted) worst = (std::max)(worst, double(b));
    // Each bound was at most the limit before it was rounded up to a float to
    // be stored; that rounding can take the float above the limit.
    CGAL_assertion(worst <= double(float_rounded_up(limit_)));
    return (std::min)(worst, limit_);
  }

private:
  // The bounds of one direction, per face.
  struct Side {
    std::vector<float> accepted;        // a bound at the accepted positions (rounded up)
    std::vector<float> trial;           // a bound at the positions of the face's last check, if it passed
    std::vector<unsigned char> flags;   // per face: the flags below
    std::vector<Index> checked, called; // the faces of the current check; those listed since the last accept()
    // Per face of `checked`: certified, failed, or deferred to the next round
    // (an input face that depends on a vertex whose move is shortened).
    enum Outcome : unsigned char { certified, failed, deferred };
    std::vector<Outcome> outcome;
    // The flags of a face: listed by the current check; listed since the last
    // accept(); (input faces) whether the accepted bound, or the trial one, was
    // found against the second ring of candidates too (Face_candidates::add_second_ring()).
    static constexpr unsigned char listed = 1, in_call = 2, accepted_wide = 4, trial_wide = 8;

    void assign(std::size_t n) { accepted.assign(n, 0.f), trial.assign(n, 0.f), flags.assign(n, 0); }
    bool has(std::size_t f, unsigned char flag) const { return (flags[f] & flag) != 0; }
    void set(std::size_t f, unsigned char flag, bool on) {
      flags[f] = static_cast<unsigned char>(on ? flags[f] | flag : flags[f] & ~flag);
    }
    bool wide(std::size_t f) const { return has(f, accepted_wide | trial_wide); }
    void start_check() {
      for (Index f : checked) set(f, listed, false);
      checked.clear();
    }
    void mark(std::size_t f) {
      if (has(f, listed)) return;
      set(f, listed, true);
      checked.push_back(Index(f));
      if (!has(f, in_call)) set(f, in_call, true), called.push_back(Index(f));
    }
    // The accepted bound grown by `drift`, or else `bound()`, if within `limit`.
    // `bound(wide)` sets `wide` when it used the second ring.
    template <class Bound> bool certify(std::size_t f, double drift, double limit, const Bound& bound) {
      const double grown = double(accepted[f]) + drift * (1. + 1e-9) + 1e-15;
      bool used_wide = has(f, accepted_wide);
      const double b = grown <= limit ? grown : bound(used_wide);
      const bool ok = b <= limit;
      trial[f] = ok ? float_rounded_up(b) : std::numeric_limits<float>::infinity();
      if (ok) set(f, trial_wide, used_wide);
      return ok;
    }
    void accept() {
      for (Index f : called) {
        if (trial[f] != std::numeric_limits<float>::infinity()) {
          accepted[f] = trial[f];
          set(f, accepted_wide, has(f, trial_wide));
        }
        set(f, trial_wide | in_call, false);
      }
      called.clear();
    }
  };

  template <class F> void for_each_dependency(const Face_candidates& candidates, const F& f) const {
    for (std::size_t k = 0; k < candidates.n; ++k)
      for (Index w : m_.faces[candidates.face[k]]) f(w);
  }

  // The corners of candidate k at `at`.
  auto corners_of(const Face_candidates& candidates, const std::vector<Vec3>& at) const {
    return [this, &candidates, &at](std::size_t k) {
      const auto& s = m_.faces[candidates.face[k]];
      return std::array<Vec3, 3>{at[s[0]], at[s[1]], at[s[2]]};
    };
  }

  // Face `f` with its corners at `corners` against the faces around its
  // vertices with theirs at `at` (the first ring), and where these cannot
  // certify it, also the faces around their neighbours (the second ring; then
  // `wide` is set): smoothed vertices slide on the input, along a crease
  // sometimes farther than the first ring reaches. The routes in the order of
  // their cost: the height route on the first ring, then on the second, then
  // the piece route on the first and on the second (distance_certificate.h).
  // A point farther than the limit from every candidate of both rings ends
  // the search: no certificate against them exists.
  double ring_bound(const std::vector<Vec3>& corners, const std::vector<Vec3>& at, std::size_t f, bool& wide) const {
    Face_candidates candidates(m_, f);
    const std::size_t first = candidates.n;
    Vec3 far;
    bool has_far = false;
    wide = false;
    double b = height_route(corners, f, candidates, at, &far, &has_far);
    if (b <= limit_) return b;
    candidates.add_second_ring(m_);
    if (!has_far) {
      // The second ring's heights, then the first ring's pieces.
      wide = true;
      b = height_route(corners, f, candidates, at, &far, &has_far);
      if (b <= limit_ || has_far) return b;
      wide = false;
      b = piece_route(corners, f, candidates, first, at, &far, &has_far);
      if (b <= limit_) return b;
      wide = true;
      if (has_far && !near_any(far, candidates, first, at)) return b;
    } else {
      // The first ring's heights found a point too far from it: the second
      // ring's are tried only if one of its faces comes near that point.
      wide = true;
      if (!near_any(far, candidates, first, at)) return b;
      has_far = false;
      b = height_route(corners, f, candidates, at, &far, &has_far);
      if (b <= limit_ || has_far) return b;
    }
    return piece_route(corners, f, candidates, candidates.n, at);
  }
  // Whether `x` is within the limit of one of the candidates from `first` on, at `at`.
  bool near_any(const Vec3& x, const Face_candidates& candidates, std::size_t first,
                const std::vector<Vec3>& at) const {
    for (std::size_t k = first; k < candidates.n; ++k) {
      const auto& s = m_.faces[candidates.face[k]];
      if (squared_distance_to_triangle(x, at[s[0]], at[s[1]], at[s[2]]) <= limit_ * limit_) return true;
    }
    return false;
  }
  // Face `f` with its corners at `corners` against the candidates with theirs
  // at `at`, by the height route and by the piece route (distance_certificate.h).
  double height_route(const std::vector<Vec3>& corners, std::size_t f, const Face_candidates& candidates,
                      const std::vector<Vec3>& at, Vec3* far, bool* has_far) const {
    const auto& t = m_.faces[f];
    std::array<unsigned char, Face_candidates::capacity> cancelled;
    cancelled_edges(m_, balanced_, candidates, cancelled);
    return height_bound(
        corners[t[0]], corners[t[1]], corners[t[2]], candidates.n, corners_of(candidates, at),
        [&](std::size_t k, std::size_t i) { return (cancelled[k] >> i & 1) != 0; }, limit_, far, has_far);
  }
  // The piece route against the first `n` candidates.
  double piece_route(const std::vector<Vec3>& corners, std::size_t f, const Face_candidates& candidates, std::size_t n,
                     const std::vector<Vec3>& at, Vec3* far = nullptr, bool* has_far = nullptr) const {
    const auto& t = m_.faces[f];
    return triangle_bound(corners[t[0]], corners[t[1]], corners[t[2]], n, corners_of(candidates, at), limit_, far,
                          has_far);
  }
  const Flat_mesh& m_;
  double tolerance_, limit_;
  Side output_, input_; // smoothed faces to the input; input faces to the smoothed surface
  static constexpr unsigned char touched = 1, being_shortened = 2;
  std::vector<unsigned char> vertex_flags_; // per vertex, in check(): touched, being_shortened (0 outside)
  std::vector<Index> shortened_;            // in check(): the vertices whose moves the smoothed faces shorten
  std::vector<unsigned char> balanced_;     // per face: which of its edges are balanced
};

} // namespace ILSA
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_POLYGON_MESH_PROCESSING_INTERNAL_ILSA_FIDELITY_CERTIFICATE_H

// Copyright (c) 2026 The Polygon_mesh_processing_ILSA authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The fidelity certificate (`ilsa_fidelity_tolerance`; user manual,
// "Fidelity certificate"): every point of every smoothed face lies within the
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
// A bound stays a bound while the vertices move, grown by the length of their
// paths (a point of a face moves by at most as much as its farthest-moving
// vertex): a face whose last bound plus that growth is within the tolerance is
// not measured again.

#ifndef CGAL_POLYGON_MESH_PROCESSING_INTERNAL_ILSA_FIDELITY_CERTIFICATE_H
#define CGAL_POLYGON_MESH_PROCESSING_INTERNAL_ILSA_FIDELITY_CERTIFICATE_H

#include <CGAL/Polygon_mesh_processing/internal/ILSA/distance_certificate.h>
#include <CGAL/Polygon_mesh_processing/internal/ILSA/flat_mesh.h>
#include <CGAL/Polygon_mesh_processing/internal/ILSA/parallel_loops.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
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
  static constexpr std::size_t capacity = 64;
  std::array<Index, capacity> face;
  std::size_t n = 0;

  Face_candidates(const Flat_mesh& m, std::size_t f) {
    const auto& t = m.faces[f];
    face[n++] = Index(f);
    // A face around t[k] that has an earlier vertex of `f` was listed with it.
    for (std::size_t k = 0; k < 3; ++k)
      for (const Index* g = m.vertex_faces.first(t[k]); g != m.vertex_faces.last(t[k]) && n < capacity; ++g) {
        const auto& s = m.faces[*g];
        bool listed = *g == f;
        for (std::size_t j = 0; j < k && !listed; ++j) listed = s[0] == t[j] || s[1] == t[j] || s[2] == t[j];
        if (!listed) face[n++] = *g;
      }
  }
};

class Fidelity_certificate {
public:
  /// `tolerance` in the normalised units of `mesh` (infinity: no bound).
  /// `mesh` must outlive the certificate.
  Fidelity_certificate(const Flat_mesh& mesh, double tolerance)
      : m_(mesh), tolerance_(tolerance), limit_(tolerance - certificate_margin) {
    if (!enabled()) return;
    const std::size_t nf = m_.number_of_faces();
    travel_.assign(m_.number_of_vertices(), 0.f);
    output_bound_.assign(nf, 0.f);
    output_travel_.assign(nf, {0.f, 0.f, 0.f});
    input_bound_.assign(nf, 0.f);
    input_travel_.assign(nf, 0.);
    output_stamp_.assign(nf, 0);
    input_stamp_.assign(nf, 0);
  }

  bool enabled() const { return std::isfinite(tolerance_); }

  /// Vertex `v` moved by `length`: its path grows (rounded up, so that it stays
  /// at least the distance between any two of its positions).
  void add_travel(std::size_t v, double length) {
    if (enabled()) travel_[v] = float_rounded_up(double(travel_[v]) + length);
  }

  /// Checks the faces whose bounds the moves of `changed` (positions `pos`)
  /// may have changed, and calls `blame(w)` for each vertex a failed face
  /// depends on (in face order: the result does not depend on the threads).
  template <class ConcurrencyTag, class Blame>
  void check(const std::vector<Vec3>& pos, const std::vector<Index>& changed, const Blame& blame) {
    if (!enabled() || changed.empty()) return;
    next_stamp();
    outputs_.clear(), inputs_.clear();
    for (std::size_t v : changed) {
      for (const Index* f = m_.vertex_faces.first(v); f != m_.vertex_faces.last(v); ++f) {
        if (output_stamp_[*f] != stamp_) output_stamp_[*f] = stamp_, outputs_.push_back(*f);
        mark_input_faces_of(*f);
      }
    }
    output_failed_.assign(outputs_.size(), 0);
    input_failed_.assign(inputs_.size(), 0);
    parallel_for<ConcurrencyTag>(outputs_.size(), [&](std::size_t i) { output_failed_[i] = !certify_output(pos, outputs_[i]); });
    parallel_for<ConcurrencyTag>(inputs_.size(), [&](std::size_t i) { input_failed_[i] = !certify_input(pos, inputs_[i]); });
    for (std::size_t i = 0; i < outputs_.size(); ++i)
      if (output_failed_[i])
        for (Index w : m_.faces[outputs_[i]]) blame(w);
    for (std::size_t i = 0; i < inputs_.size(); ++i)
      if (input_failed_[i]) for_each_dependency(inputs_[i], blame);
  }

  /// The largest distance between the smoothed surface at `pos` and the input
  /// surface, both ways, certified: at most the tolerance when every position
  /// was accepted by check(); infinity without a tolerance.
  double largest_bound(const std::vector<Vec3>& pos) const {
    if (!enabled()) return std::numeric_limits<double>::infinity();
    double worst = 0;
    for (std::size_t f = 0; f < m_.number_of_faces(); ++f) {
      double out = double(output_bound_[f]) + output_drift(f), in = double(input_bound_[f]) + input_drift(f);
      if (out > limit_) out = (std::min)(out, output_distance(pos, f, limit_));
      if (in > limit_) in = (std::min)(in, input_distance(pos, f, limit_));
      worst = (std::max)({worst, out, in});
    }
    return worst;
  }

private:
  // The stamps tell the faces already listed in this check; they start again
  // from 1 before they overflow.
  void next_stamp() {
    if (++stamp_ == 0) {
      std::fill(output_stamp_.begin(), output_stamp_.end(), 0);
      std::fill(input_stamp_.begin(), input_stamp_.end(), 0);
      stamp_ = 1;
    }
  }

  // The input faces whose candidates include the smoothed face `f`: those with
  // a vertex of `f`.
  void mark_input_faces_of(std::size_t f) {
    for (Index u : m_.faces[f])
      for (const Index* t = m_.vertex_faces.first(u); t != m_.vertex_faces.last(u); ++t)
        if (input_stamp_[*t] != stamp_) input_stamp_[*t] = stamp_, inputs_.push_back(*t);
  }

  // Calls `f(w)` for the vertices the bound of input face `t` depends on: those
  // of its candidates (a vertex may come more than once).
  template <class F> void for_each_dependency(std::size_t t, const F& f) const {
    for_each_dependency(Face_candidates(m_, t), f);
  }
  template <class F> void for_each_dependency(const Face_candidates& candidates, const F& f) const {
    for (std::size_t k = 0; k < candidates.n; ++k)
      for (Index w : m_.faces[candidates.face[k]]) f(w);
  }

  double output_drift(std::size_t f) const {
    double drift = 0;
    for (std::size_t k = 0; k < 3; ++k)
      drift = (std::max)(drift, double(travel_[m_.faces[f][k]]) - double(output_travel_[f][k]));
    return drift * (1. + 1e-9);
  }
  double input_travel(const Face_candidates& candidates) const {
    double sum = 0;
    for_each_dependency(candidates, [&](std::size_t w) { sum += double(travel_[w]); });
    return sum;
  }
  // Each vertex moved by at most the growth of its path; their sum bounds the largest.
  double input_drift(std::size_t t) const {
    return (input_travel(Face_candidates(m_, t)) - input_travel_[t]) * (1. + 1e-9) + 1e-15;
  }

  // Smoothed face `f` at `pos` against the input faces around its vertices.
  double output_distance(const std::vector<Vec3>& pos, std::size_t f, double limit) const {
    return output_distance(pos, f, Face_candidates(m_, f), limit);
  }
  double output_distance(const std::vector<Vec3>& pos, std::size_t f, const Face_candidates& candidates,
                         double limit) const {
    const auto& t = m_.faces[f];
    return triangle_bound(
        pos[t[0]], pos[t[1]], pos[t[2]], candidates.n,
        [&](std::size_t k) {
          const auto& s = m_.faces[candidates.face[k]];
          return std::array<Vec3, 3>{m_.points[s[0]], m_.points[s[1]], m_.points[s[2]]};
        },
        limit);
  }
  // Input face `f` against the smoothed faces (at `pos`) around its vertices.
  double input_distance(const std::vector<Vec3>& pos, std::size_t f, double limit) const {
    return input_distance(pos, f, Face_candidates(m_, f), limit);
  }
  double input_distance(const std::vector<Vec3>& pos, std::size_t f, const Face_candidates& candidates,
                        double limit) const {
    const auto& t = m_.faces[f];
    return triangle_bound(
        m_.points[t[0]], m_.points[t[1]], m_.points[t[2]], candidates.n,
        [&](std::size_t k) {
          const auto& s = m_.faces[candidates.face[k]];
          return std::array<Vec3, 3>{pos[s[0]], pos[s[1]], pos[s[2]]};
        },
        limit);
  }

  bool certify_output(const std::vector<Vec3>& pos, std::size_t f) {
    if (double(output_bound_[f]) + output_drift(f) <= limit_) return true;
    const double bound = output_distance(pos, f, limit_);
    if (!(bound <= limit_)) return false;
    output_bound_[f] = float_rounded_up(bound);
    for (std::size_t k = 0; k < 3; ++k) output_travel_[f][k] = travel_[m_.faces[f][k]];
    return true;
  }
  bool certify_input(const std::vector<Vec3>& pos, std::size_t t) {
    const Face_candidates candidates(m_, t);
    const double travel = input_travel(candidates);
    if (double(input_bound_[t]) + (travel - input_travel_[t]) * (1. + 1e-9) + 1e-15 <= limit_) return true;
    const double bound = input_distance(pos, t, candidates, limit_);
    if (!(bound <= limit_)) return false;
    input_bound_[t] = float_rounded_up(bound);
    input_travel_[t] = travel;
    return true;
  }

  const Flat_mesh& m_;
  double tolerance_, limit_;
  std::vector<float> travel_;                      // per vertex: length of its path so far (rounded up)
  std::vector<float> output_bound_;                // per face: its last bound, smoothed to input
  std::vector<std::array<float, 3>> output_travel_; // travel_ of its vertices then
  std::vector<float> input_bound_;                 // per face: its last bound, input to smoothed
  std::vector<double> input_travel_;               // input_travel() then
  std::vector<std::uint32_t> output_stamp_, input_stamp_;
  std::uint32_t stamp_ = 0;
  std::vector<Index> outputs_, inputs_;                   // the faces of the current check
  std::vector<unsigned char> output_failed_, input_failed_; // their results
};

} // namespace ILSA
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_POLYGON_MESH_PROCESSING_INTERNAL_ILSA_FIDELITY_CERTIFICATE_H

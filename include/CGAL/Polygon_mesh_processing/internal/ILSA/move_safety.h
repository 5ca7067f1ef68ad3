// Copyright (c) 2026 The Polygon_mesh_processing_ILSA authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Safety check after projection (`use_safety_constraints`): no triangle may
// reverse its orientation with respect to the original surface or collapse,
// the worst triangle around a moved vertex may not get worse if it ends below
// the quality floor, and the smoothed surface may not move away from an input
// vertex by more than the fidelity tolerance (it may not cut off a bump or a
// crease bend of the input), nor a crease polyline from the input crease;
// optionally (`ilsa_fidelity_input_edges`) not from inner points of the input
// edges either.
// A vertex of an offending triangle has its move halved (and re-projected) a
// few times, then dropped for this iteration. Since the moves are applied all
// at once (Jacobi), the check is repeated until no triangle offends; it ends
// because a triangle whose vertices are all back at their previous, accepted
// positions is as it was.

#ifndef CGAL_POLYGON_MESH_PROCESSING_INTERNAL_ILSA_MOVE_SAFETY_H
#define CGAL_POLYGON_MESH_PROCESSING_INTERNAL_ILSA_MOVE_SAFETY_H

#include <CGAL/Polygon_mesh_processing/triangle_quality_ilsa.h>
#include <CGAL/Polygon_mesh_processing/internal/ILSA/feature_lines.h>
#include <CGAL/Polygon_mesh_processing/internal/ILSA/flat_mesh.h>
#include <CGAL/Polygon_mesh_processing/internal/ILSA/parallel_loops.h>
#include <CGAL/Polygon_mesh_processing/internal/ILSA/projection.h>
#include <CGAL/Polygon_mesh_processing/internal/ILSA/vertex_classification.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <limits>
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

class Move_safety {
  using Round = Claim_stamps::Round; // rounds of the check, counted over the whole run

public:
  /// Relative area below which a triangle counts as collapsed: twice its area
  /// under this fraction of its longest edge squared.
  static constexpr double collapse_tolerance = 1e-6;

  /// `quality_floor`: a move may not lower the minimum aspect ratio of the
  /// vertex's star below this value (1: never lower it, the quality-monotone mode).
  /// `fidelity_tolerance`: largest distance (normalised units: the bounding-box
  /// diagonal is 1) between an input vertex and the smoothed surface around it
  /// that a move may create or increase; infinity disables the check.
  /// `reject_worsening`: drop a move that lowers the mean aspect ratio of the
  /// vertex's star, the neighbours being at their new positions.
  /// `input_edges`: the fidelity bound also holds at the points 1/4, 1/2 and
  /// 3/4 of the way along the input edges of a moved vertex
  /// (`ilsa_fidelity_input_edges`, input_edge_deviates()).
  /// `original`, `classification` and `projector` (its bounding balls of the
  /// input faces spare distances) must outlive the check: it keeps references.
  /// `incidences` (those of `original`) is read here only.
  Move_safety(const Flat_mesh& original, const Vertex_classification& classification,
              const Set_up_incidences& incidences, const Projector& projector, double quality_floor,
              double fidelity_tolerance, bool reject_worsening, std::size_t halvings, bool input_edges = false)
      : m_(original), c_(classification), projector_(projector), quality_floor_(quality_floor),
        fidelity_tolerance_(fidelity_tolerance), reject_worsening_(reject_worsening),
        input_edges_(input_edges && std::isfinite(fidelity_tolerance)),
        halvings_((std::min)(halvings, std::size_t(100))) {
    // Reference orientation of each face (see reference()): for a face that is
    // degenerate in the input, the sum of its neighbours' normals, stored.
    for (std::size_t f = 0; f < m_.number_of_faces(); ++f)
      if (unit_normal(m_.points, m_.faces[f]).isZero(0)) degenerate_faces_.push_back(Index(f));
    degenerate_references_.assign(degenerate_faces_.size(), Vec3::Zero());
    if (!degenerate_faces_.empty())
      for (const auto& fs : incidences.edge_faces)
        if (fs[0] != npos && fs[1] != npos)
          for (int k = 0; k < 2; ++k) {
            const auto found = std::lower_bound(degenerate_faces_.begin(), degenerate_faces_.end(), fs[k]);
            if (found != degenerate_faces_.end() && *found == fs[k])
              degenerate_references_[std::size_t(found - degenerate_faces_.begin())] +=
                  unit_normal(m_.points, m_.faces[fs[1 - k]]);
          }
    offends_.assign(m_.number_of_faces(), 0);
    face_round_.assign(m_.number_of_faces(), 0);
    deviation_round_.assign(m_.number_of_faces(), 0);
    bad_.assign(m_.number_of_vertices(), 0);
    failed_test_.assign(m_.number_of_vertices(), 0);
    face_now_.assign(m_.number_of_faces(), std::numeric_limits<double>::infinity());
    vertex_round_.assign(m_.number_of_vertices(), 0);
    changed_round_.assign(m_.number_of_vertices(), 0);
    ring_changed_.assign(m_.number_of_vertices(), 0);
    vertex_now_.assign(m_.number_of_vertices(), 0.);
    vertex_witness_.assign(m_.number_of_vertices(), no_witness);
    travel_.assign(m_.number_of_vertices(), 0.f);
    face_travel_.assign(m_.number_of_faces(), {0.f, 0.f, 0.f});
    face_witness_.resize(m_.number_of_faces());
    for (std::size_t f = 0; f < m_.number_of_faces(); ++f) { // the face itself, among the faces of its first vertex
      const Index* first = m_.vertex_faces.first(m_.faces[f][0]);
      const Witness w = witness_of(std::size_t(std::find(first, m_.vertex_faces.last(m_.faces[f][0]), f) - first));
      face_witness_[f] = {w, w, w, w};
    }
    tries_.assign(m_.number_of_vertices(), 0);
    queued_.assign(m_.number_of_vertices(), 0);
    dropped_in_.assign(m_.number_of_vertices(), 0);
    checked_.assign(m_.number_of_vertices(), 0);
    is_moved_.assign(m_.number_of_vertices(), 0);
    above_floor_.assign(m_.number_of_vertices(), 0);
    measured_.assign(input_edges_ ? m_.number_of_vertices() : 0, 0);
  }

  struct Counts {
    std::size_t shortened = 0, rejected = 0;
    ILSA_move_limits shortened_by, rejected_by; // by the last test each move failed
  };

  /// `previous`: accepted positions (and homes) before this iteration;
  /// `d`: the displacements (the unprojected position of `v` is
  /// `previous[v] + d[v]`); `next`/`next_home`: the
  /// projected positions, corrected in place. `moved` lists the vertices whose
  /// position changed. `project(v, q, current, home, guard)` re-projects a shortened move (`guard` false: its
  /// guard flag is not needed). `face_scratch`: a per-face array (one value
  /// per face) the check works in; its values are not read before they are
  /// written in this call, so the caller may use it between two calls.
  ///
  /// The rounds of the check (user manual, "Safety check"): a round runs
  /// either the cheap tests (cheap_tests(): flip, collapse, quality) or, once
  /// no move fails them, the fidelity tests (fidelity_tests()), then shortens
  /// the offending moves (shorten()) and lists the moved vertices whose stars
  /// the shortening changed for the next round (after_shortening()). Each of
  /// these phases is a loop over the vertices to test (or the offenders)
  /// whose iterations write only their own vertex or the elements they claim
  /// (user manual, "Parallel runs").
  template <class ConcurrencyTag, class Project>
  Counts enforce(const std::vector<Vec3>& previous, const std::vector<Index>& previous_home, const std::vector<Vec3>& d,
                 const std::vector<Index>& moved, std::vector<Vec3>& next, std::vector<Index>& next_home,
                 const Project& project, std::vector<double>& face_scratch) {
    start_call(previous, moved, next);
    // to_check: vertices for the cheap tests; to_measure: vertices that
    // passed them since their last fidelity test. (The first round checks
    // `moved` itself, not a copy.)
    std::vector<Index> to_check, to_measure, offenders;
    to_measure.reserve(moved.size()); // each moved vertex is in it at most once
    bool first = true;
    // The cheap tests run until no move fails them; only then do the costly
    // fidelity tests run, once on every vertex that passed the cheap tests
    // (user manual, "Order of the safety check's tests"): most moves the check
    // drops fail a cheap test, and each one dropped changes the stars of its
    // neighbours.
    while (!(first ? moved : to_check).empty() || !to_measure.empty()) {
      ++round_;
      const std::vector<Index>& checking = first ? moved : to_check;
      first = false;
      const bool measuring = checking.empty();
      if (!measuring)
        cheap_tests<ConcurrencyTag>(previous, next, checking, face_scratch, to_measure);
      else
        fidelity_tests<ConcurrencyTag>(previous, previous_home, next, next_home, to_measure);
      offenders.clear();
      for (std::size_t v : measuring ? to_measure : checking)
        if (bad_[v]) offenders.push_back(Index(v));
      if (measuring) to_measure.clear();
      shorten<ConcurrencyTag>(previous, previous_home, d, offenders, next, next_home, project);
      after_shortening<ConcurrencyTag>(offenders, to_check);
    }
    return finish_call(moved);
  }

  /// Whether to drop the move of `v` to `pos[v] + d[v]` without projecting and
  /// checking it: its move was dropped in the previous iteration, and the
  /// mean aspect ratio of its star, every vertex at its target, is lower than
  /// with `v` staying at `pos[v]` (`d` is zero for a fixed vertex). Every
  /// move made still passes enforce(), so the test can cost quality, never a
  /// guarantee (user manual, "Worsening pre-test"). The aspect ratios are
  /// computed here, for the few vertices the gate lets through, not for
  /// every face.
  bool drop_before_projection(const std::vector<Vec3>& pos, const std::vector<Vec3>& d, std::size_t v) const {
    if (!reject_worsening_ || call_ == 0 || dropped_in_[v] != call_) return false;
    // The worsening test of enforce(), with the targets for `next` and `pos[v]` for `previous[v]`.
    auto target = [&](std::size_t w) -> Vec3 { return pos[w] + d[w]; };
    auto staying = [&](std::size_t w) -> Vec3 { return w == v ? pos[v] : target(w); };
    return star_quality_at(v, target).mean < star_quality_at(v, staying).mean;
  }

  /// Whether the last call of enforce() dropped the move of `v` in a way that
  /// settles the vertex (user manual, "Retrying dropped moves"): by any test
  /// but the quality floor in a star that was at or above the floor.
  bool dropped_to_settle(std::size_t v) const { return call_ != 0 && dropped_in_[v] == call_ && !above_floor_[v]; }

  /// Orientation of face `f` at positions `pos` against the original surface.
  bool flipped(const std::vector<Vec3>& pos, std::size_t f) const {
    return area_vector(pos, m_.faces[f]).dot(reference(f)) <= 0;
  }

  /// Reference orientation of face `f`: its input normal, or for a face that
  /// is degenerate in the input the sum of its neighbours' normals. A face
  /// folded in the input keeps its orientation: unfolding it would be a flip
  /// with respect to the input, which the package never makes. Computed when
  /// needed (24 bytes per face less to store; a few dozen operations per test).
  Vec3 reference(std::size_t f) const {
    const Vec3 own = unit_normal(m_.points, m_.faces[f]);
    if (!own.isZero(0)) return own;
    const auto found = std::lower_bound(degenerate_faces_.begin(), degenerate_faces_.end(), Index(f));
    return degenerate_references_[std::size_t(found - degenerate_faces_.begin())];
  }

  bool collapsed(const std::vector<Vec3>& pos, std::size_t f) const {
    const auto& t = m_.faces[f];
    const double longest = (std::max)({(pos[t[1]] - pos[t[0]]).squaredNorm(), (pos[t[2]] - pos[t[1]]).squaredNorm(),
                                       (pos[t[0]] - pos[t[2]]).squaredNorm()});
    return is_collapsed(area_vector(pos, t).norm(), longest);
  }

private:
  // A witness of squared_distance_near(): the position of a face in the order
  // in which it scans the faces around a point, or no_witness. One byte per
  // point measured, not a face index (4 bytes per face instead of 16: the largest
  // meshes are at the memory bound of the user manual's "Performance"); a face
  // at position 255 or later is not remembered, and the next scan of the point
  // starts from the beginning (with the same result).
  using Witness = unsigned char;
  static constexpr Witness no_witness = 255;
  static Witness witness_of(std::size_t position) { return Witness((std::min)(position, std::size_t(no_witness))); }

  // --- The round protocol of enforce() -------------------------------------

  // Starts a call: the moved vertices and their travel, and the stamps'
  // epoch. A round either shortens a move or is followed by a round that does
  // or by none (a round of cheap tests without offenders hands over to the
  // fidelity tests), so there are at most 2 (halvings_ + 1) rounds per moved
  // vertex, plus two. If the stamps could overflow in this call, they start
  // again from 0: stamps of earlier calls only need to be older than this call's.
  void start_call(const std::vector<Vec3>& previous, const std::vector<Index>& moved, const std::vector<Vec3>& next) {
    for (std::size_t v : moved) {
      tries_[v] = 0, is_moved_[v] = 1;
      travel_[v] = added_up(travel_[v], (next[v] - previous[v]).norm());
    }
    if (std::size_t(round_) + 2 * (halvings_ + 2) * (moved.size() + 1) >
        std::size_t((std::numeric_limits<Round>::max)())) {
      for (auto* stamps : {&face_round_, &deviation_round_, &vertex_round_, &changed_round_, &ring_changed_})
        stamps->fill(0);
      round_ = 0;
    }
    first_round_ = round_ + 1;
  }

  // Ends a call: what it did to the moves of `moved`.
  Counts finish_call(const std::vector<Index>& moved) {
    ++call_;
    Counts counts;
    for (std::size_t v : moved) {
      is_moved_[v] = 0;
      if (tries_[v] > halvings_) {
        ++counts.rejected;
        ++limit_count(counts.rejected_by, v);
        dropped_in_[v] = call_;
      } else if (tries_[v] > 0) {
        ++counts.shortened;
        ++limit_count(counts.shortened_by, v);
      }
    }
    return counts;
  }

  // The tests, as recorded in failed_test_ for the statistics.
  enum class Test : unsigned char { flip_or_collapse, quality_floor, worsening, fidelity, crease };
  std::size_t& limit_count(ILSA_move_limits& limits, std::size_t v) const {
    switch (Test(failed_test_[v])) {
    case Test::flip_or_collapse:
      return limits.flip_or_collapse;
    case Test::quality_floor:
      return limits.quality_floor;
    case Test::worsening:
      return limits.worsening;
    case Test::fidelity:
      return limits.fidelity;
    default:
      return limits.crease;
    }
  }
  void failed(std::size_t v, Test test) { bad_[v] = 1, failed_test_[v] = static_cast<unsigned char>(test); }

  // Whether a value computed in round `computed` of this call still holds,
  // the positions it depends on having last changed in round `changed`.
  bool current(std::size_t computed, std::size_t changed) const {
    return computed == round_ || (computed >= first_round_ && changed < computed);
  }
  // The last round in which a vertex of face `f` changed.
  std::size_t face_changed(std::size_t f) const {
    const auto& t = m_.faces[f];
    return std::size_t((std::max)({changed_round_[t[0]], changed_round_[t[1]], changed_round_[t[2]]}));
  }
  // Whether the caller is to compute element `i` of `stamps` in this round:
  // its value is not current, and no other iteration has claimed it.
  template <class ConcurrencyTag> bool claim(Claim_stamps& stamps, std::size_t i, std::size_t changed) {
    const Round seen = stamps[i];
    return !current(seen, changed) && stamps.template claim<ConcurrencyTag>(i, seen, round_);
  }

  // --- The cheap tests ------------------------------------------------------

  // Sets bad_ for the vertices of `checking`: a face around it offends
  // (flip, collapse), or its star fails the quality floor or the worsening
  // test. Those that pass join `to_measure` for the fidelity tests.
  // `quality_now`: per face, its aspect ratio at `next`, set here.
  template <class ConcurrencyTag>
  void cheap_tests(const std::vector<Vec3>& previous, const std::vector<Vec3>& next, const std::vector<Index>& checking,
                   std::vector<double>& quality_now, std::vector<Index>& to_measure) {
    const bool quality_tests = quality_floor_ > 0 || reject_worsening_;
    // The faces around the vertices to check: which offend (unless known
    // from an earlier round of this call with the same positions), each
    // computed by the iteration that claims it.
    parallel_for<ConcurrencyTag>(checking.size(), [&](std::size_t i) {
      const std::size_t v = checking[i];
      for (const Index* f = m_.vertex_faces.first(v); f != m_.vertex_faces.last(v); ++f) {
        if (!claim<ConcurrencyTag>(face_round_, *f, face_changed(*f))) continue;
        double quality;
        offends_[*f] = offends(previous, next, *f, quality);
        if (quality_tests) quality_now[*f] = quality;
      }
    });
    // A vertex is shortened when any face around it offends, so every moved
    // vertex of an offending face is; then the quality tests.
    parallel_for<ConcurrencyTag>(checking.size(), [&](std::size_t i) {
      const std::size_t v = checking[i];
      bad_[v] = 0, above_floor_[v] = 0;
      for (const Index* f = m_.vertex_faces.first(v); f != m_.vertex_faces.last(v); ++f)
        if (offends_[*f]) failed(v, Test::flip_or_collapse);
      if (bad_[v] || !quality_tests) return;
      quality_tests_of(previous, next, v, quality_now);
    });
    if (std::isfinite(fidelity_tolerance_))
      for (std::size_t v : checking)
        if (!bad_[v] && !queued_[v]) {
          queued_[v] = 1;
          to_measure.push_back(Index(v));
        }
  }

  // The quality floor and the worsening test of `v`, whose faces pass the flip
  // and collapse tests.
  void quality_tests_of(const std::vector<Vec3>& previous, const std::vector<Vec3>& next, std::size_t v,
                        const std::vector<double>& quality_now) {
    const Star_quality now = star_quality_now(v, quality_now);
    // The star's worst triangle may not get worse and end below the floor.
    if (quality_floor_ > 0 && now.worst < quality_floor_) {
      const double before = star_quality(previous, v, previous[v]).worst;
      if (now.worst < before) {
        // A star at or above the floor before the move: if the halvings
        // fail too, the drop does not settle the vertex (user manual,
        // "Retrying dropped moves").
        failed(v, Test::quality_floor);
        above_floor_[v] = !(before < quality_floor_);
        return;
      }
    }
    if (reject_worsening_ && now.mean < star_quality(next, v, previous[v]).mean) {
      // Dropped at once: a shorter step along a worsening direction rarely
      // helps, and each halving costs a re-projection.
      failed(v, Test::worsening);
      tries_[v] = static_cast<unsigned char>(halvings_);
    }
  }

  // --- The fidelity tests ---------------------------------------------------

  // Sets bad_ for the vertices of `to_measure` that passed the cheap tests and
  // were not dropped since (the others leave the list): the fidelity bound
  // (deviates()) and the crease bound (crease_deviates()). First the
  // distances at `next` that neighbouring vertices share, unless computed in
  // an earlier round of this call with the same positions (a face's depends on
  // its vertices, a vertex's on the vertices up to two edges away), each
  // computed by the iteration that claims it; then the tests that read them.
  template <class ConcurrencyTag>
  void fidelity_tests(const std::vector<Vec3>& previous, const std::vector<Index>& previous_home,
                      const std::vector<Vec3>& next, const std::vector<Index>& next_home,
                      std::vector<Index>& to_measure) {
    std::size_t kept = 0;
    for (std::size_t v : to_measure) {
      queued_[v] = 0;
      if (tries_[v] <= halvings_) to_measure[kept++] = Index(v);
    }
    to_measure.resize(kept);
    if (input_edges_)
      for (std::size_t v : to_measure) measured_[v] = 1;
    parallel_for<ConcurrencyTag>(to_measure.size(), [&](std::size_t i) {
      const std::size_t v = to_measure[i];
      auto share = [&](std::size_t w) {
        if (claim<ConcurrencyTag>(vertex_round_, w, ring_changed_[w]))
          vertex_now_[w] = vertex_deviation(next, w, vertex_witness_[w]);
      };
      share(v);
      for (const Index* w = m_.vertex_neighbors.first(v); w != m_.vertex_neighbors.last(v); ++w) share(*w);
      for (const Index* f = m_.vertex_faces.first(v); f != m_.vertex_faces.last(v); ++f) {
        if (!claim<ConcurrencyTag>(deviation_round_, *f, face_changed(*f))) continue;
        // A face within the tolerance keeps its last value, also within
        // it: the value is only ever compared with the tolerance.
        if (face_within_tolerance(*f)) continue;
        face_now_[*f] = face_deviation(next, *f, face_witness_[*f]);
        const auto& t = m_.faces[*f];
        face_travel_[*f] = {travel_[t[0]], travel_[t[1]], travel_[t[2]]};
      }
    });
    parallel_for<ConcurrencyTag>(to_measure.size(), [&](std::size_t i) {
      const std::size_t v = to_measure[i];
      bad_[v] = 0;
      if (deviates(previous, v) || (input_edges_ && input_edge_deviates(previous, next, v)))
        failed(v, Test::fidelity);
      else if (crease_deviates(previous, previous_home, next, next_home, v))
        failed(v, Test::crease);
    });
    if (input_edges_)
      for (std::size_t v : to_measure) measured_[v] = 0;
  }

  // --- The shortening -------------------------------------------------------

  // Halves the move of each offender (re-projected), or after halvings_
  // halvings drops it.
  template <class ConcurrencyTag, class Project>
  void shorten(const std::vector<Vec3>& previous, const std::vector<Index>& previous_home, const std::vector<Vec3>& d,
               const std::vector<Index>& offenders, std::vector<Vec3>& next, std::vector<Index>& next_home,
               const Project& project) {
    parallel_for<ConcurrencyTag>(offenders.size(), [&](std::size_t i) {
      const std::size_t v = offenders[i];
      ++tries_[v];
      const Vec3 before = next[v];
      if (tries_[v] <= halvings_) {
        const double t = std::ldexp(1., -int(tries_[v]));
        const Vec3 target = previous[v] + d[v];
        const auto r = project(v, previous[v] + t * (target - previous[v]), previous[v], previous_home[v], false);
        next[v] = r.point;
        next_home[v] = Index(r.home);
      } else {
        next[v] = previous[v];
        next_home[v] = previous_home[v];
      }
      travel_[v] = added_up(travel_[v], (next[v] - before).norm());
    });
  }

  // After the shortening of `offenders`: the stamps of the stars they change,
  // and in `to_check` the moved vertices of the faces around them, each
  // offender and its neighbours (the vertices that share a face with it, or
  // only an edge, whose check then finds what its last one found).
  template <class ConcurrencyTag>
  void after_shortening(const std::vector<Index>& offenders, std::vector<Index>& to_check) {
    parallel_for<ConcurrencyTag>(offenders.size(), [&](std::size_t i) {
      const std::size_t v = offenders[i];
      changed_round_.set(v, round_);
      auto ring = [&](std::size_t u) {
        ring_changed_.set(u, round_);
        for (const Index* x = m_.vertex_neighbors.first(u); x != m_.vertex_neighbors.last(u); ++x)
          ring_changed_.set(*x, round_);
      };
      ring(v);
      for (const Index* u = m_.vertex_neighbors.first(v); u != m_.vertex_neighbors.last(v); ++u) ring(*u);
    });
    to_check.clear();
    auto recheck = [&](std::size_t w) {
      if (is_moved_[w] && tries_[w] <= halvings_ && !checked_[w]) {
        checked_[w] = 1;
        to_check.push_back(Index(w));
      }
    };
    for (std::size_t v : offenders) {
      recheck(v);
      for (const Index* w = m_.vertex_neighbors.first(v); w != m_.vertex_neighbors.last(v); ++w) recheck(*w);
    }
    for (std::size_t w : to_check) checked_[w] = 0;
  }

  // --- The tests ------------------------------------------------------------

  // The collapse criterion, from twice the area and the longest edge squared.
  static bool is_collapsed(double double_area, double longest_squared) {
    return double_area <= collapse_tolerance * longest_squared || longest_squared == 0;
  }

  // A face offends if it is collapsed now and was not before, or flipped and
  // not collapsed now and was not so before. A face collapsed before (in the
  // input: a needle, or two vertices at one point) may open again, but only
  // with its reference orientation: opening it the other way round is a flip.
  // (A face flipped and not collapsed before cannot occur: the input has none,
  // and no move makes one.)
  // The test at `next` shares its edge vectors with the face's aspect ratio
  // there, set in `quality` (collapsed(), flipped() and aspect_ratio(): the
  // same operations, the same values).
  bool offends(const std::vector<Vec3>& previous, const std::vector<Vec3>& next, std::size_t f, double& quality) const {
    const auto& t = m_.faces[f];
    const Vec3 &a = next[t[0]], &b = next[t[1]], &c = next[t[2]];
    const Vec3 ab = b - a, area = ab.cross(c - a);
    const std::array<double, 3> squared_length{(c - b).squaredNorm(), (a - c).squaredNorm(), ab.squaredNorm()};
    const double double_area = area.norm();
    quality = aspect_ratio_from(double_area, squared_length);
    const double longest = (std::max)({squared_length[0], squared_length[1], squared_length[2]});
    if (is_collapsed(double_area, longest)) return !collapsed(previous, f);
    return area.dot(reference(f)) <= 0 && (collapsed(previous, f) || !flipped(previous, f));
  }

  // Whether the move of `v` takes the smoothed surface farther than the
  // tolerance from the input surface, in either direction, where it was not
  // already: from the input position of `v` or of a neighbour to the smoothed
  // surface (a bump or crease bend cut off), or from the faces around `v` to
  // the input surface (a chord over a fold). Distances are measured to the
  // faces around the vertices concerned and, when those are not close enough,
  // to the faces around their neighbours: vertices travel less than an edge
  // length per iteration, so these faces cover the points measured.
  // The distances at `next` are computed once per round (`vertex_now_`,
  // `face_now_`): `next` does not change while a round checks its vertices,
  // and neighbouring vertices share them.
  bool deviates(const std::vector<Vec3>& previous, std::size_t v) const {
    auto cuts = [&](std::size_t w) {
      const double now = vertex_now_[w];
      if (!(now > fidelity_tolerance_)) return false;
      Witness witness = vertex_witness_[w];
      return now > vertex_deviation(previous, w, witness);
    };
    if (cuts(v)) return true;
    for (const Index* w = m_.vertex_neighbors.first(v); w != m_.vertex_neighbors.last(v); ++w)
      if (cuts(*w)) return true;
    for (const Index* f = m_.vertex_faces.first(v); f != m_.vertex_faces.last(v); ++f) {
      const double now = face_now_[*f];
      if (!(now > fidelity_tolerance_)) continue;
      std::array<Witness, 4> witnesses = face_witness_[*f];
      if (now > face_deviation(previous, *f, witnesses)) return true;
    }
    return false;
  }

  // The fidelity bound at the input edges (`ilsa_fidelity_input_edges`; user
  // manual, "Fidelity at Input Edges"): the points 1/4, 1/2 and 3/4 of the way
  // along an input edge may not end farther than the tolerance from the
  // smoothed surface around the edge's ends, unless they already were.
  // Between the input vertices, which deviates() measures, the input surface
  // can lie farther from the smoothed one. The move of `v` changes the faces
  // around its edges and around the edges opposite to it in its faces: these
  // are measured, each edge in a round once, by the vertex of lowest index
  // among those measured in the round that it concerns (its ends and the
  // vertices opposite to it), whose move an edge that fails shortens.
  bool input_edge_deviates(const std::vector<Vec3>& previous, const std::vector<Vec3>& next, std::size_t v) const {
    for (const Index* u = m_.vertex_neighbors.first(v); u != m_.vertex_neighbors.last(v); ++u)
      if (input_edge_cut(previous, next, v, v, *u)) return true;
    for (const Index* f = m_.vertex_faces.first(v); f != m_.vertex_faces.last(v); ++f) {
      const auto& t = m_.faces[*f];
      const std::size_t i = t[0] == v ? 0 : t[1] == v ? 1 : 2;
      if (input_edge_cut(previous, next, v, t[(i + 1) % 3], t[(i + 2) % 3])) return true;
    }
    return false;
  }

  // Whether the input edge from `a` to `b`, measured for the move of `v`, is
  // cut off (input_edge_deviates()). The points of an edge share a witness:
  // they lie near the same faces.
  bool input_edge_cut(const std::vector<Vec3>& previous, const std::vector<Vec3>& next, std::size_t v, std::size_t a,
                      std::size_t b) const {
    if (measured_by_lower(v, a, b)) return false;
    const std::array<std::size_t, 2> ends{a, b};
    Witness witness = no_witness;
    for (int k = 1; k < input_edge_parts; ++k) {
      const Vec3 x = m_.points[a] + (double(k) / input_edge_parts) * (m_.points[b] - m_.points[a]);
      const double now = std::sqrt(squared_distance_near(x, next, ends, witness));
      if (!(now > fidelity_tolerance_)) continue;
      Witness before = no_witness;
      if (now > std::sqrt(squared_distance_near(x, previous, ends, before))) return true;
    }
    return false;
  }

  // Whether a vertex of lower index than `v` measured in this round concerns
  // the edge from `a` to `b`: one of its ends, or of the vertices opposite to
  // it in its faces.
  bool measured_by_lower(std::size_t v, std::size_t a, std::size_t b) const {
    auto lower = [&](std::size_t w) { return w < v && measured_[w]; };
    if (lower(a) || lower(b)) return true;
    for (const Index* f = m_.vertex_faces.first(a); f != m_.vertex_faces.last(a); ++f) {
      const auto& t = m_.faces[*f];
      if (t[0] != b && t[1] != b && t[2] != b) continue;
      if (lower(std::size_t(t[0]) + t[1] + t[2] - a - b)) return true;
    }
    return false;
  }

  // The crease bound (user manual, "Crease fidelity"): the same test along
  // the feature lines of the input (its sharp edges, and the edges whose
  // dihedral angle is below the feature angle), both ways. For each feature
  // edge of `v`, the input positions of its two ends may not end farther than
  // the tolerance from the smoothed line around them (a bend cut off), nor its
  // inner input points, and the inner points of the smoothed edge may not end
  // farther from the input line (a chord across a bend), unless they already
  // were. The points are those mesh_fidelity_ilsa() samples, k / 8 of the way.
  bool crease_deviates(const std::vector<Vec3>& previous, const std::vector<Index>& previous_home,
                       const std::vector<Vec3>& next, const std::vector<Index>& next_home, std::size_t v) const {
    const Index* u = m_.vertex_neighbors.first(v);
    for (const Index* e = m_.vertex_edges.first(v); e != m_.vertex_edges.last(v); ++e, ++u) {
      if (!c_.feature_edge[*e]) continue;
      const std::size_t line = line_of(*e);
      for (std::size_t w : {v, std::size_t(*u)}) {
        if (c_.is_fixed(w)) continue; // keeps its input position, on the line
        const double now = line_vertex_deviation(next, w, line);
        if (now > fidelity_tolerance_ && now > line_vertex_deviation(previous, w, line)) return true;
      }
      // The points at which mesh_fidelity_ilsa() samples the edge, k / 8 of the way, both ways.
      for (int k = 0; k < crease_samples; ++k) { // k = crease_samples is `u`, checked with its own move
        const double t = double(k) / crease_samples;
        const double now = line_edge_deviation(next, next_home, v, *u, t, line);
        if (now > fidelity_tolerance_ && now > line_edge_deviation(previous, previous_home, v, *u, t, line))
          return true;
        if (k == 0) continue; // the input position of `v`, measured above
        const double input_now = line_input_deviation(next, v, *u, t, line);
        if (input_now > fidelity_tolerance_ && input_now > line_input_deviation(previous, v, *u, t, line)) return true;
      }
    }
    return false;
  }

  // Distance from the point at `t` along the input edge from `v` to `u` to the
  // line `line` at `pos` around them.
  double line_input_deviation(const std::vector<Vec3>& pos, std::size_t v, std::size_t u, double t,
                              std::size_t line) const {
    return distance_to_line(m_.points[v] + t * (m_.points[u] - m_.points[v]), pos, {v, u}, line);
  }

  // A crease edge belongs to its crease polyline; another feature edge is a line of its own.
  std::size_t line_of(std::size_t e) const { return c_.crease_of_edge[e] != npos ? c_.crease_of_edge[e] : e; }

  // Distance from the input position of `w` to the line `line` at `pos` around it.
  double line_vertex_deviation(const std::vector<Vec3>& pos, std::size_t w, std::size_t line) const {
    return distance_to_line(m_.points[w], pos, {w}, line);
  }

  // Distance from `x` to the line `line` at `pos` around the vertices
  // `around`: the line's edges at them and at the other ends of these edges.
  double distance_to_line(const Vec3& x, const std::vector<Vec3>& pos, std::initializer_list<std::size_t> around,
                          std::size_t line) const {
    double best = std::numeric_limits<double>::infinity();
    auto measure = [&](std::size_t e) {
      best = (std::min)(best, squared_distance_to_segment(x, pos[m_.edges[e][0]], pos[m_.edges[e][1]]));
    };
    for (std::size_t w : around)
      for_each_line_edge(w, line, [&](std::size_t e) {
        for (std::size_t end : m_.edges[e]) for_each_line_edge(end, line, measure);
      });
    return std::sqrt(best);
  }

  // Distance from the point at `t` along the segment from `v` to `u` at `pos`
  // to the input line `line` where these vertices lie: around the crease edge
  // a moving ridge vertex lies on (`home`), around the input position of
  // another (a ridge vertex outside the vertex range has no home: it does not move).
  double line_edge_deviation(const std::vector<Vec3>& pos, const std::vector<Index>& home, std::size_t v, std::size_t u,
                             double t, std::size_t line) const {
    const Vec3 x = pos[v] + t * (pos[u] - pos[v]);
    double best = std::numeric_limits<double>::infinity();
    auto measure = [&](std::size_t e) {
      best = (std::min)(best, squared_distance_to_segment(x, m_.points[m_.edges[e][0]], m_.points[m_.edges[e][1]]));
    };
    for (std::size_t w : {v, u}) {
      if (c_.type[w] != ILSA_vertex_type::Ridge || home[w] == npos) {
        for_each_line_edge(w, line, measure);
        continue;
      }
      for (std::size_t end : m_.edges[home[w]]) for_each_line_edge(end, line, measure);
    }
    return std::sqrt(best);
  }

  // The edges of the feature line `line` at vertex `w`.
  template <class F> void for_each_line_edge(std::size_t w, std::size_t line, F f) const {
    for (const Index* e = m_.vertex_edges.first(w); e != m_.vertex_edges.last(w); ++e)
      if (c_.feature_edge[*e] && line_of(*e) == line) f(*e);
  }

  // Whether face_deviation() of face `f` at `next` is certainly within the
  // tolerance, without computing it: the distance to a fixed set of faces
  // grows by at most the distance the point moves, the points measured are
  // averages of the face's vertices, and each vertex has moved by at most
  // its travel since face_now_[f] was computed (margins for rounding).
  bool face_within_tolerance(std::size_t f) const {
    const auto& t = m_.faces[f];
    double drift = 0;
    for (std::size_t k = 0; k < 3; ++k) drift = (std::max)(drift, double(travel_[t[k]]) - double(face_travel_[f][k]));
    return face_now_[f] + drift * (1. + 1e-9) + 1e-14 < fidelity_tolerance_;
  }
  // `travel + step` as a float rounded up: the travels are stored as floats,
  // and each one stays at least the length of its vertex's path.
  static float added_up(float travel, double step) { return float_rounded_up(double(travel) + step); }

  // Largest distance from the centroid and the edge midpoints of face `f` at
  // `pos` to the input surface around the face's vertices. `witnesses`: for
  // each of these points, the face looked at first (see squared_distance_near()).
  double face_deviation(const std::vector<Vec3>& pos, std::size_t f, std::array<Witness, 4>& witnesses) const {
    const auto& t = m_.faces[f];
    const Vec3 &a = pos[t[0]], &b = pos[t[1]], &c = pos[t[2]];
    const std::array<Vec3, 4> points{Vec3((a + b + c) / 3.), Vec3((a + b) / 2.), Vec3((b + c) / 2.),
                                     Vec3((c + a) / 2.)};
    double worst = 0;
    for (std::size_t i = 0; i < 4; ++i)
      worst = (std::max)(worst, squared_distance_near(points[i], m_.points, t, witnesses[i]));
    return std::sqrt(worst);
  }

  // Distance from the input position of `w` to the surface around `w` at `pos`;
  // `witness` as in squared_distance_near().
  double vertex_deviation(const std::vector<Vec3>& pos, std::size_t w, Witness& witness) const {
    return std::sqrt(squared_distance_near(m_.points[w], pos, std::array<std::size_t, 1>{w}, witness));
  }

  // Squared distance from `x` to the faces (at positions `pos`) around the
  // vertices `around`, then, if none is within the tolerance, around their
  // neighbours. Beyond the tolerance the value is the minimum over all these
  // faces (an upper bound of the distance to the surface); within it the scan
  // stops at the first face in reach, so the value depends on the scan order,
  // and callers only compare it with the tolerance: the result of the check
  // does not depend on the order. `witness`, the position of one of these
  // faces in the scan (see Witness), is looked at first, and is set to the
  // face found in reach: the one that was in reach at the last call for the
  // same point is most often in reach again, vertices move little between two
  // calls, so most scans look at one face. A face is looked at once, although
  // it lies around several of the vertices scanned (but for a face around two
  // neighbours, which costs more to tell).
  // At the input positions, a face whose bounding ball lies farther from `x`
  // than the best distance so far can neither lower it nor be in reach: its
  // distance is not computed (the result is the same).
  template <class I, std::size_t N>
  double squared_distance_near(const Vec3& x, const std::vector<Vec3>& pos, const std::array<I, N>& around,
                               Witness& witness) const {
    const double tolerance2 = fidelity_tolerance_ * fidelity_tolerance_;
    const bool input = &pos == &m_.points;
    const std::size_t first = face_in_scan(around, witness);
    std::size_t position = witness; // in the scan, of the face looked at
    double best = std::numeric_limits<double>::infinity(), reach = best;
    auto in_reach = [&](std::size_t f) {
      if (input && best != std::numeric_limits<double>::infinity() && !projector_.ball_within(x, f, reach))
        return false;
      const auto& t = m_.faces[f];
      const double d = squared_distance_to_triangle(x, pos[t[0]], pos[t[1]], pos[t[2]]);
      if (d < best) best = d, reach = std::sqrt(best) + Projector::ball_slack;
      if (best > tolerance2) return false;
      witness = witness_of(position);
      return true;
    };
    if (first != npos && in_reach(first)) return best;
    position = 0;
    // The faces around `u` but those around the first `scanned` vertices of
    // `around`, which were looked at already (all of them if `u` is one).
    for_each_scanned_vertex(around, [&](std::size_t u, std::size_t scanned) {
      if (std::find(around.begin(), around.begin() + scanned, u) != around.begin() + scanned) {
        position += m_.vertex_faces.size(u);
        return false;
      }
      for (const Index* f = m_.vertex_faces.first(u); f != m_.vertex_faces.last(u); ++f, ++position) {
        const auto& t = m_.faces[*f];
        bool seen = false;
        for (std::size_t j = 0; j < scanned; ++j)
          seen = seen || t[0] == around[j] || t[1] == around[j] || t[2] == around[j];
        if (!seen && *f != first && in_reach(*f)) return true;
      }
      return false;
    });
    return best;
  }

  // Calls `f(u, scanned)` for the vertices whose faces squared_distance_near()
  // scans, in its order, until `f` returns true: the vertices of `around`
  // (`scanned`: how many of them come before), then their neighbours
  // (`scanned`: N). Returns whether `f` returned true.
  template <class I, std::size_t N, class F>
  bool for_each_scanned_vertex(const std::array<I, N>& around, const F& f) const {
    for (std::size_t k = 0; k < N; ++k)
      if (f(std::size_t(around[k]), k)) return true;
    for (std::size_t u : around)
      for (const Index* w = m_.vertex_neighbors.first(u); w != m_.vertex_neighbors.last(u); ++w)
        if (f(std::size_t(*w), N)) return true;
    return false;
  }

  // The face at `position` in the scan of squared_distance_near() around
  // `around`, npos for no_witness.
  template <class I, std::size_t N> std::size_t face_in_scan(const std::array<I, N>& around, Witness position) const {
    if (position == no_witness) return npos;
    std::size_t k = position, face = npos;
    for_each_scanned_vertex(around, [&](std::size_t u, std::size_t) {
      const std::size_t n = m_.vertex_faces.size(u);
      if (k < n) face = m_.vertex_faces.first(u)[k];
      k -= (std::min)(k, n);
      return face != npos;
    });
    return face;
  }

  struct Star_quality {
    double worst = 1., mean = 0.;
  };

  // star_quality(next, v, next[v]) from the aspect ratios of the faces at
  // `next` computed in the current round (`quality_now`), summed in the same order.
  Star_quality star_quality_now(std::size_t v, const std::vector<double>& quality_now) const {
    Star_quality q;
    for (const Index* f = m_.vertex_faces.first(v); f != m_.vertex_faces.last(v); ++f) {
      q.worst = (std::min)(q.worst, quality_now[*f]);
      q.mean += quality_now[*f];
    }
    q.mean /= double((std::max)(m_.vertex_faces.size(v), std::size_t(1)));
    return q;
  }

  // Worst and mean aspect ratio around `v`, with `v` at `at` and the others at `pos`.
  Star_quality star_quality(const std::vector<Vec3>& pos, std::size_t v, const Vec3& at) const {
    return star_quality_at(v, [&](std::size_t w) -> const Vec3& { return w == v ? at : pos[w]; });
  }

  // The same with each vertex `w` of the star at `point(w)`.
  template <class Point> Star_quality star_quality_at(std::size_t v, const Point& point) const {
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
  const Vertex_classification& c_;
  const Projector& projector_;
  double quality_floor_;
  double fidelity_tolerance_;
  bool reject_worsening_;
  bool input_edges_;                         // the fidelity bound also at the input edges (input_edge_deviates())
  static constexpr int input_edge_parts = 4; // the points measured: k / 4 of the way along, 0 < k < 4
  std::size_t halvings_;
  std::vector<Index> degenerate_faces_;              // faces degenerate in the input, in increasing order
  std::vector<Vec3> degenerate_references_;          // their reference orientations
  std::vector<unsigned char> offends_;               // per face, in the current round
  std::vector<unsigned char> bad_;                   // per vertex: its move offends, in the current round
  std::vector<unsigned char> failed_test_;           // per vertex: the Test its move failed last
  std::vector<unsigned char> tries_;                 // halvings applied to a vertex's move (at most halvings_ + 1)
  std::vector<unsigned char> checked_;               // per vertex: already in the next list to check
  std::vector<unsigned char> queued_;                // per vertex: in the list for the fidelity tests
  Claim_stamps face_round_;                          // round in which a face's offending flag was computed
  Claim_stamps deviation_round_, vertex_round_;      // round in which the deviations below were computed
  Claim_stamps changed_round_;                       // last round in which a vertex's move changed
  Claim_stamps ring_changed_;                        // the same, for any vertex up to two edges away
  std::vector<double> face_now_, vertex_now_;        // face_deviation (see face_within_tolerance()) and
                                                     // vertex_deviation at `next`
  std::vector<Witness> vertex_witness_;              // face first looked at by vertex_deviation
  std::vector<std::array<Witness, 4>> face_witness_; // the same, for each point of face_deviation
  std::vector<float> travel_;                        // per vertex: length of the path of its position at `next`
                                                     // (at least: each step is added rounded up)
  std::vector<std::array<float, 3>> face_travel_;    // travel_ of the face's vertices then
  std::vector<unsigned char> is_moved_;
  std::vector<unsigned char> above_floor_; // per vertex: set by its last round of cheap tests (every moved vertex
                                           // has one, and one after each shortening before its fidelity tests):
                                           // it failed the quality floor in a star at or above the floor
  std::vector<std::uint32_t> dropped_in_;  // per vertex: the last call of enforce() that dropped its move
  std::vector<unsigned char> measured_;    // per vertex, with input_edges_: in the round's fidelity tests
  Round round_ = 0;
  Round first_round_ = 1;  // the first round of the current call of enforce()
  std::uint32_t call_ = 0; // calls of enforce() so far
};

} // namespace ILSA
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_POLYGON_MESH_PROCESSING_INTERNAL_ILSA_MOVE_SAFETY_H

// Copyright (c) 2026 The Polygon_mesh_processing_ILSA authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Safety check after projection (`use_safety_constraints`): the loop that
// shortens and drops moves until each guarantee holds (user manual, "Safety Check"). The guarantees: no triangle
// reverses its orientation with respect to the original surface or collapses, the worst triangle around a moved vertex
// does not get worse if it ends below the quality floor (and, but in the paper's variant, the star's mean does
// not drop): these are the cheap tests, here; the smoothed surface stays within the fidelity tolerance of the input,
// both ways (fidelity_certificate.h), and so do the feature lines (crease_certificate.h). A vertex of an offending
// triangle has its move halved (and re-projected) a few times, then dropped for this iteration. Since the moves are
// applied all at once (Jacobi), the check is repeated until no triangle offends; it ends because a triangle whose
// vertices are all back at their previous, accepted positions is as it was.

#ifndef CGAL_POLYGON_MESH_PROCESSING_INTERNAL_ILSA_MOVE_SAFETY_H
#define CGAL_POLYGON_MESH_PROCESSING_INTERNAL_ILSA_MOVE_SAFETY_H

#include <CGAL/Polygon_mesh_processing/internal/ILSA/core.h>
#include <CGAL/Polygon_mesh_processing/internal/ILSA/crease_certificate.h>
#include <CGAL/Polygon_mesh_processing/internal/ILSA/fidelity_certificate.h>
#include <CGAL/Polygon_mesh_processing/internal/ILSA/flat_mesh.h>
#include <CGAL/Polygon_mesh_processing/internal/ILSA/orientation_test.h>
#include <CGAL/Polygon_mesh_processing/internal/ILSA/parallel_loops.h>
#include <CGAL/Polygon_mesh_processing/internal/ILSA/star_quality.h>

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

class Move_safety {
  using Round = Claim_stamps::Round; // rounds of the check, counted over the whole run

public:
  /// `quality_floor`: a move may not lower the minimum aspect ratio of the
  /// vertex's star below this value (star_quality.h).
  /// `fidelity_tolerance`: the largest distance (normalised units: the
  /// bounding-box diagonal is 1) between the smoothed and the input surface,
  /// and between their feature lines; infinity disables these bounds.
  /// `reject_worsening`: drop a move that lowers the mean aspect ratio of the
  /// vertex's star, the neighbours being at their new positions.
  /// `original` and `classification` must outlive the check: it keeps
  /// references. `incidences` (those of `original`) is read here only.
  Move_safety(const Flat_mesh& original, const Vertex_classification& classification,
              const Set_up_incidences& incidences, double quality_floor, double fidelity_tolerance,
              bool reject_worsening, std::size_t halvings)
      : m_(original), orientation_(original, incidences), quality_(original, quality_floor, reject_worsening),
        halvings_((std::min)(halvings, std::size_t(100))), surface_(original, fidelity_tolerance),
        creases_(original, classification, fidelity_tolerance) {
    offends_.assign(m_.number_of_faces(), 0);
    face_round_.assign(m_.number_of_faces(), 0);
    bad_.assign(m_.number_of_vertices(), 0);
    failed_test_.assign(m_.number_of_vertices(), 0);
    changed_round_.assign(m_.number_of_vertices(), 0);
    tries_.assign(m_.number_of_vertices(), 0);
    dropped_in_.assign(m_.number_of_vertices(), 0);
    checked_.assign(m_.number_of_vertices(), 0);
    is_moved_.assign(m_.number_of_vertices(), 0);
    above_floor_.assign(m_.number_of_vertices(), 0);
    if (measures()) in_changed_.assign(m_.number_of_vertices(), 0);
  }

  /// The largest distances between the smoothed surface at `pos` and the
  /// input, and between their feature lines, both ways, certified
  /// (normalised units; infinity without a tolerance).
  double certified_distance() const { return surface_.largest_bound(); }
  double certified_crease_distance(const std::vector<Vec3>& pos) const { return creases_.largest_bound(pos); }

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
  /// The rounds of the check (user manual, "Safety Check"): a round runs
  /// either the cheap tests (cheap_tests(): flip, collapse, quality) or, once
  /// no move fails them, the certificates of the faces and feature edges the
  /// moves since the last such round changed (certificate_tests()), then
  /// shortens the offending moves (shorten()) and lists the moved vertices
  /// whose stars the shortening changed for the next round
  /// (after_shortening()). Each of these phases is a loop over the vertices
  /// to test (or the offenders, or the faces) whose iterations write only
  /// their own element or the elements they claim (user manual, "Parallel Runs").
  template <class ConcurrencyTag, class Project>
  Counts enforce(const std::vector<Vec3>& previous, const std::vector<Index>& previous_home, const std::vector<Vec3>& d,
                 const std::vector<Index>& moved, std::vector<Vec3>& next, std::vector<Index>& next_home,
                 const Project& project, std::vector<double>& face_scratch) {
    start_call(moved);
    // to_check: vertices for the cheap tests. (The first round checks `moved`
    // itself, not a copy.)
    std::vector<Index> to_check, offenders;
    bool first = true;
    // The cheap tests run until no move fails them; only then do the costly
    // certificates run, on what every move since their last round changed
    // (user manual, "Safety Check"): most moves the check
    // drops fail a cheap test, and each one dropped changes the stars of its
    // neighbours.
    while (!(first ? moved : to_check).empty() || !changed_.empty()) {
      ++round_;
      const std::vector<Index>& checking = first ? moved : to_check;
      first = false;
      offenders.clear();
      if (!checking.empty()) {
        cheap_tests<ConcurrencyTag>(previous, next, checking, face_scratch);
        for (std::size_t v : checking)
          if (bad_[v]) offenders.push_back(Index(v));
      } else {
        certificate_tests<ConcurrencyTag>(previous, next, offenders);
      }
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
  /// guarantee (user manual, "Worsening Moves"). The aspect ratios are
  /// computed here, for the few vertices the gate lets through, not for
  /// every face.
  bool drop_before_projection(const std::vector<Vec3>& pos, const std::vector<Vec3>& d, std::size_t v) const {
    if (!quality_.rejects_worsening() || call_ == 0 || dropped_in_[v] != call_) return false;
    return quality_.worse_at_targets(pos, d, v);
  }

  /// Whether the last call of enforce() dropped the move of `v` in a way that
  /// settles the vertex (user manual, "Retrying Dropped Moves"): by any test
  /// but the quality floor in a star that was at or above the floor.
  bool dropped_to_settle(std::size_t v) const { return call_ != 0 && dropped_in_[v] == call_ && !above_floor_[v]; }

  /// The orientation and collapse test the check runs.
  const Orientation_test& orientation() const { return orientation_; }

private:
  // --- The round protocol of enforce() -------------------------------------

  // Starts a call: the moved vertices and their travel, and the stamps'
  // epoch. A round either shortens a move or is followed by a round that does
  // or by none (a round of cheap tests without offenders hands over to the
  // certificates), so there are at most 2 (halvings_ + 1) rounds per moved
  // vertex, plus two. If the stamps could overflow in this call, they start
  // again from 0: stamps of earlier calls only need to be older than this call's.
  void start_call(const std::vector<Index>& moved) {
    for (std::size_t v : moved) {
      tries_[v] = 0, is_moved_[v] = 1;
      note_change(v);
    }
    if (std::size_t(round_) + 2 * (halvings_ + 2) * (moved.size() + 1) >
        std::size_t((std::numeric_limits<Round>::max)())) {
      for (auto* stamps : {&face_round_, &changed_round_}) stamps->fill(0);
      round_ = 0;
    }
    first_round_ = round_ + 1;
  }

  // Ends a call: what it did to the moves of `moved`.
  Counts finish_call(const std::vector<Index>& moved) {
    ++call_;
    surface_.accept();
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
  // test. `quality_now`: per face, its aspect ratio at `next`, set here.
  template <class ConcurrencyTag>
  void cheap_tests(const std::vector<Vec3>& previous, const std::vector<Vec3>& next, const std::vector<Index>& checking,
                   std::vector<double>& quality_now) {
    const bool quality_tests = quality_.enabled();
    // The faces around the vertices to check: which offend (unless known
    // from an earlier round of this call with the same positions), each
    // computed by the iteration that claims it.
    parallel_for<ConcurrencyTag>(checking.size(), [&](std::size_t i) {
      const std::size_t v = checking[i];
      for (const Index* f = m_.vertex_faces.first(v); f != m_.vertex_faces.last(v); ++f) {
        if (!claim<ConcurrencyTag>(face_round_, *f, face_changed(*f))) continue;
        double quality;
        offends_[*f] = orientation_.offends(previous, next, *f, quality);
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
  }

  // The quality floor and the worsening test of `v`, whose faces pass the flip
  // and collapse tests.
  void quality_tests_of(const std::vector<Vec3>& previous, const std::vector<Vec3>& next, std::size_t v,
                        const std::vector<double>& quality_now) {
    switch (quality_.test(previous, next, v, quality_now)) {
    case Star_quality_test::Verdict::pass:
      return;
    case Star_quality_test::Verdict::floor:
      failed(v, Test::quality_floor);
      return;
    case Star_quality_test::Verdict::floor_from_above:
      // A star at or above the floor before the move: if the halvings fail
      // too, the drop does not settle the vertex (user manual, "Retrying
      // Dropped Moves").
      failed(v, Test::quality_floor);
      above_floor_[v] = 1;
      return;
    case Star_quality_test::Verdict::worsening:
      // Dropped at once: a shorter step along a worsening direction rarely
      // helps, and each halving costs a re-projection.
      failed(v, Test::worsening);
      tries_[v] = static_cast<unsigned char>(halvings_);
      return;
    }
  }

  // --- The certificates -----------------------------------------------------

  // Whether the fidelity tolerance is finite: then the certificates run.
  bool measures() const { return surface_.enabled() || creases_.enabled(); }

  // Lists `v`, whose position changed, for the next certificate round.
  void note_change(std::size_t v) {
    if (!measures() || in_changed_[v]) return;
    in_changed_[v] = 1;
    changed_.push_back(Index(v));
  }

  // The fidelity certificate and the crease bound of what the moves since
  // their last round changed. A face or an edge that fails shortens the moves
  // of the vertices it depends on that can still be shortened; if none can,
  // they are all at their previous positions, where it was certified.
  template <class ConcurrencyTag>
  void certificate_tests(const std::vector<Vec3>& previous, const std::vector<Vec3>& next,
                         std::vector<Index>& offenders) {
    for (std::size_t v : changed_) in_changed_[v] = 0;
    auto blamer = [&](Test test) {
      return [&, test](std::size_t w) {
        if (!is_moved_[w] || tries_[w] > halvings_ || next[w] == previous[w]) return false;
        if (!bad_[w]) {
          failed(w, test);
          offenders.push_back(Index(w));
        }
        return true;
      };
    };
    // The crease bound first: a move it shortens counts as limited by it.
    creases_.template check<ConcurrencyTag>(next, changed_, blamer(Test::crease));
    surface_.template check<ConcurrencyTag>(previous, next, changed_, blamer(Test::fidelity));
    changed_.clear();
    for (std::size_t v : offenders) bad_[v] = 0;
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
    });
    for (std::size_t v : offenders) note_change(v);
  }

  // After the shortening of `offenders`: the stamps of the stars they change,
  // and in `to_check` the moved vertices of the faces around them, each
  // offender and its neighbours (the vertices that share a face with it, or
  // only an edge, whose check then finds what its last one found).
  template <class ConcurrencyTag>
  void after_shortening(const std::vector<Index>& offenders, std::vector<Index>& to_check) {
    parallel_for<ConcurrencyTag>(offenders.size(), [&](std::size_t i) { changed_round_.set(offenders[i], round_); });
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

  const Flat_mesh& m_;
  Orientation_test orientation_;
  Star_quality_test quality_;
  std::size_t halvings_;
  Fidelity_certificate surface_;
  Crease_certificate creases_;
  std::vector<unsigned char> offends_;     // per face, in the current round
  std::vector<unsigned char> bad_;         // per vertex: its move offends, in the current round
  std::vector<unsigned char> failed_test_; // per vertex: the Test its move failed last
  std::vector<unsigned char> tries_;       // halvings applied to a vertex's move (at most halvings_ + 1)
  std::vector<unsigned char> checked_;     // per vertex: already in the next list to check
  Claim_stamps face_round_;                // round in which a face's offending flag was computed
  Claim_stamps changed_round_;             // last round in which a vertex's move changed
  std::vector<unsigned char> is_moved_;
  std::vector<unsigned char> above_floor_; // per vertex: set by its last round of cheap tests (every moved vertex
                                           // has one, and one after each shortening): it failed the quality floor
                                           // in a star at or above the floor
  std::vector<std::uint32_t> dropped_in_;  // per vertex: the last call of enforce() that dropped its move
  std::vector<Index> changed_;             // vertices whose position changed since the last certificate round
  std::vector<unsigned char> in_changed_;  // per vertex: in changed_
  Round round_ = 0;
  Round first_round_ = 1;  // the first round of the current call of enforce()
  std::uint32_t call_ = 0; // calls of enforce() so far
};

} // namespace ILSA
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_POLYGON_MESH_PROCESSING_INTERNAL_ILSA_MOVE_SAFETY_H

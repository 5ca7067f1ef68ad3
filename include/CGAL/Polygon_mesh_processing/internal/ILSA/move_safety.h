// Copyright (c) 2026 The Polygon_mesh_processing_ILSA authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Safety check after projection (`use_safety_constraints`): the loop that
// shortens and drops moves until each guarantee holds (user manual, "Safety
// check"). The guarantees: no triangle reverses its orientation with respect
// to the original surface or collapses, the worst triangle around a moved
// vertex does not get worse if it ends below the quality floor (and, with
// `ilsa_reject_worsening_moves`, the star's mean does not drop): these are
// the cheap tests, here; the smoothed surface stays within the fidelity
// tolerance of the input, both ways (fidelity_certificate.h), and so do the
// feature lines (crease_certificate.h).
// A vertex of an offending triangle has its move halved (and re-projected) a
// few times, then dropped for this iteration. Since the moves are applied all
// at once (Jacobi), the check is repeated until no triangle offends; it ends
// because a triangle whose vertices are all back at their previous, accepted
// positions is as it was.

#ifndef CGAL_POLYGON_MESH_PROCESSING_INTERNAL_ILSA_MOVE_SAFETY_H
#define CGAL_POLYGON_MESH_PROCESSING_INTERNAL_ILSA_MOVE_SAFETY_H

#include <CGAL/Polygon_mesh_processing/triangle_quality_ilsa.h>
#include <CGAL/Polygon_mesh_processing/internal/ILSA/core.h>
#include <CGAL/Polygon_mesh_processing/internal/ILSA/crease_certificate.h>
#include <CGAL/Polygon_mesh_processing/internal/ILSA/fidelity_certificate.h>
#include <CGAL/Polygon_mesh_processing/internal/ILSA/flat_mesh.h>
#include <CGAL/Polygon_mesh_processing/internal/ILSA/parallel_loops.h>

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
      : m_(original), quality_floor_(quality_floor), reject_worsening_(reject_worsening),
        halvings_((std::min)(halvings, std::size_t(100))), surface_(original, fidelity_tolerance),
        creases_(original, classification, fidelity_tolerance) {
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
  /// The rounds of the check (user manual, "Safety check"): a round runs
  /// either the cheap tests (cheap_tests(): flip, collapse, quality) or, once
  /// no move fails them, the certificates of the faces and feature edges the
  /// moves since the last such round changed (certificate_tests()), then
  /// shortens the offending moves (shorten()) and lists the moved vertices
  /// whose stars the shortening changed for the next round
  /// (after_shortening()). Each of these phases is a loop over the vertices
  /// to test (or the offenders, or the faces) whose iterations write only
  /// their own element or the elements they claim (user manual, "Parallel runs").
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
    // (user manual, "Order of the safety check's tests"): most moves the check
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
  double quality_floor_;
  bool reject_worsening_;
  std::size_t halvings_;
  Fidelity_certificate surface_;
  Crease_certificate creases_;
  std::vector<Index> degenerate_faces_;     // faces degenerate in the input, in increasing order
  std::vector<Vec3> degenerate_references_; // their reference orientations
  std::vector<unsigned char> offends_;      // per face, in the current round
  std::vector<unsigned char> bad_;          // per vertex: its move offends, in the current round
  std::vector<unsigned char> failed_test_;  // per vertex: the Test its move failed last
  std::vector<unsigned char> tries_;        // halvings applied to a vertex's move (at most halvings_ + 1)
  std::vector<unsigned char> checked_;      // per vertex: already in the next list to check
  Claim_stamps face_round_;                 // round in which a face's offending flag was computed
  Claim_stamps changed_round_;              // last round in which a vertex's move changed
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

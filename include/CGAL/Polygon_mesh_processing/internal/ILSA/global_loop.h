// Copyright (c) 2026 The Polygon_mesh_processing_ILSA authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The global loop of ILSA (the paper's Algo. 1) on the flat copy: each
// iteration computes the displacements (Algo. 2 and 3), projects the moved
// vertices onto the input (user manual, "Projection Guard"), applies the
// safety check, and tests the stops (user manual, "Stopping Early").

#ifndef CGAL_POLYGON_MESH_PROCESSING_INTERNAL_ILSA_GLOBAL_LOOP_H
#define CGAL_POLYGON_MESH_PROCESSING_INTERNAL_ILSA_GLOBAL_LOOP_H

#include <CGAL/Polygon_mesh_processing/triangle_quality_ilsa.h>
#include <CGAL/Polygon_mesh_processing/ilsa_types.h>
#include <CGAL/Polygon_mesh_processing/internal/ILSA/core.h>
#include <CGAL/Polygon_mesh_processing/internal/ILSA/defaults.h>
#include <CGAL/Polygon_mesh_processing/internal/ILSA/flat_mesh.h>
#include <CGAL/Polygon_mesh_processing/internal/ILSA/ilsa_displacement.h>
#include <CGAL/Polygon_mesh_processing/internal/ILSA/move_safety.h>
#include <CGAL/Polygon_mesh_processing/internal/ILSA/parallel_loops.h>
#include <CGAL/Polygon_mesh_processing/internal/ILSA/parameters.h>
#include <CGAL/Polygon_mesh_processing/internal/ILSA/penalty_adjustment.h>
#include <CGAL/Polygon_mesh_processing/internal/ILSA/projection.h>
#include <CGAL/Polygon_mesh_processing/internal/ILSA/vertex_classification.h>

#include <algorithm>
#include <cstddef>
#include <limits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace ILSA {

/// The iterations of one call. `original`, `classification`, `neighborhoods`
/// and `parameters` must outlive the loop (it keeps references);
/// `incidences` is read by the constructor only (the projector's patches and
/// the safety check's reference orientations), so the caller frees it once
/// the loop is built.
template <class ConcurrencyTag> class Global_loop {
public:
  Global_loop(const Flat_mesh& original, const Vertex_classification& classification,
              const ILSA_neighborhoods& neighborhoods, const Smoothing_parameters& parameters,
              const Set_up_incidences& incidences)
      : m_(original), nb_(neighborhoods), p_(parameters), penalty_(parameters.penalty),
        projector_(original, classification, incidences, ConcurrencyTag()),
        safety_(original, classification, incidences, floor_of_check(original, parameters),
                parameters.fidelity_tolerance, parameters.reject_worsening, defaults::move_halvings),
        face_values_(original.number_of_faces()) {
    double mean_edge_length = 0;
    for (const auto& e : m_.edges) mean_edge_length += (m_.points[e[0]] - m_.points[e[1]]).norm();
    mean_edge_length /= double((std::max)(m_.edges.size(), std::size_t(1)));
    tolerance_ = 1e-4 * mean_edge_length;
    penalty_.tolerance = tolerance_;

    // T_new := T_ori. `home_` is the original face (ridge: sharp edge) each vertex lies on.
    pos_ = m_.points;
    home_.assign(pos_.size(), npos);
    moved_.reserve(nb_.adjustable.size());
    guarded_.assign(pos_.size(), 0);
    skipped_.assign(pos_.size(), 0);
    for (std::size_t v : nb_.adjustable) home_[v] = Index(projector_.initial_home(v));
    // Its weights' array, idle during the penalty step, holds the step's
    // targets (three doubles per vertex): one allocation for both.
    workspace_.weights.reserve((std::max)(m_.edges.size(), 3 * pos_.size()));
    limit_retries_ = p_.use_safety && p_.retry_distance > 0;
    retry_length_ = p_.retry_distance * mean_edge_length;
    if (limit_retries_) settled_.assign(pos_.size(), -1.f);
  }

  /// Runs the iterations until `parameters.iterations`, a stop or the callback ends them.
  void run(ILSA_statistics& stats) {
    double mean_q = p_.may_stop() ? mean_quality() : 0.;
    for (std::size_t step = 0; step < p_.iterations; ++step) {
      iterate(stats);
      if (p_.callback && !p_.callback(double(step + 1) / double(p_.iterations))) break;
      if (p_.may_stop()) {
        // Stop on a small gain of this iteration, or when this gain times the
        // iterations left (what they could still add while the gains shrink
        // from one iteration to the next) is small (user manual, "Stopping Early").
        const double before = mean_q;
        mean_q = mean_quality();
        const double gain = mean_q - before, left = double(p_.iterations) - double(step + 1);
        if (gain < p_.minimum_gain || gain * left < p_.minimum_remaining_gain) break;
      }
    }
    // What the certificates bound (user manual, "Fidelity Certificate"); without
    // the safety check or the projection no bound is enforced.
    const bool certified = p_.use_safety && p_.do_project;
    const double none = std::numeric_limits<double>::infinity();
    stats.certified_distance = certified ? safety_.certified_distance() : none;
    stats.certified_crease_distance = certified ? safety_.certified_crease_distance(pos_) : none;
  }

  /// T_new, in the normalised coordinates of the flat copy, moved out of the loop.
  std::vector<Vec3> take_positions() { return std::move(pos_); }

private:
  // The floor the safety check applies: without an explicit floor, the
  // default raised to the input's minimum aspect ratio, so that the output's
  // is never below it.
  static double floor_of_check(const Flat_mesh& m, const Smoothing_parameters& p) {
    if (!p.raise_floor_to_input_minimum) return p.quality_floor;
    double input_minimum = 1.;
    for (const auto& t : m.faces)
      input_minimum = (std::min)(input_minimum, triangle_quality_ilsa(m.points[t[0]], m.points[t[1]], m.points[t[2]]));
    return (std::max)(p.quality_floor, input_minimum);
  }

  // One global iteration: the displacements, the projected moves, the safety
  // check, the settled vertices; then T_new takes the accepted positions.
  void iterate(ILSA_statistics& stats) {
    compute_displacements();
    const std::size_t skipped_moves = project_moves(stats);
    check_moves(skipped_moves, stats);
    if (limit_retries_) update_settled();
    pos_.swap(next_);
    home_.swap(next_home_);
    ++stats.number_of_iterations;
  }

  // d(v): ILSA displacement (Algo. 2), penalty-adjusted for smooth vertices
  // (Algo. 3; the face normals of T_new give the discrete normal N(v) of
  // paper §3 where the penalty plane needs it), without its component
  // along the vertex normal, which each sweep of Algo. 3 drops (user manual,
  // "Tangential Displacements"; the paper's variant keeps it). `next_` serves
  // as the sweeps' second buffer before the projection fills it.
  void compute_displacements() {
    compute_ilsa_displacement<ConcurrencyTag>(pos_, nb_, p_.relax1, p_.sweeps, tolerance_, d_, workspace_, next_);
    adjust_displacement_by_penalty<ConcurrencyTag>(m_, pos_, nb_, penalty_, d_, face_values_, next_,
                                                   workspace_.weights);
  }

  // p(v): projection of v + d(v) onto T_ori, into `next_`; a move the check
  // dropped in the previous iteration is first tried without projection (its
  // pre-test), and a settled vertex stays. Lists the moved vertices; returns
  // the number of moves skipped by the pre-test.
  std::size_t project_moves(ILSA_statistics& stats) {
    next_ = pos_;
    next_home_ = home_;
    parallel_for<ConcurrencyTag>(nb_.adjustable.size(), [&](std::size_t i) {
      const std::size_t v = nb_.adjustable[i];
      skipped_[v] = is_settled(v) || (p_.use_safety && safety_.drop_before_projection(pos_, d_, v));
      guarded_[v] = 0;
      if (skipped_[v]) return;
      const auto r = project(v, pos_[v] + d_[v], pos_[v], home_[v], true);
      next_[v] = r.point;
      next_home_[v] = Index(r.home);
      guarded_[v] = r.guarded;
    });
    moved_.clear();
    std::size_t skipped_moves = 0;
    for (std::size_t v : nb_.adjustable) {
      stats.number_of_guarded_projections += guarded_[v];
      if (is_settled(v))
        ++stats.number_of_settled_skips;
      else
        skipped_moves += skipped_[v];
      if (next_[v] != pos_[v]) moved_.push_back(Index(v));
    }
    return skipped_moves;
  }

  // The safety check of the moves (move_safety.h), and the counts.
  void check_moves(std::size_t skipped_moves, ILSA_statistics& stats) {
    if (!p_.use_safety) {
      stats.number_of_moves += moved_.size();
      return;
    }
    const auto project_again = [this](std::size_t v, const Vec3& q, const Vec3& current, std::size_t home, bool guard) {
      return project(v, q, current, home, guard);
    };
    const auto counts = safety_.template enforce<ConcurrencyTag>(pos_, home_, d_, moved_, next_, next_home_,
                                                                 project_again, face_values_);
    stats.number_of_shortened_moves += counts.shortened;
    stats.number_of_rejected_moves += counts.rejected + skipped_moves;
    stats.number_of_moves_dropped_before_projection += skipped_moves;
    stats.number_of_moves += moved_.size() - counts.rejected;
    stats.moves_dropped_by += counts.rejected_by;
    stats.moves_shortened_by += counts.shortened_by;
  }

  Projector::Result project(std::size_t v, const Vec3& q, const Vec3& current, std::size_t home, bool guard) const {
    if (!p_.do_project) return Projector::Result{q, home, false};
    return projector_.project(v, q, current, home, guard);
  }

  // Retrying dropped moves (user manual, "Retrying Dropped Moves"): a vertex
  // whose move the safety check or the worsening pre-test dropped (but for
  // the quality floor in a star that was at or above it) is settled, left
  // untested, until its neighbours have travelled `retry_length_` in all since.
  bool is_settled(std::size_t v) const { return limit_retries_ && settled_[v] >= 0; }
  void update_settled() {
    parallel_for<ConcurrencyTag>(nb_.adjustable.size(), [&](std::size_t i) {
      const std::size_t v = nb_.adjustable[i];
      const bool was_settled = settled_[v] >= 0;
      // The neighbours' moves of this iteration count also when it dropped
      // the move of `v`: the test saw them.
      if (!was_settled && !(skipped_[v] || safety_.dropped_to_settle(v))) return;
      double travelled = was_settled ? double(settled_[v]) : 0.;
      for (const Index* w = m_.vertex_neighbors.first(v); w != m_.vertex_neighbors.last(v); ++w)
        travelled += (next_[*w] - pos_[*w]).norm();
      settled_[v] = travelled < retry_length_ ? float(travelled) : -1.f;
    });
  }

  // Convergence (user manual, "Stopping Early"): the mean aspect ratio of the
  // faces, each face's computed in parallel, summed in face order.
  double mean_quality() {
    parallel_for<ConcurrencyTag>(face_values_.size(), [&](std::size_t f) {
      const auto& t = m_.faces[f];
      face_values_[f] = aspect_ratio(pos_[t[0]], pos_[t[1]], pos_[t[2]]);
    });
    double sum = 0;
    for (double q : face_values_) sum += q;
    return sum / double((std::max)(face_values_.size(), std::size_t(1)));
  }

  const Flat_mesh& m_;
  const ILSA_neighborhoods& nb_;
  const Smoothing_parameters& p_;
  Penalty_parameters penalty_; // the parameters' with the sweeps' tolerance
  const Projector projector_;
  Move_safety safety_;
  // One per-face array, lent in turn to the penalty step (its weights), the
  // safety check (the aspect ratios at `next_`) and the convergence stop
  // (the aspect ratios at `pos_`): none reads a value another wrote.
  std::vector<double> face_values_;
  double tolerance_ = 0; // the sweeps stop once no displacement changes by more
  std::vector<Vec3> pos_, next_, d_;
  std::vector<Index> home_, next_home_, moved_;
  std::vector<unsigned char> guarded_, skipped_;
  ILSA_workspace workspace_;
  bool limit_retries_ = false;
  double retry_length_ = 0;
  // settled_[v]: the length the neighbours of `v` have travelled since it
  // settled, or -1 when `v` is not settled (one float per vertex: the largest
  // meshes are at the memory bound of the user manual's "Performance").
  std::vector<float> settled_;
};

inline namespace CGAL_ILSA_CORE_NAMESPACE { // declared in core.h, with what it does

template <class ConcurrencyTag>
std::vector<Vec3> smooth_flat_copy(const Flat_mesh& original, const Vertex_classification& classification,
                                   const ILSA_neighborhoods& neighborhoods, const Smoothing_parameters& parameters,
                                   Set_up_incidences& incidences, ILSA_statistics& stats) {
  Global_loop<ConcurrencyTag> loop(original, classification, neighborhoods, parameters, incidences);
  incidences = Set_up_incidences();
  loop.run(stats);
  return loop.take_positions();
}

} // namespace CGAL_ILSA_CORE_NAMESPACE

} // namespace ILSA
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_POLYGON_MESH_PROCESSING_INTERNAL_ILSA_GLOBAL_LOOP_H

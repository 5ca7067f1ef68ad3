// Copyright (c) 2026 The Polygon_mesh_processing_ILSA authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The core of ILSA and what it is handed: the classification of the flat copy
// (stage 1, paper §3) and the iterations (Algo. 1 to 3, projection, safety
// check). The core reads the flat copy only, never the user's mesh type, so it
// can be compiled once (user manual, "Compiling the core once"). This header
// declares its two functions, classify() and smooth_flat_copy(). Header-only
// (the default), the public headers include their definitions
// (vertex_classification.h, global_loop.h); with CGAL_ILSA_COMPILED_CORE
// defined, they do not, and src/ilsa_core.cpp defines them (for
// CGAL::Sequential_tag, and CGAL::Parallel_tag with TBB).

#ifndef CGAL_POLYGON_MESH_PROCESSING_INTERNAL_ILSA_CORE_H
#define CGAL_POLYGON_MESH_PROCESSING_INTERNAL_ILSA_CORE_H

#include <CGAL/Polygon_mesh_processing/ilsa_types.h>
#include <CGAL/Polygon_mesh_processing/internal/ILSA/defaults.h>
#include <CGAL/Polygon_mesh_processing/internal/ILSA/flat_mesh.h>

#include <CGAL/tags.h>

#include <array>
#include <cstddef>
#include <functional>
#include <type_traits>
#include <vector>

// `inline` where the core is header-only; nothing where it is compiled once.
// The two ways give the core's functions different names (an inline
// namespace), so that a program may mix files compiled both ways: each file
// calls its own way's functions, and no function has two definitions.
#ifdef CGAL_ILSA_COMPILED_CORE
#define CGAL_ILSA_CORE_INLINE
#define CGAL_ILSA_CORE_NAMESPACE compiled_core
#else
#define CGAL_ILSA_CORE_INLINE inline
#define CGAL_ILSA_CORE_NAMESPACE header_only_core
#endif

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace ILSA {

/// What the classification stage hands to the smoothing stages (read for the
/// whole call; the intermediate results stay inside classify()).
struct Vertex_classification {
  std::vector<ILSA_vertex_type> type;
  std::vector<Index> crease_of_edge;                // crease polyline of a sharp edge, npos for the other edges
  std::vector<unsigned char> feature_edge;          // sharp, or (without the user's edge map) dihedral angle below θ_f
                                                    // and, with a crease contrast, kept by it
  std::vector<std::array<Index, 2>> attached_edges; // a ridge vertex's two sharp edges
  std::size_t number_of_kinks = 0;                  // vertices with two sharp edges fixed as kinks

  bool is_fixed(std::size_t v) const {
    return type[v] == ILSA_vertex_type::Corner || type[v] == ILSA_vertex_type::Boundary;
  }
  bool is_sharp(std::size_t e) const { return crease_of_edge[e] != npos; }
};

struct Classification_options {
  // Angle between face normals above which an edge is sharp (CGAL's convention; the paper's θ_f is 180° minus it).
  double feature_angle_degrees = defaults::feature_angle;
  // Candidate without sharp edge: a corner (paper) or smooth.
  bool fix_unattached_candidates = defaults::fix_unattached_candidates;
  // A crease turning by more than this at a vertex makes it a corner (by default the feature angle).
  double kink_angle_degrees = defaults::feature_angle;
  // A feature edge between candidates is sharp only if its angle is at least this times the angle of the flatter
  // of the two other edges of each of its faces (user manual, "Crease contrast"); 0: every one is (the paper).
  double crease_contrast = defaults::crease_contrast;
  // An open set of connected feature edges with fewer edges is curvature (user manual, "Open Crease Lines");
  // 0: none is dropped (the paper).
  std::size_t minimum_open_crease_edges = defaults::minimum_open_crease_edges;
  const std::vector<unsigned char>* constrained_vertices = nullptr; // user's vertex_is_constrained_map
  const std::vector<unsigned char>* constrained_edges = nullptr;    // user's edge_is_constrained_map
};

/// Which vertices move and which neighbours drive them (paper's Algo. 2): all one-ring
/// vertices for a smooth node, only its two attached-sharp nodes for a ridge node.
struct ILSA_neighborhoods {
  const Flat_mesh* mesh = nullptr;
  const Vertex_classification* classification = nullptr;
  std::vector<Index> adjustable; // smooth and ridge vertices allowed to move
  std::vector<Index> smooth;     // the smooth ones among them (Algo. 3)

  /// Calls `f(w, e)` for each neighbour `w` driving the adjustable vertex `v`
  /// and the edge `e` between them, in the order of the one ring.
  template <class F> void for_each_neighbor(std::size_t v, F f) const {
    const Vertex_classification& c = *classification;
    if (c.type[v] == ILSA_vertex_type::Ridge) {
      for (std::size_t e : c.attached_edges[v]) {
        const auto& ends = mesh->edges[e];
        f(std::size_t(ends[0] == v ? ends[1] : ends[0]), e); // its attached-sharp node
      }
      return;
    }
    const Index* e = mesh->vertex_edges.first(v);
    for (const Index* w = mesh->vertex_neighbors.first(v); w != mesh->vertex_neighbors.last(v); ++w, ++e)
      f(std::size_t(*w), std::size_t(*e));
  }
};

/// `movable[v]` is false for the vertices outside the user's range. `m` and
/// `c` must outlive the result: it keeps pointers.
inline ILSA_neighborhoods make_neighborhoods(const Flat_mesh& m, const Vertex_classification& c,
                                             const std::vector<unsigned char>& movable) {
  ILSA_neighborhoods nb;
  nb.mesh = &m;
  nb.classification = &c;
  for (std::size_t v = 0; v < m.number_of_vertices(); ++v) {
    if (c.is_fixed(v) || !movable[v]) continue;
    nb.adjustable.push_back(Index(v));
    if (c.type[v] != ILSA_vertex_type::Ridge) nb.smooth.push_back(Index(v));
  }
  nb.adjustable.shrink_to_fit();
  nb.smooth.shrink_to_fit();
  return nb;
}

// The package's defaults; smooth_surface_mesh_ilsa() sets every member from its named parameters.
struct Penalty_parameters {
  double relax2 = defaults::penalty_relaxation;
  double mu = defaults::penalty_mu;
  double length_weight = defaults::length_weight; // wl
  double area_weight = defaults::area_weight;     // wa
  std::size_t sweeps = defaults::penalty_steps;
  bool gauss_seidel = defaults::penalty_gauss_seidel; // sweep order (user manual, "Sweep Order")
  // Each sweep drops the normal component of the displacements (user manual,
  // "Tangential Sweeps"); set only with Smoothing_parameters::tangential.
  bool tangential_sweeps = defaults::tangential_sweeps;
  double tolerance = 0; // stop once no displacement changes by more
};

struct Smoothing_parameters {
  std::size_t iterations = defaults::number_of_iterations;   // the paper's max_global_iter_num
  std::size_t sweeps = defaults::number_of_relaxation_steps; // of the ILSA step (Algo. 2)
  double relax1 = defaults::relaxation;
  Penalty_parameters penalty; // relax2, μ, wl, wa and the sweeps of the penalty step (Algo. 3)
  bool tangential = defaults::tangential_displacement;
  bool do_project = defaults::do_project;
  bool use_safety = defaults::use_safety_constraints;
  // The quality floor; without an explicit one, raised to the input's
  // minimum aspect ratio when that is higher.
  double quality_floor = defaults::quality_floor;
  bool raise_floor_to_input_minimum = true;
  bool quality_monotone = defaults::quality_monotone;
  bool reject_worsening = defaults::reject_worsening_moves;
  double fidelity_tolerance = defaults::fidelity_tolerance;
  double minimum_gain = defaults::minimum_quality_gain;
  double minimum_remaining_gain = defaults::minimum_remaining_gain;
  double retry_distance = defaults::retry_distance;
  bool verbose = false;
  std::function<bool(double)> callback;

  /// Whether the run may stop before `iterations` (user manual, "Stopping early").
  bool may_stop() const { return minimum_gain > 0 || minimum_remaining_gain > 0; }
};

/// Whether `ConcurrencyTag` runs the loops with TBB (parallel_loops.h).
template <class ConcurrencyTag>
constexpr bool is_parallel = std::is_convertible<ConcurrencyTag, CGAL::Parallel_tag>::value;

template <class ConcurrencyTag> constexpr void check_concurrency_tag() {
#ifndef CGAL_LINKED_WITH_TBB
  static_assert(!is_parallel<ConcurrencyTag>, "Parallel_tag is enabled but TBB is unavailable.");
#endif
}

/// The tag the core runs with (and, compiled once, is compiled for):
/// `CGAL::Parallel_tag` for a tag convertible to it, else `CGAL::Sequential_tag`.
template <class ConcurrencyTag>
using Core_tag = std::conditional_t<is_parallel<ConcurrencyTag>, CGAL::Parallel_tag, CGAL::Sequential_tag>;

inline namespace CGAL_ILSA_CORE_NAMESPACE {

/// Stage 1 (paper §3): the vertex types, sharp edges and crease lines of `m`
/// (vertex_classification.h).
CGAL_ILSA_CORE_INLINE Vertex_classification classify(const Flat_mesh& m, const Set_up_incidences& incidences,
                                                     const Classification_options& options);

/// The iterations of one call (Algo. 1, global_loop.h) on the classified flat
/// copy `original`: builds the projection trees, the clearances and the safety
/// check, frees `incidences`, iterates, and returns T_new in the flat copy's
/// coordinates. `copy_seconds` is the time the flat copy and classification
/// took, printed with the set-up's when `parameters.verbose`.
template <class ConcurrencyTag>
std::vector<Vec3> smooth_flat_copy(const Flat_mesh& original, const Vertex_classification& classification,
                                   const ILSA_neighborhoods& neighborhoods, const Smoothing_parameters& parameters,
                                   Set_up_incidences& incidences, double copy_seconds, ILSA_statistics& stats);

} // namespace CGAL_ILSA_CORE_NAMESPACE

} // namespace ILSA
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_POLYGON_MESH_PROCESSING_INTERNAL_ILSA_CORE_H

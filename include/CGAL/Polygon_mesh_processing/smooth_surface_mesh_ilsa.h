// Copyright (c) 2026 The Polygon_mesh_processing_ILSA authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// ILSA, the improved Laplacian smoothing approach of L. Chen, Y. Zheng,
// J. Chen and Y. Liang (ICCS 2007). The public function is the sequence of
// the stages: read the parameters (internal/ILSA/smoothing_parameters.h),
// set up (set_up.h: flat copy and classification), iterate (global_loop.h:
// displacement, penalty step, projection, safety check, stops), write back.

#ifndef CGAL_POLYGON_MESH_PROCESSING_SMOOTH_SURFACE_MESH_ILSA_H
#define CGAL_POLYGON_MESH_PROCESSING_SMOOTH_SURFACE_MESH_ILSA_H

#include <CGAL/Polygon_mesh_processing/classify_vertices_ilsa.h>
#include <CGAL/Polygon_mesh_processing/ilsa_types.h>
#include <CGAL/Polygon_mesh_processing/internal/ILSA/core.h>
#include <CGAL/Polygon_mesh_processing/internal/ILSA/set_up.h>
#include <CGAL/Polygon_mesh_processing/internal/ILSA/smoothing_parameters.h>
#ifndef CGAL_ILSA_COMPILED_CORE
#include <CGAL/Polygon_mesh_processing/internal/ILSA/global_loop.h> // smooth_flat_copy()
#endif

#include <CGAL/Real_timer.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <boost/unordered_map.hpp>

#include <iostream>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace ILSA {

/// Per flat vertex, whether it is in `range`; throws `ILSA_error` for a vertex
/// of the range that is not one of `vertex_list` (the mesh's, in flat order).
/// The range is checked against the mesh's own descriptors: an index map
/// cannot be read for a descriptor that is not the mesh's.
template <class VertexRange, class VertexDescriptor>
std::vector<unsigned char> vertices_in_range(const VertexRange& range,
                                             const std::vector<VertexDescriptor>& vertex_list) {
  boost::unordered_map<VertexDescriptor, std::size_t> flat_of;
  flat_of.reserve(vertex_list.size());
  for (std::size_t i = 0; i < vertex_list.size(); ++i) flat_of.emplace(vertex_list[i], i);
  std::vector<unsigned char> in_range(vertex_list.size(), 0);
  for (auto v : range) {
    const auto found = flat_of.find(v);
    if (found == flat_of.end()) throw ILSA_error("a vertex of the range is not a vertex of the mesh");
    in_range[found->second] = 1;
  }
  return in_range;
}

} // namespace ILSA
} // namespace internal

/*!
 * \ingroup PkgPMPILSARef
 * smooths a triangle mesh with ILSA, the improved Laplacian smoothing approach
 * of Chen et al. (ICCS 2007): the vertices of `vertices` move so that the
 * triangles get better shaped, while every moved vertex stays on the input
 * surface, boundaries, corners and crease lines are kept, and no triangle
 * inverts. The connectivity does not change.
 *
 * Each of the `number_of_iterations` global iterations computes an ILSA
 * displacement of every adjustable vertex (Laplacian, diffused with
 * inverse-distance weights), corrects that of every smooth vertex with a
 * quadratic-penalty "soap film" step, and projects the moved vertices back onto
 * a frozen copy of the input (ridge vertices onto their own crease line).
 *
 * @tparam ConcurrencyTag enables sequential or parallel sweeps: `CGAL::Sequential_tag` (the default),
 *         `CGAL::Parallel_tag` (needs TBB) or `CGAL::Parallel_if_available_tag`. The result is
 *         bit-identical whatever the tag and the number of threads.
 * @tparam VertexRange a model of `Range` of `boost::graph_traits<TriangleMesh>::%vertex_descriptor`
 * @tparam TriangleMesh a model of `VertexListGraph`, `EdgeListGraph`, `FaceListGraph` and `HalfedgeGraph`
 *         (`Surface_mesh`, `Polyhedron_3`, OpenMesh meshes through CGAL's adapters, ...); the connectivity
 *         is not changed, so `MutableFaceGraph` is not needed; its vertex descriptors must be hashable with
 *         `boost::hash` (to check the vertex range; true of all of these)
 * @tparam NamedParameters a sequence of named parameters
 *
 * @param vertices the vertices that may move; all others are fixed
 * @param tm the triangle mesh
 * @param np an optional sequence of named parameters among the ones listed below
 *
 * \cgalNamedParamsBegin
 *   \cgalParamNBegin{vertex_point_map}
 *     \cgalParamDescription{a property map associating points to the vertices of `tm`}
 *     \cgalParamType{a model of `ReadWritePropertyMap` with `vertex_descriptor` as key and `%Point_3` as value}
 *     \cgalParamDefault{`boost::get(CGAL::vertex_point, tm)`}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{geom_traits}
 *     \cgalParamDescription{an instance of a geometric traits class}
 *     \cgalParamType{a class model of `Kernel`}
 *     \cgalParamDefault{a CGAL Kernel deduced from the point type, using `CGAL::Kernel_traits`}
 *     \cgalParamExtra{The geometric traits class must be compatible with the vertex point type. The smoother
 * computes in double precision on the points' Cartesian coordinates (`CGAL::to_double()`), whatever the kernel,
 * and writes the results back as points of this type.}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{vertex_index_map}
 *     \cgalParamDescription{a property map associating to each vertex of `tm` a unique index between `0` and
 * `num_vertices(tm) - 1`} \cgalParamType{a model of `ReadablePropertyMap` with `vertex_descriptor` as key and
 * an integer type as value} \cgalParamDefault{the vertices numbered in the order of `vertices(tm)` in a dynamic
 * property map (so a `Surface_mesh` with removed elements needs no `collect_garbage()`)}
 *     \cgalParamExtra{The result does not depend on the numbering; a map that is not one to one is rejected with
 * `ILSA_error`.}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{face_index_map}
 *     \cgalParamDescription{a property map associating to each face of `tm` a unique index between `0` and
 * `num_faces(tm) - 1`} \cgalParamType{a model of `ReadablePropertyMap` with `face_descriptor` as key and
 * an integer type as value} \cgalParamDefault{the faces numbered in the order of `faces(tm)`}
 *     \cgalParamExtra{As for `vertex_index_map`.}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{number_of_iterations}
 *     \cgalParamDescription{the largest number of global iterations (the paper's max_global_iter_num); see
 * `ilsa_minimum_quality_gain` and `ilsa_minimum_remaining_gain` for the stops before it}
 *     \cgalParamType{unsigned int, at most 100000}
 *     \cgalParamDefault{`8`}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{ilsa_minimum_quality_gain}
 *     \cgalParamDescription{the run stops before `number_of_iterations` once an iteration raises the mean aspect
 * ratio of the faces by less than this (convergence); `0` disables this stop. The number of iterations run is
 * `ILSA_statistics::number_of_iterations`}
 *     \cgalParamType{`double`, non-negative}
 *     \cgalParamDefault{`1e-4`}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{ilsa_minimum_remaining_gain}
 *     \cgalParamDescription{the run also stops once the gain of mean aspect ratio of an iteration, times the number
 * of iterations left before `number_of_iterations`, is below this: the gain the remaining iterations could still
 * bring while the gains shrink from one iteration to the next (user manual, "Stopping early"); `0` disables this
 * stop. With both stops disabled every iteration runs}
 *     \cgalParamType{`double`, non-negative}
 *     \cgalParamDefault{`2e-3`}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{number_of_relaxation_steps}
 *     \cgalParamDescription{the number of sweeps of the ILSA step (Algo. 2) in each iteration
 * (max_smooth_iter_num); the sweeps stop early once no displacement changes by more than 1e-4 of the mean edge length
 * (user manual, "Sweeps per Iteration")}
 *     \cgalParamType{unsigned int, 1 to 10000}
 *     \cgalParamDefault{`2`}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{ilsa_penalty_steps}
 *     \cgalParamDescription{the number of sweeps of the penalty step (Algo. 3) in each iteration, with the same early
 * stop; the paper uses max_smooth_iter_num for both steps (`ilsa_penalty_steps(2)` with the default
 * `number_of_relaxation_steps`). The default goes with the defaults of `ilsa_penalty_relaxation`,
 * `ilsa_tangential_displacement` and `number_of_iterations` (user manual, "Fewer, Longer Iterations")}
 *     \cgalParamType{unsigned int, 1 to 10000}
 *     \cgalParamDefault{`8`}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{ilsa_penalty_gauss_seidel}
 *     \cgalParamDescription{if `true`, the sweeps of the penalty step are multicolour Gauss-Seidel sweeps: the smooth
 * vertices are coloured once so that no two neighbours share a colour, and each sweep updates one colour after the
 * other, each reading what the colours before it wrote (the result still does not depend on the number of threads);
 * `false` runs the paper's Jacobi sweeps, where every vertex reads the previous sweep's values (user manual, "Sweep
 * Order")}
 *     \cgalParamType{`bool`}
 *     \cgalParamDefault{`false`}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{ilsa_tangential_displacement}
 *     \cgalParamDescription{if `true`, the displacement of a smooth vertex loses its component along the vertex normal
 * (the area-weighted normal of its faces) before it is projected onto the input; `false` moves it as the paper does,
 * normal component included (user manual, "Fewer, Longer Iterations")}
 *     \cgalParamType{`bool`}
 *     \cgalParamDefault{`true`}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{ilsa_tangential_sweeps}
 *     \cgalParamDescription{with `ilsa_tangential_displacement(true)`: if `true`, every sweep of the penalty step drops
 * the normal component of the displacements it computes, so that the next sweep reads tangential displacements of the
 * neighbours; `false` drops it once, after the sweeps, as versions before this parameter did (user manual, "Tangential
 * Sweeps"). Ignored with `ilsa_tangential_displacement(false)`}
 *     \cgalParamType{`bool`}
 *     \cgalParamDefault{`true`}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{ilsa_relaxation}
 *     \cgalParamDescription{the ILSA relaxation factor relax1 (share of the neighbours' weighted mean displacement
 * taken in each sweep)} \cgalParamType{`double`, in (0, 1]} \cgalParamDefault{`0.5`} \cgalParamNEnd
 *   \cgalParamNBegin{ilsa_penalty_relaxation}
 *     \cgalParamDescription{the relaxation factor relax2 of the penalty step (share of the penalty minimiser taken in
 * each sweep)}
 *     \cgalParamType{`double`, in (0, 1]}
 *     \cgalParamDefault{`0.8`}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{ilsa_penalty_mu}
 *     \cgalParamDescription{the penalty parameter μ: the smaller, the more the penalty step keeps a vertex on the plane
 * of its ILSA displacement} \cgalParamType{`double`, positive} \cgalParamDefault{`1`} \cgalParamNEnd
 *   \cgalParamNBegin{ilsa_length_weight}
 *     \cgalParamDescription{the weight wl of the edge-length term of the penalty step}
 *     \cgalParamType{`double`, non-negative}
 *     \cgalParamDefault{`1`}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{ilsa_area_weight}
 *     \cgalParamDescription{the weight wa of the squared-area ("soap film") term of the penalty step}
 *     \cgalParamType{`double`, non-negative}
 *     \cgalParamDefault{`0.1`}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{ilsa_feature_angle}
 *     \cgalParamDescription{an edge is sharp when the normals of its two faces make an angle larger than this, in
 * degrees: CGAL's convention, the angle `detect_sharp_edges()` takes. The paper states it as the dihedral angle
 * θ_f = 180° − this angle. See `classify_vertices_ilsa()`}
 *     \cgalParamType{`double`, in [0, 180)}
 *     \cgalParamDefault{`20` (the paper's θ_f = 8π/9, i.e. 160°)}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{ilsa_fix_unattached_candidates}
 *     \cgalParamDescription{whether a ridge candidate with no sharp edge is fixed as a corner (the paper's rule) or
 * smoothed as a smooth vertex (user manual, "Open Crease Lines")} \cgalParamType{`bool`}
 * \cgalParamDefault{`false`} \cgalParamNEnd
 *   \cgalParamNBegin{ilsa_crease_contrast}
 *     \cgalParamDescription{an edge whose face normals are more than `ilsa_feature_angle` apart is sharp only if
 * their angle is at least this many times that of the flatter of the two other edges of each of its faces: on a
 * crease of a CAD model one of these lies in a smooth part, on a coarse curved surface they bend as much as the edge
 * (user manual, "Crease contrast"; not in the paper). An edge it drops is curvature, not a crease line: neither
 * sharp nor held by the crease bound of `ilsa_fidelity_tolerance`. `0` makes every such edge between two ridge
 * candidates sharp, the paper's rule. Ignored with an `edge_is_constrained_map`}
 *     \cgalParamType{`double`, non-negative and finite}
 *     \cgalParamDefault{`5`}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{ilsa_minimum_open_crease_edges}
 *     \cgalParamDescription{a connected set of edges beyond `ilsa_feature_angle` (kept by the crease contrast) that has
 * an end (a vertex with one of these edges only) and fewer edges than this is curvature, not a crease line: neither
 * sharp nor held by the crease bound of `ilsa_fidelity_tolerance`. Along a crease of a CAD model the feature edges run
 * from corner to corner or around a loop; on a coarse organic mesh they come in short pieces that fade out (user
 * manual, "Open Crease Lines"; not in the paper). `0` keeps every such set, the paper's rule. Ignored with an
 * `edge_is_constrained_map`}
 *     \cgalParamType{an integer, in [0, 1e9]}
 *     \cgalParamDefault{`20`}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{ilsa_crease_kink_angle}
 *     \cgalParamDescription{a vertex with two sharp (or constrained) edges is fixed like a corner when the crease
 * turns there by more than this angle, in degrees (the angle between the directions of its two edges; a straight
 * crease turns by 0): sliding it would cut off the tip of the crease. Not in the paper: `180` restores the paper's
 * rule, under which such a vertex is a ridge vertex}
 *     \cgalParamType{`double`, in [0, 180]}
 *     \cgalParamDefault{`ilsa_feature_angle` (20: a crease vertex is a kink when the crease turns by more than the
 * surface must turn across an edge to make it sharp)}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{vertex_is_constrained_map}
 *     \cgalParamDescription{a property map telling which vertices are fixed}
 *     \cgalParamType{a model of `ReadablePropertyMap` with `vertex_descriptor` as key and `bool` as value}
 *     \cgalParamDefault{no vertex is constrained}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{edge_is_constrained_map}
 *     \cgalParamDescription{when given, these edges are the crease edges instead of the detected sharp edges: with
 * `relax_constraints(true)`, a vertex with two constrained edges slides along them and one with one or more than two
 * is fixed; by default, every end of a constrained edge is fixed}
 *     \cgalParamType{a model of `ReadablePropertyMap` with `edge_descriptor` as key and `bool` as value}
 *     \cgalParamDefault{sharp edges are detected with `ilsa_feature_angle`}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{relax_constraints}
 *     \cgalParamDescription{whether the ends of the edges of `edge_is_constrained_map` may move along the constrained
 * polylines, as in CGAL's `tangential_relaxation()` (boundary vertices stay fixed in any case). Without an
 * `edge_is_constrained_map`, vertices on detected creases always slide along them, as in the paper}
 *     \cgalParamType{`bool`}
 *     \cgalParamDefault{`false`, CGAL's default: a constrained edge does not move}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{do_project}
 *     \cgalParamDescription{whether moved vertices are projected back onto the input surface (ridge vertices onto
 * their crease); without projection they stay where the displacement puts them, off the surface}
 *     \cgalParamType{`bool`}
 *     \cgalParamDefault{`true`}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{use_safety_constraints}
 *     \cgalParamDescription{whether every move is checked after projection: a move that would reverse a triangle (with
 * respect to the input surface) or collapse it is halved up to three times, then dropped for the iteration. With
 * `false`, the penalty step is the only protection against inverted triangles, as in the paper} \cgalParamType{`bool`}
 *     \cgalParamDefault{`true`}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{ilsa_quality_floor}
 *     \cgalParamDescription{with the safety check on, a move is also shortened or dropped if it lowers the minimum
 * aspect ratio of the vertex's star to a value below this floor. 0 disables this part of the check}
 *     \cgalParamType{`double`, in [0, 1)}
 *     \cgalParamDefault{the larger of `0.5` and the minimum aspect ratio of the input faces, so that the minimum
 * aspect ratio of the output is never below the input's}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{ilsa_quality_monotone}
 *     \cgalParamDescription{with the safety check on, shorten or drop every move that lowers the minimum aspect ratio
 * of the vertex's star (the same as a quality floor of 1)} \cgalParamType{`bool`} \cgalParamDefault{`false`}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{ilsa_reject_worsening_moves}
 *     \cgalParamDescription{with the safety check on, drop a vertex's move if it lowers the mean aspect ratio of the
 * triangles around the vertex, its neighbours being at their new positions ("smart" Laplacian smoothing; not in the
 * paper: `false` restores the paper's acceptance of every move the other checks allow)}
 *     \cgalParamType{`bool`} \cgalParamDefault{`true`}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{ilsa_retry_distance}
 *     \cgalParamDescription{with the safety check on, a vertex whose move it dropped (but for the quality floor
 * in a star whose worst aspect ratio was at or above the floor) stays where it is, its new moves neither projected
 * nor checked, until its neighbours have moved by this distance in all since, relative to the mean edge length of
 * the input (user manual, "Retrying dropped moves"; not in the paper). `0` tries every dropped move again in the
 * next iteration. The skips are `ILSA_statistics::number_of_settled_skips`}
 *     \cgalParamType{`double`, non-negative and finite}
 *     \cgalParamDefault{`0.03`}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{ilsa_fidelity_tolerance}
 *     \cgalParamDescription{with the safety check on, the largest distance between the smoothed and the input
 * surface, relative to the bounding-box diagonal, certified both ways for every point (no sampling): every point of
 * the result lies within this distance of the input surface, and every point of the input within it of the result.
 * The same bound holds between the feature lines of the result and those of the input: the sharp edges (or the
 * constrained edges) and the edges whose face normals are more than `ilsa_feature_angle` apart that the crease rules
 * keep. A move after which a face or a feature edge it changes cannot be certified is shortened or dropped (user
 * manual, "Fidelity Certificate"). The bound is exact up to rounding: the certificate accepts a face only 1e-12 of
 * the diagonal within the tolerance, and the coordinates are rounded once more when they are written back.
 * The bound the run reached is `ILSA_statistics::certified_distance`.
 * `std::numeric_limits<double>::infinity()` disables the bound (the paper has none)}
 *     \cgalParamType{`double`, positive}
 *     \cgalParamDefault{`5e-4`}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{callback}
 *     \cgalParamDescription{called after each iteration with the advancement, the iterations run over
 * `number_of_iterations` (the last call may come before 1 when the run stops early); when it returns `false`, the
 * run stops there, with the mesh as that iteration left it (every guarantee holds after any iteration)}
 *     \cgalParamType{an instance of `std::function<bool(double)>`}
 *     \cgalParamDefault{no callback}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{verbose}
 *     \cgalParamDescription{whether to print the vertex types, the time of the set-up and what each iteration did
 * (and its time) to `std::cerr`}
 *     \cgalParamType{`bool`}
 *     \cgalParamDefault{`false`}
 *   \cgalParamNEnd
 * \cgalNamedParamsEnd
 *
 * @return what the call did: vertex types, iterations, accepted, shortened and rejected moves
 *
 * @throws ILSA_error if `tm` has a non-triangle face or a non-finite coordinate,
 *         if a vertex of `vertices` is not a vertex of `tm`, or if a parameter
 *         is out of range. These checks run before anything is written: when
 *         the function throws, `tm` is unchanged. They do not depend on `NDEBUG`.
 *
 * @pre `tm` is a triangle mesh (checked, see above). Degenerate faces, isolated
 *      and non-manifold vertices, several connected components and
 *      self-intersections are accepted: isolated and non-manifold vertices are fixed.
 */
template <typename ConcurrencyTag = CGAL::Sequential_tag, typename VertexRange, typename TriangleMesh,
          typename NamedParameters = parameters::Default_named_parameters,
          typename = std::enable_if_t<!internal::ILSA::is_named_parameters<TriangleMesh>::value>>
ILSA_statistics smooth_surface_mesh_ilsa(const VertexRange& vertices, TriangleMesh& tm,
                                         const NamedParameters& np = parameters::default_values()) {
  namespace ilsa = internal::ILSA;
  // 1. Read and check the named parameters (the defaults: internal/ILSA/defaults.h).
  ilsa::check_concurrency_tag<ConcurrencyTag>();
  const ilsa::Smoothing_parameters smoothing = ilsa::read_smoothing_parameters(np);
  using VPM = typename GetVertexPointMap<TriangleMesh, NamedParameters>::type;
  VPM vpm = parameters::choose_parameter(parameters::get_parameter(np, internal_np::vertex_point),
                                         get_property_map(CGAL::vertex_point, tm));

  // 2. Set up: the frozen flat copy of the input (T_ori) and its vertex
  // classification (paper §3), checked before anything is written.
  CGAL::Real_timer timer; // for `verbose` (user manual, "Performance")
  timer.start();
  ilsa::Set_up_incidences incidences; // read by the set-up only, freed before the iterations
  const ilsa::Flat_input<TriangleMesh> input = ilsa::classified_flat_copy(tm, vpm, np, incidences);
  const ilsa::ILSA_neighborhoods neighborhoods =
      ilsa::make_neighborhoods(input.mesh, input.classification, ilsa::vertices_in_range(vertices, input.vertices));
  ILSA_statistics stats;
  ilsa::count_types(input.classification, stats);
  const double copy_seconds = timer.time();
  if (smoothing.verbose)
    std::cerr << "ILSA: " << stats.number_of_smooth_vertices << " smooth, " << stats.number_of_ridge_vertices
              << " ridge, " << stats.number_of_corner_vertices << " corner, " << stats.number_of_boundary_vertices
              << " boundary vertices\n";
  if (neighborhoods.adjustable.empty() || smoothing.iterations == 0) return stats;

  // 3. Iterate (the paper's Algo. 1).
  const std::vector<ilsa::Vec3> smoothed = ilsa::smooth_flat_copy<ilsa::Core_tag<ConcurrencyTag>>(
      input.mesh, input.classification, neighborhoods, smoothing, incidences, copy_seconds, stats);

  // 4. Write T_new back.
  ilsa::write_back(input.mesh, smoothed, neighborhoods.adjustable, input.vertices, vpm);
  return stats;
}

/*!
 * \ingroup PkgPMPILSARef
 * smooths all vertices of `tm` with ILSA; see the range overload for the
 * named parameters.
 */
template <typename ConcurrencyTag = CGAL::Sequential_tag, typename TriangleMesh, typename CGAL_NP_TEMPLATE_PARAMETERS>
ILSA_statistics smooth_surface_mesh_ilsa(TriangleMesh& tm, const CGAL_NP_CLASS& np = parameters::default_values()) {
  return smooth_surface_mesh_ilsa<ConcurrencyTag>(vertices(tm), tm, np);
}

} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_POLYGON_MESH_PROCESSING_SMOOTH_SURFACE_MESH_ILSA_H

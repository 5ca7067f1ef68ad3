// Copyright (c) 2026 The Polygon_mesh_processing_ILSA authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// ILSA, the improved Laplacian smoothing approach of L. Chen, Y. Zheng,
// J. Chen and Y. Liang (ICCS 2007). This header reads the named parameters and
// runs the global loop (the paper's Algo. 1); each stage lives in
// internal/ILSA/, named after it.

#ifndef CGAL_POLYGON_MESH_PROCESSING_SMOOTH_SURFACE_MESH_ILSA_H
#define CGAL_POLYGON_MESH_PROCESSING_SMOOTH_SURFACE_MESH_ILSA_H

#include <CGAL/Named_function_parameters.h>
#ifndef CGAL_ILSA_NAMED_PARAMETERS_INTERFACE
#error                                                                                                                 \
    "CGAL's named-parameter list was included without the ILSA tags: put the package's include/ directory before CGAL's in the include path."
#endif

#include <CGAL/Polygon_mesh_processing/classify_vertices_ilsa.h>
#include <CGAL/Polygon_mesh_processing/ilsa_triangle_quality.h>
#include <CGAL/Polygon_mesh_processing/ilsa_types.h>
#include <CGAL/Polygon_mesh_processing/internal/ILSA/defaults.h>
#include <CGAL/Polygon_mesh_processing/internal/ILSA/flat_mesh.h>
#include <CGAL/Polygon_mesh_processing/internal/ILSA/ilsa_displacement.h>
#include <CGAL/Polygon_mesh_processing/internal/ILSA/move_safety.h>
#include <CGAL/Polygon_mesh_processing/internal/ILSA/parallel_loops.h>
#include <CGAL/Polygon_mesh_processing/internal/ILSA/penalty_adjustment.h>
#include <CGAL/Polygon_mesh_processing/internal/ILSA/projection.h>
#include <CGAL/Polygon_mesh_processing/internal/ILSA/vertex_classification.h>

#include <CGAL/boost/graph/named_params_helper.h>

#include <boost/unordered_map.hpp>

#include <cmath>
#include <functional>
#include <iostream>
#include <string>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
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
 *     \cgalParamDefault{`20`}
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
 *     \cgalParamDescription{the number of sweeps of the ILSA and of the penalty step in each iteration
 * (max_smooth_iter_num); the sweeps stop early once no displacement changes by more than 1e-4 of the mean edge length.
 * The default goes with the default of `ilsa_penalty_relaxation` (user manual, "Sweeps per Iteration")}
 *     \cgalParamType{unsigned int, 1 to 10000}
 *     \cgalParamDefault{`2`}
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
 * smoothed as a smooth vertex} \cgalParamType{`bool`} \cgalParamDefault{`true`} \cgalParamNEnd
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
 *     \cgalParamDescription{with the safety check on, a move is also shortened or dropped if it takes the smoothed
 * surface farther than this distance from the input surface where it was not already: from the input position of the
 * vertex or of a neighbour to the smoothed faces around it (a bump or a crease bend cut off), or from the centroid and
 * edge midpoints of the faces around the vertex to the input faces around them (a chord over a fold). The same bound
 * holds along the feature lines, both ways: the input's sharp edges (or constrained edges) and the edges whose face
 * normals are more than `ilsa_feature_angle` apart may not move farther than it from their input position, nor their
 * input points end farther than it from them. Relative to the bounding-box diagonal.
 * `std::numeric_limits<double>::infinity()` disables this part of the check (the paper has no such bound)}
 * \cgalParamType{`double`, positive} \cgalParamDefault{`3e-4`} \cgalParamNEnd \cgalParamNBegin{callback}
 *     \cgalParamDescription{called after each iteration with the advancement, the iterations run over
 * `number_of_iterations` (the last call may come before 1 when the run stops early); when it returns `false`, the
 * run stops there, with the mesh as that iteration left it (every guarantee holds after any iteration)}
 *     \cgalParamType{an instance of `std::function<bool(double)>`}
 *     \cgalParamDefault{no callback}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{verbose}
 *     \cgalParamDescription{whether to print the vertex types and what each iteration did to `std::cerr`}
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
  using parameters::choose_parameter;
  using parameters::get_parameter;
  namespace ilsa = internal::ILSA;
  using GT = boost::graph_traits<TriangleMesh>;
  using Vec3 = ilsa::Vec3;

  // Named parameters, every knob in one place (the defaults: internal/ILSA/defaults.h).
  namespace defaults = ilsa::defaults;
  using VPM = typename GetVertexPointMap<TriangleMesh, NamedParameters>::type;
  using Point = typename boost::property_traits<VPM>::value_type;
  VPM vpm = choose_parameter(get_parameter(np, internal_np::vertex_point), get_property_map(CGAL::vertex_point, tm));
  const auto iterations =
      choose_parameter(get_parameter(np, internal_np::number_of_iterations), defaults::number_of_iterations);
  const auto sweeps = choose_parameter(get_parameter(np, internal_np::number_of_relaxation_steps),
                                       defaults::number_of_relaxation_steps);
  const double relax1 = choose_parameter(get_parameter(np, internal_np::ilsa_relaxation), defaults::relaxation);
  ilsa::Penalty_parameters penalty;
  penalty.relax2 =
      choose_parameter(get_parameter(np, internal_np::ilsa_penalty_relaxation), defaults::penalty_relaxation);
  penalty.mu = choose_parameter(get_parameter(np, internal_np::ilsa_penalty_mu), defaults::penalty_mu);
  penalty.length_weight = choose_parameter(get_parameter(np, internal_np::ilsa_length_weight), defaults::length_weight);
  penalty.area_weight = choose_parameter(get_parameter(np, internal_np::ilsa_area_weight), defaults::area_weight);
  const bool do_project = choose_parameter(get_parameter(np, internal_np::do_project), defaults::do_project);
  const bool use_safety =
      choose_parameter(get_parameter(np, internal_np::use_safety_constraints), defaults::use_safety_constraints);
  // Without an explicit floor: the default, raised below to the input's minimum aspect ratio.
  constexpr bool default_floor =
      parameters::is_default_parameter<NamedParameters, internal_np::ilsa_quality_floor_t>::value;
  double quality_floor = choose_parameter(get_parameter(np, internal_np::ilsa_quality_floor), defaults::quality_floor);
  const bool quality_monotone =
      choose_parameter(get_parameter(np, internal_np::ilsa_quality_monotone), defaults::quality_monotone);
  const bool reject_worsening =
      choose_parameter(get_parameter(np, internal_np::ilsa_reject_worsening_moves), defaults::reject_worsening_moves);
  const double fidelity_tolerance =
      choose_parameter(get_parameter(np, internal_np::ilsa_fidelity_tolerance), defaults::fidelity_tolerance);
  const double minimum_gain =
      choose_parameter(get_parameter(np, internal_np::ilsa_minimum_quality_gain), defaults::minimum_quality_gain);
  const double minimum_remaining_gain =
      choose_parameter(get_parameter(np, internal_np::ilsa_minimum_remaining_gain), defaults::minimum_remaining_gain);
  const double retry_distance =
      choose_parameter(get_parameter(np, internal_np::ilsa_retry_distance), defaults::retry_distance);
  const bool verbose = choose_parameter(get_parameter(np, internal_np::verbose), false);
  const std::function<bool(double)> callback =
      choose_parameter(get_parameter(np, internal_np::callback), std::function<bool(double)>());
  // (ilsa_feature_angle, ilsa_fix_unattached_candidates and the constraint
  // maps are read by read_classification_parameters() below.)

  auto require = [](bool ok, const std::string& what) {
    if (!ok) throw ILSA_error(what);
  };
  require(quality_floor >= 0 && quality_floor < 1, "ilsa_quality_floor must be in [0, 1)");
  require(fidelity_tolerance > 0, "ilsa_fidelity_tolerance must be positive (infinity disables the check)");
  require(minimum_gain >= 0 && std::isfinite(minimum_gain),
          "ilsa_minimum_quality_gain must be non-negative and finite (0 disables this stop)");
  require(minimum_remaining_gain >= 0 && std::isfinite(minimum_remaining_gain),
          "ilsa_minimum_remaining_gain must be non-negative and finite (0 disables this stop)");
  require(retry_distance >= 0 && std::isfinite(retry_distance),
          "ilsa_retry_distance must be non-negative and finite (0 retries every dropped move at once)");
  require(double(iterations) >= 0 && double(iterations) <= 100000, "number_of_iterations must be in [0, 100000]");
  require(double(sweeps) >= 1 && double(sweeps) <= 10000, "number_of_relaxation_steps must be in [1, 10000]");
  require(relax1 > 0 && relax1 <= 1, "ilsa_relaxation must be in (0, 1]");
  require(penalty.relax2 > 0 && penalty.relax2 <= 1, "ilsa_penalty_relaxation must be in (0, 1]");
  require(penalty.mu > 0 && std::isfinite(penalty.mu), "ilsa_penalty_mu must be positive and finite");
  require(penalty.length_weight >= 0 && std::isfinite(penalty.length_weight),
          "ilsa_length_weight must be non-negative and finite");
  require(penalty.area_weight >= 0 && std::isfinite(penalty.area_weight),
          "ilsa_area_weight must be non-negative and finite");
  penalty.sweeps = std::size_t(sweeps);

  // Frozen flat copy of the input (T_ori), user constraints, vertex range.
  // (Without a user map, the vertex numbering is a dynamic property of `tm`,
  // freed once the copy is made, as everything below that only the set-up needs.)
  std::vector<typename GT::vertex_descriptor> vertex_list;
  std::vector<typename GT::edge_descriptor> edge_list;
  ilsa::Flat_mesh original = [&] {
    ilsa::Flat_indices<decltype(ilsa::vertex_index_map_of(tm, np))> vertex_index{ilsa::vertex_index_map_of(tm, np), {}};
    return ilsa::build_flat_mesh(tm, vpm, vertex_list, vertex_index, ilsa::face_index_map_of(tm, np), edge_list);
  }();
  std::vector<unsigned char> constrained_vertices, constrained_edges;
  const auto options = ilsa::read_classification_parameters(tm, original, np, vertex_list, edge_list,
                                                            constrained_vertices, constrained_edges);
  std::vector<unsigned char> movable(original.number_of_vertices(), 0);
  // The range is checked against the mesh's own descriptors: an index map
  // cannot be read for a descriptor that is not the mesh's. (A scope of its
  // own: the map is freed before the smoothing allocates.)
  {
    boost::unordered_map<typename GT::vertex_descriptor, std::size_t> flat_of;
    flat_of.reserve(vertex_list.size());
    for (std::size_t i = 0; i < vertex_list.size(); ++i) flat_of.emplace(vertex_list[i], i);
    for (auto v : vertices) {
      const auto found = flat_of.find(v);
      require(found != flat_of.end(), "a vertex of the range is not a vertex of the mesh");
      movable[found->second] = 1;
    }
  }

  // Classify vertices on T_ori (paper §3).
  ilsa::Vertex_classification classification = ilsa::classify(original, options);
  ilsa::release(classification.ridge_candidate), ilsa::release(classification.attached_sharp);
  ilsa::release(edge_list), ilsa::release(constrained_vertices), ilsa::release(constrained_edges);
  ilsa::release(original.on_border), ilsa::release(original.non_manifold);
  ILSA_statistics stats;
  ilsa::count_types(classification, stats);
  if (verbose)
    std::cerr << "ILSA: " << stats.number_of_smooth_vertices << " smooth, " << stats.number_of_ridge_vertices
              << " ridge, " << stats.number_of_corner_vertices << " corner, " << stats.number_of_boundary_vertices
              << " boundary vertices\n";

  const ilsa::Ilsa_neighborhoods neighborhoods = ilsa::make_ilsa_neighborhoods(original, classification, movable);
  ilsa::release(movable);
  if (neighborhoods.adjustable.empty() || iterations == 0) return stats;

  if (default_floor) {
    // The minimum aspect ratio of the output is then never below the input's.
    double input_minimum = 1.;
    for (const auto& t : original.faces)
      input_minimum = (std::min)(
          input_minimum, triangle_aspect_ratio(original.points[t[0]], original.points[t[1]], original.points[t[2]]));
    quality_floor = (std::max)(quality_floor, input_minimum);
  }
  const ilsa::Projector projector(original, classification, ConcurrencyTag());
  // One per-face array for three uses in turn: the penalty step's weights, the
  // safety check's aspect ratios, the mean aspect ratio of the convergence stop.
  std::vector<double> face_values(original.number_of_faces());
  ilsa::Move_safety safety(original, classification, projector, quality_monotone ? 1. : quality_floor,
                           fidelity_tolerance, reject_worsening, 3, face_values);
  // Read by the classification and the two constructors above only.
  ilsa::release(original.edge_faces), ilsa::release(classification.sharp_edge);
  auto project = [&](std::size_t v, const Vec3& q, const Vec3& current, std::size_t home, bool guard) {
    if (!do_project) return ilsa::Projector::Result{q, home, false};
    return projector.project(v, q, current, home, guard);
  };

  double mean_edge_length = 0;
  for (const auto& e : original.edges) mean_edge_length += (original.points[e[0]] - original.points[e[1]]).norm();
  mean_edge_length /= double((std::max)(original.edges.size(), std::size_t(1)));
  const double tolerance = 1e-4 * mean_edge_length;
  penalty.tolerance = tolerance;

  // T_new := T_ori. `home` is the original face (ridge: sharp edge) each vertex lies on.
  // `next` also serves as the sweeps' second buffer before the projection fills it.
  std::vector<Vec3> pos = original.points, next, d;
  std::vector<ilsa::Index> home(pos.size(), ilsa::npos), next_home;
  std::vector<ilsa::Index> moved;
  moved.reserve(neighborhoods.adjustable.size());
  std::vector<unsigned char> guarded(pos.size(), 0), skipped(pos.size(), 0);
  for (std::size_t v : neighborhoods.adjustable) home[v] = projector.initial_home(v);
  ilsa::Ilsa_workspace ilsa_workspace;
  // Its weights' array, idle during the penalty step, holds the step's
  // targets (three doubles per vertex): one allocation for both.
  ilsa_workspace.weights.reserve((std::max)(original.edges.size(), 3 * pos.size()));
  // Convergence (user manual, "Stopping early"): the mean aspect ratio of the
  // faces, each face's computed in parallel, summed in face order.
  auto mean_quality = [&]() {
    ilsa::parallel_for<ConcurrencyTag>(face_values.size(), [&](std::size_t f) {
      const auto& t = original.faces[f];
      face_values[f] = ilsa::aspect_ratio(pos[t[0]], pos[t[1]], pos[t[2]]);
    });
    double sum = 0;
    for (double q : face_values) sum += q;
    return sum / double((std::max)(face_values.size(), std::size_t(1)));
  };
  const bool may_stop = minimum_gain > 0 || minimum_remaining_gain > 0;
  double mean_q = may_stop ? mean_quality() : 0.;
  // Retrying dropped moves (user manual, "Retrying dropped moves"): a vertex
  // whose move the safety check or the worsening pre-test dropped (but for
  // the quality floor in a star that was at or above it) is settled, left
  // untested, until its neighbours have travelled `retry_length` in all since.
  // `settled[v]`: the length they have travelled so far, or -1 when `v` is
  // not settled (one float per vertex: the largest meshes are at the memory
  // bound of the user manual's "Performance").
  const bool limit_retries = use_safety && retry_distance > 0;
  const double retry_length = retry_distance * mean_edge_length;
  std::vector<float> settled;
  if (limit_retries) settled.assign(pos.size(), -1.f);
  auto is_settled = [&](std::size_t v) { return limit_retries && settled[v] >= 0; };

  for (std::size_t step = 0; step < std::size_t(iterations); ++step) {
    // d(v): ILSA displacement (Algo. 2), penalty-adjusted for smooth vertices
    // (Algo. 3; the face normals of T_new give the discrete normal N(v) of
    // paper §3 where the penalty plane needs it).
    ilsa::compute_ilsa_displacement<ConcurrencyTag>(pos, neighborhoods, relax1, std::size_t(sweeps), tolerance, d,
                                                    ilsa_workspace, next);
    ilsa::adjust_displacement_by_penalty<ConcurrencyTag>(original, pos, neighborhoods, penalty, d, face_values, next,
                                                         ilsa_workspace.weights);

    // p(v): projection of v + d(v) onto T_ori (user manual, "Projection guard"), then the safety check; a
    // move the check dropped in the previous iteration is first tried without projection (its pre-test).
    next = pos;
    next_home = home;
    ilsa::parallel_for<ConcurrencyTag>(neighborhoods.adjustable.size(), [&](std::size_t i) {
      const std::size_t v = neighborhoods.adjustable[i];
      skipped[v] = is_settled(v) || (use_safety && safety.drop_before_projection(pos, d, v));
      guarded[v] = 0;
      if (skipped[v]) return;
      const auto r = project(v, pos[v] + d[v], pos[v], home[v], true);
      next[v] = r.point;
      next_home[v] = ilsa::Index(r.home);
      guarded[v] = r.guarded;
    });
    moved.clear();
    std::size_t skipped_moves = 0;
    for (std::size_t v : neighborhoods.adjustable) {
      stats.number_of_guarded_projections += guarded[v];
      if (is_settled(v))
        ++stats.number_of_settled_skips;
      else
        skipped_moves += skipped[v];
      if (next[v] != pos[v]) moved.push_back(ilsa::Index(v));
    }
    if (use_safety) {
      const auto counts = safety.template enforce<ConcurrencyTag>(pos, home, d, moved, next, next_home, project);
      stats.number_of_shortened_moves += counts.shortened;
      stats.number_of_rejected_moves += counts.rejected + skipped_moves;
      stats.number_of_moves_dropped_before_projection += skipped_moves;
      stats.number_of_moves += moved.size() - counts.rejected;
    } else {
      stats.number_of_moves += moved.size();
    }
    if (limit_retries) {
      ilsa::parallel_for<ConcurrencyTag>(neighborhoods.adjustable.size(), [&](std::size_t i) {
        const std::size_t v = neighborhoods.adjustable[i];
        const bool was_settled = settled[v] >= 0;
        // The neighbours' moves of this iteration count also when it dropped
        // the move of `v`: the test saw them.
        if (!was_settled && !(skipped[v] || safety.dropped_to_settle(v))) return;
        double travelled = was_settled ? double(settled[v]) : 0.;
        for (const ilsa::Index* w = original.vertex_neighbors.first(v); w != original.vertex_neighbors.last(v); ++w)
          travelled += (next[*w] - pos[*w]).norm();
        settled[v] = travelled < retry_length ? float(travelled) : -1.f;
      });
    }
    pos.swap(next);
    home.swap(next_home);
    ++stats.number_of_iterations;
    if (verbose)
      std::cerr << "ILSA iteration " << step + 1 << ": " << moved.size() << " moves, "
                << stats.number_of_shortened_moves << " shortened and " << stats.number_of_rejected_moves
                << " rejected so far\n";
    if (callback && !callback(double(step + 1) / double(iterations))) break;
    if (may_stop) {
      // Stop on a small gain of this iteration, or when this gain times the
      // iterations left (what they could still add while the gains shrink
      // from one iteration to the next) is small (user manual, "Stopping early").
      const double before = mean_q;
      mean_q = mean_quality();
      const double gain = mean_q - before, left = double(iterations) - double(step + 1);
      if (gain < minimum_gain || gain * left < minimum_remaining_gain) break;
    }
  }

  // T_new is written back; fixed and unmoved vertices are not touched.
  for (std::size_t v : neighborhoods.adjustable) {
    if (pos[v] == original.points[v]) continue;
    const Vec3 p = original.to_input(pos[v]);
    put(vpm, vertex_list[v], Point(p.x(), p.y(), p.z()));
  }
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

#endif

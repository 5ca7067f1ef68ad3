// Copyright (c) 2026 The Polygon_mesh_processing_ILSA authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// ILSA, the improved Laplacian smoothing approach of L. Chen, Y. Zheng,
// J. Chen and Y. Liang (ICCS 2007). The public function is the sequence of
// the stages: read the parameters (internal/ILSA/read_parameters.h),
// set up (set_up.h: flat copy and classification), iterate (global_loop.h:
// displacement, penalty step, projection, safety check, stops), write back.

#ifndef CGAL_POLYGON_MESH_PROCESSING_SMOOTH_SURFACE_MESH_ILSA_H
#define CGAL_POLYGON_MESH_PROCESSING_SMOOTH_SURFACE_MESH_ILSA_H

#include <CGAL/Polygon_mesh_processing/ilsa_types.h>
#include <CGAL/Polygon_mesh_processing/internal/ILSA/core.h>
#include <CGAL/Polygon_mesh_processing/internal/ILSA/parallel_loops.h> // Core_tag
#include <CGAL/Polygon_mesh_processing/internal/ILSA/read_parameters.h>
#include <CGAL/Polygon_mesh_processing/internal/ILSA/set_up.h>
#ifndef CGAL_ILSA_COMPILED_CORE
#include <CGAL/Polygon_mesh_processing/internal/ILSA/global_loop.h> // smooth_flat_copy()
#endif

#include <CGAL/boost/graph/named_params_helper.h>

#include <boost/unordered_map.hpp>

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

/// The body of smooth_surface_mesh_ilsa(). `given` and `rules`, when given,
/// replace what `np` selects: the tests and the benchmark vary the
/// constants of the method through them.
template <typename ConcurrencyTag, typename VertexRange, typename TriangleMesh, typename NamedParameters>
ILSA_statistics smooth(const VertexRange& vertices, TriangleMesh& tm, const NamedParameters& np,
                       const Smoothing_parameters* given = nullptr, const Classification_options* rules = nullptr) {
  namespace ilsa = internal::ILSA;
  // 1. Read and check the named parameters (the defaults: internal/ILSA/defaults.h).
  ilsa::check_concurrency_tag<ConcurrencyTag>();
  const ilsa::Smoothing_parameters smoothing = given ? *given : ilsa::read_smoothing_parameters(np);
  using VPM = typename GetVertexPointMap<TriangleMesh, NamedParameters>::type;
  VPM vpm = parameters::choose_parameter(parameters::get_parameter(np, internal_np::vertex_point),
                                         get_property_map(CGAL::vertex_point, tm));

  // 2. Set up: the frozen flat copy of the input (T_ori) and its vertex
  // classification (paper §3), checked before anything is written.
  ilsa::Set_up_incidences incidences; // read by the set-up only, freed before the iterations
  const ilsa::Flat_input<TriangleMesh> input = ilsa::classified_flat_copy(tm, vpm, np, incidences, rules);
  const ilsa::ILSA_neighborhoods neighborhoods =
      ilsa::make_neighborhoods(input.mesh, input.classification, ilsa::vertices_in_range(vertices, input.vertices));
  ILSA_statistics stats;
  ilsa::count_types(input.classification, stats);
  if (neighborhoods.adjustable.empty() || smoothing.iterations == 0) return stats;

  // 3. Iterate (the paper's Algo. 1).
  const std::vector<ilsa::Vec3> smoothed = ilsa::smooth_flat_copy<ilsa::Core_tag<ConcurrencyTag>>(
      input.mesh, input.classification, neighborhoods, smoothing, incidences, stats);

  // 4. Write T_new back.
  ilsa::write_back(input.mesh, smoothed, neighborhoods.adjustable, input.vertices, vpm);
  return stats;
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
 * @param np an optional sequence of named parameters among the ones listed below (and, as in other CGAL
 *        functions, `vertex_index_map` and `face_index_map`; the result does not depend on the numbering)
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
 *   \cgalParamNBegin{number_of_iterations}
 *     \cgalParamDescription{the largest number of global iterations (the paper's max_global_iter_num); the run
 * stops before it once the iterations stop paying (see `ilsa_minimum_quality_gain`)}
 *     \cgalParamType{unsigned int, at most 100000}
 *     \cgalParamDefault{`8`}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{ilsa_minimum_quality_gain}
 *     \cgalParamDescription{the run stops before `number_of_iterations` once an iteration raises the mean aspect
 * ratio of the faces by less than this, or once that gain times the iterations left is below 2e-3 (user manual,
 * "Stopping Early"); `0` disables both stops and every iteration runs. The number of iterations run is
 * `ILSA_statistics::number_of_iterations`}
 *     \cgalParamType{`double`, non-negative}
 *     \cgalParamDefault{`1e-4`}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{ilsa_feature_angle}
 *     \cgalParamDescription{an edge is sharp when the normals of its two faces make an angle larger than this, in
 * degrees: CGAL's convention, the angle `detect_sharp_edges()` takes. The paper states it as the dihedral angle
 * θ_f = 180° − this angle. The rules that turn such edges into crease lines are those of
 * `classify_vertices_ilsa()`}
 *     \cgalParamType{`double`, in [0, 180)}
 *     \cgalParamDefault{`20` (the paper's θ_f = 8π/9, i.e. 160°)}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{vertex_is_constrained_map}
 *     \cgalParamDescription{a property map telling which vertices are fixed}
 *     \cgalParamType{a model of `ReadablePropertyMap` with `vertex_descriptor` as key and `bool` as value}
 *     \cgalParamDefault{no vertex is constrained}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{edge_is_constrained_map}
 *     \cgalParamDescription{when given, these edges are the crease edges, and no edge is detected: the feature
 * angle and its curvature filters (the crease contrast and the open-crease rule of `classify_vertices_ilsa()`) do
 * not apply; the kink rule does. With `relax_constraints(true)`, a vertex with two constrained edges slides along
 * them and one with one or more than two is fixed; by default, every end of a constrained edge is fixed. The crease
 * bound of `ilsa_fidelity_tolerance` holds along these edges}
 *     \cgalParamType{a model of `ReadablePropertyMap` with `edge_descriptor` as key and `bool` as value}
 *     \cgalParamDefault{crease edges are detected with `ilsa_feature_angle`}
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
 * their crease); without projection they stay where the displacement puts them, off the surface, and no distance
 * is certified}
 *     \cgalParamType{`bool`}
 *     \cgalParamDefault{`true`}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{use_safety_constraints}
 *     \cgalParamDescription{whether every move is checked after projection: a move that would reverse or collapse a
 * triangle (with respect to the input surface), push one below `ilsa_quality_floor`, lower the mean aspect ratio of
 * its star, or leave `ilsa_fidelity_tolerance` uncertified is shortened, then dropped for the iteration (user manual,
 * "Safety Check"). With `false`, the penalty step is the only protection against inverted triangles, as in the
 * paper, and no distance is certified}
 *     \cgalParamType{`bool`}
 *     \cgalParamDefault{`true`}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{ilsa_quality_floor}
 *     \cgalParamDescription{with the safety check on, a move is also shortened or dropped if it lowers the minimum
 * aspect ratio of the vertex's star to a value below this floor. 0 disables this part of the check}
 *     \cgalParamType{`double`, in [0, 1)}
 *     \cgalParamDefault{the larger of `0.5` and the minimum aspect ratio of the input faces, so that the minimum
 * aspect ratio of the output is never below the input's}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{ilsa_fidelity_tolerance}
 *     \cgalParamDescription{with the safety check on, the largest distance between the smoothed and the input
 * surface, relative to the bounding-box diagonal, certified both ways for every point (no sampling): every point of
 * the result lies within this distance of the input surface, and every point of the input within it of the result.
 * The same bound holds between the feature lines of the result and those of the input: the crease edges (detected,
 * or those of `edge_is_constrained_map`) and the edges beyond `ilsa_feature_angle` that the crease rules keep. A move
 * after which a face or a feature edge it changes cannot be certified is shortened or dropped (user manual,
 * "Fidelity Certificate"). The bound is exact up to rounding: the certificate accepts a face only 1e-12 of the
 * diagonal within the tolerance, and the coordinates are rounded once more when they are written back. The bound the
 * run reached is `ILSA_statistics::certified_distance`. `std::numeric_limits<double>::infinity()` disables the bound
 * (the paper has none)}
 *     \cgalParamType{`double`, positive}
 *     \cgalParamDefault{`5e-4`}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{ilsa_paper_variant}
 *     \cgalParamDescription{if `true`, the method of the paper where the package departs from it (user manual, "The
 * Paper's Variant"): the paper's classification (every edge beyond the feature angle between two ridge candidates is
 * sharp, a candidate without sharp edge is fixed, no kink rule), the paper's displacement (normal component kept), as
 * many sweeps of the penalty step as of the ILSA step, and every move the other tests of the safety check allow.
 * The guarantees stay: use `use_safety_constraints(false)` for the paper's unchecked moves}
 *     \cgalParamType{`bool`}
 *     \cgalParamDefault{`false`}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{callback}
 *     \cgalParamDescription{called after each iteration with the advancement, the iterations run over
 * `number_of_iterations` (the last call may come before 1 when the run stops early); when it returns `false`, the
 * run stops there, with the mesh as that iteration left it (every guarantee holds after any iteration)}
 *     \cgalParamType{an instance of `std::function<bool(double)>`}
 *     \cgalParamDefault{no callback}
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
  return internal::ILSA::smooth<ConcurrencyTag>(vertices, tm, np);
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

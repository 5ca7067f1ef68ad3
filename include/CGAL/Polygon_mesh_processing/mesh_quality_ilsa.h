// Copyright (c) 2026 The Polygon_mesh_processing_ILSA authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Mesh quality and fidelity summaries, for the tool, the examples, the
// benchmark, the tests and users who evaluate a result. The triangle shape
// measures they rest on (and the smoother uses) are in triangle_quality_ilsa.h.

#ifndef CGAL_POLYGON_MESH_PROCESSING_MESH_QUALITY_ILSA_H
#define CGAL_POLYGON_MESH_PROCESSING_MESH_QUALITY_ILSA_H

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/Polygon_mesh_processing/triangle_quality_ilsa.h>
#include <CGAL/Polygon_mesh_processing/ilsa_types.h>
#include <CGAL/Polygon_mesh_processing/distance.h>
#include <CGAL/Polygon_mesh_processing/internal/ILSA/aabb_tree.h>
#include <CGAL/Polygon_mesh_processing/internal/ILSA/feature_lines.h>
#include <CGAL/Polygon_mesh_processing/internal/ILSA/read_parameters.h>
#include <CGAL/Polygon_mesh_processing/internal/ILSA/set_up.h>
#include <CGAL/Random.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/copy_face_graph.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/number_utils.h>
#include <CGAL/property_map.h>

#include <boost/unordered_map.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <cstddef>
#include <iterator>
#include <limits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {

/// \ingroup PkgPMPILSARef
/// Summary of the shape quality of a set of triangles.
struct ILSA_quality_summary {
  std::size_t number_of_faces = 0;
  std::size_t number_of_degenerate_faces = 0; ///< aspect ratio below 1e-6 (zero area, in practice)
  double min_aspect_ratio = 0, mean_aspect_ratio = 0;
  double min_radius_ratio = 0, mean_radius_ratio = 0;
  double min_mean_ratio = 0, mean_mean_ratio = 0;
  double min_angle = 0;                    ///< degrees
  double threshold = 0.3;                  ///< the threshold `share_below_threshold` refers to
  double share_below_threshold = 0;        ///< share of faces with aspect ratio below `threshold`
  std::array<std::size_t, 10> histogram{}; ///< aspect ratio counts in [0,0.1), [0.1,0.2), ..., [0.9,1]
};

/// \ingroup PkgPMPILSARef
/// Quality summary over the faces `face_range` of the triangle mesh `tm`:
/// aspect ratio `q` (triangle_quality_ilsa()), radius ratio, mean ratio and
/// smallest angle.
///
/// @tparam FaceRange a range of `boost::graph_traits<TriangleMesh>::%face_descriptor`
/// @tparam TriangleMesh a model of `FaceGraph`
/// @tparam NamedParameters a sequence of named parameters
///
/// @param face_range the faces to summarise
/// @param tm the triangle mesh the faces belong to
/// @param np an optional sequence of named parameters among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{a property map associating points to the vertices of `tm`}
///     \cgalParamType{a model of `ReadablePropertyMap` with `vertex_descriptor` as key and `%Point_3` as value}
///     \cgalParamDefault{`boost::get(CGAL::vertex_point, tm)`}
///   \cgalParamNEnd
///   \cgalParamNBegin{ilsa_quality_threshold}
///     \cgalParamDescription{the aspect ratio under which a face counts as poor in `share_below_threshold`}
///     \cgalParamType{`double`, in [0, 1]}
///     \cgalParamDefault{`0.3`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// @return the summary; with no face, every figure is 0
/// @throws ILSA_error for a face of the range that is not a triangle or has a
///         non-finite coordinate, as `smooth_surface_mesh_ilsa()` does, and
///         for a threshold out of range.
template <class FaceRange, class TriangleMesh, class NamedParameters = parameters::Default_named_parameters,
          typename = std::enable_if_t<!internal::ILSA::is_named_parameters<TriangleMesh>::value>>
ILSA_quality_summary mesh_quality_ilsa(const FaceRange& face_range, const TriangleMesh& tm,
                                       const NamedParameters& np = parameters::default_values()) {
  using parameters::choose_parameter;
  using parameters::get_parameter;
  const auto vpm =
      choose_parameter(get_parameter(np, internal_np::vertex_point), get_const_property_map(CGAL::vertex_point, tm));
  const double threshold = internal::ILSA::read_quality_threshold(np);

  ILSA_quality_summary s;
  s.threshold = threshold;
  s.min_aspect_ratio = s.min_radius_ratio = s.min_mean_ratio = 1.;
  s.min_angle = 180.;
  std::size_t below = 0;
  for (auto f : face_range) {
    const auto h = halfedge(f, tm);
    if (next(next(next(h, tm), tm), tm) != h)
      throw ILSA_error("mesh_quality_ilsa() needs triangles: a face has " + std::to_string(degree(f, tm)) +
                       " vertices");
    const auto& p0 = get(vpm, source(h, tm));
    const auto& p1 = get(vpm, target(h, tm));
    const auto& p2 = get(vpm, target(next(h, tm), tm));
    for (const auto* p : {&p0, &p1, &p2})
      if (!std::isfinite(CGAL::to_double(p->x())) || !std::isfinite(CGAL::to_double(p->y())) ||
          !std::isfinite(CGAL::to_double(p->z())))
        throw ILSA_error("mesh_quality_ilsa(): a face has a non-finite coordinate (NaN or infinity)");
    const double q = triangle_quality_ilsa(p0, p1, p2);
    const double rr = triangle_radius_ratio_ilsa(p0, p1, p2);
    const double mr = triangle_mean_ratio_ilsa(p0, p1, p2);
    ++s.number_of_faces;
    s.mean_aspect_ratio += q;
    s.mean_radius_ratio += rr;
    s.mean_mean_ratio += mr;
    s.min_aspect_ratio = (std::min)(s.min_aspect_ratio, q);
    s.min_radius_ratio = (std::min)(s.min_radius_ratio, rr);
    s.min_mean_ratio = (std::min)(s.min_mean_ratio, mr);
    s.min_angle = (std::min)(s.min_angle, triangle_minimum_angle_ilsa(p0, p1, p2));
    if (q < 1e-6) ++s.number_of_degenerate_faces;
    if (q < threshold) ++below;
    ++s.histogram[(std::min)(std::size_t(9), std::size_t((std::max)(q, 0.) * 10.))];
  }
  if (s.number_of_faces == 0) {
    s.min_aspect_ratio = s.min_radius_ratio = s.min_mean_ratio = s.min_angle = 0;
    return s;
  }
  const double n = double(s.number_of_faces);
  s.mean_aspect_ratio /= n;
  s.mean_radius_ratio /= n;
  s.mean_mean_ratio /= n;
  s.share_below_threshold = double(below) / n;
  return s;
}

/// \ingroup PkgPMPILSARef
/// Quality summary over all faces of `tm`; named parameters as in the range overload.
template <class TriangleMesh, class NamedParameters = parameters::Default_named_parameters,
          typename = std::enable_if_t<!internal::ILSA::is_named_parameters<TriangleMesh>::value &&
                                      internal::ILSA::is_named_parameters<NamedParameters>::value>>
ILSA_quality_summary mesh_quality_ilsa(const TriangleMesh& tm,
                                       const NamedParameters& np = parameters::default_values()) {
  return mesh_quality_ilsa(faces(tm), tm, np);
}

/// \ingroup PkgPMPILSARef
/// How faithful a smoothed mesh is to its original (same connectivity).
/// Distances are relative to the bounding-box diagonal of the original.
struct ILSA_fidelity_summary {
  std::size_t number_of_faces = 0;
  std::size_t number_of_flipped_faces = 0; ///< faces whose normal turned by more than 90 degrees
  double max_vertex_distance = 0;          ///< largest distance of a smoothed vertex to the original surface
  double mean_vertex_distance = 0;
  /// symmetric Hausdorff distance, certified by CGAL's
  /// `bounded_error_symmetric_Hausdorff_distance()`: the true distance lies between this value and this value
  /// plus `hausdorff_error`; NaN with `ilsa_compute_hausdorff_distance(false)`
  double hausdorff_distance = 0;
  double hausdorff_error = 0; ///< the error bound of `hausdorff_distance`: 1e-5 (of the diagonal)
  bool closed = false;
  double volume_change = 0;              ///< (V_smoothed - V_original) / V_original, closed meshes only
  std::size_t number_of_sharp_edges = 0; ///< feature lines: the edges of the original that the smoother's crease
                                         ///< bound holds (the feature edges of `classify_vertices_ilsa()`: beyond
                                         ///< the feature angle and kept by its rules), or the constrained edges
  /// Two-sided distance between the original's crease edges and the same edges of the smoothed mesh: every edge of
  /// either polyline is sampled (ends and seven inner points) and each sample is measured against the whole other
  /// polyline. A crease cut short (an original point far from the smoothed crease) and a crease bent away from the
  /// original (a smoothed point far from the original crease) both show.
  double max_crease_deviation = 0;
  double mean_crease_deviation = 0; ///< mean over the samples of both directions
};

namespace internal {
namespace ILSA {
// The steps of mesh_fidelity_ilsa(), on plain double copies of the two meshes.
namespace fidelity {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;
using Segments = std::vector<Kernel::Segment_3>;

inline Kernel::Vector_3 face_normal(const Mesh& m, Mesh::Face_index f) {
  const auto h = halfedge(f, m);
  const Point &p0 = m.point(source(h, m)), &p1 = m.point(target(h, m)), &p2 = m.point(target(next(h, m), m));
  return CGAL::cross_product(p1 - p0, p2 - p0);
}

// Faces whose normal turned by more than 90 degrees from `a` to `b`.
inline std::size_t flipped_faces(const Mesh& a, const Mesh& b) {
  std::size_t flipped = 0;
  for (auto fa = faces(a).begin(), fb = faces(b).begin(); fa != faces(a).end(); ++fa, ++fb)
    if (face_normal(a, *fa) * face_normal(b, *fb) < 0) ++flipped;
  return flipped;
}

// Largest and mean distance of the points `pb` to the surface of `a`.
inline void vertex_distances(const Mesh& a, const std::vector<Point>& pb, double scale, ILSA_fidelity_summary& r) {
  using Face_tree = AABB_tree_3<Kernel, CGAL::AABB_face_graph_triangle_primitive<Mesh>>;
  Face_tree tree(faces(a).first, faces(a).second, a);
  for (const Point& p : pb) {
    const double d = std::sqrt(tree.squared_distance(p)) * scale;
    r.max_vertex_distance = (std::max)(r.max_vertex_distance, d);
    r.mean_vertex_distance += d;
  }
  r.mean_vertex_distance /= double(pb.size());
}

// The error bound of the Hausdorff distance, relative to the diagonal.
constexpr double hausdorff_error = 1e-5;

// CGAL's bounded-error symmetric Hausdorff distance, certified: the true
// distance lies in [value, value + hausdorff_error] (relative to the diagonal).
inline double hausdorff_distance(const Mesh& a, const Mesh& b, double diagonal) {
  return bounded_error_symmetric_Hausdorff_distance<CGAL::Sequential_tag>(a, b, hausdorff_error * diagonal) / diagonal;
}

// Two-sided distance between the two crease polylines: every edge of either
// is sampled (ends and crease_samples - 1 inner points), each sample measured
// against the whole other polyline.
inline void crease_deviation(const Segments& original_crease, const Segments& smoothed_crease, double scale,
                             ILSA_fidelity_summary& r) {
  using Segment_tree = AABB_tree_3<Kernel, AABB_segment_primitive_3<Kernel, typename Segments::const_iterator>>;
  const Segment_tree original_lines(original_crease.cbegin(), original_crease.cend());
  const Segment_tree smoothed_lines(smoothed_crease.cbegin(), smoothed_crease.cend());
  constexpr int intervals = crease_samples;
  std::size_t samples = 0;
  auto measure = [&](const Segments& from, const Segment_tree& to) {
    for (const auto& s : from)
      for (int k = 0; k <= intervals; ++k) {
        const double d =
            std::sqrt(to.squared_distance(s.source() + (double(k) / intervals) * (s.target() - s.source()))) * scale;
        r.max_crease_deviation = (std::max)(r.max_crease_deviation, d);
        r.mean_crease_deviation += d;
        ++samples;
      }
  };
  measure(original_crease, smoothed_lines);
  measure(smoothed_crease, original_lines);
  r.mean_crease_deviation /= double(samples);
}

} // namespace fidelity
} // namespace ILSA
} // namespace internal

/// \ingroup PkgPMPILSARef
/// Compares `smoothed` with `original`, which must have the same vertices and
/// faces in the same order (as `smooth_surface_mesh_ilsa()` leaves them).
///
/// @tparam TriangleMesh a model of `FaceGraph` whose points are those of a CGAL kernel
/// @tparam NamedParameters a sequence of named parameters
///
/// @param original the mesh before smoothing
/// @param smoothed the mesh after smoothing
/// @param np an optional sequence of named parameters among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{ilsa_feature_angle}
///     \cgalParamDescription{as given to the smoother: the crease deviation compares the feature lines of
///       `original` that the smoother keeps (the feature edges of `classify_vertices_ilsa()`) with the same edges
///       of `smoothed`}
///     \cgalParamType{`double`, in [0, 180)}
///     \cgalParamDefault{`20`}
///   \cgalParamNEnd
///   \cgalParamNBegin{ilsa_paper_variant}
///     \cgalParamDescription{as given to the smoother: the paper's rules for the feature lines}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`false`}
///   \cgalParamNEnd
///   \cgalParamNBegin{edge_is_constrained_map}
///     \cgalParamDescription{as given to the smoother: these edges of `original` are its feature lines}
///     \cgalParamType{a model of `ReadablePropertyMap` with `edge_descriptor` as key and `bool` as value}
///     \cgalParamDefault{feature lines are detected with `ilsa_feature_angle`}
///   \cgalParamNEnd
///   \cgalParamNBegin{ilsa_compute_hausdorff_distance}
///     \cgalParamDescription{`false` skips the Hausdorff distance (`hausdorff_distance` is then NaN), the costly
///       part on large meshes (CGAL's bounded-error distance, certified to 1e-5 of the diagonal: seconds on
///       100 000 faces); the other figures take about one AABB tree query per vertex}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`true`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// @return the summary, distances relative to the bounding-box diagonal of `original`
/// @throws ILSA_error if a mesh is not a triangle mesh or has a non-finite coordinate.
template <class TriangleMesh, class NamedParameters = parameters::Default_named_parameters>
ILSA_fidelity_summary mesh_fidelity_ilsa(const TriangleMesh& original, const TriangleMesh& smoothed,
                                         const NamedParameters& np = parameters::default_values()) {
  namespace fidelity = internal::ILSA::fidelity;
  const bool with_hausdorff = internal::ILSA::read_compute_hausdorff_distance(np);
  ILSA_fidelity_summary r;

  // Plain double copies; both are made the same way, so their vertices and
  // faces correspond. `copied` maps the vertices of `original` to `a`'s.
  using vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;
  std::vector<std::pair<vertex_descriptor, fidelity::Mesh::Vertex_index>> copied;
  fidelity::Mesh a, b;
  CGAL::copy_face_graph(original, a, parameters::vertex_to_vertex_output_iterator(std::back_inserter(copied)));
  CGAL::copy_face_graph(smoothed, b);
  // The input checks of the smoother: triangles only, finite coordinates.
  for (const fidelity::Mesh* m : {&a, &b}) {
    if (!CGAL::is_triangle_mesh(*m)) throw ILSA_error("mesh_fidelity_ilsa() needs triangle meshes");
    for (const auto& p : m->points())
      if (!std::isfinite(p.x()) || !std::isfinite(p.y()) || !std::isfinite(p.z()))
        throw ILSA_error("mesh_fidelity_ilsa(): a mesh has a non-finite coordinate (NaN or infinity)");
  }
  if (num_vertices(a) != num_vertices(b) || num_faces(a) != num_faces(b) || num_faces(a) == 0) return r;
  r.number_of_faces = num_faces(a);

  const std::vector<fidelity::Point> pa(a.points().begin(), a.points().end()), pb(b.points().begin(), b.points().end());
  const auto box = CGAL::bbox_3(pa.begin(), pa.end());
  const double diagonal = std::sqrt(CGAL::square(box.xmax() - box.xmin()) + CGAL::square(box.ymax() - box.ymin()) +
                                    CGAL::square(box.zmax() - box.zmin()));
  const double scale = diagonal > 0 ? 1. / diagonal : 1.;

  r.number_of_flipped_faces = fidelity::flipped_faces(a, b);
  fidelity::vertex_distances(a, pb, scale, r);
  r.hausdorff_error = fidelity::hausdorff_error;
  r.hausdorff_distance = with_hausdorff && diagonal > 0 ? fidelity::hausdorff_distance(a, b, diagonal)
                                                        : std::numeric_limits<double>::quiet_NaN();
  r.closed = CGAL::is_closed(a);
  if (r.closed) {
    const double va = CGAL::to_double(volume(a)), vb = CGAL::to_double(volume(b));
    r.volume_change = va != 0 ? (vb - va) / std::abs(va) : 0.;
  }

  // The feature lines, by the smoother's own classification of `original`.
  internal::ILSA::Set_up_incidences incidences;
  const auto flat = internal::ILSA::classified_flat_copy(original, get_const_property_map(CGAL::vertex_point, original),
                                                         np, incidences);
  boost::unordered_map<vertex_descriptor, std::size_t> index_in_a;
  for (const auto& c : copied) index_in_a.emplace(c.first, std::size_t(c.second));
  std::pair<fidelity::Segments, fidelity::Segments> creases;
  for (std::size_t e = 0; e < flat.mesh.edges.size(); ++e) {
    if (!flat.classification.feature_edge[e]) continue;
    const std::size_t i = index_in_a.at(flat.vertices[flat.mesh.edges[e][0]]);
    const std::size_t j = index_in_a.at(flat.vertices[flat.mesh.edges[e][1]]);
    creases.first.emplace_back(pa[i], pa[j]);
    creases.second.emplace_back(pb[i], pb[j]);
  }
  r.number_of_sharp_edges = creases.first.size();
  if (!creases.first.empty()) fidelity::crease_deviation(creases.first, creases.second, scale, r);
  return r;
}

} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_POLYGON_MESH_PROCESSING_MESH_QUALITY_ILSA_H

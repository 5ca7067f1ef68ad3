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
#include <CGAL/Polygon_mesh_processing/internal/ILSA/defaults.h>
#include <CGAL/Polygon_mesh_processing/internal/ILSA/feature_lines.h>
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
#include <set>
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
/// Quality summary over the faces `face_range` of the triangle mesh `tm`.
/// Named parameters, in any order:
/// - `vertex_point_map` (default `get_const_property_map(CGAL::vertex_point, tm)`);
/// - `ilsa_quality_threshold` (default `0.3`): the aspect ratio under which a
///   face counts as poor in `share_below_threshold`.
///
/// @throws ILSA_error for a face of the range that is not a triangle or has a
///         non-finite coordinate, as `smooth_surface_mesh_ilsa()` does.
template <class FaceRange, class TriangleMesh, class NamedParameters = parameters::Default_named_parameters,
          typename = std::enable_if_t<!internal::ILSA::is_named_parameters<TriangleMesh>::value>>
ILSA_quality_summary mesh_quality_ilsa(const FaceRange& face_range, const TriangleMesh& tm,
                                       const NamedParameters& np = parameters::default_values()) {
  using parameters::choose_parameter;
  using parameters::get_parameter;
  const auto vpm =
      choose_parameter(get_parameter(np, internal_np::vertex_point), get_const_property_map(CGAL::vertex_point, tm));
  const double threshold = choose_parameter(get_parameter(np, internal_np::ilsa_quality_threshold),
                                            internal::ILSA::defaults::quality_threshold);

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
  std::size_t number_of_sharp_edges = 0; ///< crease edges: sharp edges of the original (face normals more than the
                                         ///< feature angle apart, kept by the crease contrast when one is given,
                                         ///< not in a short open set), or the constrained edges when a map is given
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
using Vertex_pairs = std::set<std::pair<std::size_t, std::size_t>>; // (lower, higher) vertex of each edge

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

// The edges of `original` that `edge_is_constrained_map` marks, as ordered
// pairs of vertices of its copy (`copied` maps the vertices).
template <class TriangleMesh, class NamedParameters, class Copied>
Vertex_pairs constrained_edges(const TriangleMesh& original, const NamedParameters& np, const Copied& copied) {
  using parameters::choose_parameter;
  using parameters::get_parameter;
  using GT = boost::graph_traits<TriangleMesh>;
  const auto ecm = choose_parameter(get_parameter(np, internal_np::edge_is_constrained),
                                    Static_boolean_property_map<typename GT::edge_descriptor, false>());
  boost::unordered_map<typename GT::vertex_descriptor, std::size_t> position;
  for (const auto& c : copied) position.emplace(c.first, std::size_t(c.second));
  Vertex_pairs constrained;
  for (auto e : edges(original))
    if (get(ecm, e)) {
      const std::size_t i = position.at(source(e, original)), j = position.at(target(e, original));
      constrained.emplace((std::min)(i, j), (std::max)(i, j));
    }
  return constrained;
}

// The crease edges of `a` (the constrained ones when `user_creases`, else the
// sharp ones: face normals more than the feature angle apart, with a crease
// `contrast` above 0 kept by keeps_crease_contrast(), and not in an open set
// of fewer than `minimum_open_edges`, drop_short_open_lines()), and the same
// edges with the points `pb` (not the smoothed mesh's own sharp edges: an edge
// near the threshold could change side).
inline std::pair<Segments, Segments> crease_edges(const Mesh& a, const std::vector<Point>& pb, bool user_creases,
                                                  const Vertex_pairs& constrained, double feature_angle,
                                                  double contrast, std::size_t minimum_open_edges) {
  const double sharp_cosine = feature_cosine(feature_angle);
  // The cosine of the angle between the face normals of each edge; 1 (flat)
  // on the border and next to a degenerate face, whose normal is zero.
  std::vector<double> cosine(num_edges(a), 1.);
  if (!user_creases)
    for (auto e : edges(a)) {
      const auto h = halfedge(e, a);
      if (is_border_edge(h, a)) continue;
      auto n0 = face_normal(a, face(h, a)), n1 = face_normal(a, face(opposite(h, a), a));
      const double l = std::sqrt(n0.squared_length() * n1.squared_length());
      if (l != 0) cosine[std::size_t(e)] = n0 * n1 / l;
    }
  auto angle = [&](Mesh::Halfedge_index h) { return normal_angle(cosine[std::size_t(edge(h, a))]); };
  // The angle of the flatter of the two edges of the face of `h` other than `h`'s.
  auto flatter = [&](Mesh::Halfedge_index h) { return (std::min)(angle(next(h, a)), angle(prev(h, a))); };
  auto ends = [&a](std::size_t e) {
    const auto h = halfedge(Mesh::Edge_index(Mesh::size_type(e)), a);
    return std::array<std::size_t, 2>{std::size_t(source(h, a)), std::size_t(target(h, a))};
  };
  std::vector<unsigned char> crease(num_edges(a), 0);
  for (auto e : edges(a)) {
    const auto h = halfedge(e, a);
    if (user_creases) {
      const auto ab = ends(std::size_t(e));
      crease[std::size_t(e)] = constrained.count({(std::min)(ab[0], ab[1]), (std::max)(ab[0], ab[1])}) > 0;
    } else
      crease[std::size_t(e)] =
          cosine[std::size_t(e)] < sharp_cosine &&
          (!(contrast > 0) || keeps_crease_contrast(angle(h), flatter(h), flatter(opposite(h, a)), contrast));
  }
  if (!user_creases)
    drop_short_open_lines(
        num_vertices(a), ends,
        [&a](std::size_t v) { return bool(CGAL::is_border(Mesh::Vertex_index(Mesh::size_type(v)), a)); }, crease,
        minimum_open_edges);
  std::pair<Segments, Segments> creases;
  for (auto e : edges(a)) {
    if (!crease[std::size_t(e)]) continue;
    const auto ab = ends(std::size_t(e));
    creases.first.emplace_back(a.point(Mesh::Vertex_index(Mesh::size_type(ab[0]))),
                               a.point(Mesh::Vertex_index(Mesh::size_type(ab[1]))));
    creases.second.emplace_back(pb[ab[0]], pb[ab[1]]);
  }
  return creases;
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
/// Named parameters:
/// - `ilsa_feature_angle` (default `20`): an edge of `original` is sharp when the
///   normals of its two faces make a larger angle, in degrees (CGAL's convention,
///   as in `detect_sharp_edges()`); the crease deviation compares these edges;
/// - `ilsa_crease_contrast` (default `5`, the smoother's): with a contrast above
///   0, only the sharp edges that keep it, as in `smooth_surface_mesh_ilsa()`
///   (user manual, "Crease contrast"); pass the smoother's value to measure its
///   crease lines, `0` to measure every edge beyond the feature angle;
/// - `ilsa_minimum_open_crease_edges` (default `20`, the smoother's): the
///   crease edges leave out every connected set of fewer edges that has an
///   end, as in `smooth_surface_mesh_ilsa()` (user manual, "Open Crease
///   Lines"); `0` keeps them;
/// - `edge_is_constrained_map`: a map from the edges of `original` to `bool`;
///   when given, its edges are the crease edges instead of the sharp ones;
/// - `ilsa_compute_hausdorff_distance` (default `true`): `false` skips the
///   Hausdorff distance (`hausdorff_distance` is then NaN), the costly part on
///   large meshes (CGAL's bounded-error distance, certified to 1e-5 of the
///   diagonal: seconds on 100 000 faces): the other figures take about one
///   AABB tree query per vertex.
///
/// @throws ILSA_error if a mesh is not a triangle mesh or has a non-finite coordinate.
template <class TriangleMesh, class NamedParameters = parameters::Default_named_parameters>
ILSA_fidelity_summary mesh_fidelity_ilsa(const TriangleMesh& original, const TriangleMesh& smoothed,
                                         const NamedParameters& np = parameters::default_values()) {
  using parameters::choose_parameter;
  using parameters::get_parameter;
  namespace fidelity = internal::ILSA::fidelity;
  const double feature_angle =
      choose_parameter(get_parameter(np, internal_np::ilsa_feature_angle), internal::ILSA::defaults::feature_angle);
  const bool with_hausdorff = choose_parameter(get_parameter(np, internal_np::ilsa_compute_hausdorff_distance), true);
  const double contrast =
      choose_parameter(get_parameter(np, internal_np::ilsa_crease_contrast), internal::ILSA::defaults::crease_contrast);
  const auto minimum_open_edges = choose_parameter(get_parameter(np, internal_np::ilsa_minimum_open_crease_edges),
                                                   internal::ILSA::defaults::minimum_open_crease_edges);
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

  constexpr bool user_creases =
      !parameters::is_default_parameter<NamedParameters, internal_np::edge_is_constrained_t>::value;
  const auto creases = fidelity::crease_edges(
      a, pb, user_creases, user_creases ? fidelity::constrained_edges(original, np, copied) : fidelity::Vertex_pairs(),
      feature_angle, contrast, double(minimum_open_edges) > 0 ? std::size_t(minimum_open_edges) : 0);
  r.number_of_sharp_edges = creases.first.size();
  if (!creases.first.empty()) fidelity::crease_deviation(creases.first, creases.second, scale, r);
  return r;
}

} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_POLYGON_MESH_PROCESSING_MESH_QUALITY_ILSA_H

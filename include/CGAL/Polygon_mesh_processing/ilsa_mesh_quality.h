// Copyright (c) 2026 The Polygon_mesh_processing_ILSA authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Triangle shape measures and mesh quality summaries. The smoother, the
// example tools, the benchmark and the tests all use these functions.

#ifndef CGAL_POLYGON_MESH_PROCESSING_ILSA_MESH_QUALITY_H
#define CGAL_POLYGON_MESH_PROCESSING_ILSA_MESH_QUALITY_H

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {

namespace internal {
namespace ILSA {

// Edge lengths, twice the area and the smallest angle of a triangle, in double.
struct Triangle_shape {
  std::array<double, 3> length; // opposite to vertex 0, 1, 2
  double double_area;
  double smallest_angle_degrees;
};

template <class P>
Triangle_shape triangle_shape(const P& p0, const P& p1, const P& p2) {
  const std::array<std::array<double, 3>, 3> v{{{CGAL::to_double(p0.x()), CGAL::to_double(p0.y()), CGAL::to_double(p0.z())},
                                                {CGAL::to_double(p1.x()), CGAL::to_double(p1.y()), CGAL::to_double(p1.z())},
                                                {CGAL::to_double(p2.x()), CGAL::to_double(p2.y()), CGAL::to_double(p2.z())}}};
  auto sub = [](const std::array<double, 3>& a, const std::array<double, 3>& b) {
    return std::array<double, 3>{a[0] - b[0], a[1] - b[1], a[2] - b[2]};
  };
  auto cross = [](const std::array<double, 3>& a, const std::array<double, 3>& b) {
    return std::array<double, 3>{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
  };
  auto dot = [](const std::array<double, 3>& a, const std::array<double, 3>& b) {
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
  };
  Triangle_shape s;
  const auto n = cross(sub(v[1], v[0]), sub(v[2], v[0]));
  s.double_area = std::sqrt(dot(n, n));
  s.smallest_angle_degrees = 180.;
  for (int i = 0; i < 3; ++i) {
    const auto a = sub(v[(i + 1) % 3], v[i]), b = sub(v[(i + 2) % 3], v[i]);
    const auto c = sub(v[(i + 2) % 3], v[(i + 1) % 3]);
    s.length[i] = std::sqrt(dot(c, c));
    const auto axb = cross(a, b);
    const double angle = std::atan2(std::sqrt(dot(axb, axb)), dot(a, b)) * 180. / 3.14159265358979323846;
    s.smallest_angle_degrees = (std::min)(s.smallest_angle_degrees, angle);
  }
  return s;
}

} // namespace ILSA
} // namespace internal

/// \ingroup PkgPMPILSARef
/// Aspect ratio `q = 2√3·r_in / l_max` of a triangle (inradius over longest
/// edge): 1 for an equilateral triangle, 0 for a degenerate one. This is the
/// paper's quality measure and the package's primary one.
/// `P` is any point type with `x()`, `y()`, `z()`.
template <class P>
double triangle_aspect_ratio(const P& p0, const P& p1, const P& p2) {
  const auto s = internal::ILSA::triangle_shape(p0, p1, p2);
  const double perimeter = s.length[0] + s.length[1] + s.length[2];
  const double longest = (std::max)({s.length[0], s.length[1], s.length[2]});
  // r_in = 2A / perimeter, so q = 2√3 · (2A / perimeter) / l_max.
  return longest > 0 ? 2. * std::sqrt(3.) * s.double_area / (perimeter * longest) : 0.;
}

/// \ingroup PkgPMPILSARef
/// Radius ratio `2·r_in / r_circ` of a triangle: 1 equilateral, 0 degenerate.
template <class P>
double triangle_radius_ratio(const P& p0, const P& p1, const P& p2) {
  const auto s = internal::ILSA::triangle_shape(p0, p1, p2);
  const double perimeter = s.length[0] + s.length[1] + s.length[2];
  const double product = s.length[0] * s.length[1] * s.length[2];
  // r_in = 2A / perimeter and r_circ = abc / (4A): 2 r_in / r_circ = 16 A² / (perimeter · abc).
  return product > 0 ? 4. * s.double_area * s.double_area / (perimeter * product) : 0.;
}

/// \ingroup PkgPMPILSARef
/// Mean ratio `4√3·A / Σ l²` of a triangle: 1 equilateral, 0 degenerate.
template <class P>
double triangle_mean_ratio(const P& p0, const P& p1, const P& p2) {
  const auto s = internal::ILSA::triangle_shape(p0, p1, p2);
  const double sum = s.length[0] * s.length[0] + s.length[1] * s.length[1] + s.length[2] * s.length[2];
  return sum > 0 ? 2. * std::sqrt(3.) * s.double_area / sum : 0.;
}

/// \ingroup PkgPMPILSARef
/// Smallest angle of a triangle, in degrees (0 for a degenerate one).
template <class P>
double triangle_minimum_angle(const P& p0, const P& p1, const P& p2) {
  const auto s = internal::ILSA::triangle_shape(p0, p1, p2);
  return s.double_area > 0 ? s.smallest_angle_degrees : 0.;
}

/// \ingroup PkgPMPILSARef
/// Summary of the shape quality of a set of triangles.
struct ILSA_quality_summary {
  std::size_t number_of_faces = 0;
  std::size_t number_of_degenerate_faces = 0; ///< aspect ratio below 1e-6 (zero area, in practice)
  double min_aspect_ratio = 0, mean_aspect_ratio = 0;
  double min_radius_ratio = 0, mean_radius_ratio = 0;
  double min_mean_ratio = 0, mean_mean_ratio = 0;
  double min_angle = 0; ///< degrees
  double threshold = 0.3;             ///< the threshold `share_below_threshold` refers to
  double share_below_threshold = 0;   ///< share of faces with aspect ratio below `threshold`
  std::array<std::size_t, 10> histogram{}; ///< aspect ratio counts in [0,0.1), [0.1,0.2), ..., [0.9,1]
};

/// \ingroup PkgPMPILSARef
/// Quality summary over the faces `face_range` of the triangle mesh `tm`.
/// `threshold` is the aspect ratio under which a face counts as poor.
/// Named parameter: `vertex_point_map`.
template <class FaceRange, class TriangleMesh, class NamedParameters = parameters::Default_named_parameters>
ILSA_quality_summary mesh_quality_ilsa(const FaceRange& face_range, const TriangleMesh& tm, double threshold = 0.3,
                                       const NamedParameters& np = parameters::default_values()) {
  using parameters::choose_parameter;
  using parameters::get_parameter;
  const auto vpm = choose_parameter(get_parameter(np, internal_np::vertex_point), get_const_property_map(CGAL::vertex_point, tm));

  ILSA_quality_summary s;
  s.threshold = threshold;
  s.min_aspect_ratio = s.min_radius_ratio = s.min_mean_ratio = 1.;
  s.min_angle = 180.;
  std::size_t below = 0;
  for (auto f : face_range) {
    const auto h = halfedge(f, tm);
    const auto& p0 = get(vpm, source(h, tm));
    const auto& p1 = get(vpm, target(h, tm));
    const auto& p2 = get(vpm, target(next(h, tm), tm));
    const double q = triangle_aspect_ratio(p0, p1, p2);
    const double rr = triangle_radius_ratio(p0, p1, p2);
    const double mr = triangle_mean_ratio(p0, p1, p2);
    ++s.number_of_faces;
    s.mean_aspect_ratio += q;
    s.mean_radius_ratio += rr;
    s.mean_mean_ratio += mr;
    s.min_aspect_ratio = (std::min)(s.min_aspect_ratio, q);
    s.min_radius_ratio = (std::min)(s.min_radius_ratio, rr);
    s.min_mean_ratio = (std::min)(s.min_mean_ratio, mr);
    s.min_angle = (std::min)(s.min_angle, triangle_minimum_angle(p0, p1, p2));
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
/// Quality summary over all faces of `tm`.
template <class TriangleMesh, class NamedParameters = parameters::Default_named_parameters>
ILSA_quality_summary mesh_quality_ilsa(const TriangleMesh& tm, double threshold = 0.3,
                                       const NamedParameters& np = parameters::default_values()) {
  return mesh_quality_ilsa(faces(tm), tm, threshold, np);
}

} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif

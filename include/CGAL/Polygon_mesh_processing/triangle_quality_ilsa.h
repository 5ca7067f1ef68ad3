// Copyright (c) 2026 The Polygon_mesh_processing_ILSA authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Triangle shape measures: the aspect ratio q (the paper's quality measure,
// which the smoother's safety check and stop use), radius ratio, mean ratio
// and smallest angle. Light on purpose: the smoother includes this header,
// not the mesh summaries of mesh_quality_ilsa.h (Hausdorff sampling, AABB
// trees, Surface_mesh copies), which include it.

#ifndef CGAL_POLYGON_MESH_PROCESSING_TRIANGLE_QUALITY_ILSA_H
#define CGAL_POLYGON_MESH_PROCESSING_TRIANGLE_QUALITY_ILSA_H

#include <CGAL/config.h>
#include <CGAL/number_type_config.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace CGAL {
namespace Polygon_mesh_processing {

namespace internal {
namespace ILSA {

// Edge lengths, twice the area and (if asked for: it costs three atan2) the
// smallest angle of a triangle, in double.
struct Triangle_shape {
  std::array<double, 3> length; // opposite to vertex 0, 1, 2
  double double_area;
  double smallest_angle_degrees;
};

template <class P> std::array<std::array<double, 3>, 3> triangle_coordinates(const P& p0, const P& p1, const P& p2) {
  return {{{CGAL::to_double(p0.x()), CGAL::to_double(p0.y()), CGAL::to_double(p0.z())},
           {CGAL::to_double(p1.x()), CGAL::to_double(p1.y()), CGAL::to_double(p1.z())},
           {CGAL::to_double(p2.x()), CGAL::to_double(p2.y()), CGAL::to_double(p2.z())}}};
}
inline std::array<double, 3> difference(const std::array<double, 3>& a, const std::array<double, 3>& b) {
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}
inline std::array<double, 3> cross_product(const std::array<double, 3>& a, const std::array<double, 3>& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
inline double dot_product(const std::array<double, 3>& a, const std::array<double, 3>& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

// Edge lengths and twice the area of the triangle with coordinates `v`.
inline Triangle_shape triangle_shape_of(const std::array<std::array<double, 3>, 3>& v) {
  Triangle_shape s;
  const auto n = cross_product(difference(v[1], v[0]), difference(v[2], v[0]));
  s.double_area = std::sqrt(dot_product(n, n));
  s.smallest_angle_degrees = 180.;
  for (int i = 0; i < 3; ++i) {
    const auto c = difference(v[(i + 2) % 3], v[(i + 1) % 3]);
    s.length[i] = std::sqrt(dot_product(c, c));
  }
  return s;
}

// The same for three points.
template <class P> Triangle_shape triangle_shape(const P& p0, const P& p1, const P& p2) {
  return triangle_shape_of(triangle_coordinates(p0, p1, p2));
}

// The same and the smallest angle (three atan2).
template <class P> Triangle_shape triangle_shape_with_angle(const P& p0, const P& p1, const P& p2) {
  const auto v = triangle_coordinates(p0, p1, p2);
  Triangle_shape s = triangle_shape_of(v);
  for (int i = 0; i < 3; ++i) {
    const auto a = difference(v[(i + 1) % 3], v[i]), b = difference(v[(i + 2) % 3], v[i]);
    const auto axb = cross_product(a, b);
    const double angle = std::atan2(std::sqrt(dot_product(axb, axb)), dot_product(a, b)) * 180. / CGAL_PI;
    s.smallest_angle_degrees = (std::min)(s.smallest_angle_degrees, angle);
  }
  return s;
}

// Aspect ratio q = 2√3·r_in / l_max from twice the area and the edge lengths:
// r_in = 2A / perimeter, so q = 2√3 · (2A / perimeter) / l_max.
inline double aspect_ratio_of_shape(double double_area, const std::array<double, 3>& length) {
  const double perimeter = length[0] + length[1] + length[2];
  const double longest = (std::max)({length[0], length[1], length[2]});
  return longest > 0 ? 2. * std::sqrt(3.) * double_area / (perimeter * longest) : 0.;
}

} // namespace ILSA
} // namespace internal

/// \ingroup PkgPMPILSARef
/// Aspect ratio `q = 2√3·r_in / l_max` of a triangle (inradius over longest
/// edge): 1 for an equilateral triangle, 0 for a degenerate one. This is the
/// paper's quality measure and the package's primary one. It is not CGAL's
/// `face_aspect_ratio()` (longest edge over smallest altitude: about 1.155 for
/// an equilateral triangle, larger is worse).
/// `P` is any point type with `x()`, `y()`, `z()`.
template <class P> double triangle_quality_ilsa(const P& p0, const P& p1, const P& p2) {
  const auto s = internal::ILSA::triangle_shape(p0, p1, p2);
  return internal::ILSA::aspect_ratio_of_shape(s.double_area, s.length);
}

/// \ingroup PkgPMPILSARef
/// Radius ratio `2·r_in / r_circ` of a triangle: 1 equilateral, 0 degenerate.
template <class P> double triangle_radius_ratio_ilsa(const P& p0, const P& p1, const P& p2) {
  const auto s = internal::ILSA::triangle_shape(p0, p1, p2);
  const double perimeter = s.length[0] + s.length[1] + s.length[2];
  const double product = s.length[0] * s.length[1] * s.length[2];
  // r_in = 2A / perimeter and r_circ = abc / (4A): 2 r_in / r_circ = 16 A² / (perimeter · abc).
  return product > 0 ? 4. * s.double_area * s.double_area / (perimeter * product) : 0.;
}

/// \ingroup PkgPMPILSARef
/// Mean ratio `4√3·A / Σ l²` of a triangle: 1 equilateral, 0 degenerate.
template <class P> double triangle_mean_ratio_ilsa(const P& p0, const P& p1, const P& p2) {
  const auto s = internal::ILSA::triangle_shape(p0, p1, p2);
  const double sum = s.length[0] * s.length[0] + s.length[1] * s.length[1] + s.length[2] * s.length[2];
  return sum > 0 ? 2. * std::sqrt(3.) * s.double_area / sum : 0.;
}

/// \ingroup PkgPMPILSARef
/// Smallest angle of a triangle, in degrees (0 for a degenerate one).
template <class P> double triangle_minimum_angle_ilsa(const P& p0, const P& p1, const P& p2) {
  const auto s = internal::ILSA::triangle_shape_with_angle(p0, p1, p2);
  return s.double_area > 0 ? s.smallest_angle_degrees : 0.;
}

} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_POLYGON_MESH_PROCESSING_TRIANGLE_QUALITY_ILSA_H

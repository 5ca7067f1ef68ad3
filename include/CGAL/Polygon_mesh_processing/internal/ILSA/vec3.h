// Copyright (c) 2026 The Polygon_mesh_processing_ILSA authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The 3-vector of the flat mesh: coordinates, displacements, normals. A plain
// struct of three doubles with the few operations the core uses, so that a
// program calling the smoother compiles no expression templates for them
// (user manual, "Compiling the Core Once"). Each operation computes the
// coordinates one by one, and dot() and squaredNorm() sum from the first
// coordinate to the last: the rounding is fixed, whatever the compiler
// vectorises.

#ifndef CGAL_POLYGON_MESH_PROCESSING_INTERNAL_ILSA_VEC3_H
#define CGAL_POLYGON_MESH_PROCESSING_INTERNAL_ILSA_VEC3_H

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace ILSA {

/// A point or a vector of the flat mesh (coordinates, displacements, normals).
class Vec3 {
public:
  Vec3() = default;
  Vec3(double x, double y, double z) : c_{x, y, z} {}
  static Vec3 Zero() { return {0., 0., 0.}; }
  static Vec3 Constant(double a) { return {a, a, a}; }

  double operator[](std::size_t i) const { return c_[i]; }
  double& operator[](std::size_t i) { return c_[i]; }
  double operator()(std::size_t i) const { return c_[i]; }
  double& operator()(std::size_t i) { return c_[i]; }
  double x() const { return c_[0]; }
  double y() const { return c_[1]; }
  double z() const { return c_[2]; }

  double dot(const Vec3& b) const { return c_[0] * b.c_[0] + c_[1] * b.c_[1] + c_[2] * b.c_[2]; }
  double squaredNorm() const { return dot(*this); }
  double norm() const { return std::sqrt(squaredNorm()); }
  /// This vector divided by its norm, or itself if its norm is zero.
  Vec3 normalized() const {
    const double n = squaredNorm();
    return n > 0 ? *this / std::sqrt(n) : *this;
  }
  Vec3 cross(const Vec3& b) const {
    return {c_[1] * b.c_[2] - c_[2] * b.c_[1], c_[2] * b.c_[0] - c_[0] * b.c_[2], c_[0] * b.c_[1] - c_[1] * b.c_[0]};
  }
  Vec3 cwiseMin(const Vec3& b) const {
    return {(std::min)(c_[0], b.c_[0]), (std::min)(c_[1], b.c_[1]), (std::min)(c_[2], b.c_[2])};
  }
  Vec3 cwiseMax(const Vec3& b) const {
    return {(std::max)(c_[0], b.c_[0]), (std::max)(c_[1], b.c_[1]), (std::max)(c_[2], b.c_[2])};
  }
  /// Whether every coordinate is at most `precision` in absolute value.
  bool isZero(double precision) const {
    return std::abs(c_[0]) <= precision && std::abs(c_[1]) <= precision && std::abs(c_[2]) <= precision;
  }
  bool allFinite() const { return std::isfinite(c_[0]) && std::isfinite(c_[1]) && std::isfinite(c_[2]); }

  Vec3 operator-() const { return {-c_[0], -c_[1], -c_[2]}; }
  Vec3& operator+=(const Vec3& b) { return *this = *this + b; }
  Vec3& operator-=(const Vec3& b) { return *this = *this - b; }
  Vec3& operator*=(double s) { return *this = *this * s; }
  Vec3& operator/=(double s) { return *this = *this / s; }
  friend Vec3 operator+(const Vec3& a, const Vec3& b) {
    return {a.c_[0] + b.c_[0], a.c_[1] + b.c_[1], a.c_[2] + b.c_[2]};
  }
  friend Vec3 operator-(const Vec3& a, const Vec3& b) {
    return {a.c_[0] - b.c_[0], a.c_[1] - b.c_[1], a.c_[2] - b.c_[2]};
  }
  friend Vec3 operator*(const Vec3& a, double s) { return {a.c_[0] * s, a.c_[1] * s, a.c_[2] * s}; }
  friend Vec3 operator*(double s, const Vec3& a) { return {s * a.c_[0], s * a.c_[1], s * a.c_[2]}; }
  friend Vec3 operator/(const Vec3& a, double s) { return {a.c_[0] / s, a.c_[1] / s, a.c_[2] / s}; }
  friend bool operator==(const Vec3& a, const Vec3& b) {
    return a.c_[0] == b.c_[0] && a.c_[1] == b.c_[1] && a.c_[2] == b.c_[2];
  }
  friend bool operator!=(const Vec3& a, const Vec3& b) { return !(a == b); }

private:
  double c_[3];
};

} // namespace ILSA
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_POLYGON_MESH_PROCESSING_INTERNAL_ILSA_VEC3_H

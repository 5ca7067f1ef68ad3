// Copyright (c) 2026 The Polygon_mesh_processing_ILSA authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The two rules of the feature lines that the smoother and the fidelity
// summary (mesh_fidelity_ilsa()) must apply alike: when an edge is a feature
// edge, and at which points a feature edge is measured (user manual,
// "Crease fidelity").

#ifndef CGAL_POLYGON_MESH_PROCESSING_INTERNAL_ILSA_FEATURE_LINES_H
#define CGAL_POLYGON_MESH_PROCESSING_INTERNAL_ILSA_FEATURE_LINES_H

#include <cmath>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace ILSA {

/// The angle between the face normals, in radians, at which an edge becomes a
/// feature edge, from `ilsa_feature_angle` in degrees: π minus the paper's
/// dihedral angle θ_f = 180° − the feature angle.
inline double feature_normal_deviation(double feature_angle_degrees) {
  const double pi = 3.14159265358979323846;
  return pi - (180. - feature_angle_degrees) * pi / 180.;
}

/// An edge is a feature edge when the cosine of the angle between its two
/// unit face normals is below this.
inline double feature_cosine(double feature_angle_degrees) {
  return std::cos(feature_normal_deviation(feature_angle_degrees));
}

/// A feature edge is measured at the points k / crease_samples of the way
/// along it, k = 0 .. crease_samples.
inline constexpr int crease_samples = 8;

} // namespace ILSA
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif

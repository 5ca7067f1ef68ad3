// Copyright (c) 2026 The Polygon_mesh_processing_ILSA authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The two rules of the feature lines that the smoother and the fidelity
// summary (mesh_fidelity_ilsa()) must apply alike: when an edge is a feature
// edge, and at which points a feature edge is measured (user manual,
// "Crease fidelity").

#ifndef CGAL_POLYGON_MESH_PROCESSING_INTERNAL_ILSA_FEATURE_LINES_H
#define CGAL_POLYGON_MESH_PROCESSING_INTERNAL_ILSA_FEATURE_LINES_H

#include <algorithm>
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

/// The angle, in radians, between two unit face normals whose dot product is `cosine`.
inline double normal_angle(double cosine) {
  return std::acos((std::max)(-1., (std::min)(1., cosine)));
}

/// The crease contrast (user manual, "Crease contrast"): whether a feature
/// edge whose face normals make the angle `angle` stays a crease line with the
/// contrast `contrast`, `flatter0` and `flatter1` being the angles of the
/// flatter of the two other edges of each of its faces. On a crease of a CAD
/// model at least one of these lies in a smooth part of the surface; on a
/// coarse curved surface they bend as much as the edge. The classification
/// (sharp and feature edges, hence the crease bound of the safety check) and
/// mesh_fidelity_ilsa() (the crease deviation) both decide by this test.
inline bool keeps_crease_contrast(double angle, double flatter0, double flatter1, double contrast) {
  return !(angle < contrast * (std::max)(flatter0, flatter1));
}

/// A feature edge is measured at the points k / crease_samples of the way
/// along it, k = 0 .. crease_samples.
inline constexpr int crease_samples = 8;

} // namespace ILSA
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif

// Copyright (c) 2026 The Polygon_mesh_processing_ILSA authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_POLYGON_MESH_PROCESSING_INTERNAL_ILSA_LEAST_SQUARES_H
#define CGAL_POLYGON_MESH_PROCESSING_INTERNAL_ILSA_LEAST_SQUARES_H

#include <CGAL/Polygon_mesh_processing/internal/ILSA/flat_mesh.h>

#include <Eigen/SVD>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace ILSA {

/// Minimum-norm least-squares solution of the symmetric 3x3 system `H x = r` by
/// SVD (the discrete normal of paper §3 and the penalty system of Algo. 3). Singular values below `relative_threshold`
/// times the largest one count as zero, so a rank-deficient `H` (a flat star, a penalty system without area term) still
/// has a well-defined, bounded solution.
inline Vec3 solve_by_svd(const Eigen::Matrix3d& H, const Vec3& r, double relative_threshold) {
  Eigen::JacobiSVD<Eigen::Matrix3d> svd(H, Eigen::ComputeFullU | Eigen::ComputeFullV);
  svd.setThreshold(relative_threshold);
  const Eigen::Vector3d x = svd.solve(Eigen::Vector3d(r[0], r[1], r[2]));
  return Vec3(x[0], x[1], x[2]);
}

} // namespace ILSA
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_POLYGON_MESH_PROCESSING_INTERNAL_ILSA_LEAST_SQUARES_H

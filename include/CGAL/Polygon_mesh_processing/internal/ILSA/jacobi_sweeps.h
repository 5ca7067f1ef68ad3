// Copyright (c) 2026 The Polygon_mesh_processing_ILSA authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The sweep loop of Algo. 2 and Algo. 3 (user manual, "Parallel Runs"): Jacobi
// sweeps, every vertex reading the previous sweep's values and writing into a
// second buffer, so the result does not depend on the vertex order.

#ifndef CGAL_POLYGON_MESH_PROCESSING_INTERNAL_ILSA_JACOBI_SWEEPS_H
#define CGAL_POLYGON_MESH_PROCESSING_INTERNAL_ILSA_JACOBI_SWEEPS_H

#include <CGAL/Polygon_mesh_processing/internal/ILSA/flat_mesh.h>
#include <CGAL/Polygon_mesh_processing/internal/ILSA/parallel_loops.h>

#include <utility>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace ILSA {

/// Runs at most `sweeps` sweeps of `update(v)` (the new value of `d[v]`, read
/// from `d`) over `vertices`, stopping once no value changes by more than
/// `tolerance`. `next` is the second buffer. `prepare()` runs before each
/// sweep, with `d` as the sweep reads it. Returns the number of sweeps run.
template <class ConcurrencyTag, class Update, class Prepare>
std::size_t run_jacobi_sweeps(const std::vector<Index>& vertices, std::size_t sweeps, double tolerance,
                              std::vector<Vec3>& d, std::vector<Vec3>& next, const Update& update,
                              const Prepare& prepare) {
  next = d; // entries the sweeps do not write stay equal in both buffers
  std::size_t sweep = 0;
  while (sweep < sweeps) {
    ++sweep;
    prepare();
    const double largest_change = parallel_max<ConcurrencyTag>(vertices.size(), [&](std::size_t i) {
      const std::size_t v = vertices[i];
      next[v] = update(v);
      return (next[v] - d[v]).norm();
    });
    std::swap(d, next);
    if (largest_change <= tolerance) break;
  }
  return sweep;
}

template <class ConcurrencyTag, class Update>
std::size_t run_jacobi_sweeps(const std::vector<Index>& vertices, std::size_t sweeps, double tolerance,
                              std::vector<Vec3>& d, std::vector<Vec3>& next, const Update& update) {
  return run_jacobi_sweeps<ConcurrencyTag>(vertices, sweeps, tolerance, d, next, update, [] {});
}

} // namespace ILSA
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_POLYGON_MESH_PROCESSING_INTERNAL_ILSA_JACOBI_SWEEPS_H

// Copyright (c) 2026 The Polygon_mesh_processing_ILSA authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Stage 2 of ILSA (paper's Algo. 2): the Laplacian displacement of
// every adjustable vertex, diffused over its neighbours with inverse-distance
// weights. Jacobi sweeps: each sweep reads the previous one's values only.

#ifndef CGAL_POLYGON_MESH_PROCESSING_INTERNAL_ILSA_ILSA_DISPLACEMENT_H
#define CGAL_POLYGON_MESH_PROCESSING_INTERNAL_ILSA_ILSA_DISPLACEMENT_H

#include <CGAL/Polygon_mesh_processing/internal/ILSA/core.h>
#include <CGAL/Polygon_mesh_processing/internal/ILSA/flat_mesh.h>
#include <CGAL/Polygon_mesh_processing/internal/ILSA/jacobi_sweeps.h>

#include <algorithm>
#include <utility>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace ILSA {

/// Buffers reused across iterations, so the sweeps do not allocate.
struct ILSA_workspace {
  std::vector<double> weights; // α_ij, per edge (the weight of an edge is the same from both ends)
};

/// Algo. 2: fills `d` (one entry per vertex, zero for fixed ones) and returns
/// the number of sweeps run. `tolerance` stops the sweeps once no displacement
/// changes by more than it. `buffer`: the sweeps' second buffer, overwritten
/// (the caller lends any per-vertex array it does not need meanwhile).
template <class ConcurrencyTag>
std::size_t compute_ilsa_displacement(const std::vector<Vec3>& pos, const ILSA_neighborhoods& nb, double relax1,
                                      std::size_t sweeps, double tolerance, std::vector<Vec3>& d, ILSA_workspace& ws,
                                      std::vector<Vec3>& buffer) {
  const Flat_mesh& m = *nb.mesh;
  d.assign(pos.size(), Vec3::Zero());

  // Inverse-distance weights α_ij = 1 / |v − v_j| (|v − v_j| and |v_j − v| are
  // the same number: the differences are exact negations of each other).
  const double shortest = 1e-12; // a zero-length edge must not give an infinite weight
  ws.weights.resize(m.edges.size());
  parallel_for<ConcurrencyTag>(m.edges.size(), [&](std::size_t e) {
    ws.weights[e] = 1. / (std::max)((pos[m.edges[e][0]] - pos[m.edges[e][1]]).norm(), shortest);
  });

  // Laplacian coordinate.
  parallel_for<ConcurrencyTag>(nb.adjustable.size(), [&](std::size_t i) {
    const std::size_t v = nb.adjustable[i];
    Vec3 centroid = Vec3::Zero();
    std::size_t count = 0;
    nb.for_each_neighbor(v, [&](std::size_t w, std::size_t) {
      centroid += pos[w];
      ++count;
    });
    d[v] = centroid / double(count) - pos[v];
  });

  return run_jacobi_sweeps<ConcurrencyTag>(nb.adjustable, sweeps, tolerance, d, buffer, [&](std::size_t v) {
    Vec3 vec = Vec3::Zero();
    double S = 0;
    nb.for_each_neighbor(v, [&](std::size_t w, std::size_t e) {
      vec += ws.weights[e] * d[w];
      S += ws.weights[e];
    });
    return Vec3((1. - relax1) * d[v] + (relax1 / S) * vec);
  });
}

} // namespace ILSA
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_POLYGON_MESH_PROCESSING_INTERNAL_ILSA_ILSA_DISPLACEMENT_H

// Copyright (c) 2026 The Polygon_mesh_processing_ILSA authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Stage 2 of ILSA (paper's Algo. 2): the Laplacian displacement of
// every adjustable vertex, diffused over its neighbours with inverse-distance
// weights. Jacobi sweeps: each sweep reads the previous one's values only.

#ifndef CGAL_POLYGON_MESH_PROCESSING_INTERNAL_ILSA_ILSA_DISPLACEMENT_H
#define CGAL_POLYGON_MESH_PROCESSING_INTERNAL_ILSA_ILSA_DISPLACEMENT_H

#include <CGAL/Polygon_mesh_processing/internal/ILSA/flat_mesh.h>
#include <CGAL/Polygon_mesh_processing/internal/ILSA/jacobi_sweeps.h>
#include <CGAL/Polygon_mesh_processing/internal/ILSA/vertex_classification.h>

#include <algorithm>
#include <utility>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace ILSA {

/// Which vertices move and which neighbours drive them (paper's Algo. 2): all one-ring
/// vertices for a smooth node, only its two attached-sharp nodes for a ridge node.
struct Ilsa_neighborhoods {
  std::vector<std::size_t> adjustable; // smooth and ridge vertices allowed to move
  std::vector<std::size_t> smooth;     // the smooth ones among them (Algo. 3)
  Adjacency neighbors;                 // per vertex; empty for a fixed vertex
};

/// `movable[v]` is false for the vertices outside the user's range.
inline Ilsa_neighborhoods make_ilsa_neighborhoods(const Flat_mesh& m, const Vertex_classification& c,
                                                  const std::vector<unsigned char>& movable) {
  Ilsa_neighborhoods nb;
  for (std::size_t v = 0; v < m.number_of_vertices(); ++v) {
    if (c.is_fixed(v) || !movable[v]) continue;
    nb.adjustable.push_back(v);
    if (c.type[v] != ILSA_vertex_type::Ridge) nb.smooth.push_back(v);
  }
  nb.neighbors.assign(m.number_of_vertices(), [&](auto emit) {
    for (std::size_t v : nb.adjustable) {
      if (c.type[v] == ILSA_vertex_type::Ridge) {
        emit(v, c.attached_sharp[v][0]);
        emit(v, c.attached_sharp[v][1]);
      } else {
        for (const Index* w = m.vertex_neighbors.first(v); w != m.vertex_neighbors.last(v); ++w) emit(v, *w);
      }
    }
  });
  return nb;
}

/// Buffers reused across iterations, so the sweeps do not allocate.
struct Ilsa_workspace {
  std::vector<Vec3> next;      // Jacobi target buffer (shared with Algo. 3)
  std::vector<double> weights; // α_ij, aligned with Ilsa_neighborhoods::neighbors.items
};

/// Algo. 2: fills `d` (one entry per vertex, zero for fixed ones) and returns
/// the number of sweeps run. `tolerance` stops the sweeps once no displacement
/// changes by more than it.
template <class ConcurrencyTag>
std::size_t compute_ilsa_displacement(const std::vector<Vec3>& pos, const Ilsa_neighborhoods& nb, double relax1,
                                      std::size_t sweeps, double tolerance, std::vector<Vec3>& d, Ilsa_workspace& ws) {
  const Adjacency& N = nb.neighbors;
  d.assign(pos.size(), Vec3::Zero());
  ws.weights.resize(N.items.size());

  // Laplacian coordinate and inverse-distance weights α_ij = 1 / |v − v_j|.
  const double shortest = 1e-12; // a zero-length edge must not give an infinite weight
  parallel_for<ConcurrencyTag>(nb.adjustable.size(), [&](std::size_t i) {
    const std::size_t v = nb.adjustable[i];
    Vec3 centroid = Vec3::Zero();
    for (std::size_t k = N.begin[v]; k < N.begin[v + 1]; ++k) {
      const Vec3& w = pos[N.items[k]];
      centroid += w;
      ws.weights[k] = 1. / (std::max)((pos[v] - w).norm(), shortest);
    }
    d[v] = centroid / double(N.size(v)) - pos[v];
  });

  return run_jacobi_sweeps<ConcurrencyTag>(nb.adjustable, sweeps, tolerance, d, ws.next, [&](std::size_t v) {
    Vec3 vec = Vec3::Zero();
    double S = 0;
    for (std::size_t k = N.begin[v]; k < N.begin[v + 1]; ++k) {
      vec += ws.weights[k] * d[N.items[k]];
      S += ws.weights[k];
    }
    return Vec3((1. - relax1) * d[v] + (relax1 / S) * vec);
  });
}

} // namespace ILSA
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif

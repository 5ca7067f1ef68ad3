// Copyright (c) 2026 The Polygon_mesh_processing_ILSA authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The sweep loops of Algo. 2 and Algo. 3 (user manual, "Parallel Runs" and
// "Sweep Order"): Jacobi sweeps, every vertex reading the previous sweep's
// values and writing into a second buffer, so the result does not depend on the
// vertex order; and, for Algo. 3 on request, multicolour Gauss-Seidel sweeps,
// one colour after the other, each reading the values the colours before it
// wrote in the same sweep (no two vertices of a colour are neighbours, so the
// result does not depend on the order within a colour either).

#ifndef CGAL_POLYGON_MESH_PROCESSING_INTERNAL_ILSA_JACOBI_SWEEPS_H
#define CGAL_POLYGON_MESH_PROCESSING_INTERNAL_ILSA_JACOBI_SWEEPS_H

#include <CGAL/Polygon_mesh_processing/internal/ILSA/flat_mesh.h>
#include <CGAL/Polygon_mesh_processing/internal/ILSA/parallel_loops.h>

#include <algorithm>
#include <limits>
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

/// A partition of vertices into colours, no two neighbours in the same colour:
/// colour `c` is `vertices[begin[c]]` to `vertices[begin[c + 1] - 1]`.
struct Vertex_colours {
  std::vector<Index> vertices;
  std::vector<std::size_t> begin{0};
  std::size_t number_of_colours() const { return begin.size() - 1; }
};

/// Greedy colouring of `vertices` (in their order, each taking the smallest
/// colour no neighbour in `m` has taken), each colour in the order of `vertices`.
inline Vertex_colours colour_vertices(const Flat_mesh& m, const std::vector<Index>& vertices) {
  constexpr Index none = std::numeric_limits<Index>::max();
  std::vector<Index> colour(m.number_of_vertices(), none);
  std::vector<std::size_t> count;
  std::vector<unsigned char> taken;
  for (Index v : vertices) {
    taken.assign(count.size() + 1, 0);
    for (const Index* w = m.vertex_neighbors.first(v); w != m.vertex_neighbors.last(v); ++w)
      if (colour[*w] != none) taken[colour[*w]] = 1;
    const Index c = Index(std::find(taken.begin(), taken.end(), 0) - taken.begin());
    colour[v] = c;
    if (c == count.size()) count.push_back(0);
    ++count[c];
  }
  Vertex_colours colours;
  for (std::size_t n : count) colours.begin.push_back(colours.begin.back() + n);
  colours.vertices.resize(vertices.size());
  std::vector<std::size_t> at(colours.begin.begin(), colours.begin.end() - 1);
  for (Index v : vertices) colours.vertices[at[colour[v]]++] = v;
  return colours;
}

/// Runs at most `sweeps` multicolour Gauss-Seidel sweeps of `update(v)` (the
/// new value of `d[v]`, read from `d`): each sweep updates `d` in place, colour
/// after colour, and calls `written(v)` after `d[v]` is written; it stops once
/// no value changes by more than `tolerance`. Returns the number of sweeps run.
template <class ConcurrencyTag, class Update, class Written>
std::size_t run_multicolour_sweeps(const Vertex_colours& colours, std::size_t sweeps, double tolerance,
                                   std::vector<Vec3>& d, const Update& update, const Written& written) {
  std::size_t sweep = 0;
  while (sweep < sweeps) {
    ++sweep;
    double largest_change = 0;
    for (std::size_t c = 0; c < colours.number_of_colours(); ++c) {
      const Index* first = colours.vertices.data() + colours.begin[c];
      const double change = parallel_max<ConcurrencyTag>(colours.begin[c + 1] - colours.begin[c], [&](std::size_t i) {
        const std::size_t v = first[i];
        const Vec3 value = update(v);
        const double moved = (value - d[v]).norm();
        d[v] = value;
        written(v);
        return moved;
      });
      largest_change = (std::max)(largest_change, change);
    }
    if (largest_change <= tolerance) break;
  }
  return sweep;
}

} // namespace ILSA
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_POLYGON_MESH_PROCESSING_INTERNAL_ILSA_JACOBI_SWEEPS_H

// Copyright (c) 2026 The Polygon_mesh_processing_ILSA authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The rules of the feature lines: when an edge is a feature edge (feature
// angle, crease contrast, open crease lines), and at which points the
// fidelity summary measures one. The classification applies them; the
// fidelity summary (mesh_fidelity_ilsa()) takes its feature edges from it.

#ifndef CGAL_POLYGON_MESH_PROCESSING_INTERNAL_ILSA_FEATURE_LINES_H
#define CGAL_POLYGON_MESH_PROCESSING_INTERNAL_ILSA_FEATURE_LINES_H

#include <CGAL/Polygon_mesh_processing/internal/ILSA/union_find.h>

#include <CGAL/number_type_config.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace ILSA {

/// The angle between the face normals, in radians, at which an edge becomes a
/// feature edge, from `ilsa_feature_angle` in degrees: π minus the paper's
/// dihedral angle θ_f = 180° − the feature angle.
inline double feature_normal_deviation(double feature_angle_degrees) {
  return CGAL_PI - (180. - feature_angle_degrees) * CGAL_PI / 180.;
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

/// The crease contrast (user manual, "Crease Contrast"): whether a feature
/// edge whose face normals make the angle `angle` stays a crease line with the
/// contrast `contrast`, `flatter0` and `flatter1` being the angles of the
/// flatter of the two other edges of each of its faces. On a crease of a CAD
/// model at least one of these lies in a smooth part of the surface; on a
/// coarse curved surface they bend as much as the edge.
inline bool keeps_crease_contrast(double angle, double flatter0, double flatter1, double contrast) {
  return !(angle < contrast * (std::max)(flatter0, flatter1));
}

/// The connected sets (edges sharing a vertex) of the edges whose flag in
/// `lines` is set: per edge its set (npos, (std::size_t)-1, for an unflagged
/// edge), per set its number of edges and whether it has a loose end, a
/// vertex with one of its edges only that is not on the border
/// (`on_border(v)`). A set is named by one of its vertices; `ends(e)` gives the
/// two vertices of edge `e`, numbered below `number_of_vertices`.
struct Line_sets {
  std::vector<std::size_t> set_of_edge;
  std::vector<std::size_t> size;    // per set
  std::vector<unsigned char> loose; // per set
};
template <class Ends, class OnBorder>
Line_sets line_sets(std::size_t number_of_vertices, const Ends& ends, const OnBorder& on_border,
                    const std::vector<unsigned char>& lines) {
  Index_union_find<> connected(number_of_vertices);
  std::vector<std::size_t> degree(number_of_vertices, 0);
  for (std::size_t e = 0; e < lines.size(); ++e)
    if (lines[e]) {
      const auto ab = ends(e);
      connected.unite(std::size_t(ab[0]), std::size_t(ab[1]));
      ++degree[std::size_t(ab[0])], ++degree[std::size_t(ab[1])];
    }
  Line_sets sets{std::vector<std::size_t>(lines.size(), std::size_t(-1)),
                 std::vector<std::size_t>(number_of_vertices, 0), std::vector<unsigned char>(number_of_vertices, 0)};
  for (std::size_t e = 0; e < lines.size(); ++e)
    if (lines[e]) ++sets.size[sets.set_of_edge[e] = connected.find(std::size_t(ends(e)[0]))];
  for (std::size_t v = 0; v < number_of_vertices; ++v)
    if (degree[v] == 1 && !on_border(v)) sets.loose[connected.find(v)] = 1;
  return sets;
}

/// The open-crease rule (user manual, "Open Crease Lines"): among the edges
/// whose flag in `lines` is set, a connected set of fewer than
/// `minimum_edges` edges that has a loose end (line_sets()) is curvature, not
/// a crease line: the flags of its edges are cleared. A closed set (a loop,
/// the edges of a polyhedron), a set running from border to border and a
/// longer one stay. Along a crease of a CAD model the feature edges run from
/// corner to corner, around a loop or to the border; on a coarse organic mesh
/// they come in short pieces that fade out on the surface.
inline bool is_short_open_line(const Line_sets& sets, std::size_t set, std::size_t minimum_edges) {
  return sets.loose[set] && sets.size[set] < minimum_edges;
}
template <class Ends, class OnBorder>
void drop_short_open_lines(std::size_t number_of_vertices, const Ends& ends, const OnBorder& on_border,
                           std::vector<unsigned char>& lines, std::size_t minimum_edges) {
  if (minimum_edges < 2) return; // no set has fewer than one edge
  const Line_sets sets = line_sets(number_of_vertices, ends, on_border, lines);
  for (std::size_t e = 0; e < lines.size(); ++e)
    if (lines[e] && is_short_open_line(sets, sets.set_of_edge[e], minimum_edges)) lines[e] = 0;
}

/// A feature edge is measured at the points k / crease_samples of the way
/// along it, k = 0 .. crease_samples.
inline constexpr int crease_samples = 8;

} // namespace ILSA
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_POLYGON_MESH_PROCESSING_INTERNAL_ILSA_FEATURE_LINES_H

// Copyright (c) 2026 The Polygon_mesh_processing_ILSA authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The first guarantee of the safety check (user manual, "Guarantees"): no
// triangle reverses its orientation with respect to the input surface, and
// none collapses. A face collapsed in the input may open again, but only the
// right way round.

#ifndef CGAL_POLYGON_MESH_PROCESSING_INTERNAL_ILSA_ORIENTATION_TEST_H
#define CGAL_POLYGON_MESH_PROCESSING_INTERNAL_ILSA_ORIENTATION_TEST_H

#include <CGAL/Polygon_mesh_processing/internal/ILSA/flat_mesh.h>
#include <CGAL/Polygon_mesh_processing/internal/ILSA/star_quality.h>

#include <algorithm>
#include <array>
#include <initializer_list>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace ILSA {

/// The orientation and collapse test of the faces of `original`.
class Orientation_test {
public:
  /// Relative area below which a triangle counts as collapsed: twice its area
  /// under this fraction of its longest edge squared. It protects the
  /// orientation test, which needs a normal to compare: a move may not make a
  /// face this thin.
  static constexpr double collapse_tolerance = 1e-6;

  /// `original` must outlive the test: it keeps a reference. `incidences`
  /// (those of `original`) is read here only.
  Orientation_test(const Flat_mesh& original, const Set_up_incidences& incidences) : m_(original) {
    // Reference orientation of each face (see reference()): for a face that is
    // degenerate in the input, the sum of its neighbours' normals, stored.
    for (std::size_t f = 0; f < m_.number_of_faces(); ++f)
      if (unit_normal(m_.points, m_.faces[f]).isZero(0)) degenerate_faces_.push_back(Index(f));
    degenerate_references_.assign(degenerate_faces_.size(), Vec3::Zero());
    if (!degenerate_faces_.empty())
      for (const auto& fs : incidences.edge_faces)
        if (fs[0] != npos && fs[1] != npos)
          for (int k = 0; k < 2; ++k) {
            const auto found = std::lower_bound(degenerate_faces_.begin(), degenerate_faces_.end(), fs[k]);
            if (found != degenerate_faces_.end() && *found == fs[k])
              degenerate_references_[std::size_t(found - degenerate_faces_.begin())] +=
                  unit_normal(m_.points, m_.faces[fs[1 - k]]);
          }
  }

  /// Orientation of face `f` at positions `pos` against the original surface.
  bool flipped(const std::vector<Vec3>& pos, std::size_t f) const {
    return area_vector(pos, m_.faces[f]).dot(reference(f)) <= 0;
  }

  /// Reference orientation of face `f`: its input normal, or for a face that
  /// is degenerate in the input the sum of its neighbours' normals. A face
  /// folded in the input keeps its orientation: unfolding it would be a flip
  /// with respect to the input, which the package never makes. Computed when
  /// needed (24 bytes per face less to store; a few dozen operations per test).
  Vec3 reference(std::size_t f) const {
    const Vec3 own = unit_normal(m_.points, m_.faces[f]);
    if (!own.isZero(0)) return own;
    const auto found = std::lower_bound(degenerate_faces_.begin(), degenerate_faces_.end(), Index(f));
    return degenerate_references_[std::size_t(found - degenerate_faces_.begin())];
  }

  bool collapsed(const std::vector<Vec3>& pos, std::size_t f) const {
    const auto& t = m_.faces[f];
    const double longest = (std::max)({(pos[t[1]] - pos[t[0]]).squaredNorm(), (pos[t[2]] - pos[t[1]]).squaredNorm(),
                                       (pos[t[0]] - pos[t[2]]).squaredNorm()});
    return is_collapsed(area_vector(pos, t).norm(), longest);
  }

  /// A face offends if it is collapsed now and was not before, or flipped and
  /// not collapsed now and was not so before. A face collapsed before (in the
  /// input: a needle, or two vertices at one point) may open again, but only
  /// with its reference orientation: opening it the other way round is a flip.
  /// (A face flipped and not collapsed before cannot occur: the input has none,
  /// and no move makes one.)
  /// The test at `next` shares its edge vectors with the face's aspect ratio
  /// there, set in `quality` (collapsed(), flipped() and aspect_ratio(): the
  /// same operations, the same values).
  bool offends(const std::vector<Vec3>& previous, const std::vector<Vec3>& next, std::size_t f, double& quality) const {
    const auto& t = m_.faces[f];
    const Vec3 &a = next[t[0]], &b = next[t[1]], &c = next[t[2]];
    const Vec3 ab = b - a, area = ab.cross(c - a);
    const std::array<double, 3> squared_length{(c - b).squaredNorm(), (a - c).squaredNorm(), ab.squaredNorm()};
    const double double_area = area.norm();
    quality = aspect_ratio_from(double_area, squared_length);
    const double longest = (std::max)({squared_length[0], squared_length[1], squared_length[2]});
    if (is_collapsed(double_area, longest)) return !collapsed(previous, f);
    return area.dot(reference(f)) <= 0 && (collapsed(previous, f) || !flipped(previous, f));
  }

private:
  // The collapse criterion, from twice the area and the longest edge squared.
  static bool is_collapsed(double double_area, double longest_squared) {
    return double_area <= collapse_tolerance * longest_squared || longest_squared == 0;
  }

  const Flat_mesh& m_;
  std::vector<Index> degenerate_faces_;     // faces degenerate in the input, in increasing order
  std::vector<Vec3> degenerate_references_; // their reference orientations
};

} // namespace ILSA
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_POLYGON_MESH_PROCESSING_INTERNAL_ILSA_ORIENTATION_TEST_H

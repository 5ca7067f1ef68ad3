// Copyright (c) 2026 The Polygon_mesh_processing_ILSA authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The disjoint sets of the package's index ranges: the smooth patches of the
// projection (faces joined across edges that are not sharp), the crease
// polylines of the classification (sharp edges chained through ridge
// vertices) and the connected sets of feature edges of the open-crease rule.
// The elements are 0 .. n - 1 and a set is named by its representative, an
// element of it, so that the names are indices too.

#ifndef CGAL_POLYGON_MESH_PROCESSING_INTERNAL_ILSA_UNION_FIND_H
#define CGAL_POLYGON_MESH_PROCESSING_INTERNAL_ILSA_UNION_FIND_H

#include <cstddef>
#include <numeric>
#include <utility>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace ILSA {

/// Disjoint sets over the indices 0 .. n - 1 (of type `I`), each element
/// first alone. (CGAL::Union_find stores handles; these sets are arrays of
/// indices.) `unite(a, b)` makes the representative of `b`'s set that of the
/// union, so the representatives depend only on the order of the calls.
template <class I = std::size_t> class Index_union_find {
public:
  explicit Index_union_find(std::size_t n) : parent_(n) { std::iota(parent_.begin(), parent_.end(), I(0)); }

  /// The representative of the set of `i` (with path halving).
  std::size_t find(std::size_t i) {
    while (std::size_t(parent_[i]) != i) i = std::size_t(parent_[i] = parent_[std::size_t(parent_[i])]);
    return i;
  }

  /// Joins the sets of `a` and `b`; the representative of `b`'s set names the union.
  void unite(std::size_t a, std::size_t b) {
    const std::size_t ra = find(a);
    parent_[ra] = I(find(b));
  }

  /// Per element, the representative of its set; the sets are left behind
  /// (the array becomes the result).
  std::vector<I> representatives() && {
    for (std::size_t i = 0; i < parent_.size(); ++i) parent_[i] = I(find(i));
    return std::move(parent_);
  }

private:
  std::vector<I> parent_;
};

} // namespace ILSA
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_POLYGON_MESH_PROCESSING_INTERNAL_ILSA_UNION_FIND_H

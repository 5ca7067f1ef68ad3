// Copyright (c) 2026 The Polygon_mesh_processing_ILSA authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The AABB tree types of the package, for every supported CGAL (user manual,
// "Supported CGAL Versions and Compilers"). CGAL 6.0 renamed the 3D traits and primitives
// `AABB_traits_3`, `AABB_segment_primitive_3` and `AABB_triangle_primitive_3`;
// the old names warn in every translation unit there and are gone when CGAL's
// old code is switched off. This header is the only place that
// chooses between the two spellings: the package, its programs and its tests
// name the aliases below.

#ifndef CGAL_POLYGON_MESH_PROCESSING_INTERNAL_ILSA_AABB_TREE_H
#define CGAL_POLYGON_MESH_PROCESSING_INTERNAL_ILSA_AABB_TREE_H

#include <CGAL/version.h>

#include <CGAL/AABB_tree.h>

#if CGAL_VERSION_NR >= 1060000000
#include <CGAL/AABB_segment_primitive_3.h>
#include <CGAL/AABB_traits_3.h>
#include <CGAL/AABB_triangle_primitive_3.h>
#else
#include <CGAL/AABB_segment_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_triangle_primitive.h>
#endif

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace ILSA {

#if CGAL_VERSION_NR >= 1060000000
using CGAL::AABB_segment_primitive_3;
using CGAL::AABB_traits_3;
using CGAL::AABB_triangle_primitive_3;
#else
template <class K, class Primitive> using AABB_traits_3 = CGAL::AABB_traits<K, Primitive>;
template <class K, class Iterator> using AABB_segment_primitive_3 = CGAL::AABB_segment_primitive<K, Iterator>;
template <class K, class Iterator> using AABB_triangle_primitive_3 = CGAL::AABB_triangle_primitive<K, Iterator>;
#endif

/// An AABB tree over `Primitive`s with the kernel `K`.
template <class K, class Primitive> using AABB_tree_3 = CGAL::AABB_tree<AABB_traits_3<K, Primitive>>;

} // namespace ILSA
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_POLYGON_MESH_PROCESSING_INTERNAL_ILSA_AABB_TREE_H

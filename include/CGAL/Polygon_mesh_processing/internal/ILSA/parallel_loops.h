// Copyright (c) 2026 The Polygon_mesh_processing_ILSA authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The loops every per-vertex and per-face stage runs through. With
// `CGAL::Parallel_tag` they run with TBB, with `CGAL::Sequential_tag` as a
// plain loop (no std::function on the hot path). Each call of `f(i)` writes
// only the slots of element `i` and reads values no other call of the same
// loop writes (Jacobi), and reductions are maxima, which do not depend on
// the order they are taken in: the result is bit-identical whatever the
// number of threads (user manual, "Parallel runs").

#ifndef CGAL_POLYGON_MESH_PROCESSING_INTERNAL_ILSA_PARALLEL_LOOPS_H
#define CGAL_POLYGON_MESH_PROCESSING_INTERNAL_ILSA_PARALLEL_LOOPS_H

#include <CGAL/assertions.h>
#include <CGAL/tags.h>

#include <algorithm>
#include <cstddef>
#include <type_traits>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>
#endif

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace ILSA {

template <class ConcurrencyTag>
constexpr bool is_parallel = std::is_convertible<ConcurrencyTag, CGAL::Parallel_tag>::value;

template <class ConcurrencyTag> constexpr void check_concurrency_tag() {
#ifndef CGAL_LINKED_WITH_TBB
  static_assert(!is_parallel<ConcurrencyTag>, "Parallel_tag is enabled but TBB is unavailable.");
#endif
}

/// Calls `f(i)` for every `i` in [0, n).
template <class ConcurrencyTag, class F> void parallel_for(std::size_t n, const F& f) {
  check_concurrency_tag<ConcurrencyTag>();
#ifdef CGAL_LINKED_WITH_TBB
  if constexpr (is_parallel<ConcurrencyTag>) {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 256), [&](const tbb::blocked_range<std::size_t>& r) {
      for (std::size_t i = r.begin(); i != r.end(); ++i) f(i);
    });
    return;
  }
#endif
  for (std::size_t i = 0; i < n; ++i) f(i);
}

/// The largest `f(i)` for `i` in [0, n), and 0 for n = 0 (`f` non-negative).
template <class ConcurrencyTag, class F> double parallel_max(std::size_t n, const F& f) {
  check_concurrency_tag<ConcurrencyTag>();
#ifdef CGAL_LINKED_WITH_TBB
  if constexpr (is_parallel<ConcurrencyTag>) {
    return tbb::parallel_reduce(
        tbb::blocked_range<std::size_t>(0, n, 256), 0.,
        [&](const tbb::blocked_range<std::size_t>& r, double m) {
          for (std::size_t i = r.begin(); i != r.end(); ++i) m = (std::max)(m, f(i));
          return m;
        },
        [](double a, double b) { return (std::max)(a, b); });
  }
#endif
  double m = 0;
  for (std::size_t i = 0; i < n; ++i) m = (std::max)(m, f(i));
  return m;
}

} // namespace ILSA
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif

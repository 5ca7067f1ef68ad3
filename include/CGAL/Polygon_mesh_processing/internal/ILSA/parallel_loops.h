// Copyright (c) 2026 The Polygon_mesh_processing_ILSA authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The loops every per-vertex and per-face stage runs through. With
// `CGAL::Parallel_tag` they run with TBB, with `CGAL::Sequential_tag` as a
// plain loop (no std::function on the hot path). Each call of `f(i)` writes
// only the slots of element `i` and reads values no other call of the same
// loop writes (Jacobi), and reductions are maxima, which do not depend on
// the order they are taken in: the result is bit-identical whatever the
// number of threads (user manual, "Parallel Runs"). Where several iterations
// reach the same element, `Claim_stamps` lets exactly one of them compute it.

#ifndef CGAL_POLYGON_MESH_PROCESSING_INTERNAL_ILSA_PARALLEL_LOOPS_H
#define CGAL_POLYGON_MESH_PROCESSING_INTERNAL_ILSA_PARALLEL_LOOPS_H

#include <CGAL/assertions.h>
#include <CGAL/tags.h>

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <memory>
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

/// Whether `ConcurrencyTag` runs the loops with TBB (parallel_loops.h).
template <class ConcurrencyTag>
constexpr bool is_parallel = std::is_convertible<ConcurrencyTag, CGAL::Parallel_tag>::value;

template <class ConcurrencyTag> constexpr void check_concurrency_tag() {
#ifndef CGAL_LINKED_WITH_TBB
  static_assert(!is_parallel<ConcurrencyTag>, "Parallel_tag is enabled but TBB is unavailable.");
#endif
}

/// The tag the core runs with (and, compiled once, is compiled for):
/// `CGAL::Parallel_tag` for a tag convertible to it, else `CGAL::Sequential_tag`.
template <class ConcurrencyTag>
using Core_tag = std::conditional_t<is_parallel<ConcurrencyTag>, CGAL::Parallel_tag, CGAL::Sequential_tag>;

/// Loops of at most this many iterations run on the calling thread: handing
/// them to TBB costs more than they take.
constexpr std::size_t parallel_grain = 256;

/// Calls `f(i)` for every `i` in [0, n).
template <class ConcurrencyTag, class F> void parallel_for(std::size_t n, const F& f) {
  check_concurrency_tag<ConcurrencyTag>();
#ifdef CGAL_LINKED_WITH_TBB
  if constexpr (is_parallel<ConcurrencyTag>) {
    if (n > parallel_grain) {
      tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, parallel_grain),
                        [&](const tbb::blocked_range<std::size_t>& r) {
                          for (std::size_t i = r.begin(); i != r.end(); ++i) f(i);
                        });
      return;
    }
  }
#endif
  for (std::size_t i = 0; i < n; ++i) f(i);
}

/// The largest `f(i)` for `i` in [0, n), and 0 for n = 0 (`f` non-negative).
template <class ConcurrencyTag, class F> double parallel_max(std::size_t n, const F& f) {
  check_concurrency_tag<ConcurrencyTag>();
#ifdef CGAL_LINKED_WITH_TBB
  if constexpr (is_parallel<ConcurrencyTag>) {
    if (n > parallel_grain)
      return tbb::parallel_reduce(
          tbb::blocked_range<std::size_t>(0, n, parallel_grain), 0.,
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

/// A stamp per element (the round in which it was last handled) that the
/// iterations of a parallel loop may read and set concurrently. `claim(i,
/// seen, r)` moves the stamp of `i` from the value `seen` read before to `r`
/// and returns true for exactly one caller per element and round, which then
/// computes the element: the values computed do not depend on which iteration
/// that is, so neither does the result.
class Claim_stamps {
public:
  using Round = std::uint32_t;

  void assign(std::size_t n, Round r) {
    stamps_ = std::make_unique<std::atomic<Round>[]>(n);
    size_ = n;
    fill(r);
  }
  void fill(Round r) {
    for (std::size_t i = 0; i < size_; ++i) stamps_[i].store(r, std::memory_order_relaxed);
  }
  Round operator[](std::size_t i) const { return stamps_[i].load(std::memory_order_relaxed); }
  void set(std::size_t i, Round r) { stamps_[i].store(r, std::memory_order_relaxed); }
  template <class ConcurrencyTag> bool claim(std::size_t i, Round seen, Round r) {
    if constexpr (!is_parallel<ConcurrencyTag>) {
      set(i, r);
      return true;
    } else {
      return stamps_[i].compare_exchange_strong(seen, r, std::memory_order_relaxed);
    }
  }

private:
  std::unique_ptr<std::atomic<Round>[]> stamps_;
  std::size_t size_ = 0;
};

} // namespace ILSA
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_POLYGON_MESH_PROCESSING_INTERNAL_ILSA_PARALLEL_LOOPS_H

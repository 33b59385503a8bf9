/*
 * pcl_flowseg - internal: large arrays on transparent huge pages, their pages mapped on all workers.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include "core/support/parallel.h"

#include <sys/mman.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace pcl_flowseg {
namespace core {

/** \brief Asks the kernel to back the 2 MiB-aligned part of [data, data + bytes) with transparent
  * huge pages (Linux, THP in "madvise" mode). Must come before the memory is first written. The
  * first write to each 4 KiB page otherwise costs a page fault, which on virtual machines can cost
  * more than the work done on the memory. Arrays above kLargestHugePageArray (larger than any
  * per-cell array up to a few million points) are left on small pages. On one development machine
  * fresh huge pages cost more than small ones at 1M points, on the next far less: the figures and
  * the choice are in docs/method.md, "The figures behind the constants". */
constexpr std::size_t kLargestHugePageArray = std::size_t (4) << 30;

inline void
adviseHugePages (const void* data, std::size_t bytes)
{
#ifdef MADV_HUGEPAGE
  constexpr std::uintptr_t kHuge = std::uintptr_t (1) << 21;
  if (bytes < 2 * kHuge || bytes > kLargestHugePageArray)
    return;
  const std::uintptr_t begin = (reinterpret_cast<std::uintptr_t> (data) + kHuge - 1) & ~(kHuge - 1);
  const std::uintptr_t end = (reinterpret_cast<std::uintptr_t> (data) + bytes) & ~(kHuge - 1);
  if (end > begin)
    madvise (reinterpret_cast<void*> (begin), end - begin, MADV_HUGEPAGE); // advice only: failure is harmless
#else
  (void) data;
  (void) bytes;
#endif
}

/** \brief Maps the pages of [data, data + bytes) in chunks on all workers before their first write
  * (MADV_POPULATE_WRITE, Linux 5.14 and later; advice only: where it fails, the first writes fault
  * the pages in as before). Filling a large fresh array otherwise takes one page fault per 4 KiB
  * page, all on the filling thread. */
inline void
populateInParallel (const void* data, std::size_t bytes)
{
#ifdef MADV_POPULATE_WRITE
  constexpr std::uintptr_t kPage = 4096, kChunk = std::uintptr_t (4) << 20;
  if (bytes < 2 * kChunk || workerThreads () < 2)
    return;
  const std::uintptr_t begin = reinterpret_cast<std::uintptr_t> (data) & ~(kPage - 1);
  const std::uintptr_t end = reinterpret_cast<std::uintptr_t> (data) + bytes;
  const std::size_t chunks = static_cast<std::size_t> ((end - begin + kChunk - 1) / kChunk);
  tbb::parallel_for (std::size_t (0), chunks, [&] (std::size_t k) {
    const std::uintptr_t from = begin + k * kChunk;
    madvise (reinterpret_cast<void*> (from), std::min<std::uintptr_t> (kChunk, end - from), MADV_POPULATE_WRITE);
  });
#else
  (void) data;
  (void) bytes;
#endif
}

/** \brief Room for \a n elements in the empty \a v, advised onto huge pages before anything is
  * written there: for arrays filled by push_back. */
template <class T>
void
reserveOnHugePages (std::vector<T>& v, std::size_t n)
{
  v.reserve (n);
  adviseHugePages (v.data (), v.capacity () * sizeof (T));
}

/** \brief \a v resized to \a n copies of \a value, its new storage advised onto huge pages and
  * mapped on all workers first. */
template <class T>
void
assignOnHugePages (std::vector<T>& v, std::size_t n, const T& value = T ())
{
  std::vector<T> ().swap (v);
  v.reserve (n);
  adviseHugePages (v.data (), n * sizeof (T));
  populateInParallel (v.data (), n * sizeof (T));
  v.assign (n, value);
}

} // namespace core
} // namespace pcl_flowseg

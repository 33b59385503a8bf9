/*
 * pcl_flowseg - internal: large arrays on transparent huge pages.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include <sys/mman.h>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace pcl_flowseg {
namespace core {

/** \brief Asks the kernel to back the 2 MiB-aligned part of [data, data + bytes) with transparent
  * huge pages (Linux, THP in "madvise" mode). Must come before the memory is first written. The
  * first write to each 4 KiB page otherwise costs a page fault, which on virtual machines can cost
  * more than the work done on the memory. Arrays above kLargestHugePageArray are left on small
  * pages: on virtual machines the first touch of fresh huge pages can cost far more than that of
  * small ones (the figures are in docs/method.md, "The figures behind the constants"). */
constexpr std::size_t kLargestHugePageArray = std::size_t (32) << 20;

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

/** \brief \a v resized to \a n copies of \a value, its new storage advised onto huge pages first. */
template <class T>
void
assignOnHugePages (std::vector<T>& v, std::size_t n, const T& value = T ())
{
  std::vector<T> ().swap (v);
  v.reserve (n);
  adviseHugePages (v.data (), n * sizeof (T));
  v.assign (n, value);
}

} // namespace core
} // namespace pcl_flowseg

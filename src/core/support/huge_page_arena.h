/*
 * pcl_flowseg - internal: large blocks carved from memory on transparent huge pages.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include <cstddef>
#include <mutex>
#include <vector>

namespace pcl_flowseg {
namespace core {

/** \brief A process-wide, thread-safe source of blocks on transparent huge pages.
  *
  * CGAL's parallel triangulation takes the blocks of its cell and vertex containers from TBB's
  * allocator, which asks for huge pages only when THP is in "always" mode; Debian's default is
  * "madvise". Each first write to a 4 KiB page then costs a page fault, and on virtual machines a
  * fault can cost more than the triangulation's work on that page (docs/method.md). This arena
  * maps 2 MiB-aligned chunks advised with MADV_HUGEPAGE and hands out blocks from them in order.
  * Blocks are not reused: a chunk goes back to the system when its last block is released, which
  * suits containers that free all their blocks together. */
class HugePageArena
{
public:
  /** The one arena of the process. */
  static HugePageArena&
  instance ();

  /** A block of \a bytes, aligned to 64 bytes. Throws std::bad_alloc when the system has no memory. */
  void*
  allocate (std::size_t bytes);

  /** Gives back a block from allocate() of the same \a bytes. */
  void
  release (void* block, std::size_t bytes);

  /** Bytes currently mapped for chunks (for tests). */
  std::size_t
  mappedBytes ();

  /** Bytes of all blocks handed out since the process started (for tests). */
  std::size_t
  handedOutBytes ();

private:
  struct Chunk
  {
    char* base;
    std::size_t size;
    std::size_t used;
    std::size_t live; ///< bytes of blocks not yet released
  };

  Chunk
  mapChunk (std::size_t bytes);

  std::mutex mutex_;
  std::vector<Chunk> chunks_; ///< the last one takes new blocks
  std::size_t handed_out_ = 0;
};

/** \brief A stateless allocator of \a T from the HugePageArena, for containers that allocate
  * large blocks (not single elements). */
template <class T>
struct HugePageArenaAllocator
{
  using value_type = T;

  HugePageArenaAllocator () = default;
  template <class U>
  HugePageArenaAllocator (const HugePageArenaAllocator<U>&) {}

  T*
  allocate (std::size_t n)
  {
    return static_cast<T*> (HugePageArena::instance ().allocate (n * sizeof (T)));
  }

  void
  deallocate (T* p, std::size_t n)
  {
    HugePageArena::instance ().release (p, n * sizeof (T));
  }

  template <class U>
  bool
  operator== (const HugePageArenaAllocator<U>&) const
  {
    return true;
  }

  template <class U>
  bool
  operator!= (const HugePageArenaAllocator<U>&) const
  {
    return false;
  }
};

} // namespace core
} // namespace pcl_flowseg

/*
 * pcl_flowseg - internal: large blocks carved from memory on transparent huge pages.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include "core/support/huge_page_arena.h"

#include <sys/mman.h>

#include <algorithm>
#include <cstdint>
#include <new>

namespace pcl_flowseg {
namespace core {

namespace {
constexpr std::size_t kHugePage = std::size_t (2) << 20;
constexpr std::size_t kChunkBytes = std::size_t (32) << 20; ///< virtual: only pages written count
constexpr std::size_t kBlockAlignment = 64;

std::size_t
roundUp (std::size_t bytes, std::size_t multiple)
{
  return (bytes + multiple - 1) / multiple * multiple;
}
} // namespace

HugePageArena&
HugePageArena::instance ()
{
  static HugePageArena* arena = new HugePageArena; // never destroyed: blocks may outlive static destructors
  return *arena;
}

HugePageArena::Chunk
HugePageArena::mapChunk (std::size_t bytes)
{
  const std::size_t size = std::max (kChunkBytes, roundUp (bytes, kHugePage));
  // Map one huge page more, then unmap the ends, so that the chunk starts on a 2 MiB boundary.
  void* mapped = mmap (nullptr, size + kHugePage, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  if (mapped == MAP_FAILED)
    throw std::bad_alloc ();
  const auto start = reinterpret_cast<std::uintptr_t> (mapped);
  const std::uintptr_t aligned = roundUp (start, kHugePage);
  if (aligned > start)
    munmap (mapped, aligned - start);
  const std::uintptr_t end = start + size + kHugePage;
  if (end > aligned + size)
    munmap (reinterpret_cast<void*> (aligned + size), end - (aligned + size));
#ifdef MADV_HUGEPAGE
  madvise (reinterpret_cast<void*> (aligned), size, MADV_HUGEPAGE); // advice only: failure is harmless
#endif
  return Chunk {reinterpret_cast<char*> (aligned), size, 0, 0};
}

void*
HugePageArena::allocate (std::size_t bytes)
{
  bytes = roundUp (std::max<std::size_t> (bytes, 1), kBlockAlignment);
  std::lock_guard<std::mutex> lock (mutex_);
  if (chunks_.empty () || chunks_.back ().size - chunks_.back ().used < bytes)
    chunks_.push_back (mapChunk (bytes));
  Chunk& chunk = chunks_.back ();
  void* block = chunk.base + chunk.used;
  chunk.used += bytes;
  chunk.live += bytes;
  handed_out_ += bytes;
  return block;
}

void
HugePageArena::release (void* block, std::size_t bytes)
{
  bytes = roundUp (std::max<std::size_t> (bytes, 1), kBlockAlignment);
  const char* p = static_cast<const char*> (block);
  std::lock_guard<std::mutex> lock (mutex_);
  for (auto chunk = chunks_.begin (); chunk != chunks_.end (); ++chunk)
    if (p >= chunk->base && p < chunk->base + chunk->size)
    {
      chunk->live -= bytes;
      if (chunk->live == 0)
      {
        munmap (chunk->base, chunk->size);
        chunks_.erase (chunk);
      }
      return;
    }
}

std::size_t
HugePageArena::mappedBytes ()
{
  std::lock_guard<std::mutex> lock (mutex_);
  std::size_t total = 0;
  for (const Chunk& chunk : chunks_)
    total += chunk.size;
  return total;
}

std::size_t
HugePageArena::handedOutBytes ()
{
  std::lock_guard<std::mutex> lock (mutex_);
  return handed_out_;
}

} // namespace core
} // namespace pcl_flowseg

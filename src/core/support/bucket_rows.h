/*
 * pcl_flowseg - internal: items listed per bucket (a counting sort), on all workers, in item order.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include "core/support/huge_pages.h"
#include "core/support/parallel.h"

#include <cstddef>
#include <vector>

namespace pcl_flowseg {
namespace core {

/** \brief Items grouped by bucket, as compressed rows: bucket b holds items[first[b] .. first[b+1]). */
struct BucketRows
{
  std::vector<std::size_t> first;
  std::vector<int> items;
};

/** \brief Lists each of \a item_count items in the buckets it belongs to (\a keys_of (item, add)
  * calls add (bucket) for each of them), every bucket's items in ascending order. Each chunk of
  * items counts its own, then fills its own slots of every bucket (after the chunks before it): the
  * result is the sequential counting sort's on any number of workers. */
template <class KeysOf>
BucketRows
bucketInOrder (std::size_t item_count, std::size_t bucket_count, const KeysOf& keys_of)
{
  struct Chunk
  {
    std::size_t begin = 0, end = 0;
    std::vector<std::size_t> next; ///< counts per bucket, then the chunk's next slot in each
  };
  std::vector<Chunk> chunks = gatherInChunks<Chunk> (item_count, [&] (std::size_t begin, std::size_t end, Chunk& chunk) {
    chunk.begin = begin;
    chunk.end = end;
    chunk.next.assign (bucket_count, 0);
    for (std::size_t k = begin; k < end; ++k)
      keys_of (k, [&] (std::size_t bucket) { ++chunk.next[bucket]; });
  });
  BucketRows rows;
  rows.first.assign (bucket_count + 1, 0);
  std::size_t total = 0;
  for (std::size_t b = 0; b < bucket_count; ++b)
  {
    rows.first[b] = total;
    for (Chunk& chunk : chunks)
    {
      const std::size_t count = chunk.next[b];
      chunk.next[b] = total;
      total += count;
    }
  }
  rows.first[bucket_count] = total;
  assignOnHugePages (rows.items, total);
  forEachTask (chunks.size (), [&] (std::size_t t) {
    Chunk& chunk = chunks[t];
    for (std::size_t k = chunk.begin; k < chunk.end; ++k)
      keys_of (k, [&] (std::size_t bucket) { rows.items[chunk.next[bucket]++] = static_cast<int> (k); });
  });
  return rows;
}

} // namespace core
} // namespace pcl_flowseg

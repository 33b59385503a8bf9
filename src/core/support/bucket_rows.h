/*
 * pcl_flowseg - internal: items listed per bucket (a counting sort), on all workers, in item order.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

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

/** \brief Lists each of \a item_count items in the buckets \a keys_of (item, add) names (add (bucket)
  * once per bucket, any number of times), every bucket's items in ascending order. Each chunk of
  * items counts its own, then fills its own slots of every bucket (after the chunks before it): the
  * result is the sequential counting sort's on any number of workers. */
template <class KeysOf>
BucketRows
bucketInOrder (std::size_t item_count, std::size_t bucket_count, const KeysOf& keys_of)
{
  std::vector<std::vector<std::size_t>> next = gatherInChunks<std::vector<std::size_t>> (
    item_count, [&] (std::size_t begin, std::size_t end, std::vector<std::size_t>& count) {
      count.assign (bucket_count, 0);
      for (std::size_t k = begin; k < end; ++k)
        keys_of (k, [&] (std::size_t bucket) { ++count[bucket]; });
    });
  BucketRows rows;
  rows.first.assign (bucket_count + 1, 0);
  std::size_t total = 0;
  for (std::size_t b = 0; b < bucket_count; ++b)
  {
    rows.first[b] = total;
    for (std::vector<std::size_t>& chunk : next)
    {
      const std::size_t count = chunk[b];
      chunk[b] = total; // from here on: the chunk's next slot in bucket b
      total += count;
    }
  }
  rows.first[bucket_count] = total;
  rows.items.resize (total);
  const std::size_t chunks = next.size ();
  forEachTask (chunks, [&] (std::size_t t) {
    std::vector<std::size_t>& slot = next[t];
    for (std::size_t k = item_count * t / chunks; k < item_count * (t + 1) / chunks; ++k)
      keys_of (k, [&] (std::size_t bucket) { rows.items[slot[bucket]++] = static_cast<int> (k); });
  });
  return rows;
}

} // namespace core
} // namespace pcl_flowseg

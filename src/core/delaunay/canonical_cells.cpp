/*
 * pcl_flowseg - internal: a canonical numbering of Delaunay cells.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include "core/delaunay/canonical_cells.h"

#include "core/support/bucket_rows.h"
#include "core/support/huge_pages.h"
#include "core/support/parallel.h"

#include <algorithm>
#include <utility>

namespace pcl_flowseg {
namespace core {

namespace {
/** How far ahead the canonical sort and copy start loading the cells they will read next: far
  * enough to hide a load from memory, near enough to stay in cache (tried: 4 and 8 buckets gave the
  * same time; 16 cells, as in extractLinks). */
constexpr std::size_t kBucketsAhead = 4;
constexpr std::size_t kCellsAhead = 16;

/** Puts the smaller of positions a and b first, carrying the slots; counts a swap in \a odd. */
inline void
compareExchange (std::array<int, 4>& vertices, std::array<int, 4>& slot, std::size_t a, std::size_t b, bool& odd)
{
  if (vertices[a] > vertices[b])
  {
    std::swap (vertices[a], vertices[b]);
    std::swap (slot[a], slot[b]);
    odd = !odd;
  }
}
} // namespace

void
canonicalVertexOrder (std::array<int, 4>& vertices, int f, std::array<int, 4>& slot)
{
  slot = {{0, 1, 2, 3}};
  bool odd = false;
  // Sorting networks (5 exchanges for 4, 3 for 3), called once per cell. Each exchange is a
  // transposition, so their count's parity is the permutation's whatever the network.
  if (f == 4)
  {
    compareExchange (vertices, slot, 0, 1, odd);
    compareExchange (vertices, slot, 2, 3, odd);
    compareExchange (vertices, slot, 0, 2, odd);
    compareExchange (vertices, slot, 1, 3, odd);
    compareExchange (vertices, slot, 1, 2, odd);
  }
  else
  {
    compareExchange (vertices, slot, 0, 1, odd);
    compareExchange (vertices, slot, 1, 2, odd);
    compareExchange (vertices, slot, 0, 1, odd);
  }
  if (odd)
  {
    std::swap (vertices[static_cast<std::size_t> (f - 2)], vertices[static_cast<std::size_t> (f - 1)]);
    std::swap (slot[static_cast<std::size_t> (f - 2)], slot[static_cast<std::size_t> (f - 1)]);
  }
}

void
orientCanonically (CellLinks& cell, int f)
{
  std::array<int, 4> slot;
  canonicalVertexOrder (cell.vertices, f, slot);
  const std::array<int, 4> neighbors = cell.neighbors;
  for (int i = 0; i < f; ++i)
    cell.neighbors[static_cast<std::size_t> (i)] = neighbors[static_cast<std::size_t> (slot[static_cast<std::size_t> (i)])];
}

std::vector<int>
canonicalCellOrder (const std::vector<CellLinks>& cells, int f)
{
  // Bucket by the first vertex (counting sort), then sort each bucket by the rest.
  int max_vertex = -1;
  for (const CellLinks& c : cells)
    max_vertex = std::max (max_vertex, c.vertices[0]);
  BucketRows buckets = bucketInOrder (cells.size (), static_cast<std::size_t> (max_vertex) + 1, [&] (std::size_t k, const auto& add) {
    add (static_cast<std::size_t> (cells[k].vertices[0]));
  });
  const std::vector<std::size_t>& first = buckets.first;
  std::vector<int>& order = buckets.items;
  const auto less = [&] (int a, int b) {
    const auto& ta = cells[static_cast<std::size_t> (a)].vertices;
    const auto& tb = cells[static_cast<std::size_t> (b)].vertices;
    return std::lexicographical_compare (ta.begin () + 1, ta.begin () + f, tb.begin () + 1, tb.begin () + f);
  };
  const std::size_t bucket_count = first.size () - 1;
  parallelFor (bucket_count, [&] (std::size_t v) {
    // The cells are compared through their indices, all over memory: a later bucket's cells start
    // loading now, so that they are there when it is sorted.
    if (v + kBucketsAhead < bucket_count)
      for (std::size_t k = first[v + kBucketsAhead]; k < first[v + kBucketsAhead + 1]; ++k)
        __builtin_prefetch (&cells[static_cast<std::size_t> (order[k])]);
    std::sort (order.begin () + static_cast<std::ptrdiff_t> (first[v]), order.begin () + static_cast<std::ptrdiff_t> (first[v + 1]), less);
  });
  return std::move (order);
}

void
buildCellsInCanonicalOrder (std::vector<CellLinks>&& cells, int dimension, std::vector<FlowCell>& flow_cells)
{
  const int f = dimension + 1;
  const std::size_t n = cells.size ();
  const std::vector<int> order = canonicalCellOrder (cells, f);
  std::vector<int> position;
  assignOnHugePages (position, n);
  parallelFor (n, [&] (std::size_t k) { position[static_cast<std::size_t> (order[k])] = static_cast<int> (k); });
  assignOnHugePages (flow_cells, n);
  parallelFor (n, [&] (std::size_t k) {
    // Read in canonical order, the cells lie all over memory: the cell kCellsAhead on starts
    // loading, and the new positions of the neighbours of the one half as far (loaded by then).
    if (k + kCellsAhead < n)
      __builtin_prefetch (&cells[static_cast<std::size_t> (order[k + kCellsAhead])]);
    if (k + kCellsAhead / 2 < n)
    {
      const CellLinks& ahead = cells[static_cast<std::size_t> (order[k + kCellsAhead / 2])];
      for (int i = 0; i < f; ++i)
        if (ahead.neighbors[i] != kInfiniteCell)
          __builtin_prefetch (&position[static_cast<std::size_t> (ahead.neighbors[i])]);
    }
    const CellLinks& c = cells[static_cast<std::size_t> (order[k])];
    FlowCell& out = flow_cells[k];
    out.vertices = c.vertices;
    for (int i = 0; i < f; ++i)
      out.neighbors[i] = c.neighbors[i] == kInfiniteCell ? kInfiniteCell : position[static_cast<std::size_t> (c.neighbors[i])];
  });
  std::vector<CellLinks> ().swap (cells);
}

} // namespace core
} // namespace pcl_flowseg

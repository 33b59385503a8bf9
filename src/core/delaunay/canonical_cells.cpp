/*
 * pcl_flowseg - internal: a canonical numbering of Delaunay cells.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include "core/delaunay/canonical_cells.h"

#include "core/support/huge_pages.h"
#include "core/support/parallel.h"

#include <algorithm>
#include <numeric>

namespace pcl_flowseg {
namespace core {

void
canonicalVertexOrder (std::array<int, 4>& vertices, int f, std::array<int, 4>& slot)
{
  for (int i = 0; i < 4; ++i)
    slot[static_cast<std::size_t> (i)] = i;
  bool odd = false;
  for (int i = 1; i < f; ++i)
    for (int j = i; j > 0 && vertices[static_cast<std::size_t> (j - 1)] > vertices[static_cast<std::size_t> (j)]; --j)
    {
      std::swap (vertices[static_cast<std::size_t> (j - 1)], vertices[static_cast<std::size_t> (j)]);
      std::swap (slot[static_cast<std::size_t> (j - 1)], slot[static_cast<std::size_t> (j)]);
      odd = !odd;
    }
  if (odd)
  {
    std::swap (vertices[static_cast<std::size_t> (f - 2)], vertices[static_cast<std::size_t> (f - 1)]);
    std::swap (slot[static_cast<std::size_t> (f - 2)], slot[static_cast<std::size_t> (f - 1)]);
  }
}

std::vector<int>
canonicalCellOrder (const std::vector<std::array<int, 4>>& tuples, int f)
{
  // Bucket by the first vertex (counting sort), then sort each bucket by the rest.
  const std::size_t n = tuples.size ();
  int max_vertex = -1;
  for (const auto& t : tuples)
    max_vertex = std::max (max_vertex, t[0]);
  std::vector<std::size_t> first (static_cast<std::size_t> (max_vertex) + 2, 0);
  for (const auto& t : tuples)
    ++first[static_cast<std::size_t> (t[0]) + 1];
  std::partial_sum (first.begin (), first.end (), first.begin ());
  std::vector<int> order;
  assignOnHugePages (order, n);
  {
    std::vector<std::size_t> fill (first.begin (), first.end () - 1);
    for (std::size_t k = 0; k < n; ++k)
      order[fill[static_cast<std::size_t> (tuples[k][0])]++] = static_cast<int> (k);
  }
  const auto less = [&] (int a, int b) {
    const auto& ta = tuples[static_cast<std::size_t> (a)];
    const auto& tb = tuples[static_cast<std::size_t> (b)];
    return std::lexicographical_compare (ta.begin () + 1, ta.begin () + f, tb.begin () + 1, tb.begin () + f);
  };
  parallelFor (first.size () - 1, [&] (std::size_t v) {
    std::sort (order.begin () + static_cast<std::ptrdiff_t> (first[v]), order.begin () + static_cast<std::ptrdiff_t> (first[v + 1]), less);
  });
  return order;
}

void
putInCanonicalOrder (std::vector<FlowCell>& cells, int dimension)
{
  const int f = dimension + 1;
  const std::size_t n = cells.size ();
  std::vector<std::array<int, 4>> tuples;
  assignOnHugePages (tuples, n);
  parallelFor (n, [&] (std::size_t k) {
    FlowCell& c = cells[k];
    std::array<int, 4> slot;
    canonicalVertexOrder (c.vertices, f, slot);
    const auto neighbors = c.neighbors;
    for (int i = 0; i < f; ++i)
      c.neighbors[static_cast<std::size_t> (i)] = neighbors[static_cast<std::size_t> (slot[static_cast<std::size_t> (i)])];
    tuples[k] = c.vertices;
  });
  const std::vector<int> order = canonicalCellOrder (tuples, f);
  std::vector<int> position;
  assignOnHugePages (position, n);
  for (std::size_t k = 0; k < n; ++k)
    position[static_cast<std::size_t> (order[k])] = static_cast<int> (k);
  std::vector<FlowCell> sorted;
  assignOnHugePages (sorted, n);
  parallelFor (n, [&] (std::size_t k) {
    FlowCell c = cells[static_cast<std::size_t> (order[k])];
    for (int i = 0; i < f; ++i)
      if (c.neighbors[i] != kInfiniteCell)
        c.neighbors[i] = position[static_cast<std::size_t> (c.neighbors[i])];
    sorted[k] = c;
  });
  cells.swap (sorted);
}

} // namespace core
} // namespace pcl_flowseg

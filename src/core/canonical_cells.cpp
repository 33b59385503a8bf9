/*
 * pcl_flowseg - internal: a canonical numbering of Delaunay cells.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include "canonical_cells.h"

#include "parallel.h"

#include <algorithm>
#include <numeric>

namespace pcl_flowseg {
namespace core {

void
putInCanonicalOrder (std::vector<FlowCell>& cells, int dimension)
{
  const int f = dimension + 1;
  const std::size_t n = cells.size ();
  // Vertices ascending within each cell (insertion sort of at most four, neighbours alongside);
  // after an odd number of swaps the last two go back, so that the orientation CGAL gave (positive)
  // is kept.
  parallelFor (n, [&] (std::size_t k) {
    FlowCell& c = cells[k];
    bool odd = false;
    for (int i = 1; i < f; ++i)
      for (int j = i; j > 0 && c.vertices[j - 1] > c.vertices[j]; --j)
      {
        std::swap (c.vertices[j - 1], c.vertices[j]);
        std::swap (c.neighbors[j - 1], c.neighbors[j]);
        odd = !odd;
      }
    if (odd)
    {
      std::swap (c.vertices[f - 2], c.vertices[f - 1]);
      std::swap (c.neighbors[f - 2], c.neighbors[f - 1]);
    }
  });

  // Cells by vertex tuple: bucket by the first vertex (counting sort), then sort each bucket.
  int max_vertex = -1;
  for (const FlowCell& c : cells)
    max_vertex = std::max (max_vertex, c.vertices[0]);
  std::vector<std::size_t> first (static_cast<std::size_t> (max_vertex) + 2, 0);
  for (const FlowCell& c : cells)
    ++first[static_cast<std::size_t> (c.vertices[0]) + 1];
  std::partial_sum (first.begin (), first.end (), first.begin ());
  std::vector<int> order (n); // new position -> old index
  {
    std::vector<std::size_t> fill (first.begin (), first.end () - 1);
    for (std::size_t k = 0; k < n; ++k)
      order[fill[static_cast<std::size_t> (cells[k].vertices[0])]++] = static_cast<int> (k);
  }
  const auto less = [&] (int a, int b) {
    const auto& va = cells[static_cast<std::size_t> (a)].vertices;
    const auto& vb = cells[static_cast<std::size_t> (b)].vertices;
    return std::lexicographical_compare (va.begin () + 1, va.begin () + f, vb.begin () + 1, vb.begin () + f);
  }; // distinct cells have distinct vertex sets, and a set has one oriented tuple
  parallelFor (first.size () - 1, [&] (std::size_t v) {
    std::sort (order.begin () + static_cast<std::ptrdiff_t> (first[v]), order.begin () + static_cast<std::ptrdiff_t> (first[v + 1]), less);
  });

  std::vector<int> position (n);
  for (std::size_t k = 0; k < n; ++k)
    position[static_cast<std::size_t> (order[k])] = static_cast<int> (k);
  std::vector<FlowCell> sorted (n);
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

/*
 * pcl_flowseg - internal: the local sample spacing, the unit of the merge rule's tolerance.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include "core/merging/sample_spacing.h"

#include "core/support/parallel.h"

#include <algorithm>
#include <limits>
#include <utility>

namespace pcl_flowseg {
namespace core {

std::vector<double>
nearestNeighbourDistances (const FlowResult& result)
{
  const int facets = result.dimension + 1;
  const std::size_t vertex_count = result.vertices.size ();
  // Each worker takes the minimum over its cells' edges; minima combine in any order exactly.
  std::vector<std::vector<double>> parts = gatherInChunks<std::vector<double>> (
    result.cells.size (), [&] (std::size_t begin, std::size_t end, std::vector<double>& nearest) {
      nearest.assign (vertex_count, std::numeric_limits<double>::infinity ());
      for (std::size_t c = begin; c < end; ++c)
      {
        const FlowCell& cell = result.cells[c];
        for (int i = 0; i < facets; ++i)
          for (int j = i + 1; j < facets; ++j)
          {
            const std::size_t a = static_cast<std::size_t> (cell.vertices[i]);
            const std::size_t b = static_cast<std::size_t> (cell.vertices[j]);
            const double length = (result.vertices[a] - result.vertices[b]).norm ();
            nearest[a] = std::min (nearest[a], length);
            nearest[b] = std::min (nearest[b], length);
          }
      }
    });
  std::vector<double>& nearest = parts.front ();
  for (std::size_t k = 1; k < parts.size (); ++k)
    for (std::size_t v = 0; v < vertex_count; ++v)
      nearest[v] = std::min (nearest[v], parts[k][v]);
  return std::move (nearest);
}

double
saddleSpacing (const SaddleFacet& saddle, const std::vector<double>& nearest, int dimension)
{
  double sum = 0.0;
  for (int k = 0; k < dimension; ++k) // a facet has d vertices
    sum += nearest[static_cast<std::size_t> (saddle.vertices[static_cast<std::size_t> (k)])];
  return sum / dimension;
}

} // namespace core
} // namespace pcl_flowseg

/*
 * pcl_flowseg - the edges of a shape's interior cells as a graph, and shortest paths along them:
 * inner distances for the shape description (internal header).
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include <pcl_flowseg/common/flow_result.h>

#include <cstddef>
#include <utility>
#include <vector>

namespace pcl_flowseg {

/** \brief The edges of the interior cells as a graph on the sample points (compressed rows): paths
  * along them run through the interior, and unlike paths between cell centroids they do not
  * zigzag across thin parts. */
struct InteriorEdges
{
  std::vector<std::size_t> first; ///< edges of vertex v: [first[v], first[v + 1])
  std::vector<int> to;
  std::vector<double> length;

  explicit InteriorEdges (const FlowResult& result);
};

/** \brief Shortest paths along \a edges from the \a seeds (distinct vertices, each with the
  * distance at which it starts): \a distance[v] for every vertex (sized to the vertices),
  * infinity where no path reaches. */
void
shortestPaths (const InteriorEdges& edges, const std::vector<std::pair<int, double>>& seeds, std::vector<double>& distance);

} // namespace pcl_flowseg

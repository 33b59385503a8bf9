/*
 * pcl_flowseg - the edges of a shape's interior cells as a graph, and shortest paths along them.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include "interior_graph.h"

#include <algorithm>
#include <functional>
#include <limits>
#include <queue>

namespace pcl_flowseg {

InteriorEdges::InteriorEdges (const FlowResult& result)
{
  std::vector<std::pair<int, int>> pairs;
  for (const FlowCell& c : result.cells)
    if (c.inside == 1)
      for (int a = 0; a <= result.dimension; ++a)
        for (int b = 0; b <= result.dimension; ++b)
          if (a != b)
            pairs.emplace_back (c.vertices[static_cast<std::size_t> (a)], c.vertices[static_cast<std::size_t> (b)]);
  std::sort (pairs.begin (), pairs.end ());
  pairs.erase (std::unique (pairs.begin (), pairs.end ()), pairs.end ());
  first.assign (result.vertices.size () + 1, 0);
  for (const auto& e : pairs)
    ++first[static_cast<std::size_t> (e.first) + 1];
  for (std::size_t v = 0; v < result.vertices.size (); ++v)
    first[v + 1] += first[v];
  for (const auto& e : pairs)
  {
    to.push_back (e.second);
    length.push_back ((result.vertices[static_cast<std::size_t> (e.first)] - result.vertices[static_cast<std::size_t> (e.second)]).norm ());
  }
}

void
shortestPaths (const InteriorEdges& edges, const std::vector<std::pair<int, double>>& seeds, std::vector<double>& distance)
{
  using Entry = std::pair<double, int>;
  std::fill (distance.begin (), distance.end (), std::numeric_limits<double>::infinity ());
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> queue;
  for (const auto& [v, d] : seeds)
  {
    distance[static_cast<std::size_t> (v)] = d;
    queue.emplace (d, v);
  }
  while (!queue.empty ())
  {
    const auto [d, v] = queue.top ();
    queue.pop ();
    if (d > distance[static_cast<std::size_t> (v)])
      continue;
    for (std::size_t e = edges.first[static_cast<std::size_t> (v)]; e < edges.first[static_cast<std::size_t> (v) + 1]; ++e)
    {
      const double through = d + edges.length[e];
      if (through < distance[static_cast<std::size_t> (edges.to[e])])
      {
        distance[static_cast<std::size_t> (edges.to[e])] = through;
        queue.emplace (through, edges.to[e]);
      }
    }
  }
}

} // namespace pcl_flowseg

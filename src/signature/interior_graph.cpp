/*
 * pcl_flowseg - the edges of a shape's interior cells as a graph, and shortest paths along them.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include "interior_graph.h"

#include <pcl_flowseg/common/parallel_jobs.h>

#include <boost/graph/detail/d_ary_heap.hpp>
#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <functional>
#include <limits>
#include <numeric>

namespace pcl_flowseg {

namespace {

/** Runs \a job (begin, end) over [0, n) in chunks on \a threads threads. */
void
inChunks (std::size_t n, unsigned threads, const std::function<void (std::size_t, std::size_t)>& job)
{
  constexpr std::size_t kChunk = 4096;
  runParallelJobs ((n + kChunk - 1) / kChunk, threads,
                   [&] (std::size_t k) { job (k * kChunk, std::min (n, (k + 1) * kChunk)); });
}

/** Every ordered pair of corners of an interior cell, bucketed by its first corner: the second
  * corners of the pairs from vertex v are ends[bucket[v] .. bucket[v + 1]), repeats included. */
std::vector<int>
cornerPairsByVertex (const FlowResult& result, std::vector<std::size_t>& bucket)
{
  const std::size_t n = result.vertices.size ();
  const int corners = result.dimension + 1;
  bucket.assign (n + 1, 0);
  for (const FlowCell& c : result.cells)
    if (c.inside == 1)
      for (int a = 0; a < corners; ++a)
        bucket[static_cast<std::size_t> (c.vertices[static_cast<std::size_t> (a)]) + 1] += static_cast<std::size_t> (corners - 1);
  std::partial_sum (bucket.begin (), bucket.end (), bucket.begin ());
  std::vector<int> ends (bucket[n]);
  std::vector<std::size_t> fill (bucket.begin (), bucket.end () - 1);
  for (const FlowCell& c : result.cells)
    if (c.inside == 1)
      for (int a = 0; a < corners; ++a)
        for (int b = 0; b < corners; ++b)
          if (a != b)
            ends[fill[static_cast<std::size_t> (c.vertices[static_cast<std::size_t> (a)])]++] = c.vertices[static_cast<std::size_t> (b)];
  return ends;
}

} // namespace

InteriorEdges::InteriorEdges (const FlowResult& result)
{
  // Each vertex's bucket sorted and its repeats dropped: the same edges in the same order as
  // sorting all pairs at once, in a fraction of the time on large inputs.
  const std::size_t n = result.vertices.size ();
  const unsigned threads = result.parameters.execution.threads;
  std::vector<std::size_t> bucket;
  std::vector<int> ends = cornerPairsByVertex (result, bucket);
  first.assign (n + 1, 0);
  inChunks (n, threads, [&] (std::size_t begin, std::size_t end) {
    for (std::size_t v = begin; v < end; ++v)
    {
      const auto from = ends.begin () + static_cast<std::ptrdiff_t> (bucket[v]);
      const auto to_end = ends.begin () + static_cast<std::ptrdiff_t> (bucket[v + 1]);
      std::sort (from, to_end);
      first[v + 1] = static_cast<std::size_t> (std::unique (from, to_end) - from);
    }
  });
  std::partial_sum (first.begin (), first.end (), first.begin ());
  to.resize (first[n]);
  length.resize (first[n]);
  inChunks (n, threads, [&] (std::size_t begin, std::size_t end) {
    for (std::size_t v = begin; v < end; ++v)
      for (std::size_t e = first[v]; e < first[v + 1]; ++e)
      {
        const int w = ends[bucket[v] + (e - first[v])];
        to[e] = w;
        length[e] = (result.vertices[v] - result.vertices[static_cast<std::size_t> (w)]).norm ();
      }
  });
}

void
shortestPaths (const InteriorEdges& edges, const std::vector<std::pair<int, double>>& seeds, std::vector<double>& distance)
{
  // An addressable 4-ary heap (Boost's, as in its Dijkstra): each vertex waits at most once and a
  // shorter path moves it up, where a queue of stale copies held several per vertex. The
  // distances do not depend on the queue: each is the least over the paths through the vertices
  // settled before it.
  constexpr std::size_t kNotQueued = static_cast<std::size_t> (-1);
  std::fill (distance.begin (), distance.end (), std::numeric_limits<double>::infinity ());
  std::vector<std::size_t> index_in_heap (distance.size (), kNotQueued);
  auto keys = boost::make_iterator_property_map (distance.begin (), boost::typed_identity_property_map<int> ());
  auto indices = boost::make_iterator_property_map (index_in_heap.begin (), boost::typed_identity_property_map<int> ());
  boost::d_ary_heap_indirect<int, 4, decltype (indices), decltype (keys), std::less<double>> queue (keys, indices);
  for (const auto& [v, d] : seeds)
    distance[static_cast<std::size_t> (v)] = d;
  for (const auto& seed : seeds)
    if (!queue.contains (seed.first))
      queue.push (seed.first);
  while (!queue.empty ())
  {
    const int v = queue.top ();
    queue.pop ();
    const double d = distance[static_cast<std::size_t> (v)];
    for (std::size_t e = edges.first[static_cast<std::size_t> (v)]; e < edges.first[static_cast<std::size_t> (v) + 1]; ++e)
    {
      const double through = d + edges.length[e];
      if (through < distance[static_cast<std::size_t> (edges.to[e])])
      {
        distance[static_cast<std::size_t> (edges.to[e])] = through;
        queue.push_or_update (edges.to[e]);
      }
    }
  }
}

} // namespace pcl_flowseg

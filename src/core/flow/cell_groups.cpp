/*
 * pcl_flowseg - internal: groups of cells (stable manifolds, segments): statistics and saddles.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include "core/flow/cell_groups.h"

#include "core/geometry/cell_geometry.h"
#include "core/support/parallel.h"

#include <algorithm>
#include <cstdint>
#include <unordered_map>

namespace pcl_flowseg {
namespace core {

std::vector<FlowSegment>
summariseCells (const std::vector<FlowCell>& cells, const std::vector<int>& group_of_cell,
                int group_count)
{
  std::vector<FlowSegment> groups (static_cast<std::size_t> (group_count));
  std::vector<Eigen::Vector3d> weighted (groups.size (), Eigen::Vector3d::Zero ());
  for (std::size_t c = 0; c < cells.size (); ++c)
  {
    const std::size_t g = static_cast<std::size_t> (group_of_cell[c]);
    groups[g].volume += cells[c].volume;
    groups[g].cell_count += 1;
    weighted[g] += cells[c].volume * cells[c].centroid;
  }
  for (std::size_t g = 0; g < groups.size (); ++g)
    groups[g].centroid = groups[g].volume > 0.0 ? Eigen::Vector3d (weighted[g] / groups[g].volume)
                                                : Eigen::Vector3d::Zero ();
  return groups;
}

namespace {
using SaddlesByPair = std::unordered_map<std::uint64_t, SaddleFacet>;

/** The highest facet between each pair of groups among the facets of cells [begin, end), each
  * facet seen from its lower cell; on equal heights the first found. */
void
collectSaddles (const FlowResult& result, const std::vector<int>& group_of_cell, std::size_t begin, std::size_t end,
                SaddlesByPair& best)
{
  const int facets = result.dimension + 1;
  for (std::size_t c = begin; c < end; ++c)
  {
    const FlowCell& cell = result.cells[c];
    for (int i = 0; i < facets; ++i)
    {
      const int nb = cell.neighbors[i];
      if (nb == kInfiniteCell || static_cast<std::size_t> (nb) < c)
        continue; // hull facet, or seen from the other side
      int ga = group_of_cell[c], gb = group_of_cell[static_cast<std::size_t> (nb)];
      if (ga == gb)
        continue;
      if (ga > gb)
        std::swap (ga, gb);
      Eigen::Vector3d centre;
      const double r2 = facetSquaredRadius (result.vertices, cell, i, result.dimension, &centre);
      const std::uint64_t key = (static_cast<std::uint64_t> (ga) << 32) | static_cast<std::uint32_t> (gb);
      auto it = best.find (key);
      if (it != best.end () && it->second.squared_radius >= r2)
        continue;
      SaddleFacet s;
      s.segment_a = ga;
      s.segment_b = gb;
      s.cell = static_cast<int> (c);
      s.facet = i;
      for (int k = 0; k < facets - 1; ++k)
        s.vertices[static_cast<std::size_t> (k)] = cell.vertices[(i + 1 + k) % facets];
      s.squared_radius = r2;
      s.location = centre;
      best[key] = s;
    }
  }
}
} // namespace

std::vector<SaddleFacet>
highestSharedFacets (const FlowResult& result, const std::vector<int>& group_of_cell)
{
  std::vector<SaddlesByPair> parts = gatherInChunks<SaddlesByPair> (
    result.cells.size (), [&] (std::size_t begin, std::size_t end, SaddlesByPair& best) {
      collectSaddles (result, group_of_cell, begin, end, best);
    });
  // Later chunks hold later cells: they win only where one pass would have let them win.
  SaddlesByPair& best = parts.front ();
  for (std::size_t k = 1; k < parts.size (); ++k)
    for (auto& kv : parts[k])
    {
      const auto [it, inserted] = best.insert (kv);
      if (!inserted && !(it->second.squared_radius >= kv.second.squared_radius))
        it->second = kv.second;
    }
  std::vector<SaddleFacet> out;
  out.reserve (best.size ());
  for (auto& kv : best)
    out.push_back (kv.second);
  std::sort (out.begin (), out.end (), [] (const SaddleFacet& x, const SaddleFacet& y) {
    return x.segment_a != y.segment_a ? x.segment_a < y.segment_a : x.segment_b < y.segment_b;
  });
  return out;
}

} // namespace core
} // namespace pcl_flowseg

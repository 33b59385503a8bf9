/*
 * pcl_flowseg - internal: groups of cells (stable manifolds, segments): statistics and saddles.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include "core/flow/cell_groups.h"

#include "core/geometry/cell_geometry.h"

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

std::vector<SaddleFacet>
highestSharedFacets (const FlowResult& result, const std::vector<int>& group_of_cell)
{
  const int facets = result.dimension + 1;
  std::unordered_map<std::uint64_t, SaddleFacet> best;
  for (std::size_t c = 0; c < result.cells.size (); ++c)
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

/*
 * pcl_flowseg - internal: the final groups of cells become the result's segments, in order.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include "core/merging/segment_assembly.h"

#include "core/flow/cell_groups.h"
#include "core/support/huge_pages.h"
#include "core/support/parallel.h"

#include <pcl_flowseg/common/feature_significance.h>

#include <algorithm>
#include <utility>

namespace pcl_flowseg {
namespace core {

namespace {
/** The segments of the groups, in group order: statistics, maxima of their manifolds, side. */
std::vector<FlowSegment>
describeGroups (const FlowResult& result, const MergeGroups& groups)
{
  std::vector<FlowSegment> segs = summariseCells (result.cells, groups.of_cell, groups.count);
  for (std::size_t k = 0; k < result.manifolds.size (); ++k)
  {
    const FlowSegment& man = result.manifolds[k];
    FlowSegment& seg = segs[static_cast<std::size_t> (groups.of_manifold[k])];
    if (man.flows_to_infinity)
    {
      seg.flows_to_infinity = true;
      seg.maximum = man.maximum;
      continue;
    }
    seg.maxima.insert (seg.maxima.end (), man.maxima.begin (), man.maxima.end ());
    if (seg.maxima.size () == man.maxima.size () || man.maximum.height > seg.maximum.height)
      seg.maximum = man.maximum;
  }
  for (int g = 0; g < groups.count; ++g)
    segs[static_cast<std::size_t> (g)].interior = groups.side[static_cast<std::size_t> (g)];
  // Segments without a maximum of their own: report their highest cell.
  for (std::size_t c = 0; c < result.cells.size (); ++c)
  {
    FlowSegment& seg = segs[static_cast<std::size_t> (groups.of_cell[c])];
    if (seg.maxima.empty () && !seg.flows_to_infinity &&
        (seg.maximum.cell < 0 || result.cells[c].squared_radius > seg.maximum.height))
    {
      seg.maximum.cell = static_cast<int> (c);
      seg.maximum.height = result.cells[c].squared_radius;
    }
  }
  for (auto& seg : segs)
    if (seg.maxima.empty () && !seg.flows_to_infinity && seg.maximum.cell >= 0)
      seg.maximum.location = result.cells[static_cast<std::size_t> (seg.maximum.cell)].centroid;
  return segs;
}

/** The groups with cells, in the order of FlowResult::segments. */
std::vector<int>
segmentOrder (const std::vector<FlowSegment>& segs)
{
  std::vector<int> order;
  for (int g = 0; g < static_cast<int> (segs.size ()); ++g)
    if (segs[static_cast<std::size_t> (g)].cell_count > 0) // the one at infinity may have lost all
      order.push_back (g);
  std::sort (order.begin (), order.end (), [&] (int x, int y) {
    const FlowSegment& a = segs[static_cast<std::size_t> (x)];
    const FlowSegment& b = segs[static_cast<std::size_t> (y)];
    if (a.flows_to_infinity != b.flows_to_infinity)
      return b.flows_to_infinity;
    if (a.interior != b.interior)
      return a.interior > b.interior;
    if (a.volume != b.volume)
      return a.volume > b.volume;
    if (a.maximum.height != b.maximum.height)
      return a.maximum.height > b.maximum.height;
    return x < y;
  });
  return order;
}
} // namespace

void
storeSegments (const MergeGroups& groups, FlowResult& result)
{
  std::vector<FlowSegment> segs = describeGroups (result, groups);
  const std::vector<int> order = segmentOrder (segs);
  std::vector<int> rank (static_cast<std::size_t> (groups.count), -1);
  result.segments.clear ();
  result.segments.reserve (order.size ());
  for (int r = 0; r < static_cast<int> (order.size ()); ++r)
  {
    rank[static_cast<std::size_t> (order[static_cast<std::size_t> (r)])] = r;
    result.segments.push_back (std::move (segs[static_cast<std::size_t> (order[static_cast<std::size_t> (r)])]));
    std::sort (result.segments.back ().maxima.begin (), result.segments.back ().maxima.end ());
  }
  std::vector<int> segment_of_cell;
  assignOnHugePages (segment_of_cell, result.cells.size ());
  parallelFor (result.cells.size (), [&] (std::size_t c) {
    result.cells[c].segment = rank[static_cast<std::size_t> (groups.of_cell[c])];
    segment_of_cell[c] = result.cells[c].segment;
  });
  result.segment_adjacency = highestSharedFacets (result, segment_of_cell);
  result.features = segmentsOnSide (result, result.parameters.features);
}

} // namespace core
} // namespace pcl_flowseg

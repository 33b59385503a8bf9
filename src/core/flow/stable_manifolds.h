/*
 * pcl_flowseg - internal: maxima and (strengthened) stable manifolds from the flow relation.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include <pcl_flowseg/common/flow_result.h>

#include <cstddef>
#include <vector>

namespace pcl_flowseg {
namespace core {

/** \brief Output of computeStableManifolds. */
struct StableManifolds
{
  std::vector<int> maxima_cells;     ///< cells holding a maximum, by decreasing height
  bool has_infinity = false;         ///< some cell flows out of the convex hull
  std::size_t cycle_breaks = 0;      ///< cells the flow order could not reach (degenerate input)
};

/** \brief Labels every cell with the stable manifold it flows into.
  *
  * One pass in reverse topological order of the flow (Kahn's algorithm, O(n)): each cell's
  * strength is the largest height among the maxima it can reach (+inf for the convex hull),
  * and it keeps the single successor of largest strength (the paper's strengthened relation
  * ~<; in 2D there is at most one successor, so this is the exact flow). Ties are broken by
  * facet order. Sets FlowCell::successor_facet and FlowCell::manifold (index into
  * maxima_cells, or maxima_cells.size() for the manifold at infinity). Cells caught in a
  * cycle (impossible with exact predicates, guarded anyway) become their own maxima. */
StableManifolds
computeStableManifolds (std::vector<FlowCell>& cells, int dimension);

} // namespace core
} // namespace pcl_flowseg

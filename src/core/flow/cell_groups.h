/*
 * pcl_flowseg - internal: groups of cells (stable manifolds, segments): statistics and saddles.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include <pcl_flowseg/common/flow_result.h>

#include <vector>

namespace pcl_flowseg {
namespace core {

/** \brief Volume, centroid and cell count of each group of cells (\a group_of_cell[c] in
  * 0..group_count-1). Maxima and flags are left to the caller. */
std::vector<FlowSegment>
summariseCells (const std::vector<FlowCell>& cells, const std::vector<int>& group_of_cell,
                int group_count);

/** \brief For every pair of groups that share a facet, the shared facet of largest
  * circumradius (the discrete saddle between them). Sorted by (segment_a, segment_b). */
std::vector<SaddleFacet>
highestSharedFacets (const FlowResult& result, const std::vector<int>& group_of_cell);

} // namespace core
} // namespace pcl_flowseg

/*
 * pcl_flowseg - internal: statistics of cell sets, saddles between them, and rho-merging.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include <pcl_flowseg/flow_result.h>

#include <vector>

namespace pcl_flowseg {
namespace core {

/** \brief Squared radius of the smallest circumsphere of facet \a facet of \a cell (the edge's
  * half length squared in 2D), computed from the input-frame vertex coordinates; its centre
  * goes to \a centre when given. */
double
facetSquaredRadius (const std::vector<Eigen::Vector3d>& vertices, const FlowCell& cell,
                    int facet, int dimension, Eigen::Vector3d* centre = nullptr);

/** \brief Volume, centroid and cell count of each group of cells (\a group_of_cell[c] in
  * 0..group_count-1). Maxima and flags are left to the caller. */
std::vector<FlowSegment>
summariseCells (const std::vector<FlowCell>& cells, const std::vector<int>& group_of_cell,
                int group_count);

/** \brief For every pair of groups that share a facet, the shared facet of largest
  * circumradius. Sorted by (segment_a, segment_b). */
std::vector<SaddleFacet>
highestSharedFacets (const FlowResult& result, const std::vector<int>& group_of_cell);

/** \brief Merges the stable manifolds of \a result by the paper's rho rule and fills
  * segments, cells[].segment, segment_adjacency. Requires manifolds and manifold_adjacency.
  *
  * Two finite manifolds A, B sharing facets are merged when, for their highest shared facet t,
  * R(max A) < rho R(t) and R(max B) < rho R(t) (circumradii). Since a facet's radius can only
  * be lower than the maximum of a manifold touching it, the highest shared facet decides
  * whether any shared facet satisfies the rule. All mergeable pairs are joined (connected
  * components), which is independent of order. The manifold at infinity is never merged. */
void
mergeManifolds (double rho, FlowResult& result);

} // namespace core
} // namespace pcl_flowseg

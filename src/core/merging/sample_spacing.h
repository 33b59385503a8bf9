/*
 * pcl_flowseg - internal: the local sample spacing, the unit of the merge rule's tolerance.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include <pcl_flowseg/common/flow_result.h>

#include <vector>

namespace pcl_flowseg {
namespace core {

/** \brief Distance from each vertex of \a result to its nearest other vertex (the shortest
  * Delaunay edge at it: a sample's nearest neighbour is always a Delaunay neighbour); +inf for a
  * vertex on no cell. */
std::vector<double>
nearestNeighbourDistances (const FlowResult& result);

/** \brief Local sample spacing at a saddle: the mean nearest-neighbour distance (\a nearest, from
  * nearestNeighbourDistances) of the facet's vertices. */
double
saddleSpacing (const SaddleFacet& saddle, const std::vector<double>& nearest, int dimension);

} // namespace core
} // namespace pcl_flowseg

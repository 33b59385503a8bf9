/*
 * pcl_flowseg - internal: the compact pass: shallow bulges no bigger than their neck merge.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include <pcl_flowseg/common/flow_result.h>

#include <vector>

namespace pcl_flowseg {
namespace core {

/** \brief Visits \a candidates (saddles between manifolds that pass the rule at compact_rho, not at
  * rho) from the shallowest on (lowest ratio of the higher maximum to the saddle, squared radii;
  * ties in adjacency order); the two groups of \a parent a saddle joins merge when the smaller
  * holds no more volume (area in 2D) than \a size balls (discs) of the saddle's radius. Group
  * volumes grow as groups merge. */
void
mergeCompactGroups (const FlowResult& result, std::vector<const SaddleFacet*>& candidates, double size,
                    std::vector<int>& parent);

} // namespace core
} // namespace pcl_flowseg

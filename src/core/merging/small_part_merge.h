/*
 * pcl_flowseg - internal: segments too small to be parts join the neighbour across their widest saddle.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include "core/merging/merge_groups.h"

#include <pcl_flowseg/common/flow_result.h>

namespace pcl_flowseg {
namespace core {

/** \brief Groups holding less than \a min_share of the volume (area in 2D) of all groups on their
  * side join the group of the same side they share their widest saddle (highest shared facet)
  * with, smallest first; a joined group's volume is the sum, and it joins on in turn while still
  * too small. The group flowing to infinity is never absorbed; a group without a neighbour on its
  * side stays. Rewrites groups.of_cell and groups.of_manifold; joined groups keep no cells. */
void
absorbSmallGroups (const FlowResult& result, double min_share, MergeGroups& groups);

} // namespace core
} // namespace pcl_flowseg

/*
 * pcl_flowseg - internal: the final groups of cells become the result's segments, in order.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include "core/merging/merge_groups.h"

#include <pcl_flowseg/common/flow_result.h>

namespace pcl_flowseg {
namespace core {

/** \brief Fills result.segments (statistics, merged maxima, side; a group without a maximum of its
  * own reports its highest cell), cells[].segment, segment_adjacency and features. Segments are
  * ordered: interior ones by decreasing volume (then height), then exterior ones, the one at
  * infinity last; groups left without cells are dropped. */
void
storeSegments (const MergeGroups& groups, FlowResult& result);

} // namespace core
} // namespace pcl_flowseg

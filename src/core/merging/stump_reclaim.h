/*
 * pcl_flowseg - internal: thin parts take back their stumps from thick ones.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include "core/merging/merge_groups.h"

#include <pcl_flowseg/common/flow_result.h>

#include <vector>

namespace pcl_flowseg {
namespace core {

/** \brief Height of each group: the squared radius of its highest maximum; -1 for groups that take
  * no part in reclaiming stumps (no maximum of their own, or the group at infinity). */
std::vector<double>
groupHeights (const FlowResult& result, const MergeGroups& groups);

/** \brief Where a thin group X borders a group Y whose height is more than \a ratio^2 times X's
  * (circumradius ratio above \a ratio), the cells of Y connected to X through cells of Y no larger
  * than X's highest maximum (and no smaller than half the radius of the saddle between X and Y)
  * join X: the flow cuts a thin part off where it is narrowest, and the stretch from there to the
  * thick part flows into the thick part. Cells holding a maximum never move; lowest cells first,
  * so the flood is deterministic. Updates \a of_cell; the number of groups does not change. */
void
reclaimStumps (const FlowResult& result, const std::vector<double>& height, double ratio, std::vector<int>& of_cell);

} // namespace core
} // namespace pcl_flowseg

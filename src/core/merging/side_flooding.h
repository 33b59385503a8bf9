/*
 * pcl_flowseg - internal: every cell joins a group of its own side (interior or exterior).
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include "core/merging/merge_groups.h"

#include <pcl_flowseg/common/flow_result.h>

namespace pcl_flowseg {
namespace core {

/** \brief Fills groups.of_cell. A cell on the side of its manifold's group keeps that group; with
  * interior/exterior separation, a cell whose flow leaves its side joins the neighbouring group of
  * its side that it touches through its highest facet (a flood over facets, highest first); a
  * region of a side that no group of that side reaches becomes a group of its own. */
void
assignCellsToTheirSide (const FlowResult& result, MergeGroups& groups);

} // namespace core
} // namespace pcl_flowseg

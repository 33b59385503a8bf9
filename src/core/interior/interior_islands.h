/*
 * pcl_flowseg - internal: tiny pockets of inside cells cut off from the rest of the interior.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include <pcl_flowseg/common/flow_result.h>

#include <cstddef>

namespace pcl_flowseg {
namespace core {

/** A connected group of inside cells holding less than this share of the inside volume is an
  * island: on a single view whose hidden side was guessed, such pockets come from the guess's
  * roughness, not from the object, and would each be reported as a feature. */
constexpr double kInteriorIslandShare = 0.001;

/** \brief Labels outside every group of inside cells, connected through shared facets, whose
  * volume is below \a min_share of all inside cells'; returns the cells relabelled. */
std::size_t
dropInteriorIslands (FlowResult& r, double min_share);

} // namespace core
} // namespace pcl_flowseg

/*
 * pcl_flowseg - which features are significant: the one place that decides it.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include <pcl_flowseg/common/flow_result.h>

#include <vector>

namespace pcl_flowseg {

/** \brief Default significance: a feature counts when its volume (area in 2D) exceeds this share of
  * the total volume of the features it is compared with. */
constexpr double kDefaultSignificance = 0.02;

/** \brief Why \a fraction cannot be a significance (it must lie in [0, 1)), or success. */
Status
checkSignificance (double fraction);

/** \brief The segments of \a result on \a side (interior: interior == 1, exterior: 0, both or no
  * separation: every segment), in the order of FlowResult::segments. With side =
  * result.parameters.features this is FlowResult::features. */
std::vector<int>
segmentsOnSide (const FlowResult& result, FeatureSide side);

/** \brief The significant ones among \a segments (indices into result.segments): those whose volume
  * exceeds \a fraction of the segments' total volume, in the given order. */
std::vector<int>
significantSegments (const FlowResult& result, const std::vector<int>& segments, double fraction);

} // namespace pcl_flowseg

/*
 * pcl_flowseg - internal: per-point labels from cell segments.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include <pcl_flowseg/common/flow_result.h>

namespace pcl_flowseg {
namespace core {

/** \brief Labels each input point with the feature (FlowResult::features) holding the largest
  * total volume among the point's incident cells of the reported side (ties: the lower feature),
  * fills FlowResult::point_labels and FlowSegment::point_count. Non-finite points and points with
  * no incident cell in a feature get kNoSegment; duplicates share their vertex's label. */
void
labelPoints (FlowResult& result);

} // namespace core
} // namespace pcl_flowseg

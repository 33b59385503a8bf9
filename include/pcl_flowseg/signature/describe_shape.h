/*
 * pcl_flowseg - describing a shape by its interior features and its interior triangulation
 * (ShapeDescription).
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include <pcl_flowseg/common/flow_result.h>
#include <pcl_flowseg/common/status.h>
#include <pcl_flowseg/signature/shape_description.h>

namespace pcl_flowseg {

/** \brief Describes the interior of a segmentation with interior/exterior separation. The result
  * depends only on \a result (a fixed sampling seed). Fails when the separation was not computed
  * or found no interior. */
Status
describeShape (const FlowResult& result, ShapeDescription& description);

} // namespace pcl_flowseg

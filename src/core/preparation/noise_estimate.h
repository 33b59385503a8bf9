/*
 * pcl_flowseg - internal: the noise of a point sample, estimated from its local neighbourhoods.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include <pcl_flowseg/common/flow_result.h>

#include <vector>

namespace pcl_flowseg {
namespace core {

/** \brief NoiseEstimate of \a vertices (unique, finite) of a \a dimension-D sample: the
  * neighbourhoods of at most kNoiseEstimatePoints evenly spaced vertices, their neighbours among
  * all vertices (an evenly spaced 50,000 of them when there are more). */
NoiseEstimate
estimateNoise (const std::vector<Eigen::Vector3d>& vertices, int dimension);

} // namespace core
} // namespace pcl_flowseg

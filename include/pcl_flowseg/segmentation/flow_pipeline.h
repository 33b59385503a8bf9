/*
 * pcl_flowseg - the flow segmentation on raw coordinates: the whole run, and merging again.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include <pcl_flowseg/common/status.h>
#include <pcl_flowseg/common/system_memory.h>
#include <pcl_flowseg/common/flow_parameters.h>
#include <pcl_flowseg/common/flow_result.h>

#include <Eigen/Core>

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace pcl_flowseg {

/** \brief Progress report: a stage name and the share of the whole run done (0..1). */
using ProgressCallback = std::function<void (const std::string& stage, double fraction)>;

/** \brief Estimated peak memory, in bytes, of segmenting \a points points in \a dimension (2 or 3;
  * 0 = not known yet, taken as 3), interior/exterior separation and denoising included. */
std::size_t
estimateSegmentationMemory (std::size_t points, int dimension);

/** \brief Runs the whole flow segmentation on raw coordinates.
  * \param[in] points input coordinates; NaN/Inf points are skipped and counted, duplicates take
  *            the label of their first copy and are counted.
  * \param[in] normals empty, or one outward normal per point: evidence for interior/exterior.
  * \param[in] params checked first (checkParameters).
  * \param[out] result everything computed, with \a params in result.parameters; empty on failure.
  * \param[in] progress optional.
  * \return success, or why the input cannot be segmented (too few points, collinear, coplanar in
  *         3D mode, too large for the memory, ...). Never throws for bad input. */
Status
runFlowSegmentation (const std::vector<Eigen::Vector3d>& points, const std::vector<Eigen::Vector3d>& normals,
                     const FlowParameters& params, FlowResult& result,
                     const ProgressCallback& progress = ProgressCallback ());

/** \brief runFlowSegmentation without normals. */
Status
runFlowSegmentation (const std::vector<Eigen::Vector3d>& points, const FlowParameters& params, FlowResult& result,
                     const ProgressCallback& progress = ProgressCallback ());

/** \brief Merges the stable manifolds of \a result again with \a merge (result.parameters.merge
  * becomes \a merge); the triangulation, flow and interior are kept, so this is cheap. */
Status
remergeFlowSegmentation (const MergeParameters& merge, FlowResult& result);

} // namespace pcl_flowseg

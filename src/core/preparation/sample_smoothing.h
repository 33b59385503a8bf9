/*
 * pcl_flowseg - internal: smoothing of a noisy 3D sample before its triangulation.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include <pcl_flowseg/common/flow_parameters.h>
#include <pcl_flowseg/common/flow_result.h>

#include <vector>

namespace pcl_flowseg {
namespace core {

/** \brief Smooths the 3D sample \a vertices in place as \a params asks (PreparationParameters::smoothing)
  * and returns the passes made: none when off, or automatic on a sample whose \a noise shows no
  * roughness above kRoughSample; automatic passes stop once the roughness is kSmoothedRoughness. */
unsigned
smoothSample (std::vector<Eigen::Vector3d>& vertices, const NoiseEstimate& noise, const PreparationParameters& params);

} // namespace core
} // namespace pcl_flowseg

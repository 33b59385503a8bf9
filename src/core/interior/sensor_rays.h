/*
 * pcl_flowseg - internal: free space seen by the sensor of a single-view scan.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include <pcl_flowseg/common/flow_result.h>

#include <cstdint>
#include <vector>

namespace pcl_flowseg {
namespace core {

/** \brief The cells crossed by the segments from every sample to \a viewpoint (the cell at the
  * sample itself excepted: at grazing angles it may lie behind the surface): free space, hence
  * outside. Only the first \a seen vertices are samples. One flag per cell; \a marked counts them. */
std::vector<std::uint8_t>
freeSpaceCells (const std::vector<Eigen::Vector3d>& vertices, std::size_t seen, const std::vector<FlowCell>& cells, int dimension,
                const Eigen::Vector3d& viewpoint, std::size_t& marked);

} // namespace core
} // namespace pcl_flowseg

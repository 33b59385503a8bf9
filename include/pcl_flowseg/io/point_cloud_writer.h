/*
 * pcl_flowseg - writing point clouds and per-point labels as PCD files.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include <pcl_flowseg/common/status.h>

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <string>

namespace pcl_flowseg {

/** \brief Writes \a labels as a PCD file (ASCII or binary). The file appears whole or not at all. */
Status
writeLabelCloud (const std::string& path, const pcl::PointCloud<pcl::PointXYZL>& labels, bool binary);

/** \brief Writes a plain point cloud as PCD (ASCII or binary). Atomic. Fails for a \a path that
  * does not end in .pcd (any case). */
Status
writePointCloud (const std::string& path, const pcl::PointCloud<pcl::PointXYZ>& cloud, bool binary);

} // namespace pcl_flowseg

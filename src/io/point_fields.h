/*
 * pcl_flowseg - internal: coordinates (and normals) out of a PCLPointCloud2, field by field.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include <pcl_flowseg/common/status.h>

#include <pcl/PCLPointCloud2.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <Eigen/Core>

#include <string>
#include <vector>

namespace pcl_flowseg {
namespace detail {

/** \brief Appends the points of \a blob to \a cloud, reading x, y (required) and z in whatever
  * numeric type the file used, and the normals (normal_x/y/z or nx/ny/nz) when \a normals is
  * given and the fields exist. Checks that the data is as long as the header says and that every
  * field lies inside the point record (PCL's own conversion does neither). */
Status
readPointFields (const pcl::PCLPointCloud2& blob, const std::string& path, pcl::PointCloud<pcl::PointXYZ>& cloud,
                std::vector<Eigen::Vector3d>* normals);

/** \brief As above, straight into points with normals (zero, and \a has_normals false, when the
  * file has none): no intermediate cloud to copy. */
Status
readPointFields (const pcl::PCLPointCloud2& blob, const std::string& path, pcl::PointCloud<pcl::PointNormal>& cloud,
                bool& has_normals);

} // namespace detail
} // namespace pcl_flowseg

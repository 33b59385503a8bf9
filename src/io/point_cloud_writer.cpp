/*
 * pcl_flowseg - writing point clouds and per-point labels as PCD files.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include <pcl_flowseg/io/point_cloud_writer.h>

#include <pcl_flowseg/io/atomic_file.h>

#include <pcl/io/pcd_io.h>

namespace pcl_flowseg {

Status
writeLabelCloud (const std::string& path, const pcl::PointCloud<pcl::PointXYZL>& labels, bool binary)
{
  return writeFileAtomically (path, [&] (const std::string& tmp) {
    pcl::PCDWriter writer;
    const int rc = binary ? writer.writeBinary (tmp, labels) : writer.writeASCII (tmp, labels, 8);
    return rc == 0 ? Status::success () : Status::error ("PCD writer failed");
  });
}

Status
writePointCloud (const std::string& path, const pcl::PointCloud<pcl::PointXYZ>& cloud, bool binary)
{
  return writeFileAtomically (path, [&] (const std::string& tmp) {
    pcl::PCDWriter writer;
    const int rc = binary ? writer.writeBinary (tmp, cloud) : writer.writeASCII (tmp, cloud, 7);
    return rc == 0 ? Status::success () : Status::error ("PCD writer failed");
  });
}

} // namespace pcl_flowseg

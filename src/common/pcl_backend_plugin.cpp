/*
 * pcl_flowseg - the plugin libpcl_flowseg_pcl.so: PCL's I/O and filters behind the table the library
 * opens on first use (common/pcl_backend.h says why).
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include "common/pcl_backend.h"

#include <pcl/filters/statistical_outlier_removal.h>
#include <pcl/io/pcd_io.h>
#include <pcl/io/ply_io.h>

namespace {

int
loadPcd (const std::string& path, pcl::PCLPointCloud2& blob, Eigen::Vector4f& origin, Eigen::Quaternionf& orientation)
{
  return pcl::io::loadPCDFile (path, blob, origin, orientation);
}

int
loadPlyCloud (const std::string& path, pcl::PCLPointCloud2& blob)
{
  return pcl::io::loadPLYFile (path, blob);
}

int
loadPlyMesh (const std::string& path, pcl::PolygonMesh& mesh)
{
  return pcl::io::loadPLYFile (path, mesh);
}

int
writePcdXyz (const std::string& path, const pcl::PointCloud<pcl::PointXYZ>& cloud, bool binary)
{
  pcl::PCDWriter writer;
  return binary ? writer.writeBinary (path, cloud) : writer.writeASCII (path, cloud, 7);
}

int
writePcdXyzlBinary (const std::string& path, const pcl::PointCloud<pcl::PointXYZL>& cloud)
{
  pcl::PCDWriter writer;
  return writer.writeBinary (path, cloud);
}

void
statisticalOutliers (const pcl::PointCloud<pcl::PointXYZ>::ConstPtr& cloud, int mean_k, double deviations,
                     pcl::Indices& kept)
{
  pcl::StatisticalOutlierRemoval<pcl::PointXYZ> filter;
  filter.setInputCloud (cloud);
  filter.setMeanK (mean_k);
  filter.setStddevMulThresh (deviations);
  filter.filter (kept);
}

const pcl_flowseg::detail::PclBackend kTable{&loadPcd,    &loadPlyCloud,       &loadPlyMesh,
                                             &writePcdXyz, &writePcdXyzlBinary, &statisticalOutliers};

} // namespace

extern "C" __attribute__ ((visibility ("default"))) const pcl_flowseg::detail::PclBackend*
pcl_flowseg_pcl_backend_v1 ()
{
  return &kTable;
}

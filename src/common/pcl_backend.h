/*
 * pcl_flowseg - internal: PCL's I/O and filters, loaded the first time they are needed.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include <pcl_flowseg/common/status.h>

#include <pcl/PCLPointCloud2.h>
#include <pcl/PolygonMesh.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>
#include <pcl/types.h>

#include <string>

namespace pcl_flowseg {
namespace detail {

/** \brief The calls into pcl_io and pcl_filters the library makes, as a table.
  *
  * pcl_io pulls in VTK: linking it would load about 40 libraries into every process that uses
  * pcl_flowseg, most of its start-up time. The library reads and writes its usual formats itself
  * and reaches PCL only for the rest (compressed PCD, PLY, PCL's PCD writer, the statistical outlier
  * filter); those calls live in the plugin libpcl_flowseg_pcl.so beside the library, opened on first
  * use. Every function returns PCL's own code: negative (or non-zero for the writers) on failure. */
struct PclBackend
{
  int (*load_pcd) (const std::string& path, pcl::PCLPointCloud2& blob, Eigen::Vector4f& origin,
                   Eigen::Quaternionf& orientation);
  int (*load_ply_cloud) (const std::string& path, pcl::PCLPointCloud2& blob);
  int (*load_ply_mesh) (const std::string& path, pcl::PolygonMesh& mesh);
  int (*write_pcd_xyz) (const std::string& path, const pcl::PointCloud<pcl::PointXYZ>& cloud, bool binary);
  int (*write_pcd_xyzl_binary) (const std::string& path, const pcl::PointCloud<pcl::PointXYZL>& cloud);
  /** StatisticalOutlierRemoval with \a mean_k neighbours and \a deviations standard deviations. */
  void (*statistical_outliers) (const pcl::PointCloud<pcl::PointXYZ>::ConstPtr& cloud, int mean_k, double deviations,
                                pcl::Indices& kept);
};

/** \brief The symbol the plugin exports: a function returning its table (the suffix is the table's
  * version; a plugin from another build of the table does not have it). */
constexpr const char* kPclBackendSymbol = "pcl_flowseg_pcl_backend_v1";

/** \brief The plugin's table, loaded once (thread-safe); null with \a why set when the plugin cannot
  * be opened (missing, or built for another version). */
const PclBackend*
pclBackend (Status& why);

} // namespace detail
} // namespace pcl_flowseg

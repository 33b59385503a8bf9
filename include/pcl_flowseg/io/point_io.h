/*
 * pcl_flowseg - reading point samples from the file formats the apps accept.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include <pcl_flowseg/common/status.h>

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <string>
#include <vector>

namespace pcl_flowseg {

/** \brief Reads the points of \a path into \a cloud, choosing the format by extension:
  * - `.pcd`, `.ply` (fields x, y required; z = 0 when absent): ascii and binary PCD by a strict
  *   reader of our own, binary_compressed PCD and PLY by PCL's readers after a header check;
  * - `.xyz`, `.txt`, `.csv`: one point per line, 2 or more numbers separated by white space or
  *   commas (x y [z], further columns ignored); `#` starts a comment;
  * - `.off`, `.obj`: the vertices of the mesh (faces are ignored).
  * Fails with a message naming the file (and the line, for text formats) on a missing or
  * unreadable file, an unknown extension, a malformed file or a file without points.
  * Non-finite coordinates are kept (the segmentation skips and counts them). */
Status
loadPointCloud (const std::string& path, pcl::PointCloud<pcl::PointXYZ>& cloud);

/** \brief As above, and also the normals when the file has them (PCD/PLY fields normal_x/y/z or
  * nx/ny/nz; text files with 6 or more columns: x y z nx ny nz); \a normals is left empty
  * otherwise. A PCD file's VIEWPOINT becomes the cloud's sensor_origin_. */
Status
loadPointCloud (const std::string& path, pcl::PointCloud<pcl::PointXYZ>& cloud, std::vector<Eigen::Vector3d>& normals);

/** \brief As above, into a cloud that carries the normals (zero when the file has none, then
  * \a has_normals is false) and the file's VIEWPOINT as sensor_origin_: what
  * pcl::FlowSegmentation<pcl::PointNormal> takes with setUseNormals and setUseSensorOrigin. */
Status
loadPointCloud (const std::string& path, pcl::PointCloud<pcl::PointNormal>& cloud, bool& has_normals);

/** \brief True when loadPointCloud knows the extension of \a path. */
bool
isSupportedPointFile (const std::string& path);

/** \brief True when files like \a path carry a sensor origin (the viewpoint of a single-view
  * scan): PCD files, by their VIEWPOINT (0 0 0 when the header has none, as the format says).
  * The others (PLY, text, meshes) carry none, and their cloud's sensor_origin_ means nothing. */
bool
carriesSensorOrigin (const std::string& path);

} // namespace pcl_flowseg

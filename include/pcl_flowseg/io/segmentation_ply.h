/*
 * pcl_flowseg - a segmentation as PLY files a viewer shows: coloured points, the reconstructed surface.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include <pcl_flowseg/common/flow_result.h>
#include <pcl_flowseg/common/status.h>

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <string>

namespace pcl_flowseg {

/** \brief Every input point coloured by its feature and, in 2D, the Delaunay triangles as faces
  * coloured by feature. \a labels holds one point per point handed to the segmentation, in that
  * order (FlowSegmentation::getLabelCloud of a run without setIndices). Points with non-finite
  * coordinates are not written. Atomic. ASCII, or little-endian binary with \a binary (smaller,
  * faster to write and read). */
Status
writeSegmentationPly (const std::string& path, const FlowResult& result,
                      const pcl::PointCloud<pcl::PointXYZL>& labels, bool binary = false);

/** \brief The reconstructed surface as a PLY mesh: in 3D the boundary triangles, in 2D the
  * interior triangles as faces and the boundary curve as edges. Atomic. Fails when the
  * interior/exterior separation was not run. ASCII, or little-endian binary with \a binary. */
Status
writeSurfacePly (const std::string& path, const FlowResult& result, bool binary = false);

} // namespace pcl_flowseg

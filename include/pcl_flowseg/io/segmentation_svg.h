/*
 * pcl_flowseg - a 2D segmentation as an SVG drawing.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include <pcl_flowseg/common/flow_result.h>
#include <pcl_flowseg/common/status.h>

#include <string>

namespace pcl_flowseg {

/** \brief Writes a 2D result as SVG, which a browser shows: the Delaunay triangles coloured by
  * feature (others light grey), the edges between stable manifolds (Gabriel edges, the exact
  * boundaries of the stable manifolds in 2D) in black, the reconstructed curve in blue, the sample
  * points and the maxima of the features (red dots). Fails for 3D results. Atomic. */
Status
writeSegmentationSvg (const std::string& path, const FlowResult& result);

} // namespace pcl_flowseg

/*
 * pcl_flowseg - writing segmentation results: labelled PCD, JSON summary, coloured PLY.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include <pcl_flowseg/segmentation/flow_result.h>
#include <pcl_flowseg/signature/signature.h>
#include <pcl_flowseg/common/status.h>

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <array>
#include <cstdint>
#include <string>

namespace pcl_flowseg {

/** \brief A distinct colour for segment \a id (golden-ratio hues); grey for kNoSegment and for
  * the segment at infinity. */
std::array<std::uint8_t, 3>
segmentColour (std::uint32_t id, bool infinity = false);

/** \brief Writes \a labels as a PCD file (ASCII or binary). The file appears whole or not at all. */
Status
writeLabelCloud (const std::string& path, const pcl::PointCloud<pcl::PointXYZL>& labels, bool binary);

/** \brief Writes a plain point cloud as PCD (ASCII or binary). Atomic. */
Status
writePointCloud (const std::string& path, const pcl::PointCloud<pcl::PointXYZ>& cloud, bool binary);

/** \brief Extra facts for the JSON summary that the result does not hold. */
struct RunInfo
{
  std::string input;   ///< input file name
  /** Features above this share of the reported features' volume are marked "significant". */
  double significance = kDefaultSignificance;
  double read_ms = 0.0;
};

/** \brief Writes a JSON summary: the parameters, counts (points, cells, maxima, manifolds, segments), the
  * segments (id, volume, centroid, point and cell counts, maximum height and location), the
  * adjacency (saddles), timings per stage in ms, warnings. Atomic. */
Status
writeSegmentationJson (const std::string& path, const FlowResult& result, const RunInfo& info);

/** \brief Writes a PLY a viewer shows in colour: every input point coloured by its segment,
  * and in 2D the Delaunay triangles as faces coloured by segment. \a labels holds one point per
  * point handed to the segmentation, in that order (FlowSegmentation::getLabelCloud of a run
  * without setIndices). Points with non-finite coordinates are not written. Atomic. */
Status
writeSegmentationPly (const std::string& path, const FlowResult& result,
                      const pcl::PointCloud<pcl::PointXYZL>& labels);

/** \brief Writes a 2D result as SVG, which a browser shows: the Delaunay triangles coloured by
  * feature (others light grey), the edges between stable manifolds (Gabriel edges, the exact
  * boundaries of the stable manifolds in 2D) in black, the reconstructed curve in blue, the sample
  * points and the maxima of the features (red dots). Fails for 3D results. Atomic. */
Status
writeSegmentationSvg (const std::string& path, const FlowResult& result);

/** \brief The interior/exterior boundary as triangles (3D; oriented so that their normals point
  * out of the interior) or edges (2D; each edge listed with the interior on its left), over the
  * vertices of \a result. Empty when interior/exterior separation was not run. */
std::vector<std::array<int, 3>>
boundaryFacets (const FlowResult& result);

/** \brief Writes the reconstructed surface as a PLY mesh: 3D the boundary triangles, 2D the
  * interior triangles as faces and the boundary curve as edges. Atomic. Fails when interior/
  * exterior separation was not run. */
Status
writeSurfacePly (const std::string& path, const FlowResult& result);

} // namespace pcl_flowseg

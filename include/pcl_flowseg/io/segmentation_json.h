/*
 * pcl_flowseg - the JSON summary of a segmentation: parameters, counts, features, segments, saddles.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include <pcl_flowseg/common/feature_significance.h>
#include <pcl_flowseg/common/flow_result.h>
#include <pcl_flowseg/common/status.h>

#include <string>

namespace pcl_flowseg {

/** \brief Facts for the JSON summary that the result does not hold. */
struct RunInfo
{
  std::string input;   ///< input file name
  /** Features above this share of the reported features' volume are marked "significant"
    * (significantSegments). */
  double significance = kDefaultSignificance;
  double read_ms = 0.0; ///< time to read the input
};

/** \brief Writes a JSON summary: the parameters, counts (points, cells, maxima, manifolds,
  * segments), the interior/exterior report, the segments (id, volume, centroid, point and cell
  * counts, maximum height and location, significant), the adjacency (saddles), timings per stage
  * in ms, warnings. Atomic. */
Status
writeSegmentationJson (const std::string& path, const FlowResult& result, const RunInfo& info);

} // namespace pcl_flowseg

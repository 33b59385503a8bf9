/*
 * pcl_flowseg - internal: isolated points (outliers) left out before the triangulation.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include "core/preparation/point_preparation.h"

#include <pcl_flowseg/common/status.h>

#include <cstddef>
#include <vector>

namespace pcl_flowseg {
namespace core {

/** \brief Neighbours PCL's StatisticalOutlierRemoval averages the distance over. */
constexpr int kOutlierNeighbours = 8;
/** \brief A point is an outlier when its mean neighbour distance exceeds the mean over all points by
  * this many standard deviations. */
constexpr double kOutlierDeviations = 3.0;

/** \brief Removes from \a prepared the vertices PCL's StatisticalOutlierRemoval rejects: the vertex
  * list (and the plane coordinates in 2D) shrink, their input points map to -1 (no segment).
  * Keeps every vertex when fewer than dimension + 2 would remain. Sets \a removed_points to the input
  * points left out; fails only when PCL's filters cannot be loaded (common/pcl_backend.h). */
Status
removeOutliers (PreparedPoints& prepared, std::size_t& removed_points);

/** \brief Removes the vertices whose \a keep flag is 0 (see removeOutliers). */
std::size_t
removeVertices (PreparedPoints& prepared, const std::vector<char>& keep);

} // namespace core
} // namespace pcl_flowseg

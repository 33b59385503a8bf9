/*
 * pcl_flowseg - internal: the points of a sample a camera sees.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include <pcl_flowseg/signature/view_description.h>

namespace pcl_flowseg {
namespace internal {

/** \brief The points of \a points a pinhole camera at \a camera looking at \a target sees: a depth
  * buffer of square image cells of about \a spacing at the target's distance; a point is seen when
  * it lies within \a tolerance cells' width of the nearest depth of the cells within \a reach of
  * its own (reach 1: the 3 x 3 cells around it, so that the gaps of a sparse front hide what lies
  * behind). */
std::vector<Eigen::Vector3d>
visiblePoints (const std::vector<Eigen::Vector3d>& points, const Eigen::Vector3d& camera, const Eigen::Vector3d& target,
               double spacing, long reach = 1, double tolerance = 2.0);

} // namespace internal
} // namespace pcl_flowseg

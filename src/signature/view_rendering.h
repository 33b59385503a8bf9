/*
 * pcl_flowseg - internal: the points of a sample a camera sees, and their description.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include <pcl_flowseg/signature/view_description.h>

namespace pcl_flowseg {
namespace internal {

/** \brief Describes \a visible, the points a camera at \a camera sees (at least kMinViewPoints). */
Status
describeVisiblePoints (const std::vector<Eigen::Vector3d>& visible, const Eigen::Vector3d& camera, ViewDescription& view);

/** \brief At most \a count of \a points spread evenly over them whatever their density
  * (farthest-point sampling from the point nearest their centroid); any prefix is spread evenly too. */
std::vector<Eigen::Vector3f>
farthestPoints (const std::vector<Eigen::Vector3d>& points, std::size_t count);

/** \brief The unit normal (unoriented) of \a cloud at each of \a at: the direction of least spread
  * of the kNormalNeighbours points of \a cloud nearest to it. */
std::vector<Eigen::Vector3f>
pointNormals (const std::vector<Eigen::Vector3d>& cloud, const std::vector<Eigen::Vector3f>& at);

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

/*
 * pcl_flowseg - internal: the description of the points one view sees.
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

} // namespace internal
} // namespace pcl_flowseg

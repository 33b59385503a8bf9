/*
 * pcl_flowseg - internal: the image plane of a sensor at a viewpoint.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include <Eigen/Core>

#include <vector>

namespace pcl_flowseg {
namespace core {

/** \brief A pinhole image seen from a viewpoint: a direction becomes the point where it meets the
  * plane at unit distance along the view axis (aimed at the centroid of the scene). */
struct ViewImage
{
  Eigen::Vector3d origin = Eigen::Vector3d::Zero ();
  Eigen::Vector3d axis = Eigen::Vector3d::UnitZ (), right = Eigen::Vector3d::UnitX (), up = Eigen::Vector3d::UnitY ();

  /** Image coordinates of \a p (z = 0); false for a point not in front of the sensor. */
  bool project (const Eigen::Vector3d& p, Eigen::Vector2d& image) const;
};

/** \brief The image of a sensor at \a viewpoint looking at the centroid of \a points. */
ViewImage
viewImage (const std::vector<Eigen::Vector3d>& points, const Eigen::Vector3d& viewpoint);

/** \brief The k nearest of \a points (image coordinates) to each of \a queries, FLANN kd-tree on
  * all cores: row q holds ids[q k .. q k + k - 1] and their distances, nearest first. Fewer points
  * than k give rows padded with -1 and infinite distances. */
void
nearestImagePoints (const std::vector<Eigen::Vector2d>& points, const std::vector<Eigen::Vector2d>& queries, int k,
                    std::vector<int>& ids, std::vector<double>& distances);

} // namespace core
} // namespace pcl_flowseg

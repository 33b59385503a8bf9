/*
 * pcl_flowseg - outliers for robustness tests: sample points replaced by uniform points in the box.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include <Eigen/Core>

#include <cstdint>
#include <vector>

namespace pcl_flowseg {

/** \brief Replaces round(\a share * n) of \a points, chosen at random, by points drawn uniformly
  * from the axis-aligned bounding box of all points (a flat box for planar points); reproducible
  * for \a seed. \a share is clamped to [0, 1]. Returns how many points were replaced. */
std::size_t
replaceWithOutliers (std::vector<Eigen::Vector3d>& points, double share, std::uint32_t seed);

} // namespace pcl_flowseg

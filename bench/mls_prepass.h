/*
 * PCL's MovingLeastSquares as a pre-pass before the segmentation: the benchmarks weigh it against
 * the module's own smoothing before the triangulation (PreparationParameters::smoothing).
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include <Eigen/Core>

#include <vector>

namespace flowseg_bench {

/** \brief \a points, each projected by pcl::MovingLeastSquares (quadratic fit, no upsampling)
  * onto the surface fitted to its neighbours within \a radius_in_spacings sample spacings (the
  * median distance to the 4th nearest neighbour). A point MLS leaves out keeps its position, so
  * the result holds the same points in the same order. \a seconds, when given, receives the time. */
std::vector<Eigen::Vector3d>
movingLeastSquares (const std::vector<Eigen::Vector3d>& points, double radius_in_spacings, double* seconds = nullptr);

} // namespace flowseg_bench

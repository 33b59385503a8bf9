/*
 * pcl_flowseg - internal: sample points that lie off the surface their neighbours sample (outliers).
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include <Eigen/Core>

#include <cstddef>
#include <vector>

namespace pcl_flowseg {
namespace core {

/** \brief A point is detached when it lies off the PCA plane (2D: line) of its neighbours by more than
  * this many sample spacings ... */
constexpr double kDetachedSpacings = 1.0;
/** \brief ... plus this many standard deviations of the neighbours along the plane's normal (noise and
  * curvature move surface points off the plane by about that much, outliers by more). */
constexpr double kDetachedDeviations = 2.0;
/** \brief A point is also detached when its 4th nearest neighbour lies this many times farther than
  * its neighbours' own (alone beside the surface rather than off it). */
constexpr double kDetachedReach = 4.0;

/** \brief Whether \a point lies off the PCA plane (2D: line) of the points \a others[0 .. count-1]
  * by more than kDetachedSpacings times \a spacing plus kDetachedDeviations times their standard
  * deviation along its normal. */
bool
liesOffNeighbours (const std::vector<Eigen::Vector3d>& points, std::size_t point, const int* others, std::size_t count,
                   double spacing, int dimension);

/** \brief 1 for every point of \a points that is detached from the surface (2D: curve) its
  * kNoiseNeighbours nearest neighbours sample, 0 for the others: it lies off their plane
  * (liesOffNeighbours, the spacing being the median of the neighbours' Neighbourhoods::reach), or
  * its own reach exceeds kDetachedReach times that spacing. Every point is tested (both cores). */
std::vector<char>
detachedPoints (const std::vector<Eigen::Vector3d>& points, int dimension);

} // namespace core
} // namespace pcl_flowseg

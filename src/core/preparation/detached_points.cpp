/*
 * pcl_flowseg - internal: sample points that lie off the surface their neighbours sample (outliers).
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include "core/preparation/detached_points.h"

#include "core/geometry/point_neighbourhoods.h"
#include "core/support/parallel.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace pcl_flowseg {
namespace core {

bool
liesOffNeighbours (const std::vector<Eigen::Vector3d>& points, std::size_t point, const int* others, std::size_t count,
                   double spacing, int dimension)
{
  const PlaneFit fit = fitPlane (points, others, count, dimension);
  if (fit.normal.isZero ())
    return false;
  const Eigen::Vector3d e = points[point] - fit.mean;
  // 2D: the points lie in one plane, so the offset across the curve's direction is the one in the plane.
  const double offset = dimension == 3 ? std::abs (e.dot (fit.normal)) : (e - e.dot (fit.direction) * fit.direction).norm ();
  return offset > kDetachedSpacings * spacing + kDetachedDeviations * std::sqrt (fit.normal_variance);
}

std::vector<char>
detachedPoints (const std::vector<Eigen::Vector3d>& points, int dimension)
{
  const std::size_t n = points.size ();
  std::vector<char> detached (n, 0);
  if (n <= static_cast<std::size_t> (kNoiseNeighbours))
    return detached;
  const Neighbourhoods hoods = nearestNeighbourhoods (points, 1);
  parallelFor (n, [&] (std::size_t i) {
    std::array<int, kNoiseNeighbours> others;
    std::array<float, kNoiseNeighbours> reach;
    std::size_t count = 0;
    for (std::size_t k = hoods.first[i]; k < hoods.first[i + 1] && count < others.size (); ++k)
      if (hoods.ids[k] != static_cast<int> (i))
      {
        others[count] = hoods.ids[k];
        reach[count] = hoods.reach[static_cast<std::size_t> (hoods.ids[k])];
        ++count;
      }
    std::nth_element (reach.begin (), reach.begin () + static_cast<long> (count / 2), reach.begin () + static_cast<long> (count));
    const double spacing = reach[count / 2];
    const bool alone = spacing > 0.0 && hoods.reach[i] > kDetachedReach * spacing;
    detached[i] = alone || liesOffNeighbours (points, i, others.data (), count, spacing, dimension) ? 1 : 0;
  });
  return detached;
}

} // namespace core
} // namespace pcl_flowseg

/*
 * pcl_flowseg - outliers for robustness tests: sample points replaced by uniform points in the box.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include <pcl_flowseg/io/sample_outliers.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>

namespace pcl_flowseg {

std::size_t
replaceWithOutliers (std::vector<Eigen::Vector3d>& points, double share, std::uint32_t seed)
{
  if (points.empty () || !(share > 0.0))
    return 0;
  const std::size_t count = static_cast<std::size_t> (std::llround (std::min (share, 1.0) * static_cast<double> (points.size ())));
  Eigen::Vector3d lo = points.front (), hi = lo;
  for (const auto& p : points)
  {
    lo = lo.cwiseMin (p);
    hi = hi.cwiseMax (p);
  }
  std::vector<std::size_t> order (points.size ());
  std::iota (order.begin (), order.end (), 0);
  std::mt19937_64 rng (seed);
  std::shuffle (order.begin (), order.end (), rng);
  std::uniform_real_distribution<double> u (0.0, 1.0);
  for (std::size_t k = 0; k < count; ++k)
  {
    const Eigen::Vector3d t (u (rng), u (rng), u (rng));
    points[order[k]] = lo + t.cwiseProduct (hi - lo);
  }
  return count;
}

} // namespace pcl_flowseg

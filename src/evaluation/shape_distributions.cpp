/*
 * pcl_flowseg evaluation - shape distributions: Osada's D2 and PCL's ESF, the global descriptors signatures are compared with.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include <pcl_flowseg/evaluation/shape_distributions.h>

#include <pcl/features/esf.h>

#include <algorithm>
#include <cmath>
#include <random>

namespace pcl_flowseg {

std::vector<double>
d2Distribution (const std::vector<Eigen::Vector3d>& points, std::size_t pairs, int bins, std::uint32_t seed)
{
  std::vector<double> h (static_cast<std::size_t> (std::max (1, bins)), 0.0);
  if (points.size () < 2 || pairs == 0)
    return h;
  std::mt19937 rng (seed);
  std::uniform_int_distribution<std::size_t> pick (0, points.size () - 1);
  std::vector<double> d (pairs);
  double mean = 0.0;
  for (auto& v : d)
  {
    v = (points[pick (rng)] - points[pick (rng)]).norm ();
    mean += v;
  }
  mean /= static_cast<double> (pairs);
  if (!(mean > 0.0))
    return h;
  for (double v : d)
  {
    const int b = static_cast<int> (v / mean / 3.0 * bins);
    h[static_cast<std::size_t> (std::min (std::max (b, 0), bins - 1))] += 1.0 / static_cast<double> (pairs);
  }
  return h;
}

Status
esfDescriptor (const std::vector<Eigen::Vector3d>& points, std::vector<double>& h)
{
  h.clear ();
  pcl::PointCloud<pcl::PointXYZ>::Ptr cloud (new pcl::PointCloud<pcl::PointXYZ>);
  // ESF voxelises the cloud: scale it to a fixed size first (its histograms are scale invariant
  // in intent, its voxel grid is not).
  Eigen::Vector3d lo = points.empty () ? Eigen::Vector3d::Zero () : points.front (), hi = lo;
  for (const auto& p : points)
  {
    lo = lo.cwiseMin (p);
    hi = hi.cwiseMax (p);
  }
  const double diag = (hi - lo).norm ();
  for (const auto& p : points)
  {
    const Eigen::Vector3d q = diag > 0 ? Eigen::Vector3d ((p - lo) / diag) : Eigen::Vector3d::Zero ();
    cloud->push_back (pcl::PointXYZ (static_cast<float> (q.x ()), static_cast<float> (q.y ()), static_cast<float> (q.z ())));
  }
  pcl::ESFEstimation<pcl::PointXYZ, pcl::ESFSignature640> esf;
  esf.setInputCloud (cloud);
  pcl::PointCloud<pcl::ESFSignature640> out;
  esf.compute (out);
  if (out.size () != 1)
    return Status::error ("PCL's ESF estimation gave no descriptor for " + std::to_string (points.size ()) + " points");
  double sum = 0.0;
  for (float v : out[0].histogram)
  {
    h.push_back (v);
    sum += v;
  }
  if (sum > 0)
    for (auto& v : h)
      v /= sum;
  return Status::success ();
}

double
histogramSimilarity (const std::vector<double>& a, const std::vector<double>& b)
{
  double l1 = 0.0;
  for (std::size_t k = 0; k < std::min (a.size (), b.size ()); ++k)
    l1 += std::abs (a[k] - b[k]);
  return 1.0 - 0.5 * l1;
}

} // namespace pcl_flowseg

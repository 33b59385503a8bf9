/*
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include "mls_prepass.h"

#include <pcl/point_types.h>
#include <pcl/search/kdtree.h>
#include <pcl/surface/mls.h>

#include <algorithm>
#include <chrono>
#include <cmath>

namespace flowseg_bench {

namespace {

/** The median distance to the 4th nearest neighbour over at most 2000 evenly spaced points. */
double
medianSpacing (const pcl::PointCloud<pcl::PointXYZ>& cloud, const pcl::search::KdTree<pcl::PointXYZ>& tree)
{
  std::vector<double> distances;
  const std::size_t step = std::max<std::size_t> (1, cloud.size () / 2000);
  pcl::Indices ids;
  std::vector<float> squared;
  for (std::size_t i = 0; i < cloud.size (); i += step)
    if (tree.nearestKSearch (cloud[i], 5, ids, squared) == 5)
      distances.push_back (std::sqrt (static_cast<double> (squared[4])));
  if (distances.empty ())
    return 0.0;
  std::nth_element (distances.begin (), distances.begin () + distances.size () / 2, distances.end ());
  return distances[distances.size () / 2];
}

} // namespace

std::vector<Eigen::Vector3d>
movingLeastSquares (const std::vector<Eigen::Vector3d>& points, double radius_in_spacings, double* seconds)
{
  const auto start = std::chrono::steady_clock::now ();
  std::vector<Eigen::Vector3d> result (points);
  if (points.size () < 5 || !(radius_in_spacings > 0.0))
    return result;
  // Coordinates relative to the first point: PCL works in float.
  const Eigen::Vector3d origin = points.front ();
  pcl::PointCloud<pcl::PointXYZ>::Ptr cloud (new pcl::PointCloud<pcl::PointXYZ>);
  for (const Eigen::Vector3d& p : points)
  {
    const Eigen::Vector3f q = (p - origin).cast<float> ();
    cloud->push_back (pcl::PointXYZ (q.x (), q.y (), q.z ()));
  }
  pcl::search::KdTree<pcl::PointXYZ>::Ptr tree (new pcl::search::KdTree<pcl::PointXYZ>);
  tree->setInputCloud (cloud);
  pcl::MovingLeastSquares<pcl::PointXYZ, pcl::PointXYZ> mls;
  mls.setInputCloud (cloud);
  mls.setSearchMethod (tree);
  mls.setPolynomialOrder (2);
  mls.setSearchRadius (radius_in_spacings * medianSpacing (*cloud, *tree));
  pcl::PointCloud<pcl::PointXYZ> projected;
  mls.process (projected);
  const pcl::PointIndicesPtr input_of = mls.getCorrespondingIndices ();
  for (std::size_t k = 0; k < projected.size () && k < input_of->indices.size (); ++k)
    result[static_cast<std::size_t> (input_of->indices[k])] = origin + projected[k].getVector3fMap ().cast<double> ();
  if (seconds)
    *seconds = std::chrono::duration<double> (std::chrono::steady_clock::now () - start).count ();
  return result;
}

} // namespace flowseg_bench

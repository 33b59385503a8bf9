/*
 * pcl_flowseg - internal: isolated points (outliers) left out before the triangulation.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include "core/preparation/outlier_removal.h"

#include <pcl/filters/statistical_outlier_removal.h>
#include <pcl/point_types.h>

#include <algorithm>
#include <vector>

namespace pcl_flowseg {
namespace core {

namespace {

/** The vertices PCL's filter keeps, as a flag per vertex. */
std::vector<char>
keptVertices (const std::vector<Eigen::Vector3d>& vertices)
{
  pcl::PointCloud<pcl::PointXYZ>::Ptr cloud (new pcl::PointCloud<pcl::PointXYZ>);
  cloud->reserve (vertices.size ());
  const Eigen::Vector3d origin = vertices.front (); // relative coordinates keep float precision far from 0
  for (const Eigen::Vector3d& v : vertices)
  {
    const Eigen::Vector3d r = v - origin;
    cloud->push_back (pcl::PointXYZ (static_cast<float> (r.x ()), static_cast<float> (r.y ()), static_cast<float> (r.z ())));
  }
  pcl::StatisticalOutlierRemoval<pcl::PointXYZ> filter;
  filter.setInputCloud (cloud);
  filter.setMeanK (kOutlierNeighbours);
  filter.setStddevMulThresh (kOutlierDeviations);
  pcl::Indices kept;
  filter.filter (kept);
  std::vector<char> keep (vertices.size (), 0);
  for (const auto i : kept)
    keep[static_cast<std::size_t> (i)] = 1;
  return keep;
}

} // namespace

std::size_t
removeOutliers (PreparedPoints& prepared)
{
  const std::size_t n = prepared.vertices.size ();
  if (n <= static_cast<std::size_t> (kOutlierNeighbours))
    return 0;
  return removeVertices (prepared, keptVertices (prepared.vertices));
}

std::size_t
removeVertices (PreparedPoints& prepared, const std::vector<char>& keep)
{
  const std::size_t n = prepared.vertices.size ();
  const auto kept_count = static_cast<std::size_t> (std::count (keep.begin (), keep.end (), 1));
  if (kept_count == n || kept_count < static_cast<std::size_t> (prepared.dimension) + 2)
    return 0; // nothing to remove, or too little would be left: keep the sample as it is
  std::vector<int> new_index (n, -1);
  std::size_t kept = 0;
  for (std::size_t v = 0; v < n; ++v)
    if (keep[v])
    {
      new_index[v] = static_cast<int> (kept);
      prepared.vertices[kept] = prepared.vertices[v];
      if (!prepared.planar.empty ())
        prepared.planar[kept] = prepared.planar[v];
      ++kept;
    }
  prepared.vertices.resize (kept);
  if (!prepared.planar.empty ())
    prepared.planar.resize (kept);
  std::size_t removed_points = 0;
  for (int& v : prepared.point_to_vertex)
    if (v >= 0)
    {
      v = new_index[static_cast<std::size_t> (v)];
      removed_points += v < 0;
    }
  return removed_points;
}

} // namespace core
} // namespace pcl_flowseg

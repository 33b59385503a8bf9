/*
 * pcl_flowseg - internal: isolated points (outliers) left out before the triangulation.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include "core/preparation/outlier_removal.h"

#include "common/pcl_backend.h"

#include <algorithm>
#include <vector>

namespace pcl_flowseg {
namespace core {

namespace {

/** The vertices PCL's filter keeps, as a flag per vertex. */
std::vector<char>
keptVertices (const detail::PclBackend& pcl_filters, const std::vector<Eigen::Vector3d>& vertices)
{
  pcl::PointCloud<pcl::PointXYZ>::Ptr cloud (new pcl::PointCloud<pcl::PointXYZ>);
  cloud->reserve (vertices.size ());
  const Eigen::Vector3d origin = vertices.front (); // relative coordinates keep float precision far from 0
  for (const Eigen::Vector3d& v : vertices)
  {
    const Eigen::Vector3d r = v - origin;
    cloud->push_back (pcl::PointXYZ (static_cast<float> (r.x ()), static_cast<float> (r.y ()), static_cast<float> (r.z ())));
  }
  pcl::Indices kept;
  pcl_filters.statistical_outliers (cloud, kOutlierNeighbours, kOutlierDeviations, kept);
  std::vector<char> keep (vertices.size (), 0);
  for (const auto i : kept)
    keep[static_cast<std::size_t> (i)] = 1;
  return keep;
}

} // namespace

Status
removeOutliers (PreparedPoints& prepared, std::size_t& removed_points)
{
  removed_points = 0;
  const std::size_t n = prepared.vertices.size ();
  if (n <= static_cast<std::size_t> (kOutlierNeighbours))
    return Status::success ();
  Status loaded;
  const detail::PclBackend* pcl_filters = detail::pclBackend (loaded);
  if (!pcl_filters)
    return loaded;
  removed_points = removeVertices (prepared, keptVertices (*pcl_filters, prepared.vertices));
  return Status::success ();
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

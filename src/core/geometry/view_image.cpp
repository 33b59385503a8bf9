/*
 * pcl_flowseg - internal: the image plane of a sensor at a viewpoint.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include "core/geometry/view_image.h"

#include <Eigen/Geometry>
#include <flann/flann.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace pcl_flowseg {
namespace core {

bool
ViewImage::project (const Eigen::Vector3d& p, Eigen::Vector2d& image) const
{
  const Eigen::Vector3d q = p - origin;
  const double depth = q.dot (axis);
  if (!(depth > 0))
    return false;
  image = Eigen::Vector2d (q.dot (right) / depth, q.dot (up) / depth);
  return true;
}

ViewImage
viewImage (const std::vector<Eigen::Vector3d>& points, const Eigen::Vector3d& viewpoint)
{
  Eigen::Vector3d centre = Eigen::Vector3d::Zero ();
  for (const Eigen::Vector3d& p : points)
    centre += p;
  ViewImage view;
  view.origin = viewpoint;
  if (points.empty () || (centre / static_cast<double> (points.size ()) - viewpoint).squaredNorm () == 0.0)
    return view;
  view.axis = (centre / static_cast<double> (points.size ()) - viewpoint).normalized ();
  const Eigen::Vector3d helper = std::abs (view.axis.x ()) < 0.9 ? Eigen::Vector3d::UnitX () : Eigen::Vector3d::UnitY ();
  view.right = view.axis.cross (helper).normalized ();
  view.up = view.axis.cross (view.right);
  return view;
}

void
nearestImagePoints (const std::vector<Eigen::Vector2d>& points, const std::vector<Eigen::Vector2d>& queries, int k,
                    std::vector<int>& ids, std::vector<double>& distances)
{
  const std::size_t rows = queries.size (), kk = static_cast<std::size_t> (k);
  ids.assign (rows * kk, -1);
  distances.assign (rows * kk, std::numeric_limits<double>::infinity ());
  const std::size_t found = std::min (kk, points.size ());
  if (rows == 0 || found == 0)
    return;
  // Coordinates relative to the first point keep float precision.
  std::vector<float> data (2 * points.size ()), query_data (2 * rows);
  for (std::size_t i = 0; i < points.size (); ++i)
    for (int a = 0; a < 2; ++a)
      data[2 * i + static_cast<std::size_t> (a)] = static_cast<float> (points[i][a] - points[0][a]);
  for (std::size_t i = 0; i < rows; ++i)
    for (int a = 0; a < 2; ++a)
      query_data[2 * i + static_cast<std::size_t> (a)] = static_cast<float> (queries[i][a] - points[0][a]);
  flann::Matrix<float> matrix (data.data (), points.size (), 2), query (query_data.data (), rows, 2);
  flann::Index<flann::L2_Simple<float>> index (matrix, flann::KDTreeSingleIndexParams (10));
  index.buildIndex ();
  std::vector<int> found_ids (rows * found);
  std::vector<float> found_dist (rows * found);
  flann::Matrix<int> id_matrix (found_ids.data (), rows, found);
  flann::Matrix<float> dist_matrix (found_dist.data (), rows, found);
  flann::SearchParams search (flann::FLANN_CHECKS_UNLIMITED, 0.0f, true);
  search.cores = 0; // all cores
  index.knnSearch (query, id_matrix, dist_matrix, found, search);
  for (std::size_t r = 0; r < rows; ++r)
    for (std::size_t j = 0; j < found; ++j)
    {
      ids[r * kk + j] = found_ids[r * found + j];
      distances[r * kk + j] = std::sqrt (static_cast<double> (found_dist[r * found + j]));
    }
}

} // namespace core
} // namespace pcl_flowseg

/*
 * pcl_flowseg - internal: the nearest neighbours of a point sample's points, the PCA plane fits of
 * those neighbourhoods and medians over them (noise estimate, outliers, smoothing, denoising).
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include "core/geometry/point_neighbourhoods.h"

#include <pcl_flowseg/common/flow_result.h>

#include <flann/flann.hpp>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>

namespace pcl_flowseg {
namespace core {

PlaneFit
fitPlane (const std::vector<Eigen::Vector3d>& points, const int* ids, std::size_t count, int dimension)
{
  PlaneFit fit;
  if (count < static_cast<std::size_t> (dimension + 1))
    return fit;
  for (std::size_t k = 0; k < count; ++k)
    fit.mean += points[static_cast<std::size_t> (ids[k])];
  fit.mean /= static_cast<double> (count);
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero ();
  for (std::size_t k = 0; k < count; ++k)
  {
    const Eigen::Vector3d e = points[static_cast<std::size_t> (ids[k])] - fit.mean;
    cov += e * e.transpose ();
  }
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es (cov);
  // Surfaces: the normal is the smallest direction. Curves in a plane: the smallest eigenvalue
  // belongs to the plane's normal, the next one to the curve's normal.
  const int normal_axis = dimension == 3 ? 0 : 1;
  const double top = dimension == 3 ? es.eigenvalues ().sum () : es.eigenvalues ()[1] + es.eigenvalues ()[2];
  const double normal_spread = std::max (0.0, es.eigenvalues ()[normal_axis]);
  fit.normal = es.eigenvectors ().col (normal_axis);
  fit.direction = es.eigenvectors ().col (2);
  fit.variation = top > 0 ? normal_spread / top : 0.0;
  fit.normal_variance = normal_spread / static_cast<double> (count);
  return fit;
}

namespace {

/** The upper median of \a values (reordered); 0 when empty. */
double
median (std::vector<double>& values)
{
  if (values.empty ())
    return 0.0;
  std::nth_element (values.begin (), values.begin () + static_cast<long> (values.size () / 2), values.end ());
  return values[values.size () / 2];
}

} // namespace

Neighbourhoods
nearestNeighbourhoods (const std::vector<Eigen::Vector3d>& points, std::size_t stride)
{
  Neighbourhoods h;
  const std::size_t n = points.size (), rows = stride > 0 ? (n + stride - 1) / stride : 0;
  h.first.assign (rows + 1, 0);
  if (rows == 0)
    return h;
  const std::size_t k = std::min<std::size_t> (kNoiseNeighbours, n);
  // Coordinates relative to the first point keep float precision for large offsets.
  std::vector<float> data (3 * n);
  for (std::size_t i = 0; i < n; ++i)
    for (int a = 0; a < 3; ++a)
      data[3 * i + static_cast<std::size_t> (a)] = static_cast<float> (points[i][a] - points[0][a]);
  std::vector<float> query_data (3 * rows);
  for (std::size_t r = 0; r < rows; ++r)
    std::copy_n (data.begin () + static_cast<long> (3 * r * stride), 3, query_data.begin () + static_cast<long> (3 * r));
  flann::Matrix<float> matrix (data.data (), n, 3), queries (query_data.data (), rows, 3);
  flann::Index<flann::L2_Simple<float>> index (matrix, flann::KDTreeSingleIndexParams (10));
  index.buildIndex ();
  h.ids.resize (rows * k);
  std::vector<float> distances (rows * k);
  flann::Matrix<int> ids (h.ids.data (), rows, k);
  flann::Matrix<float> dist (distances.data (), rows, k);
  flann::SearchParams search (flann::FLANN_CHECKS_UNLIMITED, 0.0f, false);
  search.cores = 0; // all cores
  index.knnSearch (queries, ids, dist, k, search);
  for (std::size_t r = 0; r <= rows; ++r)
    h.first[r] = r * k;
  h.reach.resize (rows);
  const std::size_t nth = std::min<std::size_t> (kIsolationNeighbour, k - 1); // the row holds the point itself
  for (std::size_t r = 0; r < rows; ++r) // squared L2 distances, unsorted
  {
    const auto row = distances.begin () + static_cast<long> (r * k);
    std::nth_element (row, row + static_cast<long> (nth), row + static_cast<long> (k));
    h.reach[r] = std::sqrt (row[static_cast<long> (nth)]);
  }
  return h;
}

double
medianVariation (const std::vector<Eigen::Vector3d>& points, const Neighbourhoods& hoods, int dimension)
{
  std::vector<double> variation (hoods.first.size () - 1, 0.0);
  forEachNeighbourhood (points, hoods, dimension, [&] (std::size_t i, const PlaneFit& fit) { variation[i] = fit.variation; });
  return median (variation);
}

double
medianNormalDeviation (const std::vector<Eigen::Vector3d>& points, const Neighbourhoods& hoods, int dimension)
{
  std::vector<double> deviation (hoods.first.size () - 1, 0.0);
  forEachNeighbourhood (points, hoods, dimension,
                        [&] (std::size_t i, const PlaneFit& fit) { deviation[i] = std::sqrt (fit.normal_variance); });
  return median (deviation);
}

double
medianReach (const Neighbourhoods& hoods)
{
  std::vector<double> reach (hoods.reach.begin (), hoods.reach.end ());
  return median (reach);
}

double
medianRoughness (const std::vector<Eigen::Vector3d>& points, const Neighbourhoods& hoods, std::size_t stride, std::size_t row_step,
                 int dimension, double spacing)
{
  const std::size_t rows = hoods.first.size () - 1;
  if (!(spacing > 0.0) || rows == 0)
    return 0.0;
  std::vector<double> deviation;
  deviation.reserve (rows / row_step + 1);
  std::vector<std::pair<double, int>> row;
  std::vector<int> nearest;
  for (std::size_t r = 0; r < rows; r += row_step)
  {
    const Eigen::Vector3d& query = points[r * stride];
    row.clear ();
    for (std::size_t k = hoods.first[r]; k < hoods.first[r + 1]; ++k)
      row.emplace_back ((points[static_cast<std::size_t> (hoods.ids[k])] - query).squaredNorm (), hoods.ids[k]);
    const std::size_t n = std::min (kRoughnessNeighbours, row.size ());
    std::partial_sort (row.begin (), row.begin () + static_cast<long> (n), row.end ());
    nearest.clear ();
    for (std::size_t k = 0; k < n; ++k)
      nearest.push_back (row[k].second);
    deviation.push_back (std::sqrt (fitPlane (points, nearest.data (), n, dimension).normal_variance));
  }
  return median (deviation) / spacing;
}

} // namespace core
} // namespace pcl_flowseg

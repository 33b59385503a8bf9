/*
 * pcl_flowseg - internal: the noise of a point sample, estimated from its local neighbourhoods.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include "core/preparation/noise_estimate.h"

#include "core/geometry/point_neighbourhoods.h"
#include "core/preparation/detached_points.h"

#include <algorithm>

namespace pcl_flowseg {
namespace core {

namespace {
/** Most vertices the neighbours are looked for among: a subset thins the sample evenly, the
  * neighbourhoods stay small against the shape's features. */
constexpr std::size_t kNoiseIndexPoints = 50000;

/** Share of the rows of \a hoods (row r: point r * \a stride of \a points) whose point lies off the
  * plane of its other neighbours (liesOffNeighbours at the sample \a spacing). */
double
detachedShare (const std::vector<Eigen::Vector3d>& points, const Neighbourhoods& hoods, std::size_t stride, double spacing,
               int dimension)
{
  const std::size_t rows = hoods.reach.size ();
  if (rows == 0 || !(spacing > 0.0))
    return 0.0;
  std::size_t detached = 0;
  std::vector<int> others;
  for (std::size_t r = 0; r < rows; ++r)
  {
    const std::size_t point = r * stride;
    others.clear ();
    for (std::size_t k = hoods.first[r]; k < hoods.first[r + 1]; ++k)
      if (hoods.ids[k] != static_cast<int> (point))
        others.push_back (hoods.ids[k]);
    detached += liesOffNeighbours (points, point, others.data (), others.size (), spacing, dimension);
  }
  return static_cast<double> (detached) / static_cast<double> (rows);
}

} // namespace

NoiseEstimate
estimateNoise (const std::vector<Eigen::Vector3d>& vertices, int dimension)
{
  NoiseEstimate estimate;
  if (vertices.size () <= static_cast<std::size_t> (dimension))
    return estimate;
  const std::size_t stride = (vertices.size () + kNoiseIndexPoints - 1) / kNoiseIndexPoints;
  std::vector<Eigen::Vector3d> used;
  used.reserve (vertices.size () / stride + 1);
  for (std::size_t i = 0; i < vertices.size (); i += stride)
    used.push_back (vertices[i]);
  Eigen::Vector3d lo = vertices.front (), hi = lo;
  for (const auto& v : vertices)
  {
    lo = lo.cwiseMin (v);
    hi = hi.cwiseMax (v);
  }
  const std::size_t query_stride = (used.size () + kNoiseEstimatePoints - 1) / kNoiseEstimatePoints;
  const Neighbourhoods hoods = nearestNeighbourhoods (used, query_stride);
  estimate.sigma = medianNormalDeviation (used, hoods, dimension);
  const double spacing = medianReach (hoods);
  estimate.roughness = medianRoughness (used, hoods, query_stride, 1, dimension, spacing);
  const double limit = kIsolatedDistance * spacing;
  // A zero median (points closer than float precision) tells nothing: none counts as isolated.
  const auto isolated = limit > 0.0 ? std::count_if (hoods.reach.begin (), hoods.reach.end (), [&] (float r) { return r > limit; }) : 0;
  estimate.isolated_share = static_cast<double> (isolated) / static_cast<double> (hoods.reach.size ());
  estimate.detached_share = detachedShare (used, hoods, query_stride, spacing, dimension);
  const double diagonal = (hi - lo).norm ();
  estimate.share = diagonal > 0.0 ? estimate.sigma / diagonal : 0.0;
  estimate.points_used = hoods.reach.size ();
  return estimate;
}

} // namespace core
} // namespace pcl_flowseg

/*
 * pcl_flowseg - internal: the noise of a point sample, estimated from its local neighbourhoods.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include "core/interior/noise_estimate.h"

#include "core/interior/denoising.h"

namespace pcl_flowseg {
namespace core {

NoiseEstimate
estimateNoise (const std::vector<Eigen::Vector3d>& vertices, int dimension)
{
  NoiseEstimate estimate;
  if (vertices.size () <= static_cast<std::size_t> (dimension))
    return estimate;
  const std::size_t stride = (vertices.size () + kNoiseEstimatePoints - 1) / kNoiseEstimatePoints;
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
  estimate.sigma = medianNormalDeviation (used, nearestNeighbourhoods (used), dimension);
  const double diagonal = (hi - lo).norm ();
  estimate.share = diagonal > 0.0 ? estimate.sigma / diagonal : 0.0;
  estimate.points_used = used.size ();
  return estimate;
}

} // namespace core
} // namespace pcl_flowseg

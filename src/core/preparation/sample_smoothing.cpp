/*
 * pcl_flowseg - internal: smoothing of a noisy 3D sample before its triangulation.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include "core/preparation/sample_smoothing.h"

#include "core/geometry/point_neighbourhoods.h"
#include "core/support/parallel.h"

#include <cmath>

namespace pcl_flowseg {
namespace core {

namespace {

/** Every kRoughnessRowStep-th vertex measures the roughness between passes: a stable median at a
  * fraction of a pass's cost. */
constexpr std::size_t kRoughnessRowStep = 4;

/** One pass: every vertex moves along the PCA normal of its neighbourhood by the mean offset of its
  * neighbours from it, each weighted by exp(-offset^2 / (2 offset_scale^2)). Neighbours across a
  * wall thicker than a few offset scales weigh nothing, so the wall keeps its two sides, where a
  * projection onto the neighbourhood's plane would move both into the middle. */
std::vector<Eigen::Vector3d>
offsetWeightedPass (const std::vector<Eigen::Vector3d>& points, const Neighbourhoods& hoods, double offset_scale)
{
  std::vector<Eigen::Vector3d> out (points);
  parallelFor (points.size (), [&] (std::size_t i) {
    const int* ids = hoods.ids.data () + hoods.first[i];
    const std::size_t count = hoods.first[i + 1] - hoods.first[i];
    const Eigen::Vector3d normal = fitPlane (points, ids, count, 3).normal;
    double sum = 0.0, weights = 0.0;
    for (std::size_t k = 0; k < count; ++k)
    {
      const double offset = (points[static_cast<std::size_t> (ids[k])] - points[i]).dot (normal);
      const double z = offset / offset_scale; // offset_scale > 0: finite or +-inf, never NaN
      const double weight = std::exp (-0.5 * z * z);
      sum += weight * offset;
      weights += weight;
    }
    out[i] = points[i] + (sum / weights) * normal; // the vertex itself weighs 1
  });
  return out;
}

} // namespace

unsigned
smoothSample (std::vector<Eigen::Vector3d>& vertices, const NoiseEstimate& noise, const PreparationParameters& params)
{
  const bool automatic = params.smoothing == Smoothing::Automatic;
  if (params.smoothing == Smoothing::Off || (automatic && !(noise.roughness > kRoughSample)))
    return 0;
  // A sample without measurable noise has nothing to smooth (and the weights need a scale).
  if (!(noise.sigma > 0.0) || vertices.size () <= static_cast<std::size_t> (kNoiseNeighbours))
    return 0;
  const Neighbourhoods hoods = nearestNeighbourhoods (vertices);
  const double spacing = medianReach (hoods);
  unsigned passes = 0;
  while (passes < params.smoothing_passes)
  {
    vertices = offsetWeightedPass (vertices, hoods, noise.sigma);
    ++passes;
    if (automatic && medianRoughness (vertices, hoods, 1, kRoughnessRowStep, 3, spacing) <= kSmoothedRoughness)
      break;
  }
  return passes;
}

} // namespace core
} // namespace pcl_flowseg

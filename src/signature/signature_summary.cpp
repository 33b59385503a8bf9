/*
 * pcl_flowseg - a short, rotation-invariant vector that summarises a signature.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include <pcl_flowseg/signature/signature_summary.h>

#include "contour_matching.h"
#include "description_distances.h"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>

namespace pcl_flowseg {

std::array<float, kSummarySize>
signatureSummary (const Signature& signature)
{
  constexpr std::size_t kHeaviest = 8, kPairPoints = 4;
  std::array<float, kSummarySize> out{};
  const auto& pts = signature.points; // ordered by decreasing weight
  std::size_t at = 0;
  for (std::size_t i = 0; i < kHeaviest; ++i)
    out[at++] = i < pts.size () ? static_cast<float> (pts[i].weight) : 0.0f;
  for (std::size_t i = 0; i < kHeaviest; ++i)
    out[at++] = i < pts.size () ? static_cast<float> (pts[i].position.norm ()) : 0.0f;
  for (std::size_t i = 0; i < kPairPoints; ++i)
    for (std::size_t j = i + 1; j < kPairPoints; ++j)
      out[at++] = j < pts.size () ? static_cast<float> ((pts[i].position - pts[j].position).norm ()) : 0.0f;
  Eigen::Matrix3d moments = Eigen::Matrix3d::Zero ();
  for (const WeightedPoint& p : pts)
    moments += p.weight * p.position * p.position.transpose ();
  const Eigen::Vector3d eigen = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> (moments, Eigen::EigenvaluesOnly).eigenvalues ();
  for (int k = 2; k >= 0; --k) // largest first
    out[at++] = static_cast<float> (std::sqrt (std::max (0.0, eigen[k])));
  return out;
}

namespace {

/** The profiles in 48 numbers: of the inner-distance profiles the mean cumulative sum of each
  * group of 4 rows at every 4th bin, times the bin width in log distance (so that Euclidean distance
  * follows the profiles' earth mover's distance), times their weight; then the
  * thickness profile less its mean over its rows, times its weight. */
void
appendCoarseProfiles (const ShapeDescription& d, const DescriptionWeights& w, std::array<float, kDescriptionSummarySize>& out,
                      std::size_t& at)
{
  const InnerProfiles& profiles = d.inner_profiles;
  constexpr std::size_t kGroups = 4, kSteps = 8;
  const double scale = w.inner_profile * (kInnerLogHigh - kInnerLogLow) / static_cast<double> (kDistributionBins);
  for (std::size_t g = 0; g < kGroups; ++g)
  {
    std::array<double, kDistributionBins> cumulative{};
    for (std::size_t r = g * kProfileRows / kGroups; r < (g + 1) * kProfileRows / kGroups; ++r)
    {
      double below = 0.0;
      for (std::size_t b = 0; b < kDistributionBins; ++b)
        cumulative[b] += (below += profiles[r][b]) * kGroups / static_cast<double> (kProfileRows);
    }
    for (std::size_t k = 0; k < kSteps; ++k)
      out[at++] = static_cast<float> (scale * cumulative[k * (kDistributionBins / kSteps) + kDistributionBins / kSteps / 2]);
  }
  double mean = 0.0;
  for (double v : d.thickness_profile)
    mean += v / static_cast<double> (kProfileRows);
  for (double v : d.thickness_profile)
    out[at++] = static_cast<float> (w.thickness_profile * (v - mean) / static_cast<double> (kProfileRows));
}

/** The contour in 30 numbers that neither the start on the outline nor mirroring change: the mean
  * of its histograms with each sector added to its mirror image's (theta and pi - theta), square
  * roots (Euclidean distance then behaves like chi-square), times its weight. */
void
appendContourSummary (const ShapeDescription& d, const DescriptionWeights& w, std::array<float, kDescriptionSummarySize>& out,
                      std::size_t& at)
{
  std::array<double, kContourSummarySize> folded{};
  for (const ContourHistogram& h : d.contour)
    for (std::size_t ring = 0; ring < kContourDistanceBins; ++ring)
      for (std::size_t sector = 0; sector < kContourAngleBins; ++sector)
      {
        // The pairs of mirrored sectors, numbered 0 to 5 by the lower: (0 5) (1 4) (2 3) (6 11) (7 10) (8 9).
        const std::size_t low = std::min (sector, mirroredSector (sector));
        const std::size_t pair = low < kContourAngleBins / 4 ? low : low - kContourAngleBins / 4;
        folded[ring * kContourAngleBins / 2 + pair] +=
            h[ring * kContourAngleBins + sector] / static_cast<double> (d.contour.size ());
      }
  for (double v : folded)
    out[at++] = static_cast<float> (w.contour * std::sqrt (v));
}

/** The inner contexts in kContextSummarySize numbers: their mean cumulative histogram times the bin
  * width (the assignment's earth mover's distances are at least the distance of these means) and
  * their mean thickness times kContextThicknessWeight, times their weight. */
void
appendContextSummary (const ShapeDescription& d, const DescriptionWeights& w, std::array<float, kDescriptionSummarySize>& out,
                      std::size_t& at)
{
  std::array<double, kContextBins> cumulative{};
  double thickness = 0.0;
  const double share = d.inner_contexts.empty () ? 0.0 : 1.0 / static_cast<double> (d.inner_contexts.size ());
  for (const InnerContext& c : d.inner_contexts)
  {
    double below = 0.0;
    for (std::size_t k = 0; k < kContextBins; ++k)
      cumulative[k] += share * (below += static_cast<double> (c.distances[k]));
    thickness += share * static_cast<double> (c.thickness);
  }
  const double bin_width = (kContextLogHigh - kContextLogLow) / static_cast<double> (kContextBins);
  for (double v : cumulative)
    out[at++] = static_cast<float> (w.inner_context * bin_width * v);
  out[at++] = static_cast<float> (w.inner_context * kContextThicknessWeight * thickness);
}

} // namespace

std::array<float, kDescriptionSummarySize>
descriptionSummary (const Signature& signature, const DescriptionWeights& w)
{
  std::array<float, kDescriptionSummarySize> out{};
  const ShapeDescription& d = signature.description;
  if (d.empty ())
    return out;
  std::size_t at = 0;
  for (const auto& [h, weight] : {std::pair<const Distribution*, double> (&d.thickness, w.thickness),
                                  {&d.inner_distance, w.inner_distance}, {&d.solid_distance, w.solid_distance}})
    for (double v : *h)
      out[at++] = static_cast<float> (weight * std::sqrt (v));
  Eigen::Matrix<double, 6, 1> mean = Eigen::Matrix<double, 6, 1>::Zero (), square = mean;
  const std::vector<double> masses = partMasses (d);
  for (std::size_t k = 0; k < d.parts.size (); ++k)
  {
    const Eigen::Matrix<double, 6, 1> x = partPoint (d.parts[k]);
    mean += masses[k] * x;
    square += masses[k] * x.cwiseProduct (x);
  }
  const Eigen::Matrix<double, 6, 1> spread = (square - mean.cwiseProduct (mean)).cwiseMax (0.0).cwiseSqrt ();
  for (int k = 0; k < 6; ++k)
    out[at++] = static_cast<float> (w.parts * mean[k]);
  for (int k = 0; k < 6; ++k)
    out[at++] = static_cast<float> (w.parts * spread[k]);
  appendCoarseProfiles (d, w, out, at);
  appendContourSummary (d, w, out, at);
  appendContextSummary (d, w, out, at);
  return out;
}

} // namespace pcl_flowseg

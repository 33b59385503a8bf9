/*
 * pcl_flowseg - a short, rotation-invariant vector that summarises a signature.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include <pcl_flowseg/signature/signature_summary.h>

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

} // namespace pcl_flowseg

/*
 * pcl_flowseg - shape signatures: significant features as weighted points (paper, section 5).
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include <pcl_flowseg/signature/signature.h>

#include <pcl_flowseg/common/feature_significance.h>

#include <algorithm>
#include <cmath>

namespace pcl_flowseg {

Status
signatureFromSegmentation (const FlowResult& result, double significance, Signature& signature)
{
  signature = Signature ();
  if (const Status s = checkSignificance (significance); !s)
    return s;
  if (!result.interior.computed)
    return Status::error ("a signature needs interior/exterior separation");
  const std::vector<int> interior = segmentsOnSide (result, FeatureSide::Interior);
  double total = 0.0;
  Eigen::Vector3d centre = Eigen::Vector3d::Zero ();
  for (int k : interior)
  {
    const FlowSegment& s = result.segments[static_cast<std::size_t> (k)];
    total += s.volume;
    centre += s.volume * s.centroid;
  }
  if (!(total > 0.0))
    return Status::error ("the shape has no interior: no signature");
  centre /= total;
  signature.dimension = result.dimension;
  signature.interior_volume = total;
  signature.significance = significance;
  signature.unit = std::pow (total, 1.0 / result.dimension);

  double kept = 0.0;
  for (int k : significantSegments (result, interior, significance))
  {
    const FlowSegment& s = result.segments[static_cast<std::size_t> (k)];
    WeightedPoint p;
    p.position = (s.centroid - centre) / signature.unit;
    p.weight = s.volume;
    kept += s.volume;
    signature.points.push_back (p);
  }
  for (auto& p : signature.points)
    p.weight /= kept;
  std::sort (signature.points.begin (), signature.points.end (),
             [] (const WeightedPoint& a, const WeightedPoint& b) { return a.weight > b.weight; });
  return Status::success ();
}

} // namespace pcl_flowseg

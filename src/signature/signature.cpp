/*
 * pcl_flowseg - shape signatures: significant features as weighted points (paper, section 5).
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include <pcl_flowseg/signature/signature.h>

#include <pcl_flowseg/common/feature_significance.h>
#include <pcl_flowseg/signature/describe_shape.h>

#include <algorithm>
#include <cmath>

namespace pcl_flowseg {

namespace {

/** The views of the segmented sample: its vertices without those guessed behind a single view,
  * seen from the viewpoint the segmentation had, or rendered when it had none. */
Status
describeResultViews (const FlowResult& result, ViewSet& views)
{
  const std::size_t seen = result.vertices.size () - std::min (result.hidden_side_vertices, result.vertices.size ());
  const std::vector<Eigen::Vector3d> points (result.vertices.begin (),
                                            result.vertices.begin () + static_cast<std::ptrdiff_t> (seen));
  return describeViewSet (points, result.dimension, result.parameters.interior.viewpoint, views);
}

} // namespace

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
  if (const Status described = describeShape (result, signature.description); !described)
    return described;
  return describeResultViews (result, signature.views);
}

Status
checkSignature (const Signature& signature)
{
  const Signature& s = signature;
  if (s.dimension != 2 && s.dimension != 3)
    return Status::error ("dimension " + std::to_string (s.dimension) + " is neither 2 nor 3");
  if (!std::isfinite (s.unit) || s.unit <= 0.0)
    return Status::error ("the unit must be a finite number > 0");
  if (!std::isfinite (s.interior_volume) || s.interior_volume < 0.0)
    return Status::error ("the interior volume must be a finite number >= 0");
  if (const Status f = checkSignificance (s.significance); !f)
    return f;
  double total = 0.0;
  for (std::size_t k = 0; k < s.points.size (); ++k)
  {
    const WeightedPoint& p = s.points[k];
    if (!p.position.allFinite () || p.position.cwiseAbs ().maxCoeff () > kLargestSignatureCoordinate)
      return Status::error ("point " + std::to_string (k + 1) + " lies outside the normalised frame");
    if (!(p.weight >= 0.0 && p.weight <= 1.0))
      return Status::error ("point " + std::to_string (k + 1) + " has a weight outside [0, 1]");
    if (k > 0 && p.weight > s.points[k - 1].weight)
      return Status::error ("the points are not ordered by decreasing weight");
    total += p.weight;
  }
  if (!s.points.empty () && std::abs (total - 1.0) > 1e-9)
    return Status::error ("the weights sum to " + std::to_string (total) + ", not 1");
  if (const Status d = checkShapeDescription (s.description); !d)
    return d;
  return checkViewSet (s.views);
}

} // namespace pcl_flowseg

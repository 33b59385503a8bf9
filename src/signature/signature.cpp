/*
 * pcl_flowseg - shape signatures: significant features as weighted points (paper, section 5).
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include <pcl_flowseg/signature/signature.h>

#include <algorithm>
#include <cmath>

namespace pcl_flowseg {

Status
signatureFromSegmentation (const FlowResult& result, double significance, Signature& signature)
{
  signature = Signature ();
  if (!std::isfinite (significance) || significance < 0.0 || significance >= 1.0)
    return Status::error ("significance must be a fraction in [0, 1), got " + std::to_string (significance));
  if (!result.interior.computed)
    return Status::error ("a signature needs interior/exterior separation");
  double total = 0.0;
  Eigen::Vector3d centre = Eigen::Vector3d::Zero ();
  for (const FlowSegment& s : result.segments)
    if (s.interior == 1)
    {
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
  for (const FlowSegment& s : result.segments)
    if (s.interior == 1 && s.volume > significance * total)
    {
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

Status
signatureOfShapeFile (const std::string& path, const ShapeInputOptions& input, const FlowParameters& params,
                      double significance, Signature& signature)
{
  std::vector<Eigen::Vector3d> points;
  FlowResult result;
  Status s = loadShapeSample (path, input, points);
  if (s.ok)
    s = runFlowSegmentation (points, params, result);
  if (s.ok)
    s = signatureFromSegmentation (result, significance, signature);
  if (!s.ok && s.message.find (path) == std::string::npos)
    s.message = path + ": " + s.message;
  return s;
}

} // namespace pcl_flowseg

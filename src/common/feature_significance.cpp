/*
 * pcl_flowseg - which features are significant: the one place that decides it.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include <pcl_flowseg/common/feature_significance.h>

#include <cmath>
#include <string>

namespace pcl_flowseg {

Status
checkSignificance (double fraction)
{
  if (!std::isfinite (fraction) || fraction < 0.0 || fraction >= 1.0)
    return Status::error ("significance must be a fraction in [0, 1), got " + std::to_string (fraction));
  return Status::success ();
}

std::vector<int>
segmentsOnSide (const FlowResult& result, FeatureSide side)
{
  std::vector<int> out;
  const bool sided = result.interior.computed;
  for (int k = 0; k < static_cast<int> (result.segments.size ()); ++k)
  {
    const std::int8_t interior = result.segments[static_cast<std::size_t> (k)].interior;
    if (!sided || side == FeatureSide::Both || (side == FeatureSide::Interior && interior == 1) ||
        (side == FeatureSide::Exterior && interior == 0))
      out.push_back (k);
  }
  return out;
}

std::vector<int>
significantSegments (const FlowResult& result, const std::vector<int>& segments, double fraction)
{
  double total = 0.0;
  for (int k : segments)
    total += result.segments[static_cast<std::size_t> (k)].volume;
  std::vector<int> out;
  for (int k : segments)
    if (result.segments[static_cast<std::size_t> (k)].volume > fraction * total)
      out.push_back (k);
  return out;
}

} // namespace pcl_flowseg

/*
 * pcl_flowseg - internal: the rho rule (paper, section 4), with the sampling tolerance.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include "core/merging/merge_rule.h"

#include "core/merging/sample_spacing.h"
#include "core/merging/union_find.h"

#include <cmath>

namespace pcl_flowseg {
namespace core {

std::vector<std::int8_t>
manifoldSides (const FlowResult& result)
{
  std::vector<std::int8_t> side (result.manifolds.size (), -1);
  if (!result.interior.computed)
    return side;
  for (std::size_t k = 0; k < side.size (); ++k)
  {
    const FlowSegment& man = result.manifolds[k];
    side[k] = man.flows_to_infinity ? 0 : result.cells[static_cast<std::size_t> (man.maximum.cell)].inside;
  }
  return side;
}

namespace {
/** Both maxima below \a limit (radii). */
bool
bothBelow (const FlowSegment& a, const FlowSegment& b, double limit)
{
  return std::sqrt (a.maximum.height) < limit && std::sqrt (b.maximum.height) < limit;
}
} // namespace

std::vector<const SaddleFacet*>
joinMergeableManifolds (const MergeParameters& params, const FlowResult& result, const std::vector<std::int8_t>& side,
                        std::vector<int>& parent)
{
  const double rho = params.rho;
  // rho < 1 merges nothing, whatever the tolerance or compact pass (the paper's "no merging", Figure 6).
  const bool tolerant = params.sampling_tolerance > 0.0 && rho >= 1.0;
  const bool compact = params.compact_size > 0.0 && params.compact_rho > rho && rho >= 1.0;
  const std::vector<double> nearest = tolerant ? nearestNeighbourDistances (result) : std::vector<double> ();
  std::vector<const SaddleFacet*> compact_candidates;
  for (const SaddleFacet& s : result.manifold_adjacency)
  {
    const FlowSegment& a = result.manifolds[static_cast<std::size_t> (s.segment_a)];
    const FlowSegment& b = result.manifolds[static_cast<std::size_t> (s.segment_b)];
    if (a.flows_to_infinity || b.flows_to_infinity ||
        side[static_cast<std::size_t> (s.segment_a)] != side[static_cast<std::size_t> (s.segment_b)])
      continue;
    const double tolerance_term = tolerant ? params.sampling_tolerance * saddleSpacing (s, nearest, result.dimension) : 0.0;
    bool mergeable;
    if (tolerant)
      mergeable = bothBelow (a, b, rho * std::sqrt (s.squared_radius) + tolerance_term);
    else
    {
      // The paper's rule, in squared radii (bit for bit the result without a tolerance).
      const double limit = rho * rho * s.squared_radius;
      mergeable = a.maximum.height < limit && b.maximum.height < limit;
    }
    if (!mergeable && compact && bothBelow (a, b, params.compact_rho * std::sqrt (s.squared_radius) + tolerance_term))
      compact_candidates.push_back (&s);
    if (mergeable)
    {
      const int ra = findRoot (parent, s.segment_a), rb = findRoot (parent, s.segment_b);
      if (ra != rb)
        joinRoots (parent, ra, rb);
    }
  }
  return compact_candidates;
}

} // namespace core
} // namespace pcl_flowseg

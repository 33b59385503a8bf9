/*
 * pcl_flowseg - internal: stable manifolds merged into segments, step by step.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include "core/merging/manifold_merging.h"

#include "core/merging/compact_merge.h"
#include "core/merging/merge_groups.h"
#include "core/merging/merge_rule.h"
#include "core/merging/segment_assembly.h"
#include "core/merging/side_flooding.h"
#include "core/merging/small_part_merge.h"
#include "core/merging/stump_reclaim.h"

#include <numeric>

namespace pcl_flowseg {
namespace core {

void
mergeManifolds (const MergeParameters& params, FlowResult& result)
{
  const std::vector<std::int8_t> side = manifoldSides (result);
  std::vector<int> parent (result.manifolds.size ());
  std::iota (parent.begin (), parent.end (), 0);
  std::vector<const SaddleFacet*> compact_candidates = joinMergeableManifolds (params, result, side, parent);
  if (!compact_candidates.empty ())
    mergeCompactGroups (result, compact_candidates, params.compact_size, parent);
  MergeGroups groups = groupsOfManifolds (parent, side);
  assignCellsToTheirSide (result, groups);
  if (params.stump_ratio > 0.0)
    reclaimStumps (result, groupHeights (result, groups), params.stump_ratio, groups.of_cell);
  absorbSmallGroups (result, result.hidden_side_vertices > 0 ? params.single_view_min_part_share : params.min_part_share,
                     groups);
  storeSegments (groups, result);
}

} // namespace core
} // namespace pcl_flowseg

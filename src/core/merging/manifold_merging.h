/*
 * pcl_flowseg - internal: stable manifolds merged into segments, step by step.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include <pcl_flowseg/common/flow_parameters.h>
#include <pcl_flowseg/common/flow_result.h>

namespace pcl_flowseg {
namespace core {

/** \brief Merges the stable manifolds of \a result (manifolds and manifold_adjacency filled) into
  * segments and fills segments, cells[].segment, segment_adjacency and features. The steps, each
  * in a file of its own (docs/method.md says why each exists):
  *   1. the rho rule with the sampling tolerance (merge_rule.h), order-independent;
  *   2. the compact pass, when compact_size > 0 and compact_rho > rho >= 1 (compact_merge.h);
  *   3. every cell joins a group of its own side (side_flooding.h);
  *   4. thin parts take back their stumps, when stump_ratio > 0 (stump_reclaim.h);
  *   5. segments too small to be parts join a neighbour, when min_part_share > 0
  *      (single_view_min_part_share on a single view with a guessed hidden side;
  *      small_part_merge.h);
  *   6. the groups become ordered segments (segment_assembly.h).
  * With sampling_tolerance, stump_ratio, compact_size and both part shares 0 this is the paper's
  * segmentation. */
void
mergeManifolds (const MergeParameters& params, FlowResult& result);

} // namespace core
} // namespace pcl_flowseg

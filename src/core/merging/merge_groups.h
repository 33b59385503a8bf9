/*
 * pcl_flowseg - internal: groups of cells on their way from merged manifolds to segments.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include <cstdint>
#include <vector>

namespace pcl_flowseg {
namespace core {

/** \brief The groups the merge steps pass on: one per set of merged manifolds (numbered in the
  * order of their lowest manifold), then one per region of a side that no such group reaches. */
struct MergeGroups
{
  std::vector<int> of_manifold;  ///< group of each stable manifold
  std::vector<int> of_cell;      ///< group of each cell (-1 while unassigned)
  std::vector<std::int8_t> side; ///< side of each group: 1 inside, 0 outside, -1 not separated
  int count = 0;                 ///< number of groups
};

/** \brief The groups of the union-find forest \a parent over the manifolds, with their sides (the
  * side of the group's root manifold, from \a manifold_side). of_cell is left empty. */
MergeGroups
groupsOfManifolds (std::vector<int>& parent, const std::vector<std::int8_t>& manifold_side);

} // namespace core
} // namespace pcl_flowseg

/*
 * pcl_flowseg - internal: groups of cells on their way from merged manifolds to segments.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include "core/merging/merge_groups.h"

#include "core/merging/union_find.h"

namespace pcl_flowseg {
namespace core {

MergeGroups
groupsOfManifolds (std::vector<int>& parent, const std::vector<std::int8_t>& manifold_side)
{
  MergeGroups groups;
  const int m = static_cast<int> (parent.size ());
  groups.of_manifold.assign (parent.size (), -1);
  for (int k = 0; k < m; ++k)
  {
    const std::size_t r = static_cast<std::size_t> (findRoot (parent, k));
    if (groups.of_manifold[r] < 0)
    {
      groups.of_manifold[r] = groups.count++;
      groups.side.push_back (manifold_side[r]);
    }
    groups.of_manifold[static_cast<std::size_t> (k)] = groups.of_manifold[r];
  }
  return groups;
}

} // namespace core
} // namespace pcl_flowseg

/*
 * pcl_flowseg - internal: union-find over stable manifolds, the lower root always winning.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include <algorithm>
#include <vector>

namespace pcl_flowseg {
namespace core {

/** \brief Root of \a x in the forest \a parent (path halving). */
inline int
findRoot (std::vector<int>& parent, int x)
{
  while (parent[static_cast<std::size_t> (x)] != x)
  {
    parent[static_cast<std::size_t> (x)] = parent[static_cast<std::size_t> (parent[static_cast<std::size_t> (x)])];
    x = parent[static_cast<std::size_t> (x)];
  }
  return x;
}

/** \brief Joins the trees of the distinct roots \a ra and \a rb under the lower one, which it
  * returns: the result does not depend on the order of the joins. */
inline int
joinRoots (std::vector<int>& parent, int ra, int rb)
{
  const int lo = std::min (ra, rb), hi = std::max (ra, rb);
  parent[static_cast<std::size_t> (hi)] = lo;
  return lo;
}

} // namespace core
} // namespace pcl_flowseg

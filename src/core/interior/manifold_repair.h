/*
 * pcl_flowseg - internal: the interior/exterior boundary made a manifold by relabelling cells
 * around the vertices where it is not one.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include <pcl_flowseg/common/flow_result.h>

#include <cstddef>
#include <vector>

namespace pcl_flowseg {
namespace core {

/** \brief Most rounds of repairManifold: each round repairs the vertices found non-manifold at its
  * start; a relabelled cell can spoil a neighbouring vertex, which the next round repairs. */
constexpr int kMaxManifoldRepairRounds = 8;

/** \brief 3D: makes the boundary between inside and outside cells (FlowCell::inside) a manifold at
  * the vertices where it is not one (\a nonmanifold: what measureBoundary returned for the cells
  * as they are; it measures the report again after every round). Around such a vertex the inside cells
  * must form one group and the outside cells another, linked through the facets that hold the
  * vertex (the cells beyond the hull count as one outside group); while they do not, the group of
  * least volume changes side (never the group beyond the hull). Nothing changes in 2D or on a
  * boundary that is already a manifold. Returns the cells relabelled. */
std::size_t
repairManifold (FlowResult& result, std::vector<int> nonmanifold);

} // namespace core
} // namespace pcl_flowseg

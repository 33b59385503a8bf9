/*
 * pcl_flowseg - internal: the NN-crust of a 2D sample (Dey & Kumar): the edges of the sampled curve.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include <pcl_flowseg/common/flow_result.h>

#include <cstdint>
#include <unordered_set>
#include <vector>

namespace pcl_flowseg {
namespace core {

/** \brief Key of the undirected edge between vertices \a a and \a b. */
std::uint64_t
edgeKey (int a, int b);

/** \brief NN-crust (Dey & Kumar): every sample joined to its nearest neighbour, and to its nearest
  * neighbour among the samples on the other side of that first edge. Both are Delaunay edges, so
  * the cells' edges suffice. Keys by edgeKey. */
std::unordered_set<std::uint64_t>
nnCrust (const std::vector<Eigen::Vector3d>& vertices, const std::vector<FlowCell>& cells);

} // namespace core
} // namespace pcl_flowseg

/*
 * pcl_flowseg - internal: is the interior/exterior boundary a closed manifold?
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include <pcl_flowseg/common/flow_result.h>

#include <vector>

namespace pcl_flowseg {
namespace core {

/** \brief Recomputes FlowResult::interior's figures from the cells' inside flags: inside volume
  * and cells, boundary facets, non-manifold edges (3D) and vertices, samples off the boundary,
  * closed and manifold. The other fields of the report are left as they are. Returns, in 3D, the
  * vertices (ascending) at which the boundary is not a manifold: an edge of theirs bounds other
  * than two boundary facets, or their boundary facets form more than one fan (2D: none). */
std::vector<int>
measureBoundary (FlowResult& result);

} // namespace core
} // namespace pcl_flowseg

/*
 * pcl_flowseg - the interior/exterior boundary of a result: the reconstructed surface (curve).
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include <pcl_flowseg/common/flow_result.h>

#include <array>
#include <vector>

namespace pcl_flowseg {

/** \brief The facets between inside and outside cells: triangles in 3D (oriented so that their
  * normals point out of the interior) or edges in 2D (third index -1; each edge with the interior
  * on its left), over the vertices of \a result. Empty when the separation was not run. */
std::vector<std::array<int, 3>>
boundaryFacets (const FlowResult& result);

} // namespace pcl_flowseg

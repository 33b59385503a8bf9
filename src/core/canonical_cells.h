/*
 * pcl_flowseg - internal: a canonical numbering of Delaunay cells.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include <pcl_flowseg/flow_result.h>

#include <vector>

namespace pcl_flowseg {
namespace core {

/** \brief Puts \a cells (vertices and neighbors filled) into an order that depends only on the
  * triangulation, not on how it was built: each cell's vertices ascending except that the last two
  * are swapped when that keeps the cell's orientation (neighbors permuted with them, so
  * neighbors[i] stays opposite vertices[i]), cells ordered by their vertex tuples. The
  * parallel triangulation numbers cells differently on every run; after this every later stage,
  * ties included, sees the same input. */
void
putInCanonicalOrder (std::vector<FlowCell>& cells, int dimension);

} // namespace core
} // namespace pcl_flowseg

/*
 * pcl_flowseg - internal: a canonical numbering of Delaunay cells.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include <pcl_flowseg/common/flow_result.h>

#include <array>
#include <vector>

namespace pcl_flowseg {
namespace core {

/** \brief Sorts the first \a f entries of \a vertices ascending, except that the last two are
  * swapped back when the sort was an odd permutation, so that the cell keeps its orientation.
  * \a slot[i] receives the old position of the vertex now at position i. */
void
canonicalVertexOrder (std::array<int, 4>& vertices, int f, std::array<int, 4>& slot);

/** \brief The order of cells by their canonical vertex tuples (\a tuples as made by
  * canonicalVertexOrder): order[new position] = old index. Distinct cells have distinct tuples. */
std::vector<int>
canonicalCellOrder (const std::vector<std::array<int, 4>>& tuples, int f);

/** \brief Puts \a cells (vertices and neighbors filled) into an order that depends only on the
  * triangulation, not on how it was built: each cell's vertices by canonicalVertexOrder (neighbors
  * permuted with them, so neighbors[i] stays opposite vertices[i]), cells by canonicalCellOrder.
  * The parallel triangulation numbers cells differently on every run; after this every later
  * stage, ties included, sees the same input. */
void
putInCanonicalOrder (std::vector<FlowCell>& cells, int dimension);

} // namespace core
} // namespace pcl_flowseg

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

/** \brief A cell as the triangulation gives it, before it becomes a FlowCell: vertices and
  * neighbours only (neighbors[i] opposite vertices[i], kInfiniteCell beyond the hull). A third of
  * a FlowCell, so the triangulation can be copied out and released before the cells are built. */
struct CellLinks
{
  std::array<int, 4> vertices{{-1, -1, -1, -1}};
  std::array<int, 4> neighbors{{kInfiniteCell, kInfiniteCell, kInfiniteCell, kInfiniteCell}};
};

/** \brief Sorts the first \a f entries of \a vertices ascending, except that the last two are
  * swapped back when the sort was an odd permutation, so that the cell keeps its orientation.
  * \a slot[i] receives the old position of the vertex now at position i. */
void
canonicalVertexOrder (std::array<int, 4>& vertices, int f, std::array<int, 4>& slot);

/** \brief \a cell's vertices in canonicalVertexOrder, its neighbours permuted with them. */
void
orientCanonically (CellLinks& cell, int f);

/** \brief The order of cells by their canonical vertex tuples (cells oriented by
  * orientCanonically): order[new position] = old index. Distinct cells have distinct tuples. */
std::vector<int>
canonicalCellOrder (const std::vector<CellLinks>& cells, int f);

/** \brief \a cells (oriented canonically, neighbours by index into \a cells) become \a flow_cells in
  * an order that depends only on the triangulation, not on how it was built (canonicalCellOrder),
  * neighbours renumbered. The parallel triangulation numbers cells differently on every run;
  * after this every later stage, ties included, sees the same input. \a cells is released. */
void
buildCellsInCanonicalOrder (std::vector<CellLinks>&& cells, int dimension, std::vector<FlowCell>& flow_cells);

} // namespace core
} // namespace pcl_flowseg

/*
 * pcl_flowseg - internal: the stable manifolds as FlowSegments, with their maxima and saddles.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include "core/flow/manifold_summary.h"

#include "core/flow/cell_groups.h"
#include "core/geometry/cell_geometry.h"
#include "core/support/huge_pages.h"

#include <limits>

namespace pcl_flowseg {
namespace core {

void
describeManifolds (const StableManifolds& sm, FlowResult& result)
{
  const int dim = result.dimension;
  result.maxima.clear ();
  for (int c : sm.maxima_cells)
  {
    FlowMaximum m;
    m.cell = c;
    m.height = result.cells[static_cast<std::size_t> (c)].squared_radius;
    m.location = cellCircumcentre (result.vertices, result.cells[static_cast<std::size_t> (c)], dim);
    result.maxima.push_back (m);
  }
  const int count = static_cast<int> (sm.maxima_cells.size ()) + (sm.has_infinity ? 1 : 0);
  std::vector<int> manifold_of_cell;
  assignOnHugePages (manifold_of_cell, result.cells.size ());
  for (std::size_t c = 0; c < result.cells.size (); ++c)
    manifold_of_cell[c] = result.cells[c].manifold;
  result.manifolds = summariseCells (result.cells, manifold_of_cell, count);
  for (std::size_t k = 0; k < result.maxima.size (); ++k)
  {
    result.manifolds[k].maximum = result.maxima[k];
    result.manifolds[k].maxima = {static_cast<int> (k)};
  }
  if (sm.has_infinity)
  {
    FlowSegment& inf = result.manifolds.back ();
    inf.flows_to_infinity = true;
    inf.maximum.height = std::numeric_limits<double>::infinity ();
  }
  result.manifold_adjacency = highestSharedFacets (result, manifold_of_cell);
}

} // namespace core
} // namespace pcl_flowseg

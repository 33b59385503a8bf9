/*
 * pcl_flowseg - internal: every cell joins a group of its own side (interior or exterior).
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include "core/merging/side_flooding.h"

#include "core/geometry/cell_geometry.h"

#include <queue>
#include <utility>

namespace pcl_flowseg {
namespace core {

namespace {
/** Floods the unassigned cells from the assigned ones, across the highest facets first. */
class SideFlood
{
public:
  SideFlood (const FlowResult& result, MergeGroups& groups) : result_ (result), groups_ (groups) {}

  void
  run ()
  {
    std::vector<int>& of_cell = groups_.of_cell;
    const std::size_t n = result_.cells.size ();
    for (std::size_t c = 0; c < n; ++c)
      if (of_cell[c] >= 0)
        offer (c);
    for (std::size_t next_cell = 0;;)
    {
      drain ();
      // A region of one side that no group of that side reaches (its cells all flow across the
      // boundary) becomes a group of its own.
      while (next_cell < n && of_cell[next_cell] >= 0)
        ++next_cell;
      if (next_cell == n)
        break;
      of_cell[next_cell] = groups_.count++;
      groups_.side.push_back (result_.cells[next_cell].inside);
      offer (next_cell);
    }
  }

private:
  /** Offers the unassigned neighbours of the same side of cell \a c its group. */
  void
  offer (std::size_t c)
  {
    const FlowCell& cell = result_.cells[c];
    for (int i = 0; i <= result_.dimension; ++i)
    {
      const int nb = cell.neighbors[i];
      if (nb >= 0 && groups_.of_cell[static_cast<std::size_t> (nb)] < 0 &&
          result_.cells[static_cast<std::size_t> (nb)].inside == cell.inside)
        queue_.emplace (facetSquaredRadius (result_.vertices, cell, i, result_.dimension),
                        std::make_pair (nb, groups_.of_cell[c]));
    }
  }

  void
  drain ()
  {
    while (!queue_.empty ())
    {
      const Entry e = queue_.top ();
      queue_.pop ();
      const std::size_t c = static_cast<std::size_t> (e.second.first);
      if (groups_.of_cell[c] >= 0)
        continue;
      groups_.of_cell[c] = e.second.second;
      offer (c);
    }
  }

  using Entry = std::pair<double, std::pair<int, int>>; // facet height, (cell, group)
  const FlowResult& result_;
  MergeGroups& groups_;
  std::priority_queue<Entry> queue_;
};
} // namespace

void
assignCellsToTheirSide (const FlowResult& result, MergeGroups& groups)
{
  const bool sided = result.interior.computed;
  const std::size_t n = result.cells.size ();
  groups.of_cell.assign (n, -1);
  for (std::size_t c = 0; c < n; ++c)
  {
    const int group = groups.of_manifold[static_cast<std::size_t> (result.cells[c].manifold)];
    if (!sided || groups.side[static_cast<std::size_t> (group)] == result.cells[c].inside)
      groups.of_cell[c] = group;
  }
  if (sided)
    SideFlood (result, groups).run ();
}

} // namespace core
} // namespace pcl_flowseg

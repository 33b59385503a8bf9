/*
 * pcl_flowseg - internal: every cell joins a group of its own side (interior or exterior).
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include "core/merging/side_flooding.h"

#include "core/geometry/cell_geometry.h"
#include "core/support/huge_pages.h"
#include "core/support/parallel.h"

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
    offerFromAllAssigned ();
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
  using Entry = std::pair<double, std::pair<int, int>>; // facet height, (cell, group)

  /** The offers of cell \a c: its group to each unassigned neighbour of the same side. */
  template <class Sink>
  void
  offersOf (std::size_t c, Sink&& sink) const
  {
    const FlowCell& cell = result_.cells[c];
    for (int i = 0; i <= result_.dimension; ++i)
    {
      const int nb = cell.neighbors[i];
      if (nb >= 0 && groups_.of_cell[static_cast<std::size_t> (nb)] < 0 &&
          result_.cells[static_cast<std::size_t> (nb)].inside == cell.inside)
        sink (Entry (facetSquaredRadius (result_.vertices, cell, i, result_.dimension), std::make_pair (nb, groups_.of_cell[c])));
    }
  }

  void
  offer (std::size_t c)
  {
    offersOf (c, [this] (const Entry& e) { queue_.push (e); });
  }

  /** The first offers, of every assigned cell, gathered on all workers and queued in cell order,
    * as one loop would (the same heap even where a degenerate facet's height is not a number). */
  void
  offerFromAllAssigned ()
  {
    const std::vector<Entry> offers = gatherListInOrder<Entry> (
      result_.cells.size (), [&] (std::size_t begin, std::size_t end, std::vector<Entry>& found) {
        for (std::size_t c = begin; c < end; ++c)
          if (groups_.of_cell[c] >= 0)
            offersOf (c, [&found] (const Entry& e) { found.push_back (e); });
      });
    for (const Entry& e : offers)
      queue_.push (e);
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
  assignOnHugePages (groups.of_cell, n, -1);
  parallelFor (n, [&] (std::size_t c) {
    const int group = groups.of_manifold[static_cast<std::size_t> (result.cells[c].manifold)];
    if (!sided || groups.side[static_cast<std::size_t> (group)] == result.cells[c].inside)
      groups.of_cell[c] = group;
  });
  if (sided)
    SideFlood (result, groups).run ();
}

} // namespace core
} // namespace pcl_flowseg

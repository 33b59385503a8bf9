/*
 * pcl_flowseg - internal: thin parts take back their stumps from thick ones.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include "core/merging/stump_reclaim.h"

#include "core/flow/cell_groups.h"
#include "core/support/parallel.h"

#include <algorithm>
#include <cstdint>
#include <functional>
#include <queue>
#include <unordered_map>
#include <utility>

namespace pcl_flowseg {
namespace core {

namespace {
/** Smallest cell a stump may take, as a share of the circumradius of the saddle between the two
  * groups: keeps the flood in the core of the thin part's tube instead of letting it run along the
  * thick part's surface, where the cells are small (docs/method.md). */
constexpr double kStumpFloor = 0.5;
} // namespace

std::vector<double>
groupHeights (const FlowResult& result, const MergeGroups& groups)
{
  std::vector<double> height (static_cast<std::size_t> (groups.count), -1.0);
  for (std::size_t k = 0; k < result.manifolds.size (); ++k)
  {
    const FlowSegment& man = result.manifolds[k];
    double& h = height[static_cast<std::size_t> (groups.of_manifold[k])];
    if (!man.flows_to_infinity)
      h = std::max (h, man.maximum.height);
  }
  for (std::size_t k = 0; k < result.manifolds.size (); ++k)
    if (result.manifolds[k].flows_to_infinity)
      height[static_cast<std::size_t> (groups.of_manifold[k])] = -1.0;
  return height;
}

void
reclaimStumps (const FlowResult& result, const std::vector<double>& height, double ratio, std::vector<int>& of_cell)
{
  const std::size_t n = result.cells.size ();
  const int facets = result.dimension + 1;
  const double ratio2 = ratio * ratio;
  std::vector<char> fixed (n, 0); // maxima never move (segments keep their maxima's cells)
  for (const FlowSegment& man : result.manifolds)
    if (!man.flows_to_infinity && man.maximum.cell >= 0)
      fixed[static_cast<std::size_t> (man.maximum.cell)] = 1;
  const std::vector<int> original (of_cell);
  std::unordered_map<std::uint64_t, double> saddle; // (a < b) -> squared radius of their saddle
  auto key = [] (int a, int b) {
    return (static_cast<std::uint64_t> (std::min (a, b)) << 32) | static_cast<std::uint32_t> (std::max (a, b));
  };
  for (const SaddleFacet& s : highestSharedFacets (result, original))
    saddle[key (s.segment_a, s.segment_b)] = s.squared_radius;
  const double floor2 = kStumpFloor * kStumpFloor;
  // May thin group x take cell c (of its original group, a neighbour of x)? Only from a group more
  // than ratio times thicker, and only cells no larger than x's own maximum and not much smaller
  // than the saddle between the two.
  auto takes = [&] (int x, std::size_t c) {
    const int y = original[c];
    const double hx = height[static_cast<std::size_t> (x)], hy = height[static_cast<std::size_t> (y)];
    if (x == y || fixed[c] || !(hx > 0.0) || !(hy > 0.0) || !(ratio2 * hx < hy))
      return false;
    const double h = result.cells[c].squared_radius;
    const auto s = saddle.find (key (x, y));
    return h <= hx && s != saddle.end () && h >= floor2 * s->second;
  };
  // Lowest cells first (ties: lower cell, then lower group): a deterministic flood from every
  // boundary between a thin and a thick group at once. The seeds are gathered in parallel; the
  // queue's order is total (takes admits finite heights only), so the order of gathering does
  // not matter.
  using Entry = std::pair<double, std::pair<int, int>>; // cell height, (cell, thin group)
  std::vector<Entry> seeds = gatherListInOrder<Entry> (
    n, [&] (std::size_t begin, std::size_t end, std::vector<Entry>& found) {
      for (std::size_t c = begin; c < end; ++c)
        for (int i = 0; i < facets; ++i)
        {
          const int nb = result.cells[c].neighbors[i];
          if (nb < 0 || result.cells[static_cast<std::size_t> (nb)].inside != result.cells[c].inside)
            continue;
          const int x = original[static_cast<std::size_t> (nb)];
          if (takes (x, c))
            found.emplace_back (result.cells[c].squared_radius, std::make_pair (static_cast<int> (c), x));
        }
    });
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> queue (std::greater<Entry> (), std::move (seeds));
  std::vector<char> taken (n, 0);
  while (!queue.empty ())
  {
    const Entry e = queue.top ();
    queue.pop ();
    const std::size_t c = static_cast<std::size_t> (e.second.first);
    const int x = e.second.second;
    if (taken[c])
      continue;
    taken[c] = 1;
    of_cell[c] = x;
    for (int i = 0; i < facets; ++i)
    {
      const int nb = result.cells[c].neighbors[i];
      if (nb >= 0 && !taken[static_cast<std::size_t> (nb)] && original[static_cast<std::size_t> (nb)] == original[c] &&
          takes (x, static_cast<std::size_t> (nb)))
        queue.emplace (result.cells[static_cast<std::size_t> (nb)].squared_radius, std::make_pair (nb, x));
    }
  }
}

} // namespace core
} // namespace pcl_flowseg

/*
 * pcl_flowseg - internal: thin parts take back their stumps from thick ones.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include "core/merging/stump_reclaim.h"

#include "core/flow/cell_groups.h"
#include "core/support/huge_pages.h"
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

namespace {
/** The flood of reclaimStumps: thin groups take cells of thicker neighbours, lowest cells first. */
class StumpFlood
{
public:
  StumpFlood (const FlowResult& result, const std::vector<double>& height, double ratio, const std::vector<int>& of_cell)
    : result_ (result), height_ (height), ratio2_ (ratio * ratio)
  {
    assignOnHugePages (fixed_, result.cells.size (), char (0));
    assignOnHugePages (original_, of_cell.size ());
    parallelFor (of_cell.size (), [&] (std::size_t c) { original_[c] = of_cell[c]; });
    for (const FlowSegment& man : result.manifolds)
      if (!man.flows_to_infinity && man.maximum.cell >= 0)
        fixed_[static_cast<std::size_t> (man.maximum.cell)] = 1; // segments keep their maxima's cells
    for (const SaddleFacet& s : highestSharedFacets (result, original_))
      saddle_[key (s.segment_a, s.segment_b)] = s.squared_radius;
  }

  /** Lowest cells first (ties: lower cell, then lower group): a deterministic flood from every
    * boundary between a thin and a thick group at once. Writes the takers into \a of_cell. */
  void
  run (std::vector<int>& of_cell)
  {
    Queue queue (std::greater<Entry> (), seeds ());
    std::vector<char> taken;
    assignOnHugePages (taken, result_.cells.size (), char (0));
    while (!queue.empty ())
    {
      const Entry e = queue.top ();
      queue.pop ();
      if (!queue.empty ()) // the flood is bound by memory latency: the next cell starts loading
        __builtin_prefetch (&result_.cells[static_cast<std::size_t> (queue.top ().second.first)]);
      const std::size_t c = static_cast<std::size_t> (e.second.first);
      const int x = e.second.second;
      if (taken[c])
        continue;
      taken[c] = 1;
      of_cell[c] = x;
      // c's neighbours in its original group pair x with the same group as c did: only their own
      // heights are left to check (takes' other conditions held when c was queued).
      const double highest = height_[static_cast<std::size_t> (x)];
      const double lowest = kFloor2 * saddle_.find (key (x, original_[c]))->second;
      for (int i = 0; i <= result_.dimension; ++i)
      {
        const int nb = result_.cells[c].neighbors[i];
        if (nb < 0 || taken[static_cast<std::size_t> (nb)] || original_[static_cast<std::size_t> (nb)] != original_[c] ||
            fixed_[static_cast<std::size_t> (nb)])
          continue;
        const double h = result_.cells[static_cast<std::size_t> (nb)].squared_radius;
        if (h <= highest && h >= lowest)
          queue.emplace (h, std::make_pair (nb, x));
      }
    }
  }

private:
  using Entry = std::pair<double, std::pair<int, int>>; // cell height, (cell, thin group)
  using Queue = std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>>;
  static constexpr double kFloor2 = kStumpFloor * kStumpFloor;

  static std::uint64_t
  key (int a, int b)
  {
    return (static_cast<std::uint64_t> (std::min (a, b)) << 32) | static_cast<std::uint32_t> (std::max (a, b));
  }

  /** May thin group x take cell c (of its original group, a neighbour of x)? Only from a group more
    * than ratio times thicker, and only cells no larger than x's own maximum and not much smaller
    * than the saddle between the two. */
  bool
  takes (int x, std::size_t c) const
  {
    const int y = original_[c];
    const double hx = height_[static_cast<std::size_t> (x)], hy = height_[static_cast<std::size_t> (y)];
    if (x == y || fixed_[c] || !(hx > 0.0) || !(hy > 0.0) || !(ratio2_ * hx < hy))
      return false;
    const double h = result_.cells[c].squared_radius;
    const auto s = saddle_.find (key (x, y));
    return h <= hx && s != saddle_.end () && h >= kFloor2 * s->second;
  }

  /** The cells a neighbouring thin group may take, gathered on all workers. The queue's order is
    * total (takes admits finite heights only), so the order of gathering does not matter. */
  std::vector<Entry>
  seeds () const
  {
    return gatherListInOrder<Entry> (result_.cells.size (), [&] (std::size_t begin, std::size_t end, std::vector<Entry>& found) {
      for (std::size_t c = begin; c < end; ++c)
        for (int i = 0; i <= result_.dimension; ++i)
        {
          const int nb = result_.cells[c].neighbors[i];
          // Most neighbours share c's group: that test first, before loading the neighbour cell.
          if (nb < 0 || original_[static_cast<std::size_t> (nb)] == original_[c] ||
              result_.cells[static_cast<std::size_t> (nb)].inside != result_.cells[c].inside)
            continue;
          const int x = original_[static_cast<std::size_t> (nb)];
          if (takes (x, c))
            found.emplace_back (result_.cells[c].squared_radius, std::make_pair (static_cast<int> (c), x));
        }
    });
  }

  const FlowResult& result_;
  const std::vector<double>& height_;
  const double ratio2_;
  std::vector<int> original_; ///< the groups before the flood
  std::vector<char> fixed_;
  std::unordered_map<std::uint64_t, double> saddle_; ///< (a < b) -> squared radius of their saddle
};
} // namespace

void
reclaimStumps (const FlowResult& result, const std::vector<double>& height, double ratio, std::vector<int>& of_cell)
{
  StumpFlood (result, height, ratio, of_cell).run (of_cell);
}

} // namespace core
} // namespace pcl_flowseg

/*
 * pcl_flowseg - internal: segments too small to be parts join the neighbour across their widest saddle.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include "core/merging/small_part_merge.h"

#include "core/flow/cell_groups.h"
#include "core/merging/union_find.h"

#include <array>
#include <functional>
#include <queue>
#include <utility>

namespace pcl_flowseg {
namespace core {

namespace {
/** A saddle seen from one group: its squared radius and the group on the other side. */
struct Neighbour
{
  double squared_radius;
  int group;
};

/** What the absorption works on: per group its volume, whether it may be absorbed, and the
  * saddles to groups of its side (of the whole tree once groups are joined). */
struct GroupState
{
  std::vector<double> volume;
  std::vector<char> absorbable;
  std::vector<std::vector<Neighbour>> neighbours;
  std::vector<int> parent;
};

GroupState
initialState (const FlowResult& result, const MergeGroups& groups)
{
  const std::size_t n = static_cast<std::size_t> (groups.count);
  GroupState state;
  const std::vector<FlowSegment> summary = summariseCells (result.cells, groups.of_cell, groups.count);
  state.volume.resize (n);
  state.absorbable.assign (n, 1);
  state.neighbours.resize (n);
  state.parent.resize (n);
  for (std::size_t g = 0; g < n; ++g)
  {
    state.volume[g] = summary[g].volume;
    state.parent[g] = static_cast<int> (g);
  }
  for (std::size_t k = 0; k < result.manifolds.size (); ++k)
    if (result.manifolds[k].flows_to_infinity)
      state.absorbable[static_cast<std::size_t> (groups.of_manifold[k])] = 0;
  for (const SaddleFacet& s : highestSharedFacets (result, groups.of_cell))
  {
    const std::size_t a = static_cast<std::size_t> (s.segment_a), b = static_cast<std::size_t> (s.segment_b);
    if (groups.side[a] != groups.side[b])
      continue;
    state.neighbours[a].push_back ({s.squared_radius, s.segment_b});
    state.neighbours[b].push_back ({s.squared_radius, s.segment_a});
  }
  return state;
}

/** The root of the group across \a root's widest saddle to another tree; -1 if there is none. */
int
widestNeighbour (GroupState& state, int root)
{
  int best = -1;
  double best_radius = -1.0;
  for (const Neighbour& n : state.neighbours[static_cast<std::size_t> (root)])
  {
    const int other = findRoot (state.parent, n.group);
    if (other == root)
      continue;
    if (n.squared_radius > best_radius || (n.squared_radius == best_radius && other < best))
    {
      best_radius = n.squared_radius;
      best = other;
    }
  }
  return best;
}

/** Joins the trees of \a a and \a b; the new root carries their volume and saddles. */
int
joinGroups (GroupState& state, int a, int b)
{
  const int root = joinRoots (state.parent, a, b), gone = root == a ? b : a;
  const std::size_t r = static_cast<std::size_t> (root), g = static_cast<std::size_t> (gone);
  state.volume[r] += state.volume[g];
  state.absorbable[r] = state.absorbable[r] && state.absorbable[g];
  if (state.neighbours[r].size () < state.neighbours[g].size ())
    std::swap (state.neighbours[r], state.neighbours[g]);
  state.neighbours[r].insert (state.neighbours[r].end (), state.neighbours[g].begin (), state.neighbours[g].end ());
  std::vector<Neighbour> ().swap (state.neighbours[g]);
  return root;
}

/** Volume of all groups per side (index side + 1). */
std::array<double, 3>
sideVolumes (const GroupState& state, const MergeGroups& groups)
{
  std::array<double, 3> total{{0.0, 0.0, 0.0}};
  for (std::size_t g = 0; g < state.volume.size (); ++g)
    total[static_cast<std::size_t> (groups.side[g] + 1)] += state.volume[g];
  return total;
}
} // namespace

void
absorbSmallGroups (const FlowResult& result, double min_share, MergeGroups& groups)
{
  if (min_share <= 0.0 || groups.count < 2)
    return;
  GroupState state = initialState (result, groups);
  const std::array<double, 3> side_volume = sideVolumes (state, groups);
  const auto too_small = [&] (int g) {
    const std::size_t k = static_cast<std::size_t> (g);
    return state.absorbable[k] && state.volume[k] < min_share * side_volume[static_cast<std::size_t> (groups.side[k] + 1)];
  };
  using Entry = std::pair<double, int>; // volume when queued, group
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> queue;
  for (int g = 0; g < groups.count; ++g)
    if (too_small (g))
      queue.push ({state.volume[static_cast<std::size_t> (g)], g});
  while (!queue.empty ())
  {
    const auto [volume, g] = queue.top ();
    queue.pop ();
    if (state.parent[static_cast<std::size_t> (g)] != g || volume != state.volume[static_cast<std::size_t> (g)])
      continue; // joined or grown since it was queued
    const int neighbour = widestNeighbour (state, g);
    if (neighbour < 0)
      continue;
    const int root = joinGroups (state, g, neighbour);
    if (too_small (root))
      queue.push ({state.volume[static_cast<std::size_t> (root)], root});
  }
  for (int& g : groups.of_cell)
    g = findRoot (state.parent, g);
  for (int& g : groups.of_manifold)
    g = findRoot (state.parent, g);
}

} // namespace core
} // namespace pcl_flowseg

/*
 * pcl_flowseg - internal: the interior/exterior boundary made a manifold by relabelling cells
 * around the vertices where it is not one.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include "core/interior/manifold_repair.h"

#include "core/interior/boundary_measure.h"

#include <algorithm>
#include <limits>
#include <numeric>
#include <vector>

namespace pcl_flowseg {
namespace core {

namespace {

/** The cells around each of \a vertices (ascending), as compressed rows in the vertices' order. */
struct Stars
{
  std::vector<std::size_t> first;
  std::vector<int> cells;
};

Stars
starsOf (const std::vector<FlowCell>& cells, const std::vector<int>& vertices)
{
  std::vector<int> row_of;
  const int top = vertices.empty () ? 0 : vertices.back () + 1;
  row_of.assign (static_cast<std::size_t> (top), -1);
  for (std::size_t k = 0; k < vertices.size (); ++k)
    row_of[static_cast<std::size_t> (vertices[k])] = static_cast<int> (k);
  std::vector<std::vector<int>> rows (vertices.size ());
  for (std::size_t c = 0; c < cells.size (); ++c)
    for (int v : cells[c].vertices)
      if (v >= 0 && v < top && row_of[static_cast<std::size_t> (v)] >= 0)
        rows[static_cast<std::size_t> (row_of[static_cast<std::size_t> (v)])].push_back (static_cast<int> (c));
  Stars s;
  s.first.assign (1, 0);
  for (const auto& row : rows)
  {
    s.cells.insert (s.cells.end (), row.begin (), row.end ());
    s.first.push_back (s.cells.size ());
  }
  return s;
}

/** Groups of the cells \a star around vertex \a v with equal labels, linked through facets holding
  * \a v; the last element stands for the cells beyond the hull (outside). */
struct StarGroups
{
  std::vector<int> parent;
  bool on_hull = false; ///< some cell of the star faces the hull through a facet holding the vertex
  int find (int x)
  {
    while (parent[static_cast<std::size_t> (x)] != x)
      x = parent[static_cast<std::size_t> (x)] = parent[static_cast<std::size_t> (parent[static_cast<std::size_t> (x)])];
    return x;
  }
  void join (int a, int b) { parent[static_cast<std::size_t> (find (a))] = find (b); }
};

/** The label of star element \a k (the last one: beyond the hull, outside). */
int
labelOf (const std::vector<FlowCell>& cells, const std::vector<int>& star, std::size_t k)
{
  return k < star.size () ? cells[static_cast<std::size_t> (star[k])].inside : 0;
}

StarGroups
groupStar (const std::vector<FlowCell>& cells, int v, const std::vector<int>& star)
{
  const std::size_t m = star.size (), hull = m;
  StarGroups g;
  g.parent.resize (m + 1);
  std::iota (g.parent.begin (), g.parent.end (), 0);
  for (std::size_t k = 0; k < m; ++k)
  {
    const FlowCell& c = cells[static_cast<std::size_t> (star[k])];
    for (int i = 0; i < 4; ++i)
    {
      if (c.vertices[i] == v)
        continue; // the facet opposite v does not hold it
      const int nb = c.neighbors[i];
      g.on_hull |= nb < 0;
      const auto at = nb < 0 ? hull : static_cast<std::size_t> (std::lower_bound (star.begin (), star.end (), nb) - star.begin ());
      if (nb >= 0 && (at == m || star[at] != nb))
        continue; // not around v: cells that do not fit together are left as they are
      if (labelOf (cells, star, at) == c.inside)
        g.join (static_cast<int> (k), static_cast<int> (at));
    }
  }
  return g;
}

/** What the groups around a vertex call for: nothing (one inside and one outside group), or the
  * group of least volume to change side (root: its element in the star; -1 when every group
  * that could change is fixed). */
struct StarChoice
{
  bool manifold = true;
  int root = -1;
  double volume = std::numeric_limits<double>::infinity ();
};

/** Groups beyond the hull or holding a cell relabelled before never change side: relabelling back
  * and forth between two vertices would never end. */
StarChoice
chooseGroup (const std::vector<FlowCell>& cells, StarGroups& g, const std::vector<int>& star, const std::vector<char>& changed)
{
  constexpr double kFixed = std::numeric_limits<double>::infinity ();
  const std::size_t m = star.size ();
  std::vector<double> volume (m + 1, 0.0);
  for (std::size_t k = 0; k < m; ++k)
  {
    const auto cell = static_cast<std::size_t> (star[k]);
    volume[static_cast<std::size_t> (g.find (static_cast<int> (k)))] += changed[cell] ? kFixed : cells[cell].volume;
  }
  if (g.on_hull)
    volume[static_cast<std::size_t> (g.find (static_cast<int> (m)))] = kFixed;
  int groups[2] = {0, 0};
  StarChoice choice;
  for (std::size_t k = 0; k <= m; ++k)
  {
    if (g.find (static_cast<int> (k)) != static_cast<int> (k) || (k == m && !g.on_hull))
      continue;
    ++groups[labelOf (cells, star, k) == 1 ? 1 : 0];
    if (k < m && volume[k] < choice.volume)
    {
      choice.root = static_cast<int> (k);
      choice.volume = volume[k];
    }
  }
  choice.manifold = groups[0] <= 1 && groups[1] <= 1;
  return choice;
}

/** Relabels groups around \a v (\a star: its cells, ascending) until one inside and one outside
  * group are left or none may change; returns the cells relabelled. */
std::size_t
repairStar (std::vector<FlowCell>& cells, int v, const std::vector<int>& star, std::vector<char>& changed)
{
  std::size_t relabelled = 0;
  for (std::size_t guard = 0; guard <= star.size (); ++guard)
  {
    StarGroups g = groupStar (cells, v, star);
    const StarChoice choice = chooseGroup (cells, g, star, changed);
    if (choice.manifold || choice.root < 0)
      break;
    for (std::size_t k = 0; k < star.size (); ++k)
      if (g.find (static_cast<int> (k)) == choice.root)
      {
        FlowCell& c = cells[static_cast<std::size_t> (star[k])];
        c.inside = c.inside == 1 ? 0 : 1;
        changed[static_cast<std::size_t> (star[k])] = 1;
        ++relabelled;
      }
  }
  return relabelled;
}

/** The cells around the \a b-th vertex of \a stars, ascending. */
std::vector<int>
starRow (const Stars& stars, std::size_t b)
{
  std::vector<int> star (stars.cells.begin () + static_cast<long> (stars.first[b]),
                         stars.cells.begin () + static_cast<long> (stars.first[b + 1]));
  std::sort (star.begin (), star.end ());
  return star;
}

} // namespace

std::size_t
repairManifold (FlowResult& r, std::vector<int> bad)
{
  std::size_t relabelled = 0;
  std::vector<char> changed;
  for (int round = 0; round < kMaxManifoldRepairRounds && !bad.empty (); ++round)
  {
    const Stars stars = starsOf (r.cells, bad);
    changed.resize (r.cells.size (), 0);
    // Smallest change first: the order of the vertices' numbers, which a rotated copy of the
    // sample does not share, must not decide which side of a pinch gives way.
    std::vector<std::pair<double, std::size_t>> order;
    for (std::size_t b = 0; b < bad.size (); ++b)
    {
      const std::vector<int> star = starRow (stars, b);
      StarGroups g = groupStar (r.cells, bad[b], star);
      order.emplace_back (chooseGroup (r.cells, g, star, changed).volume, b);
    }
    std::sort (order.begin (), order.end ());
    for (const auto& [volume, b] : order)
      relabelled += repairStar (r.cells, bad[b], starRow (stars, b), changed);
    bad = measureBoundary (r);
  }
  return relabelled;
}

} // namespace core
} // namespace pcl_flowseg

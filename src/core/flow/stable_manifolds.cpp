/*
 * pcl_flowseg - internal: maxima and (strengthened) stable manifolds from the flow relation.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include "core/flow/stable_manifolds.h"

#include "core/geometry/cell_geometry.h"
#include "core/support/huge_pages.h"

#include <algorithm>
#include <limits>
#include <numeric>

namespace pcl_flowseg {
namespace core {

namespace {
constexpr int kRootInfinity = -2;
constexpr int kRootUnknown = -1;

} // namespace

StableManifolds
computeStableManifolds (std::vector<FlowCell>& cells, int dimension)
{
  const int facets = dimension + 1;
  const std::size_t n = cells.size ();
  const double inf = std::numeric_limits<double>::infinity ();

  std::vector<int> root, pending, ready; // maximum cell reached (or kRootInfinity); finite successors not yet resolved
  std::vector<double> strength;
  assignOnHugePages (root, n, kRootUnknown);
  assignOnHugePages (strength, n, 0.0);
  assignOnHugePages (pending, n, 0);
  ready.reserve (n);
  adviseHugePages (ready.data (), n * sizeof (int));

  for (std::size_t c = 0; c < n; ++c)
  {
    const FlowCell& cell = cells[c];
    for (int i = 0; i < facets; ++i)
      if ((cell.flow_mask >> i & 1u) && cell.neighbors[i] != kInfiniteCell)
        ++pending[c];
    if (pending[c] == 0)
      ready.push_back (static_cast<int> (c));
  }

  // Chooses the successor of largest strength among the resolved ones; a cell with no
  // successor at all is a maximum.
  auto resolve = [&] (int c) {
    FlowCell& cell = cells[static_cast<std::size_t> (c)];
    int best_facet = -1;
    double best_strength = -inf;
    int best_root = kRootUnknown;
    for (int i = 0; i < facets; ++i)
    {
      if (!(cell.flow_mask >> i & 1u))
        continue;
      const int nb = cell.neighbors[i];
      double s;
      int r;
      if (nb == kInfiniteCell)
      {
        s = inf;
        r = kRootInfinity;
      }
      else
      {
        if (root[static_cast<std::size_t> (nb)] == kRootUnknown)
          continue; // only during cycle breaking
        s = strength[static_cast<std::size_t> (nb)];
        r = root[static_cast<std::size_t> (nb)];
      }
      if (s > best_strength)
      {
        best_strength = s;
        best_facet = i;
        best_root = r;
      }
    }
    cell.successor_facet = static_cast<std::int8_t> (best_facet);
    if (best_facet < 0)
    {
      root[static_cast<std::size_t> (c)] = c;
      strength[static_cast<std::size_t> (c)] = cell.squared_radius;
    }
    else
    {
      root[static_cast<std::size_t> (c)] = best_root;
      strength[static_cast<std::size_t> (c)] = best_strength;
    }
  };

  // Reverse topological order: a cell is resolved once all cells it flows into are.
  std::size_t resolved = 0;
  while (!ready.empty ())
  {
    const int c = ready.back ();
    ready.pop_back ();
    resolve (c);
    ++resolved;
    const FlowCell& cell = cells[static_cast<std::size_t> (c)];
    for (int i = 0; i < facets; ++i)
    {
      const int nb = cell.neighbors[i];
      if (nb == kInfiniteCell)
        continue;
      const FlowCell& other = cells[static_cast<std::size_t> (nb)];
      const int back = facetTowards (other, c, dimension);
      if (back >= 0 && (other.flow_mask >> back & 1u) && --pending[static_cast<std::size_t> (nb)] == 0)
        ready.push_back (nb);
    }
  }

  StableManifolds out;
  if (resolved < n)
  {
    // Only reachable if the flow had a cycle: resolve the rest from the highest cell down,
    // so that they mostly find resolved successors; a cell with none becomes a maximum.
    std::vector<int> rest;
    for (std::size_t c = 0; c < n; ++c)
      if (root[c] == kRootUnknown)
        rest.push_back (static_cast<int> (c));
    std::sort (rest.begin (), rest.end (), [&] (int a, int b) {
      return cells[static_cast<std::size_t> (a)].squared_radius > cells[static_cast<std::size_t> (b)].squared_radius;
    });
    for (int c : rest)
      resolve (c);
    out.cycle_breaks = rest.size ();
  }

  for (std::size_t c = 0; c < n; ++c)
  {
    if (root[c] == static_cast<int> (c))
      out.maxima_cells.push_back (static_cast<int> (c));
    if (root[c] == kRootInfinity)
      out.has_infinity = true;
  }
  std::sort (out.maxima_cells.begin (), out.maxima_cells.end (), [&] (int a, int b) {
    const double ha = cells[static_cast<std::size_t> (a)].squared_radius;
    const double hb = cells[static_cast<std::size_t> (b)].squared_radius;
    return ha != hb ? ha > hb : a < b;
  });

  std::vector<int> manifold_of_max (n, -1);
  for (std::size_t k = 0; k < out.maxima_cells.size (); ++k)
    manifold_of_max[static_cast<std::size_t> (out.maxima_cells[k])] = static_cast<int> (k);
  const int infinity_manifold = static_cast<int> (out.maxima_cells.size ());
  for (std::size_t c = 0; c < n; ++c)
    cells[c].manifold = root[c] == kRootInfinity ? infinity_manifold
                                                 : manifold_of_max[static_cast<std::size_t> (root[c])];
  return out;
}

} // namespace core
} // namespace pcl_flowseg

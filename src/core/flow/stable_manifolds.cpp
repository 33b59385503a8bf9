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

/** The strengthened flow, resolved cell by cell: each cell's root (the maximum it reaches, or
  * infinity) and strength (that maximum's height, +inf for infinity). */
class StrengthenedFlow
{
public:
  StrengthenedFlow (std::vector<FlowCell>& cells, int dimension)
    : cells_ (cells), facets_ (dimension + 1), dimension_ (dimension)
  {
    const std::size_t n = cells.size ();
    assignOnHugePages (root_, n, kRootUnknown);
    assignOnHugePages (strength_, n, 0.0);
    assignOnHugePages (pending_, n, 0);
  }

  /** Resolves the cells in reverse topological order of the flow (Kahn's algorithm): a cell once
    * all cells it flows into are resolved. Returns how many were resolved (all, unless a cycle). */
  std::size_t
  resolveInFlowOrder ()
  {
    std::vector<int> ready;
    reserveOnHugePages (ready, cells_.size ());
    for (std::size_t c = 0; c < cells_.size (); ++c)
    {
      for (int i = 0; i < facets_; ++i)
        if ((cells_[c].flow_mask >> i & 1u) && cells_[c].neighbors[i] != kInfiniteCell)
          ++pending_[c];
      if (pending_[c] == 0)
        ready.push_back (static_cast<int> (c));
    }
    std::size_t resolved = 0;
    while (!ready.empty ())
    {
      const int c = ready.back ();
      ready.pop_back ();
      resolve (c);
      ++resolved;
      releasePredecessors (c, ready);
    }
    return resolved;
  }

  /** Only reachable if the flow had a cycle: resolves the rest from the highest cell down, so that
    * they mostly find resolved successors; a cell with none becomes a maximum. Returns how many. */
  std::size_t
  breakCycles ()
  {
    std::vector<int> rest;
    for (std::size_t c = 0; c < cells_.size (); ++c)
      if (root_[c] == kRootUnknown)
        rest.push_back (static_cast<int> (c));
    std::sort (rest.begin (), rest.end (), [&] (int a, int b) {
      return cells_[static_cast<std::size_t> (a)].squared_radius > cells_[static_cast<std::size_t> (b)].squared_radius;
    });
    for (int c : rest)
      resolve (c);
    return rest.size ();
  }

  /** The maxima by decreasing height (ties: lower cell), and every cell's manifold label. */
  void
  collect (StableManifolds& out) const
  {
    for (std::size_t c = 0; c < cells_.size (); ++c)
    {
      if (root_[c] == static_cast<int> (c))
        out.maxima_cells.push_back (static_cast<int> (c));
      if (root_[c] == kRootInfinity)
        out.has_infinity = true;
    }
    std::sort (out.maxima_cells.begin (), out.maxima_cells.end (), [&] (int a, int b) {
      const double ha = cells_[static_cast<std::size_t> (a)].squared_radius;
      const double hb = cells_[static_cast<std::size_t> (b)].squared_radius;
      return ha != hb ? ha > hb : a < b;
    });
    std::vector<int> manifold_of_max;
    assignOnHugePages (manifold_of_max, cells_.size (), -1);
    for (std::size_t k = 0; k < out.maxima_cells.size (); ++k)
      manifold_of_max[static_cast<std::size_t> (out.maxima_cells[k])] = static_cast<int> (k);
    const int infinity_manifold = static_cast<int> (out.maxima_cells.size ());
    for (std::size_t c = 0; c < cells_.size (); ++c)
      cells_[c].manifold = root_[c] == kRootInfinity ? infinity_manifold : manifold_of_max[static_cast<std::size_t> (root_[c])];
  }

private:
  /** Keeps the resolved successor of largest strength; a cell without one is a maximum. */
  void
  resolve (int c)
  {
    FlowCell& cell = cells_[static_cast<std::size_t> (c)];
    const double inf = std::numeric_limits<double>::infinity ();
    int best_facet = -1;
    double best_strength = -inf;
    int best_root = kRootUnknown;
    for (int i = 0; i < facets_; ++i)
    {
      if (!(cell.flow_mask >> i & 1u))
        continue;
      const int nb = cell.neighbors[i];
      if (nb != kInfiniteCell && root_[static_cast<std::size_t> (nb)] == kRootUnknown)
        continue; // only while breaking cycles
      const double s = nb == kInfiniteCell ? inf : strength_[static_cast<std::size_t> (nb)];
      if (s > best_strength)
      {
        best_strength = s;
        best_facet = i;
        best_root = nb == kInfiniteCell ? kRootInfinity : root_[static_cast<std::size_t> (nb)];
      }
    }
    cell.successor_facet = static_cast<std::int8_t> (best_facet);
    root_[static_cast<std::size_t> (c)] = best_facet < 0 ? c : best_root;
    strength_[static_cast<std::size_t> (c)] = best_facet < 0 ? cell.squared_radius : best_strength;
  }

  /** The neighbours flowing into \a c have one unresolved successor fewer; those left with none are ready. */
  void
  releasePredecessors (int c, std::vector<int>& ready)
  {
    const FlowCell& cell = cells_[static_cast<std::size_t> (c)];
    for (int i = 0; i < facets_; ++i)
    {
      const int nb = cell.neighbors[i];
      if (nb == kInfiniteCell)
        continue;
      const FlowCell& other = cells_[static_cast<std::size_t> (nb)];
      const int back = facetTowards (other, c, dimension_);
      if (back >= 0 && (other.flow_mask >> back & 1u) && --pending_[static_cast<std::size_t> (nb)] == 0)
        ready.push_back (nb);
    }
  }

  std::vector<FlowCell>& cells_;
  const int facets_;
  const int dimension_;
  std::vector<int> root_;       ///< maximum cell reached, kRootInfinity, or kRootUnknown
  std::vector<double> strength_;
  std::vector<int> pending_;    ///< finite successors not yet resolved
};
} // namespace

StableManifolds
computeStableManifolds (std::vector<FlowCell>& cells, int dimension)
{
  StrengthenedFlow flow (cells, dimension);
  StableManifolds out;
  if (flow.resolveInFlowOrder () < cells.size ())
    out.cycle_breaks = flow.breakCycles ();
  flow.collect (out);
  return out;
}

} // namespace core
} // namespace pcl_flowseg

/*
 * pcl_flowseg - internal: tiny pockets of inside cells cut off from the rest of the interior.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include "core/interior/interior_islands.h"

#include <vector>

namespace pcl_flowseg {
namespace core {

std::size_t
dropInteriorIslands (FlowResult& r, double min_share)
{
  const std::size_t n = r.cells.size ();
  const int facets = r.dimension + 1;
  double inside_volume = 0.0;
  for (const FlowCell& c : r.cells)
    inside_volume += c.inside ? c.volume : 0.0;
  std::vector<int> group (n, -1);
  std::vector<std::size_t> members, stack;
  std::size_t relabelled = 0;
  for (std::size_t seed = 0; seed < n; ++seed)
  {
    if (!r.cells[seed].inside || group[seed] >= 0)
      continue;
    // Flood the group of inside cells around the seed.
    members.clear ();
    stack.assign (1, seed);
    group[seed] = static_cast<int> (seed);
    double volume = 0.0;
    while (!stack.empty ())
    {
      const std::size_t c = stack.back ();
      stack.pop_back ();
      members.push_back (c);
      volume += r.cells[c].volume;
      for (int i = 0; i < facets; ++i)
      {
        const int nb = r.cells[c].neighbors[i];
        if (nb >= 0 && r.cells[static_cast<std::size_t> (nb)].inside && group[static_cast<std::size_t> (nb)] < 0)
        {
          group[static_cast<std::size_t> (nb)] = static_cast<int> (seed);
          stack.push_back (static_cast<std::size_t> (nb));
        }
      }
    }
    if (volume < min_share * inside_volume)
    {
      for (std::size_t c : members)
        r.cells[c].inside = 0;
      relabelled += members.size ();
    }
  }
  return relabelled;
}

} // namespace core
} // namespace pcl_flowseg

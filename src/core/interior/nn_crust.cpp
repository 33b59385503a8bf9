/*
 * pcl_flowseg - internal: the NN-crust of a 2D sample (Dey & Kumar): the edges of the sampled curve.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include "core/interior/nn_crust.h"

#include <limits>
#include <utility>

namespace pcl_flowseg {
namespace core {

std::uint64_t
edgeKey (int a, int b)
{
  if (a > b)
    std::swap (a, b);
  return (static_cast<std::uint64_t> (static_cast<std::uint32_t> (a)) << 32) | static_cast<std::uint32_t> (b);
}


std::unordered_set<std::uint64_t>
nnCrust (const std::vector<Eigen::Vector3d>& vertices, const std::vector<FlowCell>& cells)
{
  std::vector<std::vector<int>> adjacent (vertices.size ());
  for (const FlowCell& c : cells)
    for (int i = 0; i < 3; ++i)
    {
      const int a = c.vertices[(i + 1) % 3], b = c.vertices[(i + 2) % 3];
      if (c.neighbors[i] < 0 || a < b) // each interior edge once from one side; hull edges once
      {
        adjacent[static_cast<std::size_t> (a)].push_back (b);
        adjacent[static_cast<std::size_t> (b)].push_back (a);
      }
    }
  std::unordered_set<std::uint64_t> crust;
  for (std::size_t p = 0; p < adjacent.size (); ++p)
  {
    const Eigen::Vector3d& x = vertices[p];
    int nearest = -1;
    double best = std::numeric_limits<double>::infinity ();
    for (int q : adjacent[p])
    {
      const double d = (vertices[static_cast<std::size_t> (q)] - x).squaredNorm ();
      if (d < best || (d == best && q < nearest))
      {
        best = d;
        nearest = q;
      }
    }
    if (nearest < 0)
      continue;
    crust.insert (edgeKey (static_cast<int> (p), nearest));
    const Eigen::Vector3d dir = vertices[static_cast<std::size_t> (nearest)] - x;
    int half = -1;
    best = std::numeric_limits<double>::infinity ();
    for (int q : adjacent[p])
    {
      const Eigen::Vector3d e = vertices[static_cast<std::size_t> (q)] - x;
      if (e.dot (dir) >= 0)
        continue;
      const double d = e.squaredNorm ();
      if (d < best || (d == best && q < half))
      {
        best = d;
        half = q;
      }
    }
    if (half >= 0)
      crust.insert (edgeKey (static_cast<int> (p), half));
  }
  return crust;
}

} // namespace core
} // namespace pcl_flowseg

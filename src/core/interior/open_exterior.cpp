/*
 * pcl_flowseg - internal: the space reached from beyond the convex hull through wide openings.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include "core/interior/open_exterior.h"

#include "core/geometry/cell_geometry.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace pcl_flowseg {
namespace core {

namespace {
/** Squared length of the shortest edge of the facet of \a cell opposite its vertex \a skip. */
double
shortestFacetEdge2 (const std::vector<Eigen::Vector3d>& vertices, const FlowCell& cell, int skip)
{
  const Eigen::Vector3d* corner[3];
  int k = 0;
  for (int j = 0; j < 4; ++j)
    if (j != skip)
      corner[k++] = &vertices[static_cast<std::size_t> (cell.vertices[static_cast<std::size_t> (j)])];
  return std::min ({(*corner[0] - *corner[1]).squaredNorm (), (*corner[1] - *corner[2]).squaredNorm (),
                    (*corner[0] - *corner[2]).squaredNorm ()});
}
} // namespace

double
medianNearestDistance (const std::vector<Eigen::Vector3d>& vertices, const std::vector<FlowCell>& cells)
{
  std::vector<double> nearest2 (vertices.size (), std::numeric_limits<double>::infinity ());
  for (const FlowCell& c : cells)
    for (std::size_t i = 0; i < 4; ++i)
      for (std::size_t j = i + 1; j < 4; ++j)
      {
        const auto a = static_cast<std::size_t> (c.vertices[i]), b = static_cast<std::size_t> (c.vertices[j]);
        const double length2 = (vertices[a] - vertices[b]).squaredNorm ();
        nearest2[a] = std::min (nearest2[a], length2);
        nearest2[b] = std::min (nearest2[b], length2);
      }
  nearest2.erase (std::remove_if (nearest2.begin (), nearest2.end (), [] (double d) { return !std::isfinite (d); }), nearest2.end ());
  if (nearest2.empty ())
    return 0.0;
  const auto middle = nearest2.begin () + static_cast<std::ptrdiff_t> (nearest2.size () / 2);
  std::nth_element (nearest2.begin (), middle, nearest2.end ());
  return std::sqrt (*middle);
}

std::vector<std::uint8_t>
openExteriorCells (const std::vector<Eigen::Vector3d>& vertices, const std::vector<FlowCell>& cells, double opening)
{
  std::vector<std::uint8_t> reached (cells.size (), 0);
  if (!(opening > 0.0))
    return reached;
  const double cell_limit2 = opening * opening, edge_limit2 = 4.0 * opening * opening;
  const auto wide = [&] (std::size_t c, int facet) { return shortestFacetEdge2 (vertices, cells[c], facet) > edge_limit2; };
  std::vector<std::size_t> front;
  for (std::size_t c = 0; c < cells.size (); ++c)
  {
    if (!(cells[c].squared_radius > cell_limit2))
      continue;
    for (int i = 0; i < 4 && !reached[c]; ++i)
      if (cells[c].neighbors[static_cast<std::size_t> (i)] < 0 && wide (c, i))
      {
        reached[c] = 1;
        front.push_back (c);
      }
  }
  while (!front.empty ())
  {
    const std::size_t c = front.back ();
    front.pop_back ();
    for (int i = 0; i < 4; ++i)
    {
      const int next = cells[c].neighbors[static_cast<std::size_t> (i)];
      if (next < 0 || reached[static_cast<std::size_t> (next)])
        continue;
      const auto n = static_cast<std::size_t> (next);
      if (cells[n].squared_radius > cell_limit2 && wide (c, i))
      {
        reached[n] = 1;
        front.push_back (n);
      }
    }
  }
  return reached;
}

std::vector<Eigen::Vector3d>
openingNormals (const std::vector<Eigen::Vector3d>& vertices, const std::vector<FlowCell>& cells, const std::vector<std::uint8_t>& reached)
{
  std::vector<Eigen::Vector3d> normals (vertices.size (), Eigen::Vector3d::Zero ());
  for (std::size_t c = 0; c < cells.size (); ++c)
  {
    if (!reached[c])
      continue;
    const Eigen::Vector3d centre = cellCircumcentre (vertices, cells[c], 3);
    for (int i = 0; i < 4; ++i)
    {
      const auto v = static_cast<std::size_t> (cells[c].vertices[static_cast<std::size_t> (i)]);
      const Eigen::Vector3d outward = centre - vertices[v];
      const double length = outward.norm ();
      if (length > 0.0 && std::isfinite (length))
        normals[v] += outward / length;
    }
  }
  for (auto& n : normals)
    if (n.squaredNorm () > 0.0)
      n.normalize ();
  return normals;
}

} // namespace core
} // namespace pcl_flowseg

/*
 * pcl_flowseg - internal: geometry of Delaunay cells in double precision, and vertex incidence.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include "core/geometry/cell_geometry.h"

#include "core/support/bucket_rows.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cstdint>
#include <utility>

namespace pcl_flowseg {
namespace core {

Eigen::Vector3d
cellCircumcentre (const std::vector<Eigen::Vector3d>& vertices, const FlowCell& cell, int dimension)
{
  if (dimension == 2)
  {
    // A triangle's circumcentre is the centre of the smallest sphere through its three vertices:
    // the facet formula applied to a "facet" made of all three.
    FlowCell tri = cell;
    tri.vertices = {{-1, cell.vertices[0], cell.vertices[1], cell.vertices[2]}};
    Eigen::Vector3d centre;
    facetSquaredRadius (vertices, tri, 0, 3, &centre);
    return centre;
  }
  // Closed form: with u, v, w the edges from a, the centre is
  // a + (|u|^2 (v x w) + |v|^2 (w x u) + |w|^2 (u x v)) / (2 u . (v x w)).
  const Eigen::Vector3d& a = vertices[static_cast<std::size_t> (cell.vertices[0])];
  const Eigen::Vector3d u = vertices[static_cast<std::size_t> (cell.vertices[1])] - a;
  const Eigen::Vector3d v = vertices[static_cast<std::size_t> (cell.vertices[2])] - a;
  const Eigen::Vector3d w = vertices[static_cast<std::size_t> (cell.vertices[3])] - a;
  const Eigen::Vector3d vw = v.cross (w);
  return a + (u.squaredNorm () * vw + v.squaredNorm () * w.cross (u) + w.squaredNorm () * u.cross (v)) / (2.0 * u.dot (vw));
}

Eigen::Vector3d
outwardFacetNormal (const std::vector<Eigen::Vector3d>& vertices, const FlowCell& cell, int facet, int dimension)
{
  const int f = dimension + 1;
  const Eigen::Vector3d& apex = vertices[static_cast<std::size_t> (cell.vertices[facet])];
  const Eigen::Vector3d& a = vertices[static_cast<std::size_t> (cell.vertices[(facet + 1) % f])];
  const Eigen::Vector3d& b = vertices[static_cast<std::size_t> (cell.vertices[(facet + 2) % f])];
  Eigen::Vector3d n;
  if (dimension == 2)
  {
    // In the triangle's plane: the component of (a - apex) orthogonal to the edge.
    const Eigen::Vector3d e = (b - a).normalized ();
    n = (a - apex) - (a - apex).dot (e) * e;
  }
  else
  {
    const Eigen::Vector3d& c = vertices[static_cast<std::size_t> (cell.vertices[(facet + 3) % f])];
    n = (b - a).cross (c - a);
    if (n.dot (a - apex) < 0)
      n = -n;
  }
  const double len = n.norm ();
  return len > 0 ? Eigen::Vector3d (n / len) : Eigen::Vector3d::Zero ();
}

VertexIncidence
vertexIncidence (const std::vector<FlowCell>& cells, std::size_t vertex_count, int dimension)
{
  const int f = dimension + 1;
  BucketRows rows = bucketInOrder (cells.size (), vertex_count, [&] (std::size_t c, const auto& add) {
    for (int i = 0; i < f; ++i)
      add (static_cast<std::size_t> (cells[c].vertices[i]));
  });
  VertexIncidence inc;
  inc.first = std::move (rows.first);
  inc.cells = std::move (rows.items);
  return inc;
}

int
locateCell (const std::vector<Eigen::Vector3d>& vertices, const std::vector<FlowCell>& cells, int dimension,
            const Eigen::Vector3d& point, int hint)
{
  if (cells.empty ())
    return -1;
  const int f = dimension + 1;
  int c = hint >= 0 && static_cast<std::size_t> (hint) < cells.size () ? hint : 0;
  std::uint32_t turn = 12345u;
  // Visibility walk: cross any facet whose plane separates the cell from the point. It ends in
  // a Delaunay triangulation; the rotating start facet and the step bound guard against rounding.
  for (std::size_t steps = 0; steps <= cells.size (); ++steps)
  {
    const FlowCell& cell = cells[static_cast<std::size_t> (c)];
    turn = turn * 1103515245u + 12345u;
    const int start = static_cast<int> ((turn >> 16) % static_cast<std::uint32_t> (f));
    int next = -2;
    for (int k = 0; k < f && next == -2; ++k)
    {
      const int i = (start + k) % f;
      const Eigen::Vector3d n = outwardFacetNormal (vertices, cell, i, dimension);
      const Eigen::Vector3d& on = vertices[static_cast<std::size_t> (cell.vertices[(i + 1) % f])];
      if ((point - on).dot (n) > 0)
        next = cell.neighbors[i];
    }
    if (next == -2)
      return c;
    if (next < 0)
      return -1;
    c = next;
  }
  return c;
}

int
facetTowards (const FlowCell& from, int to, int dimension)
{
  for (int i = 0; i <= dimension; ++i)
    if (from.neighbors[i] == to)
      return i;
  return -1;
}

double
facetSquaredRadius (const std::vector<Eigen::Vector3d>& vertices, const FlowCell& cell,
                    int facet, int dimension, Eigen::Vector3d* centre)
{
  const int facets = dimension + 1;
  const Eigen::Vector3d& a = vertices[static_cast<std::size_t> (cell.vertices[(facet + 1) % facets])];
  const Eigen::Vector3d& b = vertices[static_cast<std::size_t> (cell.vertices[(facet + 2) % facets])];
  if (dimension == 2)
  {
    if (centre)
      *centre = 0.5 * (a + b);
    return 0.25 * (b - a).squaredNorm ();
  }
  const Eigen::Vector3d& c = vertices[static_cast<std::size_t> (cell.vertices[(facet + 3) % facets])];
  const Eigen::Vector3d u = b - a, v = c - a;
  const Eigen::Vector3d w = u.cross (v);
  const double w2 = w.squaredNorm ();
  if (!(w2 > 0.0))
  {
    // Cannot happen for a facet of a valid triangulation; fall back to the longest edge.
    const double e = std::max ({u.squaredNorm (), v.squaredNorm (), (c - b).squaredNorm ()});
    if (centre)
      *centre = (a + b + c) / 3.0;
    return 0.25 * e;
  }
  const Eigen::Vector3d offset = (u.squaredNorm () * v.cross (w) + v.squaredNorm () * w.cross (u)) / (2.0 * w2);
  if (centre)
    *centre = a + offset;
  return offset.squaredNorm ();
}

} // namespace core
} // namespace pcl_flowseg

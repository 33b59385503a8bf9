/*
 * pcl_flowseg - internal: free space seen by the sensor of a single-view scan.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include "core/interior/sensor_rays.h"

#include "core/geometry/cell_geometry.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace pcl_flowseg {
namespace core {

namespace {
/** Walks from the sample \a vertex towards \a target through the triangulation and marks every cell
  * the segment crosses; returns the number of cells marked. */
std::size_t
markRay (const std::vector<Eigen::Vector3d>& vertices, const std::vector<FlowCell>& cells, int d,
         const VertexIncidence& inc, int vertex, const Eigen::Vector3d& target, std::vector<std::uint8_t>& free_space)
{
  const int f = d + 1;
  const Eigen::Vector3d origin = vertices[static_cast<std::size_t> (vertex)];
  const Eigen::Vector3d dir = target - origin;
  if (dir.squaredNorm () == 0.0)
    return 0;
  // A point just off the sample along the ray locates the first cell.
  auto contains = [&] (const FlowCell& c, const Eigen::Vector3d& p) {
    for (int i = 0; i < f; ++i)
    {
      const Eigen::Vector3d n = outwardFacetNormal (vertices, c, i, d);
      const Eigen::Vector3d& on = vertices[static_cast<std::size_t> (c.vertices[(i + 1) % f])];
      if ((p - on).dot (n) > 0)
        return false;
    }
    return true;
  };
  int cell = -1;
  double scale = 0.0;
  for (std::size_t k = inc.first[static_cast<std::size_t> (vertex)]; k < inc.first[static_cast<std::size_t> (vertex) + 1]; ++k)
    scale = std::max (scale, std::sqrt (cells[static_cast<std::size_t> (inc.cells[k])].squared_radius));
  const Eigen::Vector3d probe = origin + dir.normalized () * (1e-6 * scale);
  for (std::size_t k = inc.first[static_cast<std::size_t> (vertex)]; k < inc.first[static_cast<std::size_t> (vertex) + 1] && cell < 0; ++k)
    if (contains (cells[static_cast<std::size_t> (inc.cells[k])], probe))
      cell = inc.cells[k];
  std::size_t marked = 0;
  double t = 0.0;
  for (std::size_t steps = 0; cell >= 0 && steps < cells.size (); ++steps)
  {
    const FlowCell& c = cells[static_cast<std::size_t> (cell)];
    // The cell at the sample itself is skipped: at grazing angles it may lie behind the surface.
    if (steps > 0 && !free_space[static_cast<std::size_t> (cell)])
    {
      free_space[static_cast<std::size_t> (cell)] = 1;
      ++marked;
    }
    // Exit facet: the smallest parameter beyond t at which the ray leaves through a facet plane.
    int exit = -1;
    double t_exit = std::numeric_limits<double>::infinity ();
    for (int i = 0; i < f; ++i)
    {
      const Eigen::Vector3d n = outwardFacetNormal (vertices, c, i, d);
      const double speed = dir.dot (n);
      if (speed <= 0)
        continue;
      const Eigen::Vector3d& on = vertices[static_cast<std::size_t> (c.vertices[(i + 1) % f])];
      const double ti = (on - origin).dot (n) / speed;
      if (ti > t && ti < t_exit)
      {
        t_exit = ti;
        exit = i;
      }
    }
    if (exit < 0 || t_exit >= 1.0)
      break; // the target lies in this cell
    t = t_exit;
    cell = c.neighbors[exit];
  }
  return marked;
}

} // namespace

std::vector<std::uint8_t>
freeSpaceCells (const std::vector<Eigen::Vector3d>& vertices, std::size_t seen, const std::vector<FlowCell>& cells, int dimension,
                const Eigen::Vector3d& viewpoint, std::size_t& marked)
{
  const VertexIncidence inc = vertexIncidence (cells, vertices.size (), dimension);
  std::vector<std::uint8_t> free_space (cells.size (), 0);
  marked = 0;
  for (std::size_t v = 0; v < seen; ++v)
    marked += markRay (vertices, cells, dimension, inc, static_cast<int> (v), viewpoint, free_space);
  return free_space;
}

} // namespace core
} // namespace pcl_flowseg

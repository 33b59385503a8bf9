/*
 * pcl_flowseg - the interior/exterior boundary of a result: the reconstructed surface (curve).
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include <pcl_flowseg/common/interior_boundary.h>

#include <Eigen/Geometry>

#include <utility>

namespace pcl_flowseg {

std::vector<std::array<int, 3>>
boundaryFacets (const FlowResult& r)
{
  std::vector<std::array<int, 3>> out;
  if (!r.interior.computed)
    return out;
  const int d = r.dimension, f = d + 1;
  auto onBoundary = [&] (const FlowCell& c, int i) {
    const int nb = c.neighbors[i];
    return nb < 0 || r.cells[static_cast<std::size_t> (nb)].inside != 1;
  };
  // A closed surface through all V vertices has 2V - 4 triangles (a curve V segments): reserved,
  // so that growing the list does not copy it and touch twice the fresh memory.
  out.reserve (static_cast<std::size_t> (d - 1) * r.vertices.size ());
  for (const FlowCell& c : r.cells)
  {
    if (c.inside != 1)
      continue;
    for (int i = 0; i < f; ++i)
    {
      if (!onBoundary (c, i))
        continue;
      std::array<int, 3> t{{c.vertices[(i + 1) % f], c.vertices[(i + 2) % f], d == 3 ? c.vertices[(i + 3) % f] : -1}};
      // Orient away from the cell: the apex must lie behind the facet.
      const Eigen::Vector3d& apex = r.vertices[static_cast<std::size_t> (c.vertices[i])];
      const Eigen::Vector3d& a = r.vertices[static_cast<std::size_t> (t[0])];
      const Eigen::Vector3d& b = r.vertices[static_cast<std::size_t> (t[1])];
      if (d == 3)
      {
        const Eigen::Vector3d& e = r.vertices[static_cast<std::size_t> (t[2])];
        if ((b - a).cross (e - a).dot (apex - a) > 0)
          std::swap (t[1], t[2]);
      }
      else
      {
        // In the cells' plane: the interior (apex) on the left of a -> b.
        const Eigen::Vector3d normal = (b - a).cross (apex - a);
        const Eigen::Vector3d& p0 = r.vertices[static_cast<std::size_t> (c.vertices[0])];
        const Eigen::Vector3d& p1 = r.vertices[static_cast<std::size_t> (c.vertices[1])];
        const Eigen::Vector3d& p2 = r.vertices[static_cast<std::size_t> (c.vertices[2])];
        const Eigen::Vector3d plane = (p1 - p0).cross (p2 - p0); // CGAL faces are counter-clockwise
        if (normal.dot (plane) < 0)
          std::swap (t[0], t[1]);
      }
      out.push_back (t);
    }
  }
  return out;
}

} // namespace pcl_flowseg

/*
 * pcl_flowseg - internal: 3D Delaunay triangulation and the exact flow relation between tetrahedra.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include "delaunay_cells.h"

#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Delaunay_triangulation_cell_base_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_cell_base_with_info_3.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>

#include <cmath>
#include <utility>

namespace pcl_flowseg {
namespace core {

namespace {
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using VertexBase = CGAL::Triangulation_vertex_base_with_info_3<int, Kernel>;
using CellBase = CGAL::Triangulation_cell_base_with_info_3<
    int, Kernel, CGAL::Delaunay_triangulation_cell_base_3<Kernel>>;
using DataStructure = CGAL::Triangulation_data_structure_3<VertexBase, CellBase>;
using Delaunay3 = CGAL::Delaunay_triangulation_3<Kernel, DataStructure>;
using Point3 = Kernel::Point_3;
} // namespace

bool
triangulate3D (const std::vector<Eigen::Vector3d>& points,
               std::vector<FlowCell>& cells, std::string& error)
{
  cells.clear ();
  if (points.size () < 4)
  {
    error = "3D segmentation needs at least 4 distinct points, got " + std::to_string (points.size ());
    return false;
  }
  std::vector<std::pair<Point3, int>> input;
  input.reserve (points.size ());
  for (std::size_t i = 0; i < points.size (); ++i)
    input.emplace_back (Point3 (points[i].x (), points[i].y (), points[i].z ()), static_cast<int> (i));

  Delaunay3 dt;
  dt.insert (input.begin (), input.end ()); // spatially sorted insertion
  if (dt.dimension () < 3)
  {
    error = dt.dimension () == 2
                ? "all points are coplanar: use 2D mode (dimension 2) for planar input"
                : "all points are collinear: a 3D triangulation needs 4 points not on one plane";
    return false;
  }

  int next = 0;
  for (auto c = dt.finite_cells_begin (); c != dt.finite_cells_end (); ++c)
    c->info () = next++;
  cells.resize (static_cast<std::size_t> (next));

  for (auto c = dt.finite_cells_begin (); c != dt.finite_cells_end (); ++c)
  {
    FlowCell& cell = cells[static_cast<std::size_t> (c->info ())];
    const Point3* p[4];
    for (int i = 0; i < 4; ++i)
    {
      cell.vertices[i] = c->vertex (i)->info ();
      p[i] = &c->vertex (i)->point ();
      auto nb = c->neighbor (i);
      cell.neighbors[i] = dt.is_infinite (nb) ? kInfiniteCell : nb->info ();
    }
    for (int i = 0; i < 4; ++i)
    {
      // The tetrahedron flows across the facet opposite p[i] exactly when p[i] lies strictly
      // inside the facet's diametral sphere (exact predicate, no circumcentre built).
      const Point3& a = *p[(i + 1) % 4];
      const Point3& b = *p[(i + 2) % 4];
      const Point3& d = *p[(i + 3) % 4];
      if (CGAL::side_of_bounded_sphere (a, b, d, *p[i]) == CGAL::ON_BOUNDED_SIDE)
        cell.flow_mask |= static_cast<std::uint8_t> (1u << i);
    }
    cell.squared_radius = CGAL::squared_radius (*p[0], *p[1], *p[2], *p[3]);
    cell.volume = std::abs (CGAL::volume (*p[0], *p[1], *p[2], *p[3]));
  }
  return true;
}

} // namespace core
} // namespace pcl_flowseg

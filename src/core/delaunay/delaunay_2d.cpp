/*
 * pcl_flowseg - internal: 2D Delaunay triangulation and the exact flow relation between triangles.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include "core/delaunay/delaunay_cells.h"

#include "core/delaunay/canonical_cells.h"
#include "core/support/parallel.h"

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <cmath>
#include <utility>

namespace pcl_flowseg {
namespace core {

namespace {
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using VertexBase = CGAL::Triangulation_vertex_base_with_info_2<int, Kernel>;
using FaceBase = CGAL::Triangulation_face_base_with_info_2<int, Kernel>;
using DataStructure = CGAL::Triangulation_data_structure_2<VertexBase, FaceBase>;
using Delaunay2 = CGAL::Delaunay_triangulation_2<Kernel, DataStructure>;
using Point2 = Kernel::Point_2;
} // namespace

Status
triangulate2D (const std::vector<Eigen::Vector2d>& points, std::vector<FlowCell>& cells)
{
  cells.clear ();
  if (points.size () < 3)
    return Status::error ("2D segmentation needs at least 3 distinct points, got " + std::to_string (points.size ()));
  std::vector<std::pair<Point2, int>> input;
  input.reserve (points.size ());
  for (std::size_t i = 0; i < points.size (); ++i)
    input.emplace_back (Point2 (points[i].x (), points[i].y ()), static_cast<int> (i));

  Delaunay2 dt;
  dt.insert (input.begin (), input.end ()); // spatially sorted insertion
  if (dt.dimension () < 2)
    return Status::error ("all points are collinear: a 2D triangulation needs 3 points not on one line");

  int next = 0;
  for (auto f = dt.finite_faces_begin (); f != dt.finite_faces_end (); ++f)
    f->info () = next++;
  std::vector<CellLinks> links (static_cast<std::size_t> (next));
  for (auto f = dt.finite_faces_begin (); f != dt.finite_faces_end (); ++f)
  {
    CellLinks& cell = links[static_cast<std::size_t> (f->info ())];
    for (int i = 0; i < 3; ++i)
    {
      cell.vertices[static_cast<std::size_t> (i)] = f->vertex (i)->info ();
      const auto nb = f->neighbor (i);
      cell.neighbors[static_cast<std::size_t> (i)] = dt.is_infinite (nb) ? kInfiniteCell : nb->info ();
    }
    orientCanonically (cell, 3);
  }
  buildCellsInCanonicalOrder (std::move (links), 2, cells);
  return Status::success ();
}

namespace {
/** Calls \a body (cell, corners) for every triangle, its corners as CGAL points, on all cores. */
template <class Body>
void
forEachTriangle (const std::vector<Eigen::Vector2d>& points, std::vector<FlowCell>& cells, const Body& body)
{
  parallelFor (cells.size (), [&] (std::size_t k) {
    Point2 p[3];
    for (int i = 0; i < 3; ++i)
    {
      const Eigen::Vector2d& v = points[static_cast<std::size_t> (cells[k].vertices[i])];
      p[i] = Point2 (v.x (), v.y ());
    }
    body (cells[k], p);
  });
}
} // namespace

void
computeFlowMask2D (const std::vector<Eigen::Vector2d>& points, std::vector<FlowCell>& cells)
{
  forEachTriangle (points, cells, [] (FlowCell& cell, const Point2 (&p)[3]) {
    cell.flow_mask = 0;
    for (int i = 0; i < 3; ++i)
    {
      // The triangle and its circumcentre lie on opposite sides of the edge opposite p[i]
      // exactly when the angle at p[i] is obtuse (exact predicate, no circumcentre built).
      if (CGAL::angle (p[(i + 1) % 3], p[i], p[(i + 2) % 3]) == CGAL::OBTUSE)
        cell.flow_mask |= static_cast<std::uint8_t> (1u << i);
    }
  });
}

void
computeCellMeasures2D (const std::vector<Eigen::Vector2d>& points, std::vector<FlowCell>& cells)
{
  forEachTriangle (points, cells, [] (FlowCell& cell, const Point2 (&p)[3]) {
    cell.squared_radius = CGAL::squared_radius (p[0], p[1], p[2]);
    cell.volume = std::abs (CGAL::area (p[0], p[1], p[2]));
  });
}

void
computeFlowRelation2D (const std::vector<Eigen::Vector2d>& points, std::vector<FlowCell>& cells)
{
  computeFlowMask2D (points, cells);
  computeCellMeasures2D (points, cells);
}

} // namespace core
} // namespace pcl_flowseg

/*
 * pcl_flowseg - internal: 3D Delaunay triangulation and the exact flow relation between tetrahedra.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include "delaunay_cells.h"

#include "canonical_cells.h"
#include "flow_predicate.h"
#include "parallel.h"

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
using Point3 = Kernel::Point_3;

/** The triangulation type, sequential or (with TBB) parallel. Vertices carry their index. */
template <class Concurrency>
struct Triangulation3
{
  using VertexBase = CGAL::Triangulation_vertex_base_with_info_3<int, Kernel>;
  using CellBase = CGAL::Triangulation_cell_base_with_info_3<
      int, Kernel, CGAL::Delaunay_triangulation_cell_base_3<Kernel>>;
  using DataStructure = CGAL::Triangulation_data_structure_3<VertexBase, CellBase, Concurrency>;
  using Type = CGAL::Delaunay_triangulation_3<Kernel, DataStructure>;
};

/** Copies the finite cells' vertex indices and neighbours (in CGAL's order) into \a cells. */
template <class Delaunay>
void
extractCells (Delaunay& dt, std::vector<FlowCell>& cells)
{
  std::vector<typename Delaunay::Cell_handle> handles;
  handles.reserve (dt.number_of_finite_cells ());
  for (auto c = dt.finite_cells_begin (); c != dt.finite_cells_end (); ++c)
  {
    c->info () = static_cast<int> (handles.size ());
    handles.push_back (c);
  }
  cells.assign (handles.size (), FlowCell ());
  parallelFor (handles.size (), [&] (std::size_t k) {
    const auto c = handles[k];
    FlowCell& cell = cells[k];
    for (int i = 0; i < 4; ++i)
    {
      cell.vertices[i] = c->vertex (i)->info ();
      const auto nb = c->neighbor (i);
      cell.neighbors[i] = dt.is_infinite (nb) ? kInfiniteCell : nb->info ();
    }
  });
}

template <class Concurrency>
bool
triangulateWith (const std::vector<Eigen::Vector3d>& points, std::vector<FlowCell>& cells, std::string& error)
{
  using Delaunay = typename Triangulation3<Concurrency>::Type;
  std::vector<std::pair<Point3, int>> input;
  input.reserve (points.size ());
  for (std::size_t i = 0; i < points.size (); ++i)
    input.emplace_back (Point3 (points[i].x (), points[i].y (), points[i].z ()), static_cast<int> (i));

  int dimension;
  if constexpr (std::is_same<Concurrency, CGAL::Parallel_tag>::value)
  {
    CGAL::Bbox_3 box;
    for (const auto& p : input)
      box += p.first.bbox ();
    typename Delaunay::Lock_data_structure locks (box, 50);
    Delaunay dt (&locks);
    dt.insert (input.begin (), input.end ()); // parallel, spatially sorted insertion
    dimension = dt.dimension ();
    if (dimension == 3)
      extractCells (dt, cells);
  }
  else
  {
    Delaunay dt;
    dt.insert (input.begin (), input.end ()); // spatially sorted insertion
    dimension = dt.dimension ();
    if (dimension == 3)
      extractCells (dt, cells);
  }
  if (dimension < 3)
  {
    error = dimension == 2 ? "all points are coplanar: use 2D mode (dimension 2) for planar input"
                           : "all points are collinear: a 3D triangulation needs 4 points not on one plane";
    return false;
  }
  return true;
}
} // namespace

bool
triangulate3D (const std::vector<Eigen::Vector3d>& points, std::vector<FlowCell>& cells, std::string& error)
{
  cells.clear ();
  if (points.size () < 4)
  {
    error = "3D segmentation needs at least 4 distinct points, got " + std::to_string (points.size ());
    return false;
  }
  // The parallel triangulation pays from a few thousand points on.
  const bool parallel = workerThreads () > 1 && points.size () >= 5000;
  const bool ok = parallel ? triangulateWith<CGAL::Parallel_tag> (points, cells, error)
                           : triangulateWith<CGAL::Sequential_tag> (points, cells, error);
  if (ok)
    putInCanonicalOrder (cells, 3);
  return ok;
}

void
computeFlowRelation3D (const std::vector<Eigen::Vector3d>& points, std::vector<FlowCell>& cells)
{
  parallelFor (cells.size (), [&] (std::size_t k) {
    FlowCell& cell = cells[k];
    const Eigen::Vector3d* v[4];
    for (int i = 0; i < 4; ++i)
      v[i] = &points[static_cast<std::size_t> (cell.vertices[i])];
    cell.flow_mask = 0;
    // The tetrahedron flows across the facet opposite v[i] exactly when v[i] lies strictly inside
    // the facet's diametral sphere (exact predicate, no circumcentre built).
    for (int i = 0; i < 4; ++i)
      if (insideDiametralSphere (*v[(i + 1) % 4], *v[(i + 2) % 4], *v[(i + 3) % 4], *v[i]))
        cell.flow_mask |= static_cast<std::uint8_t> (1u << i);
    Point3 p[4];
    for (int i = 0; i < 4; ++i)
      p[i] = Point3 (v[i]->x (), v[i]->y (), v[i]->z ());
    cell.squared_radius = CGAL::squared_radius (p[0], p[1], p[2], p[3]);
    cell.volume = std::abs (CGAL::volume (p[0], p[1], p[2], p[3]));
  });
}

} // namespace core
} // namespace pcl_flowseg

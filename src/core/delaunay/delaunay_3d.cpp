/*
 * pcl_flowseg - internal: 3D Delaunay triangulation and the exact flow relation between tetrahedra.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include "core/delaunay/delaunay_cells.h"

#include "core/delaunay/canonical_cells.h"
#include "core/delaunay/flow_predicate.h"
#include "core/delaunay/huge_page_cells.h"
#include "core/support/huge_pages.h"
#include "core/support/parallel.h"
#include "core/support/system_load.h"

#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Delaunay_triangulation_cell_base_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_cell_base_with_info_3.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <thread>
#include <type_traits>
#include <utility>

namespace pcl_flowseg {
namespace core {

namespace {
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point3 = Kernel::Point_3;

/** The triangulation type, sequential or (with TBB) parallel. Vertices carry their index. The
  * parallel one keeps its cells and vertices on huge pages (core/delaunay/huge_page_cells.h). */
template <class Concurrency>
struct Triangulation3
{
  static constexpr bool kParallel = std::is_same<Concurrency, CGAL::Parallel_tag>::value;
  template <class Base>
  using Storage = std::conditional_t<kParallel, OnHugePages<Base>, Base>;
  using VertexBase = Storage<CGAL::Triangulation_vertex_base_with_info_3<int, Kernel>>;
  using CellBase = Storage<CGAL::Triangulation_cell_base_with_info_3<
      int, Kernel, CGAL::Delaunay_triangulation_cell_base_3<Kernel>>>;
  using DataStructure = CGAL::Triangulation_data_structure_3<VertexBase, CellBase, Concurrency>;
  using Type = CGAL::Delaunay_triangulation_3<Kernel, DataStructure>;
};

/** The finite cells of \a dt, oriented canonically, neighbours by their index here. Only a third
  * of the size of the FlowCells, so that the triangulation can be released before those are built
  * (the two together are the peak of memory otherwise). */
template <class Delaunay>
std::vector<CellLinks>
extractLinks (Delaunay& dt)
{
  std::vector<typename Delaunay::Cell_handle> handles;
  reserveOnHugePages (handles, dt.number_of_finite_cells ());
  // Every cell numbered, the infinite ones kInfiniteCell: a neighbour's number then says whether
  // it is infinite, without visiting its vertices.
  for (auto c = dt.all_cells_begin (); c != dt.all_cells_end (); ++c)
    if (dt.is_infinite (c))
      c->info () = kInfiniteCell;
    else
    {
      c->info () = static_cast<int> (handles.size ());
      handles.push_back (c);
    }
  std::vector<CellLinks> links;
  assignOnHugePages (links, handles.size ());
  const std::size_t count = handles.size ();
  parallelFor (count, [&] (std::size_t k) {
    // Pointer chasing all over CGAL's cells: the cell 16 ahead starts loading, and the vertices
    // and neighbours of the cell 8 ahead (loaded by then).
    if (k + 16 < count)
      __builtin_prefetch (&*handles[k + 16]);
    if (k + 8 < count)
      for (int i = 0; i < 4; ++i)
      {
        __builtin_prefetch (&*handles[k + 8]->vertex (i));
        __builtin_prefetch (&*handles[k + 8]->neighbor (i));
      }
    CellLinks& cell = links[k];
    for (int i = 0; i < 4; ++i)
    {
      cell.vertices[static_cast<std::size_t> (i)] = handles[k]->vertex (i)->info ();
      cell.neighbors[static_cast<std::size_t> (i)] = handles[k]->neighbor (i)->info ();
    }
    orientCanonically (cell, 4);
  });
  return links;
}

template <class Concurrency>
Status
triangulateWith (const std::vector<Eigen::Vector3d>& points, std::vector<FlowCell>& cells)
{
  using Delaunay = typename Triangulation3<Concurrency>::Type;
  std::vector<std::pair<Point3, int>> input;
  reserveOnHugePages (input, points.size ());
  for (std::size_t i = 0; i < points.size (); ++i)
    input.emplace_back (Point3 (points[i].x (), points[i].y (), points[i].z ()), static_cast<int> (i));

  int dimension;
  std::vector<CellLinks> links;
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
      links = extractLinks (dt);
  }
  else
  {
    Delaunay dt;
    dt.insert (input.begin (), input.end ()); // spatially sorted insertion
    dimension = dt.dimension ();
    if (dimension == 3)
      links = extractLinks (dt);
  }
  if (dimension < 3)
    return Status::error (dimension == 2 ? "all points are coplanar: use 2D mode (dimension 2) for planar input"
                                         : "all points are collinear: a 3D triangulation needs 4 points not on one plane");
  std::vector<std::pair<Point3, int>> ().swap (input);
  buildCellsInCanonicalOrder (std::move (links), 3, cells); // the triangulation is gone by now
  return Status::success ();
}

/** True when CGAL's parallel insertion should run: two or more workers allowed, a few thousand
  * points at least, and a core to spare from other processes right now. Its threads spin on cell
  * locks; when they must share cores with other busy processes they wait out each other's time
  * slices, which can cost several times the sequential time (docs/method.md). The result is the
  * same either way (canonical order). Where /proc cannot be read, the 1-minute load average. */
bool
parallelTriangulationPays (std::size_t points)
{
  const std::size_t workers = workerThreads ();
  if (workers < 2 || points < 5000)
    return false;
  const int cores = static_cast<int> (std::max (1u, std::thread::hardware_concurrency ()));
  const int others = otherRunnableThreads ();
  if (others >= 0)
    return others <= cores - 2; // this thread and one more have a core each
  double load = 0.0;
  if (std::FILE* f = std::fopen ("/proc/loadavg", "r"))
  {
    if (std::fscanf (f, "%lf", &load) != 1)
      load = 0.0;
    std::fclose (f);
  }
  return load < cores - 0.5;
}
} // namespace

Status
triangulate3D (const std::vector<Eigen::Vector3d>& points, std::vector<FlowCell>& cells, Insertion insertion)
{
  cells.clear ();
  if (points.size () < 4)
    return Status::error ("3D segmentation needs at least 4 distinct points, got " + std::to_string (points.size ()));
  const bool parallel = insertion == Insertion::Parallel ? workerThreads () > 1
                        : insertion == Insertion::Sequential ? false
                                                              : parallelTriangulationPays (points.size ());
  return parallel ? triangulateWith<CGAL::Parallel_tag> (points, cells)
                  : triangulateWith<CGAL::Sequential_tag> (points, cells);
}

void
computeFlowMask3D (const std::vector<Eigen::Vector3d>& points, std::vector<FlowCell>& cells)
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
  });
}

void
computeCellMeasures3D (const std::vector<Eigen::Vector3d>& points, std::vector<FlowCell>& cells)
{
  parallelFor (cells.size (), [&] (std::size_t k) {
    FlowCell& cell = cells[k];
    Point3 p[4];
    for (int i = 0; i < 4; ++i)
    {
      const Eigen::Vector3d& v = points[static_cast<std::size_t> (cell.vertices[i])];
      p[i] = Point3 (v.x (), v.y (), v.z ());
    }
    cell.squared_radius = CGAL::squared_radius (p[0], p[1], p[2], p[3]);
    cell.volume = std::abs (CGAL::volume (p[0], p[1], p[2], p[3]));
  });
}

void
computeFlowRelation3D (const std::vector<Eigen::Vector3d>& points, std::vector<FlowCell>& cells)
{
  computeFlowMask3D (points, cells);
  computeCellMeasures3D (points, cells);
}

} // namespace core
} // namespace pcl_flowseg

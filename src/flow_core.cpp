/*
 * pcl_flowseg - the compiled core: preparation, Delaunay, flow, merging, per-point labels.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include <pcl_flowseg/flow_core.h>

#include "core/delaunay_cells.h"
#include "core/point_preparation.h"
#include "core/point_labels.h"
#include "core/segment_graph.h"
#include "core/stable_manifolds.h"

#include <Eigen/LU>

#include <chrono>
#include <cmath>
#include <exception>
#include <limits>
#include <new>

namespace pcl_flowseg {

namespace {
using Clock = std::chrono::steady_clock;

double
millisecondsSince (Clock::time_point start)
{
  return std::chrono::duration<double, std::milli> (Clock::now () - start).count ();
}

/** Circumcentre of a cell from its input-frame vertices. */
Eigen::Vector3d
cellCircumcentre (const std::vector<Eigen::Vector3d>& vertices, const FlowCell& cell, int dimension)
{
  if (dimension == 2)
  {
    Eigen::Vector3d centre;
    // The circumcentre of a triangle is the centre of the smallest sphere through its vertices
    // lying in its plane: the facet formula applied to the "facet" made of all three vertices.
    FlowCell tri = cell;
    tri.vertices = {{-1, cell.vertices[0], cell.vertices[1], cell.vertices[2]}};
    core::facetSquaredRadius (vertices, tri, 0, 3, &centre);
    return centre;
  }
  const Eigen::Vector3d& a = vertices[static_cast<std::size_t> (cell.vertices[0])];
  Eigen::Matrix3d m;
  Eigen::Vector3d rhs;
  for (int i = 1; i < 4; ++i)
  {
    const Eigen::Vector3d d = vertices[static_cast<std::size_t> (cell.vertices[i])] - a;
    m.row (i - 1) = d.transpose ();
    rhs[i - 1] = 0.5 * d.squaredNorm ();
  }
  return a + m.partialPivLu ().solve (rhs);
}

/** Stable manifolds as FlowSegments, with their maxima and statistics. */
void
buildManifolds (const core::StableManifolds& sm, FlowResult& result)
{
  const int dim = result.dimension;
  result.maxima.clear ();
  for (int c : sm.maxima_cells)
  {
    FlowMaximum m;
    m.cell = c;
    m.height = result.cells[static_cast<std::size_t> (c)].squared_radius;
    m.location = cellCircumcentre (result.vertices, result.cells[static_cast<std::size_t> (c)], dim);
    result.maxima.push_back (m);
  }
  const int count = static_cast<int> (sm.maxima_cells.size ()) + (sm.has_infinity ? 1 : 0);
  std::vector<int> manifold_of_cell (result.cells.size ());
  for (std::size_t c = 0; c < result.cells.size (); ++c)
    manifold_of_cell[c] = result.cells[c].manifold;
  result.manifolds = core::summariseCells (result.cells, manifold_of_cell, count);
  for (std::size_t k = 0; k < result.maxima.size (); ++k)
  {
    result.manifolds[k].maximum = result.maxima[k];
    result.manifolds[k].maxima = {static_cast<int> (k)};
  }
  if (sm.has_infinity)
  {
    FlowSegment& inf = result.manifolds.back ();
    inf.flows_to_infinity = true;
    inf.maximum.height = std::numeric_limits<double>::infinity ();
  }
  result.manifold_adjacency = core::highestSharedFacets (result, manifold_of_cell);
}

Status
failure (FlowResult& result, const std::string& message)
{
  const std::size_t n = result.input_points;
  result = FlowResult ();
  result.input_points = n;
  return Status::error (message);
}
} // namespace

Status
remergeFlowSegmentation (double rho, FlowResult& result)
{
  if (!std::isfinite (rho) || rho <= 0.0)
    return Status::error ("rho must be a finite number > 0, got " + std::to_string (rho));
  if (result.cells.empty ())
    return Status::error ("no flow segmentation to merge: run runFlowSegmentation first");
  const auto start = Clock::now ();
  core::mergeManifolds (rho, result);
  result.timings.merge_ms = millisecondsSince (start);
  const auto labels = Clock::now ();
  core::labelPoints (result);
  result.timings.labels_ms = millisecondsSince (labels);
  return Status::success ();
}

Status
runFlowSegmentation (const std::vector<Eigen::Vector3d>& points, const FlowParameters& params,
                     FlowResult& result, const ProgressCallback& progress)
{
  result = FlowResult ();
  result.input_points = points.size ();
  if (!std::isfinite (params.rho) || params.rho <= 0.0)
    return failure (result, "rho must be a finite number > 0, got " + std::to_string (params.rho));
  if (!std::isfinite (params.planar_tolerance) || params.planar_tolerance < 0.0)
    return failure (result, "planar tolerance must be a finite number >= 0");
  auto report = [&] (const char* stage, double fraction) {
    if (progress)
      progress (stage, fraction);
  };

  try
  {
    const auto start = Clock::now ();
    report ("preparation", 0.0);
    core::PreparedPoints prepared;
    std::string error;
    if (!core::preparePoints (points, params, prepared, result.warnings, error))
      return failure (result, error);
    result.dimension = prepared.dimension;
    result.non_finite_points = prepared.non_finite;
    result.duplicate_points = prepared.duplicates;
    result.point_to_vertex = std::move (prepared.point_to_vertex);
    result.vertices = std::move (prepared.vertices);
    result.timings.preparation_ms = millisecondsSince (start);

    report ("delaunay", 0.05);
    auto stage = Clock::now ();
    const bool ok = result.dimension == 2 ? core::triangulate2D (prepared.planar, result.cells, error)
                                          : core::triangulate3D (result.vertices, result.cells, error);
    if (!ok)
      return failure (result, error);
    const int facets = result.dimension + 1;
    for (FlowCell& cell : result.cells)
    {
      Eigen::Vector3d sum = Eigen::Vector3d::Zero ();
      for (int i = 0; i < facets; ++i)
        sum += result.vertices[static_cast<std::size_t> (cell.vertices[i])];
      cell.centroid = sum / facets;
    }
    result.timings.delaunay_ms = millisecondsSince (stage);

    report ("flow", 0.6);
    stage = Clock::now ();
    const core::StableManifolds sm = core::computeStableManifolds (result.cells, result.dimension);
    result.cycle_breaks = sm.cycle_breaks;
    if (sm.cycle_breaks > 0)
      result.warnings.push_back (std::to_string (sm.cycle_breaks) +
                                 " cell(s) not ordered by the flow (degenerate input): resolved by height");
    buildManifolds (sm, result);
    result.timings.flow_ms = millisecondsSince (stage);

    report ("merge", 0.8);
    stage = Clock::now ();
    core::mergeManifolds (params.rho, result);
    result.timings.merge_ms = millisecondsSince (stage);

    report ("labels", 0.9);
    stage = Clock::now ();
    core::labelPoints (result);
    result.timings.labels_ms = millisecondsSince (stage);
    result.timings.total_ms = millisecondsSince (start);
    report ("done", 1.0);
  }
  catch (const std::bad_alloc&)
  {
    return failure (result, "out of memory while segmenting " + std::to_string (points.size ()) + " points");
  }
  catch (const std::exception& e)
  {
    return failure (result, std::string ("internal error: ") + e.what ());
  }
  return Status::success ();
}

} // namespace pcl_flowseg

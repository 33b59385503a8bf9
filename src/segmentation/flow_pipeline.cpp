/*
 * pcl_flowseg - the compiled core: preparation, Delaunay, flow, merging, per-point labels.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include <pcl_flowseg/segmentation/flow_pipeline.h>

#include "core/geometry/cell_geometry.h"
#include "core/delaunay/delaunay_cells.h"
#include "core/interior/interior_labelling.h"
#include "core/support/parallel.h"
#include "core/preparation/point_preparation.h"
#include "core/labels/point_labels.h"
#include "core/merging/manifold_merging.h"
#include "core/flow/stable_manifolds.h"

#include <chrono>
#include <cstdio>
#include <fstream>
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
    m.location = core::cellCircumcentre (result.vertices, result.cells[static_cast<std::size_t> (c)], dim);
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

/** Why the merge parameters are unusable, or empty when they are fine. */
std::string
mergeParameterProblem (const FlowParameters& params)
{
  if (!std::isfinite (params.rho) || params.rho <= 0.0)
    return "rho must be a finite number > 0, got " + std::to_string (params.rho);
  if (!std::isfinite (params.sampling_tolerance) || params.sampling_tolerance < 0.0)
    return "the sampling tolerance must be a finite number >= 0, got " + std::to_string (params.sampling_tolerance);
  if (!std::isfinite (params.stump_ratio) || (params.stump_ratio != 0.0 && params.stump_ratio < 1.0))
    return "the stump ratio must be 0 (off) or a finite number >= 1, got " + std::to_string (params.stump_ratio);
  if (!std::isfinite (params.compact_rho) || params.compact_rho <= 0.0)
    return "the compact rho must be a finite number > 0, got " + std::to_string (params.compact_rho);
  if (!std::isfinite (params.compact_size) || params.compact_size < 0.0)
    return "the compact size must be a finite number >= 0, got " + std::to_string (params.compact_size);
  return std::string ();
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

std::size_t
estimateSegmentationMemory (std::size_t points, int dimension)
{
  return points * (dimension == 2 ? 1024u : 3072u);
}

std::size_t
availableMemory ()
{
  std::ifstream meminfo ("/proc/meminfo");
  std::string key;
  std::size_t value = 0;
  std::string unit;
  while (meminfo >> key >> value >> unit)
    if (key == "MemAvailable:")
      return value * 1024;
  return 0;
}

Status
remergeFlowSegmentation (double rho, FlowResult& result)
{
  FlowParameters params;
  params.rho = rho;
  return remergeFlowSegmentation (params, result);
}

Status
remergeFlowSegmentation (const FlowParameters& params, FlowResult& result)
{
  if (const std::string problem = mergeParameterProblem (params); !problem.empty ())
    return Status::error (problem);
  if (result.cells.empty ())
    return Status::error ("no flow segmentation to merge: run runFlowSegmentation first");
  const auto start = Clock::now ();
  core::mergeManifolds (params, result);
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
  if (const std::string problem = mergeParameterProblem (params); !problem.empty ())
    return failure (result, problem);
  if (!std::isfinite (params.planar_tolerance) || params.planar_tolerance < 0.0)
    return failure (result, "planar tolerance must be a finite number >= 0");
  if (!params.normals.empty () && params.normals.size () != points.size ())
    return failure (result, "normals: " + std::to_string (params.normals.size ()) + " given for " +
                                std::to_string (points.size ()) + " points");
  if (params.use_viewpoint && !params.viewpoint.allFinite ())
    return failure (result, "the viewpoint has non-finite coordinates");
  {
    const std::size_t limit = params.memory_limit ? params.memory_limit : availableMemory ();
    const int dim = params.dimension == DimensionMode::Planar ? 2 : 3;
    const std::size_t need = estimateSegmentationMemory (points.size (), dim);
    if (limit > 0 && need > limit)
    {
      char message[256];
      std::snprintf (message, sizeof (message),
                     "%zu points need about %.1f GiB to segment, more than the %.1f GiB available: refused before starting",
                     points.size (), need / 1073741824.0, limit / 1073741824.0);
      return failure (result, message);
    }
  }
  auto report = [&] (const char* stage, double fraction) {
    if (progress)
      progress (stage, fraction);
  };

  try
  {
    const core::WorkerThreads workers (params.threads);
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
    result.timings.delaunay_ms = millisecondsSince (stage);

    report ("flow", 0.5);
    stage = Clock::now ();
    if (result.dimension == 2)
      core::computeFlowRelation2D (prepared.planar, result.cells);
    else
      core::computeFlowRelation3D (result.vertices, result.cells);
    const int facets = result.dimension + 1;
    core::parallelFor (result.cells.size (), [&] (std::size_t k) {
      FlowCell& cell = result.cells[k];
      Eigen::Vector3d sum = Eigen::Vector3d::Zero ();
      for (int i = 0; i < facets; ++i)
        sum += result.vertices[static_cast<std::size_t> (cell.vertices[i])];
      cell.centroid = sum / facets;
    });
    result.timings.flow_ms = millisecondsSince (stage);

    // The stable manifolds and the interior/exterior labelling read the same cells and write
    // different fields of them (manifold and successor, inside): they run side by side.
    report (params.separate_interior ? "manifolds and interior" : "manifolds", 0.6);
    std::vector<std::string> manifold_warnings;
    auto manifolds = [&] () {
      const auto begin = Clock::now ();
      const core::StableManifolds sm = core::computeStableManifolds (result.cells, result.dimension);
      result.cycle_breaks = sm.cycle_breaks;
      if (sm.cycle_breaks > 0)
        manifold_warnings.push_back (std::to_string (sm.cycle_breaks) +
                                     " cell(s) not ordered by the flow (degenerate input): resolved by height");
      buildManifolds (sm, result);
      result.timings.manifolds_ms = millisecondsSince (begin);
    };
    auto interior = [&] () {
      if (!params.separate_interior)
        return;
      const auto begin = Clock::now ();
      std::vector<Eigen::Vector3d> vertex_normals;
      if (!params.normals.empty ())
      {
        vertex_normals.assign (result.vertices.size (), Eigen::Vector3d::Zero ());
        for (std::size_t i = result.point_to_vertex.size (); i-- > 0;) // the first copy wins
          if (result.point_to_vertex[i] >= 0)
            vertex_normals[static_cast<std::size_t> (result.point_to_vertex[i])] = params.normals[i];
      }
      core::labelInterior (result, params, vertex_normals); // the only writer of result.warnings here
      if (!result.interior.closed)
        result.warnings.push_back ("the interior/exterior boundary is not closed");
      else if (!result.interior.manifold)
        result.warnings.push_back ("the interior/exterior boundary has " + std::to_string (result.interior.nonmanifold_edges) +
                                   " non-manifold edge(s) and " + std::to_string (result.interior.nonmanifold_vertices) +
                                   " non-manifold vertex(es)");
      if (result.interior.inside_cells == 0)
        result.warnings.push_back ("no cell was labelled inside: the sample may not enclose a volume (open scan, hole?)");
      result.timings.interior_ms = millisecondsSince (begin);
    };
    const std::size_t earlier_warnings = result.warnings.size ();
    core::runSideBySide (manifolds, interior);
    result.warnings.insert (result.warnings.begin () + static_cast<std::ptrdiff_t> (earlier_warnings),
                            manifold_warnings.begin (), manifold_warnings.end ());
    result.feature_side = params.features;

    report ("merge", 0.8);
    stage = Clock::now ();
    core::mergeManifolds (params, result);
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

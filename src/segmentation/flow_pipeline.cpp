/*
 * pcl_flowseg - the flow segmentation pipeline: preparation, Delaunay, flow, stable manifolds and
 * interior, merging, per-point labels; each stage timed.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include <pcl_flowseg/segmentation/flow_pipeline.h>

#include "core/delaunay/delaunay_cells.h"
#include "core/flow/manifold_summary.h"
#include "core/flow/stable_manifolds.h"
#include "core/interior/facet_agreement.h"
#include "core/interior/interior_labelling.h"
#include "core/labels/point_labels.h"
#include "core/merging/manifold_merging.h"
#include "core/preparation/detached_points.h"
#include "core/preparation/hidden_side.h"
#include "core/preparation/noise_estimate.h"
#include "core/preparation/outlier_removal.h"
#include "core/preparation/point_preparation.h"
#include "core/preparation/sample_smoothing.h"
#include "core/support/parallel.h"

#include <chrono>
#include <cstdio>
#include <exception>
#include <new>

namespace pcl_flowseg {

namespace {
using Clock = std::chrono::steady_clock;

double
millisecondsSince (Clock::time_point start)
{
  return std::chrono::duration<double, std::milli> (Clock::now () - start).count ();
}

Status
failure (FlowResult& result, const std::string& message)
{
  const std::size_t n = result.input_points;
  result = FlowResult ();
  result.input_points = n;
  return Status::error (message);
}

/** Refuses, before any work, an input whose estimated need exceeds the memory allowed. */
Status
checkMemory (std::size_t points, const FlowParameters& params)
{
  const std::size_t limit = params.execution.memory_limit ? params.execution.memory_limit : availableMemory ();
  const int dimension = params.preparation.dimension == DimensionMode::Planar ? 2 : 3;
  const std::size_t need = estimateSegmentationMemory (points, dimension);
  if (limit == 0 || need <= limit)
    return Status::success ();
  char message[256];
  std::snprintf (message, sizeof (message),
                 "%zu points need about %.1f GiB to segment, more than the %.1f GiB available: refused before starting",
                 points, need / 1073741824.0, limit / 1073741824.0);
  return Status::error (message);
}

/** One run of the pipeline: its input, parameters and result. */
struct Run
{
  const std::vector<Eigen::Vector3d>& points;
  const std::vector<Eigen::Vector3d>& normals;
  const FlowParameters& params;
  FlowResult& result;
  const ProgressCallback& progress;

  void
  report (const char* stage, double fraction) const
  {
    if (progress)
      progress (stage, fraction);
  }
};

/** The sample's noise and isolated points, from the vertices: reported, and the isolated share
  * decides the automatic outlier removal (the automatic denoising still decides by its own signs,
  * docs/method.md). */
void
noiseStage (const core::PreparedPoints& prepared, FlowResult& result)
{
  const auto start = Clock::now ();
  result.noise = core::estimateNoise (prepared.vertices, prepared.dimension);
  result.timings.noise_ms = millisecondsSince (start);
}

/** Whether this run leaves out outliers: forced, off, or by the sample's isolated or detached share. */
bool
wantsOutlierRemoval (const PreparationParameters& params, const NoiseEstimate& noise)
{
  switch (params.outliers)
  {
    case OutlierRemoval::Always: return true;
    case OutlierRemoval::Off: return false;
    case OutlierRemoval::Automatic: break;
  }
  const auto enough = [&] (double share, double threshold) {
    return share > threshold && share * static_cast<double> (noise.points_used) + 0.5 >= static_cast<double> (kIsolatedMinimum);
  };
  return enough (noise.isolated_share, kIsolatedShare) || enough (noise.detached_share, kDetachedShare);
}

/** When wanted, PCL's StatisticalOutlierRemoval on the vertices (points far from all others), then
  * the vertices still detached from the surface their neighbours sample (outliers near it, which
  * break the big interior balls); counted and warned about. */
Status
outlierStage (const Run& run, core::PreparedPoints& prepared)
{
  FlowResult& result = run.result;
  if (!wantsOutlierRemoval (run.params.preparation, result.noise))
    return Status::success ();
  const auto start = Clock::now ();
  if (const Status s = core::removeOutliers (prepared, result.outlier_points); !s)
    return s;
  std::vector<char> keep = core::detachedPoints (prepared.vertices, prepared.dimension);
  for (char& k : keep)
    k = !k;
  result.outlier_points += core::removeVertices (prepared, keep);
  if (result.outlier_points > 0)
    result.warnings.push_back (std::to_string (result.outlier_points) +
                               " isolated or detached point(s) left out as outliers (no segment); --outliers off keeps them");
  result.timings.preparation_ms += millisecondsSince (start);
  return Status::success ();
}

/** Smoothing of a 3D sample's vertices before the triangulation (PreparationParameters::smoothing). */
void
smoothingStage (const Run& run, core::PreparedPoints& prepared)
{
  const PreparationParameters& params = run.params.preparation;
  FlowResult& result = run.result;
  if (prepared.dimension != 3)
  {
    if (params.smoothing == Smoothing::Always)
      result.warnings.push_back ("smoothing applies to 3D samples only: this 2D sample was not smoothed");
    return;
  }
  const auto start = Clock::now ();
  result.smoothing_passes = core::smoothSample (prepared.vertices, result.noise, params);
  if (params.smoothing == Smoothing::Always && result.smoothing_passes == 0)
    result.warnings.push_back ("smoothing asked for, but the sample shows no noise to smooth (estimated sigma 0)");
  result.timings.preparation_ms += millisecondsSince (start);
}

/** A single view (viewpoint given, 3D, InteriorParameters::hidden_side): the side the sensor cannot
  * see, guessed by mirroring, added as the last vertices; they label no point. */
void
hiddenSideStage (const Run& run, core::PreparedPoints& prepared)
{
  const InteriorParameters& interior = run.params.interior;
  if (!interior.viewpoint || !interior.hidden_side || !interior.separate || prepared.dimension != 3)
    return;
  const auto start = Clock::now ();
  const std::vector<Eigen::Vector3d> hidden = core::mirroredHiddenSide (prepared.vertices, *interior.viewpoint);
  prepared.vertices.insert (prepared.vertices.end (), hidden.begin (), hidden.end ());
  run.result.hidden_side_vertices = hidden.size ();
  run.result.timings.preparation_ms += millisecondsSince (start);
}

/** Finite filter, duplicates, dimension, noise, outliers, smoothing: the vertices of the triangulation. */
Status
prepareStage (const Run& run, core::PreparedPoints& prepared)
{
  const auto start = Clock::now ();
  FlowResult& result = run.result;
  if (const Status s = core::preparePoints (run.points, run.params.preparation, prepared, result.warnings); !s)
    return s;
  result.timings.preparation_ms = millisecondsSince (start);
  run.report ("noise", 0.03);
  noiseStage (prepared, result);
  if (const Status s = outlierStage (run, prepared); !s)
    return s;
  smoothingStage (run, prepared);
  hiddenSideStage (run, prepared);
  result.dimension = prepared.dimension;
  result.non_finite_points = prepared.non_finite;
  result.duplicate_points = prepared.duplicates;
  result.point_to_vertex = std::move (prepared.point_to_vertex);
  result.vertices = std::move (prepared.vertices);
  return Status::success ();
}

Status
delaunayStage (const Run& run, const core::PreparedPoints& prepared)
{
  const auto start = Clock::now ();
  FlowResult& result = run.result;
  const Status s = result.dimension == 2 ? core::triangulate2D (prepared.planar, result.cells)
                                         : core::triangulate3D (result.vertices, result.cells);
  result.timings.delaunay_ms = millisecondsSince (start);
  return s;
}

/** Calls the 2D form of a per-cell computation on the plane coordinates, or the 3D form on the
  * vertices, by the run's dimension. */
void
onCells (const core::PreparedPoints& prepared, FlowResult& result,
         void (*planar) (const std::vector<Eigen::Vector2d>&, std::vector<FlowCell>&),
         void (*spatial) (const std::vector<Eigen::Vector3d>&, std::vector<FlowCell>&))
{
  if (result.dimension == 2)
    planar (prepared.planar, result.cells);
  else
    spatial (result.vertices, result.cells);
}

/** Circumradii, volumes and centroids of the cells: what the interior reads, on all cores. */
void
cellMeasuresStage (const core::PreparedPoints& prepared, FlowResult& result)
{
  const auto start = Clock::now ();
  onCells (prepared, result, core::computeCellMeasures2D, core::computeCellMeasures3D);
  const int facets = result.dimension + 1;
  core::parallelFor (result.cells.size (), [&] (std::size_t k) {
    FlowCell& cell = result.cells[k];
    Eigen::Vector3d sum = Eigen::Vector3d::Zero ();
    for (int i = 0; i < facets; ++i)
      sum += result.vertices[static_cast<std::size_t> (cell.vertices[i])];
    cell.centroid = sum / facets;
  });
  result.timings.flow_ms = millisecondsSince (start);
}

/** The flow relation (exact predicates): read by the stable manifolds alone, so it runs on their
  * thread, beside the interior's sequential pass. */
void
flowMaskStage (const core::PreparedPoints& prepared, FlowResult& result)
{
  const auto start = Clock::now ();
  onCells (prepared, result, core::computeFlowMask2D, core::computeFlowMask3D);
  result.timings.flow_ms += millisecondsSince (start);
}

/** The strengthened flow, its maxima and stable manifolds; writes cells' manifold and successor. */
void
manifoldStage (FlowResult& result, std::vector<std::string>& warnings)
{
  const auto start = Clock::now ();
  const core::StableManifolds sm = core::computeStableManifolds (result.cells, result.dimension);
  result.cycle_breaks = sm.cycle_breaks;
  if (sm.cycle_breaks > 0)
    warnings.push_back (std::to_string (sm.cycle_breaks) +
                        " cell(s) not ordered by the flow (degenerate input): resolved by height");
  core::describeManifolds (sm, result);
  result.timings.manifolds_ms = millisecondsSince (start);
}

/** The per-vertex normals of the triangulation's vertices (the first copy of a duplicate wins). */
std::vector<Eigen::Vector3d>
vertexNormals (const Run& run)
{
  std::vector<Eigen::Vector3d> normals;
  if (run.normals.empty ())
    return normals;
  const FlowResult& result = run.result;
  normals.assign (result.vertices.size (), Eigen::Vector3d::Zero ());
  for (std::size_t i = result.point_to_vertex.size (); i-- > 0;)
    if (result.point_to_vertex[i] >= 0)
      normals[static_cast<std::size_t> (result.point_to_vertex[i])] = run.normals[i];
  return normals;
}

/** The vertices as they were before the smoothing: the first input point of each (the hidden side's
  * vertices as they are). */
std::vector<Eigen::Vector3d>
unsmoothedVertices (const Run& run)
{
  const FlowResult& result = run.result;
  std::vector<Eigen::Vector3d> raw (result.vertices);
  for (std::size_t i = result.point_to_vertex.size (); i-- > 0;)
    if (result.point_to_vertex[i] >= 0)
      raw[static_cast<std::size_t> (result.point_to_vertex[i])] = run.points[i];
  return raw;
}

/** When a sample smoothed before the triangulation leaves more than kSmoothedOffBoundaryShare of
  * its samples off the interior boundary, the smoothing collapsed thin parts: the interior is
  * labelled again on the unsmoothed sample (with its own denoising) and carried over. */
void
relabelWhenSmoothingFailed (const Run& run)
{
  FlowResult& result = run.result;
  const double off = static_cast<double> (result.interior.vertices_off_boundary) / std::max<std::size_t> (1, result.vertices.size ());
  if (result.smoothing_passes == 0 || result.dimension != 3 || off <= core::kSmoothedOffBoundaryShare)
    return;
  if (const Status s = core::labelInteriorFromRawSample (result, run.params.interior, vertexNormals (run), unsmoothedVertices (run)); !s)
  {
    result.warnings.push_back ("the interior of the smoothed sample leaves many samples off its boundary; relabelling on the unsmoothed sample failed: " + s.message);
    return;
  }
  result.warnings.push_back (std::to_string (static_cast<int> (100.0 * off + 0.5)) +
                             "% of the smoothed samples lay off the interior boundary (thin parts collapsed?): "
                             "the interior was labelled on the unsmoothed sample");
}

/** Interior/exterior labelling of the cells (writes cells' inside flags and result.warnings), on
  * \a agreements measured ahead in \a measured_ms (none: measured here when needed). */
void
interiorStage (const Run& run, std::vector<core::GreedyCell>&& agreements, double measured_ms)
{
  if (!run.params.interior.separate)
    return;
  const auto start = Clock::now ();
  FlowResult& result = run.result;
  core::labelInterior (result, run.params.interior, vertexNormals (run), std::move (agreements));
  relabelWhenSmoothingFailed (run);
  const InteriorReport& in = result.interior;
  if (!in.closed)
    result.warnings.push_back ("the interior/exterior boundary is not closed");
  else if (!in.manifold)
    result.warnings.push_back ("the interior/exterior boundary has " + std::to_string (in.nonmanifold_edges) +
                               " non-manifold edge(s) and " + std::to_string (in.nonmanifold_vertices) +
                               " non-manifold vertex(es)");
  if (in.inside_cells == 0)
    result.warnings.push_back ("no cell was labelled inside: the sample may not enclose a volume (open scan, hole?)");
  result.timings.interior_ms = measured_ms + millisecondsSince (start);
}

/** The flow relation with the stable manifolds, and the interior, read the same cells and write
  * different fields of them: they run side by side, after the interior's parallel part (the facet
  * agreements) has had all cores. Warnings come in stage order whatever the timing. */
void
manifoldsAndInteriorStage (const Run& run, const core::PreparedPoints& prepared)
{
  run.report (run.params.interior.separate ? "manifolds and interior" : "manifolds", 0.6);
  const InteriorParameters& interior = run.params.interior;
  const auto start = Clock::now ();
  std::vector<core::GreedyCell> agreements;
  if (interior.separate && interior.denoising != Denoising::Always)
    agreements = core::measureFacetAgreements (run.result.vertices, run.result.cells, run.result.dimension);
  const double measured_ms = millisecondsSince (start);
  std::vector<std::string> manifold_warnings;
  const std::size_t earlier_warnings = run.result.warnings.size ();
  core::runSideBySide ([&] () {
                         flowMaskStage (prepared, run.result);
                         manifoldStage (run.result, manifold_warnings);
                       },
                       [&] () { interiorStage (run, std::move (agreements), measured_ms); });
  run.result.warnings.insert (run.result.warnings.begin () + static_cast<std::ptrdiff_t> (earlier_warnings),
                              manifold_warnings.begin (), manifold_warnings.end ());
}

/** Merging and per-point labels, timed: the end of a run and the whole of a remerge. */
void
mergeAndLabelStages (const MergeParameters& merge, FlowResult& result, const Run* run)
{
  if (run)
    run->report ("merge", 0.8);
  auto start = Clock::now ();
  core::mergeManifolds (merge, result);
  result.timings.merge_ms = millisecondsSince (start);
  if (run)
    run->report ("labels", 0.9);
  start = Clock::now ();
  core::labelPoints (result);
  result.timings.labels_ms = millisecondsSince (start);
}

Status
runStages (const Run& run)
{
  const core::WorkerThreads workers (run.params.execution.threads);
  const auto start = Clock::now ();
  run.report ("preparation", 0.0);
  core::PreparedPoints prepared;
  if (const Status s = prepareStage (run, prepared); !s)
    return s;
  run.report ("delaunay", 0.05);
  if (const Status s = delaunayStage (run, prepared); !s)
    return s;
  run.report ("flow", 0.5);
  cellMeasuresStage (prepared, run.result);
  manifoldsAndInteriorStage (run, prepared);
  mergeAndLabelStages (run.params.merge, run.result, &run);
  run.result.timings.total_ms = millisecondsSince (start);
  run.report ("done", 1.0);
  return Status::success ();
}
} // namespace

std::size_t
estimateSegmentationMemory (std::size_t points, int dimension)
{
  // From the measured peaks (docs/measurements.md).
  return points * (dimension == 2 ? 1024u : 3072u);
}

Status
remergeFlowSegmentation (const MergeParameters& merge, FlowResult& result)
{
  if (const Status s = checkMergeParameters (merge); !s)
    return s;
  if (result.cells.empty ())
    return Status::error ("no flow segmentation to merge: run runFlowSegmentation first");
  result.parameters.merge = merge;
  mergeAndLabelStages (merge, result, nullptr);
  return Status::success ();
}

Status
runFlowSegmentation (const std::vector<Eigen::Vector3d>& points, const FlowParameters& params, FlowResult& result,
                     const ProgressCallback& progress)
{
  return runFlowSegmentation (points, std::vector<Eigen::Vector3d> (), params, result, progress);
}

Status
runFlowSegmentation (const std::vector<Eigen::Vector3d>& points, const std::vector<Eigen::Vector3d>& normals,
                     const FlowParameters& params, FlowResult& result, const ProgressCallback& progress)
{
  result = FlowResult ();
  result.input_points = points.size ();
  if (const Status s = checkParameters (params); !s)
    return failure (result, s.message);
  if (!normals.empty () && normals.size () != points.size ())
    return failure (result, "normals: " + std::to_string (normals.size ()) + " given for " +
                                std::to_string (points.size ()) + " points");
  if (const Status s = checkMemory (points.size (), params); !s)
    return failure (result, s.message);
  result.parameters = params;
  try
  {
    if (const Status s = runStages (Run{points, normals, params, result, progress}); !s)
      return failure (result, s.message);
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

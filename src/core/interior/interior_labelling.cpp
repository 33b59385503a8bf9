/*
 * pcl_flowseg - internal: interior/exterior labelling of Delaunay cells, on a smoothed copy of a
 * noisy sample when the sample shows noise.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include "core/interior/interior_labelling.h"

#include "core/geometry/cell_geometry.h"
#include "core/geometry/point_neighbourhoods.h"
#include "core/interior/boundary_measure.h"
#include "core/interior/denoising.h"
#include "core/interior/greedy_labelling.h"
#include "core/interior/interior_islands.h"
#include "core/interior/manifold_repair.h"
#include "core/support/parallel.h"

#include <algorithm>
#include <utility>

namespace pcl_flowseg {
namespace core {

namespace {
/** Measures the boundary and, where it is not a manifold, repairs it (repairManifold, which
  * measures it again), unless the repair is switched off or the sample is a single view. On a single
  * view with a guessed hidden side, tiny pockets of inside cells are labelled outside first. */
void
measureAndRepair (FlowResult& r, const InteriorParameters& params)
{
  if (r.hidden_side_vertices > 0)
    r.interior.island_cells = dropInteriorIslands (r, kInteriorIslandShare);
  std::vector<int> nonmanifold = measureBoundary (r);
  if (params.manifold_repair && !params.viewpoint && !nonmanifold.empty ())
    r.interior.repaired_cells = repairManifold (r, std::move (nonmanifold));
}

/** Labels \a r's cells by the greedy labelling of the raw sample (on \a agreements, when measured). */
void
labelRawSample (FlowResult& r, const InteriorParameters& params, const std::vector<Eigen::Vector3d>& vertex_normals,
                std::vector<GreedyCell>&& agreements = {})
{
  if (agreements.size () != r.cells.size ())
    agreements = measureFacetAgreements (r.vertices, r.cells, r.dimension);
  const ExtraEvidence extra = labelCellsGreedily (r.vertices, r.cells, r.dimension, params, vertex_normals,
                                                  r.vertices.size () - r.hidden_side_vertices, std::move (agreements));
  r.interior.ray_cells = extra.ray_cells;
  r.interior.opening_cells = extra.opening_cells;
  measureAndRepair (r, params);
}

/** Gives every cell of \a r the label of the cell of \a smooth_cells (a triangulation of \a points)
  * that holds its centroid; each walk starts at a smoothed cell of the cell's first vertex, since
  * the sample moved little. The walks are independent: they run on all cores. */
void
transferLabels (const std::vector<Eigen::Vector3d>& points, const std::vector<FlowCell>& smooth_cells, FlowResult& r)
{
  const int d = r.dimension;
  std::vector<int> cell_of_vertex (points.size (), 0);
  for (std::size_t k = 0; k < smooth_cells.size (); ++k)
    for (int i = 0; i <= d; ++i)
      cell_of_vertex[static_cast<std::size_t> (smooth_cells[k].vertices[i])] = static_cast<int> (k);
  parallelFor (r.cells.size (), [&] (std::size_t k) {
    FlowCell& c = r.cells[k];
    const int hint = cell_of_vertex[static_cast<std::size_t> (c.vertices[0])];
    const int found = locateCell (points, smooth_cells, d, c.centroid, hint);
    c.inside = found >= 0 ? smooth_cells[static_cast<std::size_t> (found)].inside : 0;
  });
}

/** Noisy sample: in/out decided on a smoothed copy of \a points (the vertices, or the same vertices
  * before the smoothing before the triangulation; \a hoods: their neighbourhoods; the greedy
  * labelling needs a thin sample) and transferred to the cells. */
void
labelSmoothedSample (FlowResult& r, const InteriorParameters& params, const std::vector<Eigen::Vector3d>& vertex_normals,
                     const Neighbourhoods& hoods, std::vector<Eigen::Vector3d> points)
{
  const int d = r.dimension;
  for (int it = 0; it < kMaxDenoisingPasses; ++it)
  {
    points = smoothPoints (points, hoods, d);
    ++r.interior.smoothing_passes;
    if (medianVariation (points, hoods, d) <= kNoiseVariation)
      break;
  }
  std::vector<FlowCell> smooth_cells;
  if (const Status s = triangulateWorking (points, d, smooth_cells); !s)
  {
    r.warnings.push_back ("denoising skipped: " + s.message);
    r.interior.smoothing_passes = 0;
    if (params.denoising == Denoising::Always)
      labelRawSample (r, params, vertex_normals);
    return;
  }
  const ExtraEvidence extra = labelCellsGreedily (points, smooth_cells, d, params, vertex_normals, points.size () - r.hidden_side_vertices);
  r.interior.ray_cells = extra.ray_cells;
  r.interior.opening_cells = extra.opening_cells;
  transferLabels (points, smooth_cells, r);
  measureAndRepair (r, params);
}
} // namespace

void
labelInterior (FlowResult& r, const InteriorParameters& params, const std::vector<Eigen::Vector3d>& vertex_normals,
               std::vector<GreedyCell>&& raw_agreements)
{
  r.interior = InteriorReport ();
  r.interior.computed = true;
  // First on the sample as given: right for clean samples, and cheap.
  if (params.denoising != Denoising::Always)
    labelRawSample (r, params, vertex_normals, std::move (raw_agreements));
  if (params.denoising == Denoising::Off)
    return;
  // Noise shows twice: in a raw labelling that leaves many samples off the boundary it finds, and
  // in the local PCA fits (undersampled sharp parts show only the first). The first is free, so
  // the nearest-neighbour search for the second runs only when the first is seen.
  const double off_boundary = static_cast<double> (r.interior.vertices_off_boundary) / std::max<std::size_t> (1, r.vertices.size ());
  if (params.denoising == Denoising::Automatic && off_boundary <= kOffBoundaryShare)
    return;
  const Neighbourhoods hoods = nearestNeighbourhoods (r.vertices);
  r.interior.surface_variation = medianVariation (r.vertices, hoods, r.dimension);
  if (params.denoising == Denoising::Automatic && r.interior.surface_variation <= kNoiseVariation)
    return;
  labelSmoothedSample (r, params, vertex_normals, hoods, r.vertices);
}

Status
labelInteriorFromRawSample (FlowResult& r, const InteriorParameters& params, const std::vector<Eigen::Vector3d>& vertex_normals,
                            const std::vector<Eigen::Vector3d>& raw_vertices)
{
  InteriorParameters own = params;
  own.denoising = Denoising::Off; // if its triangulation fails, the cells keep their labels
  r.interior = InteriorReport ();
  r.interior.computed = true;
  const std::size_t warnings = r.warnings.size ();
  labelSmoothedSample (r, own, vertex_normals, nearestNeighbourhoods (raw_vertices), raw_vertices);
  if (r.interior.smoothing_passes > 0)
    return Status::success ();
  const std::string why = r.warnings.size () > warnings ? r.warnings.back () : "the unsmoothed sample could not be triangulated";
  r.warnings.resize (warnings);
  measureBoundary (r);
  return Status::error (why);
}

} // namespace core
} // namespace pcl_flowseg

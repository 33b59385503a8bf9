/*
 * pcl_flowseg - internal: interior/exterior labelling of Delaunay cells, on a smoothed copy of a
 * noisy sample when the sample shows noise.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include "core/interior/facet_agreement.h"

#include <pcl_flowseg/common/flow_parameters.h>
#include <pcl_flowseg/common/flow_result.h>
#include <pcl_flowseg/common/status.h>

#include <vector>

namespace pcl_flowseg {
namespace core {

/** \brief Labels every cell inside (1) or outside (0) the sampled shape (FlowCell::inside) and
  * fills result.interior. The cells are labelled by labelCellsGreedily on the sample as given;
  * a noisy sample (Automatic: a raw labelling that leaves more than kOffBoundaryShare of the
  * samples off its boundary and a median surface variation above kNoiseVariation; Always: every
  * sample) is labelled on a smoothed copy, whose labels the cells take by locating their
  * centroids. \a vertex_normals: empty, or one oriented normal per vertex. \a raw_agreements:
  * empty, or measureFacetAgreements of the result's cells, measured ahead (the pipeline does so
  * while both cores are free). */
void
labelInterior (FlowResult& result, const InteriorParameters& params, const std::vector<Eigen::Vector3d>& vertex_normals,
               std::vector<GreedyCell>&& raw_agreements = {});

/** \brief Share of the samples off the interior boundary above which a labelling of a sample
  * smoothed before the triangulation counts as failed (its thin parts collapsed: docs/method.md). */
constexpr double kSmoothedOffBoundaryShare = 0.15;

/** \brief Labels \a result's cells (triangulated from smoothed vertices) as a noisy sample is
  * labelled, on \a raw_vertices (the same vertices before that smoothing) smoothed by the
  * interior's own projections: each cell takes the label of the cell of that copy's triangulation
  * that holds its centroid; then the boundary is measured (and repaired). On failure the cells keep
  * their labels. */
Status
labelInteriorFromRawSample (FlowResult& result, const InteriorParameters& params, const std::vector<Eigen::Vector3d>& vertex_normals,
                            const std::vector<Eigen::Vector3d>& raw_vertices);

} // namespace core
} // namespace pcl_flowseg

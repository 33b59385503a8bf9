/*
 * pcl_flowseg - internal: interior/exterior labelling of Delaunay cells, on a smoothed copy of a
 * noisy sample when the sample shows noise.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include "core/interior/facet_agreement.h"

#include <pcl_flowseg/common/flow_parameters.h>
#include <pcl_flowseg/common/flow_result.h>

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

} // namespace core
} // namespace pcl_flowseg

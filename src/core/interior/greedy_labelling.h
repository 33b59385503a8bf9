/*
 * pcl_flowseg - internal: cells labelled inside or outside by evidence on their facets, most certain first.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include "core/interior/facet_agreement.h"

#include <pcl_flowseg/common/flow_parameters.h>
#include <pcl_flowseg/common/flow_result.h>

#include <vector>

namespace pcl_flowseg {
namespace core {

/** \brief Cells that heard evidence other than their facets'. */
struct ExtraEvidence
{
  std::size_t ray_cells = 0;     ///< free space on a sensor ray
  std::size_t opening_cells = 0; ///< reached through wide openings (InteriorParameters::exterior_opening)
};

/** \brief Sets FlowCell::inside of every cell of \a cells (a triangulation of \a vertices).
  *
  * Evidence lives on facets (measureFacetAgreements): the cosine of the angle between the
  * circumspheres of the two cells sharing a facet is near +1 when both balls lie on one side of the
  * sampled surface and near -1 when they lie on opposite sides; beyond the convex hull lies the
  * outside. In 2D the NN-crust marks the curve edges. Oriented \a vertex_normals (optional) and sensor rays from
  * params.viewpoint (optional) add evidence per cell. Labels are then propagated from the most
  * certain cell (largest margin between its summed inside and outside evidence) on, as the power
  * crust labels its poles, so that weak, contradictory evidence is decided last.
  * Only the first \a seen_vertices vertices are samples the sensor saw (the rest were guessed
  * behind them: they cast no ray).
  * In 3D without a viewpoint, the cells reached from beyond the hull through openings wider than
  * params.exterior_opening sample spacings (openExteriorCells) are evidence of the outside, as
  * strong as a sensor ray.
  * \return the cells marked by each kind of evidence beyond the facets. */
ExtraEvidence
labelCellsGreedily (const std::vector<Eigen::Vector3d>& vertices, std::vector<FlowCell>& cells, int dimension,
                    const InteriorParameters& params, const std::vector<Eigen::Vector3d>& vertex_normals,
                    std::size_t seen_vertices);

/** \brief The same, on agreements \a measured ahead by measureFacetAgreements of the same cells. */
ExtraEvidence
labelCellsGreedily (const std::vector<Eigen::Vector3d>& vertices, std::vector<FlowCell>& cells, int dimension,
                    const InteriorParameters& params, const std::vector<Eigen::Vector3d>& vertex_normals,
                    std::size_t seen_vertices, std::vector<GreedyCell>&& measured);

} // namespace core
} // namespace pcl_flowseg

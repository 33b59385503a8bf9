/*
 * pcl_flowseg - internal: interior/exterior labelling of Delaunay cells.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include <pcl_flowseg/common/flow_parameters.h>
#include <pcl_flowseg/common/flow_result.h>

#include <vector>

namespace pcl_flowseg {
namespace core {

/** \brief Labels every cell inside (1) or outside (0) the sampled shape; sets FlowCell::inside and
  * fills \a report (boundary closed / manifold, counts).
  *
  * Evidence lives on facets. Two cells sharing a facet have circumspheres through the facet's
  * vertices; the cosine of the angle between the spheres there, (ra^2 + rb^2 - d^2) / (2 ra rb),
  * is near +1 when both balls lie on one side of the sampled surface and near -1 when they lie on
  * opposite sides of it (both balls are empty and nearly tangent to the surface). Beyond a convex
  * hull facet lies the outside, a half-space. In 2D the NN-crust of the sample (each point joined
  * to its nearest neighbour and to its nearest neighbour on the other side, Dey & Kumar) marks the
  * curve edges, which are given at least moderate "opposite" weight, the other edges at least
  * moderate "same" weight. Oriented normals and sensor rays add direct evidence per cell.
  *
  * Labels are propagated greedily from the outside, the cell with the largest margin between its
  * summed inside and outside evidence first (as the power crust labels its poles), so that weak,
  * contradictory evidence (slivers, noise) is decided last, by the votes of all its labelled
  * neighbours.
  *
  * Noisy samples (median surface variation above kNoiseVariation and, in Automatic mode, a raw
  * labelling that leaves more than kOffBoundaryShare of the samples off its boundary) are labelled
  * on a smoothed copy of the sample, whose labels are transferred by locating the cells' centroids. */
void
labelInterior (FlowResult& result, const InteriorParameters& params, const std::vector<Eigen::Vector3d>& vertex_normals);

/** \brief Recomputes FlowResult::interior's boundary figures (facet counts, closed, manifold)
  * from the cells' inside flags. */
void
measureBoundary (FlowResult& result);

} // namespace core
} // namespace pcl_flowseg

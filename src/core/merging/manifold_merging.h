/*
 * pcl_flowseg - internal: rho-merging of stable manifolds into segments.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include <pcl_flowseg/common/flow_result.h>

#include <vector>

namespace pcl_flowseg {
namespace core {

/** \brief Distance from each vertex of \a result to its nearest other vertex (the shortest
  * Delaunay edge at it: a sample's nearest neighbour is always a Delaunay neighbour); +inf for a
  * vertex on no cell. */
std::vector<double>
nearestNeighbourDistances (const FlowResult& result);

/** \brief Local sample spacing at a saddle: the mean nearest-neighbour distance
  * (\a nearest, from nearestNeighbourDistances) of the facet's vertices. */
double
saddleSpacing (const SaddleFacet& saddle, const std::vector<double>& nearest, int dimension);

/** \brief Merges the stable manifolds of \a result with the merge parameters of \a params (rho,
  * sampling_tolerance, stump_ratio, compact_rho, compact_size) and fills segments,
  * cells[].segment, segment_adjacency. Requires manifolds and manifold_adjacency. With
  * sampling_tolerance, stump_ratio and compact_size 0: the paper's segmentation exactly.
  *
  * Two finite manifolds A, B of the same side sharing facets are merged when, for their highest
  * shared facet t,
  *   R(max A) < rho R(t) + tolerance s(t)   and   R(max B) < rho R(t) + tolerance s(t)
  * (circumradii), where s(t) is the local sample spacing at t (saddleSpacing). With tolerance 0
  * this is the paper's rule, evaluated exactly as before (squared radii, R(max)^2 < rho^2 R(t)^2).
  * rho < 1 merges nothing, with or without a tolerance. Since a facet's radius can only be lower
  * than the maximum of a manifold touching it, the highest shared facet decides whether any shared
  * facet satisfies the rule. All mergeable pairs are joined (connected components), which is
  * independent of order. The manifold at infinity is never merged. Without the compact pass a
  * larger rho or tolerance never gives more segments.
  *
  * Compact pass (compact_size > 0, compact_rho > rho >= 1; before the stumps): the shared facets
  * that fail the rule at rho but pass it with compact_rho in its place are visited from the
  * shallowest (lowest ratio of the higher of the two maxima to the facet, squared radii) on; the
  * two current groups they join merge when the smaller holds no more volume (area in 2D) than
  * compact_size balls (discs) of the facet's circumradius. Group volumes are sums of manifold
  * volumes and grow as groups merge. Why: a protrusion that runs far beyond its neck (a handle, a
  * finger) is a part; a bulge no bigger than a couple of balls of its neck is not, however deep
  * (on the PSB both kinds have ratios near 1.1). Groups grow, so a larger rho can leave a candidate
  * between two groups that are no longer compact: the pass is not monotone in rho.
  *
  * Why the tolerance: the sample's distance function differs from the surface's by up to about
  * the sample spacing (a point of the surface is that close to a sample, not on it), so heights of
  * maxima and saddles carry an additive sampling error of that size. In parts about as thin as the
  * spacing (walls, plates) all maxima and saddles lie within that error of each other and the
  * ratio test alone splits them into hundreds of pieces; in thick parts the term is negligible.
  *
  * Stumps (stump_ratio > 0; after merging, and after the cells that leave their side have joined a
  * segment of it): where a thin segment X borders a segment Y whose highest maximum is more than
  * stump_ratio times thicker (circumradius), the cells of Y connected to X through cells of Y no
  * larger than X's highest maximum (and at least half as large as the saddle between X and Y)
  * join X. The flow cuts a thin part off where it is narrowest (the saddle); the stretch between
  * there and the thick part widens towards it and flows into it (the "stump" the paper notes on
  * fingers, section 6). That stretch continues the thin part's tube, no wider than the part
  * itself, up to the junction, where the radius jumps to the thick part's. Cells holding a maximum
  * never move; groups without a maximum of their own and the one at infinity take no part. The
  * number of segments does not change. */
void
mergeManifolds (const MergeParameters& params, FlowResult& result);

} // namespace core
} // namespace pcl_flowseg

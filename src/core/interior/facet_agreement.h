/*
 * pcl_flowseg - internal: how strongly the two cells across each facet lie on the same side of the
 * sampled surface, measured for the greedy labelling.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include <pcl_flowseg/common/flow_result.h>

#include <array>
#include <vector>

namespace pcl_flowseg {
namespace core {

/** \brief What the greedy labelling reads and writes for one cell, in one cache line: the greedy
  * pass visits cells in the order of their margins, all over memory, so each cell should cost one
  * miss, not one per array. */
struct alignas (64) GreedyCell
{
  std::array<int, 4> neighbors;    ///< as FlowCell::neighbors
  std::array<double, 4> agreement; ///< across the facet opposite vertex i: see measureFacetAgreements
  double in_score, out_score;      ///< summed evidence for inside and outside, 0 until the labelling
};

/** \brief One GreedyCell per cell of \a cells (a triangulation of \a vertices), in parallel: the
  * part of the greedy labelling that parallelises, so the pipeline runs it before the sequential
  * parts, which share the cores with the stable manifolds.
  *
  * The agreement across a facet is > 0 when both cells lie on one side, < 0 when on opposite sides,
  * |value| the confidence: the cosine of the angle between the two circumspheres, measured at a
  * facet vertex (on both) as the angle between the directions to the two centres; unlike the law
  * of cosines this stays accurate for the huge spheres of flat cells, whose centres are far away
  * but in a well-defined direction. A hull facet compares the sphere with the outward normal. In
  * 2D the NN-crust's verdict on the edge bounds it. */
std::vector<GreedyCell>
measureFacetAgreements (const std::vector<Eigen::Vector3d>& vertices, const std::vector<FlowCell>& cells, int dimension);

} // namespace core
} // namespace pcl_flowseg

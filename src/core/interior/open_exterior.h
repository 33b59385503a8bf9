/*
 * pcl_flowseg - internal: the space a ball reaches from beyond the convex hull through openings of
 * the sample wider than a few sample spacings (a cup's cavity, the space under a table).
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include <pcl_flowseg/common/flow_result.h>

#include <cstdint>
#include <vector>

namespace pcl_flowseg {
namespace core {

/** \brief Median over the vertices of \a cells (a 3D triangulation of \a vertices) of the distance to
  * the nearest other vertex, read off the Delaunay edges (the nearest neighbour is always one); 0
  * when there are no cells. */
double
medianNearestDistance (const std::vector<Eigen::Vector3d>& vertices, const std::vector<FlowCell>& cells);

/** \brief 1 for every cell of the 3D triangulation \a cells of \a vertices that a flood from beyond
  * the convex hull reaches through openings wider than \a opening: it crosses a facet, hull facets
  * included, only when each of the facet's edges is longer than 2 \a opening, and enters a cell only
  * when its circumradius exceeds \a opening. The surface of a sample blocks it: its facets join
  * near samples, and the cells inside it are reached only through a gap in the sample wider than
  * the opening. */
std::vector<std::uint8_t>
openExteriorCells (const std::vector<Eigen::Vector3d>& vertices, const std::vector<FlowCell>& cells, double opening);

/** \brief Outward directions of the samples the open exterior touches: for every vertex of a cell
  * marked in \a reached (openExteriorCells), the mean direction from it to those cells'
  * circumcentres (as the power crust's outer poles point outward), unit length; zero for the other
  * vertices. Where the two sides of a noisy thin wall merge, each sample still faces the side it
  * was reached from. */
std::vector<Eigen::Vector3d>
openingNormals (const std::vector<Eigen::Vector3d>& vertices, const std::vector<FlowCell>& cells, const std::vector<std::uint8_t>& reached);

} // namespace core
} // namespace pcl_flowseg

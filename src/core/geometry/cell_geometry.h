/*
 * pcl_flowseg - internal: geometry of Delaunay cells in double precision, and vertex incidence.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include <pcl_flowseg/common/flow_result.h>

#include <vector>

namespace pcl_flowseg {
namespace core {

/** \brief Circumcentre of a cell (triangle or tetrahedron) from its input-frame vertices. */
Eigen::Vector3d
cellCircumcentre (const std::vector<Eigen::Vector3d>& vertices, const FlowCell& cell, int dimension);

/** \brief Squared radius of the smallest circumsphere of facet \a facet of \a cell (the edge's
  * half length squared in 2D), computed from the input-frame vertex coordinates; its centre
  * goes to \a centre when given. */
double
facetSquaredRadius (const std::vector<Eigen::Vector3d>& vertices, const FlowCell& cell,
                    int facet, int dimension, Eigen::Vector3d* centre = nullptr);

/** \brief Unit normal of facet \a facet (opposite vertices[facet]) pointing away from the cell;
  * in 2D the normal of the edge within the cell's plane. */
Eigen::Vector3d
outwardFacetNormal (const std::vector<Eigen::Vector3d>& vertices, const FlowCell& cell, int facet, int dimension);

/** \brief Cells incident to each vertex, as compressed rows: the cells of vertex v are
  * cells[first[v]] .. cells[first[v+1]-1]. */
struct VertexIncidence
{
  std::vector<std::size_t> first;
  std::vector<int> cells;
};

VertexIncidence
vertexIncidence (const std::vector<FlowCell>& cells, std::size_t vertex_count, int dimension);

/** \brief Cell containing \a point (in 2D a point of the cells' plane), found by walking from
  * \a hint towards it; -1 when the point lies outside the convex hull. */
int
locateCell (const std::vector<Eigen::Vector3d>& vertices, const std::vector<FlowCell>& cells, int dimension,
            const Eigen::Vector3d& point, int hint);

/** \brief Index of the facet of \a from whose neighbour is \a to, or -1. */
int
facetTowards (const FlowCell& from, int to, int dimension);

} // namespace core
} // namespace pcl_flowseg

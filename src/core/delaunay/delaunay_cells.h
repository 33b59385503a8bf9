/*
 * pcl_flowseg - internal: Delaunay triangulation turned into flat, CGAL-free cells.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include <pcl_flowseg/common/status.h>
#include <pcl_flowseg/common/flow_result.h>

#include <string>
#include <vector>

namespace pcl_flowseg {
namespace core {

/** \brief Triangulates 2D points (CGAL, exact predicates) into \a cells: vertices and neighbors
  * only, in canonical order (buildCellsInCanonicalOrder). Fails when the points do not span the plane
  * (fewer than 3 or all collinear). Points must be distinct. */
Status
triangulate2D (const std::vector<Eigen::Vector2d>& points, std::vector<FlowCell>& cells);

/** \brief How triangulate3D inserts the points. */
enum class Insertion
{
  Automatic,  ///< in parallel when it pays (see triangulate3D)
  Sequential,
  Parallel    ///< whenever TBB may use two workers (tests)
};

/** \brief Triangulates 3D points into tetrahedra (vertices and neighbors, canonical order); in
  * parallel (CGAL with TBB) when workerThreads() > 1, the input is large enough and other
  * processes leave a core to spare (otherRunnableThreads). Fails when the points do not span space (fewer than 4, collinear
  * or coplanar). Points must be distinct. */
Status
triangulate3D (const std::vector<Eigen::Vector3d>& points, std::vector<FlowCell>& cells,
               Insertion insertion = Insertion::Automatic);

/** \brief The flow relation of triangles: flow_mask alone (exact test: a triangle flows across the
  * edge opposite an obtuse angle). */
void
computeFlowMask2D (const std::vector<Eigen::Vector2d>& points, std::vector<FlowCell>& cells);

/** \brief The measures of triangles: squared_radius and volume (area). */
void
computeCellMeasures2D (const std::vector<Eigen::Vector2d>& points, std::vector<FlowCell>& cells);

/** \brief Both computeFlowMask2D and computeCellMeasures2D. Centroids are left for the caller, who
  * knows the input frame. */
void
computeFlowRelation2D (const std::vector<Eigen::Vector2d>& points, std::vector<FlowCell>& cells);

/** \brief The flow relation of tetrahedra: flow_mask alone (exact test: v[i] strictly inside the
  * diametral sphere of the facet opposite it). */
void
computeFlowMask3D (const std::vector<Eigen::Vector3d>& points, std::vector<FlowCell>& cells);

/** \brief The measures of tetrahedra: squared_radius and volume. */
void
computeCellMeasures3D (const std::vector<Eigen::Vector3d>& points, std::vector<FlowCell>& cells);

/** \brief Both computeFlowMask3D and computeCellMeasures3D. */
void
computeFlowRelation3D (const std::vector<Eigen::Vector3d>& points, std::vector<FlowCell>& cells);

} // namespace core
} // namespace pcl_flowseg

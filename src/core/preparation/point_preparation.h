/*
 * pcl_flowseg - internal: finite filter, duplicate merging and dimension detection.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include <pcl_flowseg/common/status.h>
#include <pcl_flowseg/common/flow_parameters.h>

#include <Eigen/Core>

#include <string>
#include <vector>

namespace pcl_flowseg {
namespace core {

/** \brief Input points reduced to distinct finite vertices, and the frame they are triangulated in. */
struct PreparedPoints
{
  /** Distinct finite points, in Z-order through their bounding box; in 2D without a constant
    * axis, projected onto the best-fit plane so that 3D and plane coordinates describe the same
    * geometry. */
  std::vector<Eigen::Vector3d> vertices;
  std::vector<int> point_to_vertex;        ///< per input point: vertex index, or -1 (not finite)
  std::size_t non_finite = 0;
  std::size_t duplicates = 0;
  int dimension = 3;                       ///< 2 or 3
  std::vector<Eigen::Vector2d> planar;     ///< 2D: vertices in plane coordinates (isometric)
  double thickness = 0.0;                  ///< spread normal to the best-fit plane
};

/** \brief Filters, deduplicates and chooses the dimension; fails when no finite point is left.
  * 2D coordinates drop a constant axis exactly when there is one, otherwise they are the best-fit
  * plane's orthonormal basis coordinates. */
Status
preparePoints (const std::vector<Eigen::Vector3d>& points, const PreparationParameters& params,
               PreparedPoints& out, std::vector<std::string>& warnings);

} // namespace core
} // namespace pcl_flowseg

/*
 * pcl_flowseg - internal: the interior's own smoothing of a noisy sample's working copy (for in/out
 * decisions): when it applies, its passes, the copy's triangulation.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include "core/interior/denoising.h"

#include "core/delaunay/delaunay_cells.h"

#include <Eigen/Eigenvalues>

#include <algorithm>

namespace pcl_flowseg {
namespace core {

std::vector<Eigen::Vector3d>
smoothPoints (const std::vector<Eigen::Vector3d>& points, const Neighbourhoods& hoods, int dimension)
{
  std::vector<Eigen::Vector3d> out (points);
  forEachNeighbourhood (points, hoods, dimension, [&] (std::size_t i, const PlaneFit& fit) {
    out[i] = points[i] - (points[i] - fit.mean).dot (fit.normal) * fit.normal;
  });
  return out;
}

Status
triangulateWorking (const std::vector<Eigen::Vector3d>& points, int dimension, std::vector<FlowCell>& cells)
{
  if (dimension == 3)
  {
    const Status s = triangulate3D (points, cells);
    if (s)
      computeFlowRelation3D (points, cells);
    return s;
  }
  // Plane coordinates in an orthonormal basis of the points' plane.
  Eigen::Vector3d mean = Eigen::Vector3d::Zero ();
  for (const auto& p : points)
    mean += p;
  mean /= static_cast<double> (std::max<std::size_t> (1, points.size ()));
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero ();
  for (const auto& p : points)
    cov += (p - mean) * (p - mean).transpose ();
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es (cov);
  const Eigen::Vector3d u = es.eigenvectors ().col (2), v = es.eigenvectors ().col (1);
  std::vector<Eigen::Vector2d> planar;
  planar.reserve (points.size ());
  for (const auto& p : points)
    planar.emplace_back ((p - mean).dot (u), (p - mean).dot (v));
  const Status s = triangulate2D (planar, cells);
  if (s)
    computeFlowRelation2D (planar, cells);
  return s;
}

} // namespace core
} // namespace pcl_flowseg

/*
 * flowseg_bench_interior - the peer a user would try instead: Poisson surface reconstruction on
 * normals estimated and oriented from the points alone.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include <pcl_flowseg/common/status.h>

#include <Eigen/Core>

#include <memory>
#include <vector>

namespace flowseg_bench {

/** \brief The solid CGAL's Poisson reconstruction (Kazhdan, Bolitho, Hoppe 2006) encloses, for a
  * point sample without normals: CGAL::jet_estimate_normals and CGAL::mst_orient_normals (both
  * over \a neighbours nearest samples, the CGAL examples' 18 by default), the points whose normal
  * could not be oriented left out, then Poisson_reconstruction_function with CGAL's defaults. A
  * point is inside where the implicit function is below its contouring value. */
class PoissonSolid
{
public:
  PoissonSolid ();
  ~PoissonSolid ();

  /** Solves for the implicit function of \a points; fails on too few points or when the solver
    * does not converge. \a seconds, when given, receives the time. */
  pcl_flowseg::Status
  reconstruct (const std::vector<Eigen::Vector3d>& points, unsigned neighbours = 18, double* seconds = nullptr);

  /** True where the reconstructed solid holds \a p; reconstruct must have succeeded. */
  bool
  inside (const Eigen::Vector3d& p) const;

  /** How many points mst_orient_normals could not orient (left out of the reconstruction). */
  std::size_t
  unorientedPoints () const { return unoriented_; }

private:
  struct Function;
  std::unique_ptr<Function> function_;
  std::size_t unoriented_ = 0;
};

} // namespace flowseg_bench

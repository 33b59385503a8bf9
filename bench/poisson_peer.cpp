/*
 * flowseg_bench_interior - Poisson surface reconstruction as the peer of the interior labelling.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include "poisson_peer.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Poisson_reconstruction_function.h>
#include <CGAL/jet_estimate_normals.h>
#include <CGAL/mst_orient_normals.h>
#include <CGAL/property_map.h>

#include <chrono>
#include <exception>
#include <string>
#include <utility>

namespace flowseg_bench {

namespace {
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using PointWithNormal = std::pair<Kernel::Point_3, Kernel::Vector_3>;
using PointMap = CGAL::First_of_pair_property_map<PointWithNormal>;
using NormalMap = CGAL::Second_of_pair_property_map<PointWithNormal>;
} // namespace

struct PoissonSolid::Function
{
  explicit Function (const std::vector<PointWithNormal>& points)
    : implicit (points.begin (), points.end (), PointMap (), NormalMap ())
  {}
  CGAL::Poisson_reconstruction_function<Kernel> implicit;
};

PoissonSolid::PoissonSolid () = default;
PoissonSolid::~PoissonSolid () = default;

pcl_flowseg::Status
PoissonSolid::reconstruct (const std::vector<Eigen::Vector3d>& points, unsigned neighbours, double* seconds)
{
  const auto start = std::chrono::steady_clock::now ();
  function_.reset ();
  unoriented_ = 0;
  if (points.size () < 4 * static_cast<std::size_t> (neighbours))
    return pcl_flowseg::Status::error ("Poisson peer: " + std::to_string (points.size ()) + " points are too few");
  std::vector<PointWithNormal> samples;
  samples.reserve (points.size ());
  for (const auto& p : points)
    samples.emplace_back (Kernel::Point_3 (p.x (), p.y (), p.z ()), Kernel::Vector_3 (0, 0, 0));
  try
  {
    const auto params = CGAL::parameters::point_map (PointMap ()).normal_map (NormalMap ());
    CGAL::jet_estimate_normals<CGAL::Sequential_tag> (samples, neighbours, params);
    const auto unoriented = CGAL::mst_orient_normals (samples, neighbours, params);
    unoriented_ = static_cast<std::size_t> (std::distance (unoriented, samples.end ()));
    samples.erase (unoriented, samples.end ());
    function_ = std::make_unique<Function> (samples);
    if (!function_->implicit.compute_implicit_function ())
    {
      function_.reset ();
      return pcl_flowseg::Status::error ("Poisson peer: the solver did not converge");
    }
  }
  catch (const std::exception& e)
  {
    function_.reset ();
    return pcl_flowseg::Status::error (std::string ("Poisson peer failed: ") + e.what ());
  }
  if (seconds)
    *seconds = std::chrono::duration<double> (std::chrono::steady_clock::now () - start).count ();
  return pcl_flowseg::Status::success ();
}

bool
PoissonSolid::inside (const Eigen::Vector3d& p) const
{
  return function_ && function_->implicit (Kernel::Point_3 (p.x (), p.y (), p.z ())) < 0.0;
}

} // namespace flowseg_bench

/*
 * pcl_flowseg - internal: the exact 3D flow predicate, with a fast floating-point filter.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include "core/delaunay/flow_predicate.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <Eigen/Geometry> // cross products

#include <algorithm>
#include <cmath>

namespace pcl_flowseg {
namespace core {

namespace {
bool
exactInside (const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c, const Eigen::Vector3d& p)
{
  using Point3 = CGAL::Exact_predicates_inexact_constructions_kernel::Point_3;
  return CGAL::side_of_bounded_sphere (Point3 (a.x (), a.y (), a.z ()), Point3 (b.x (), b.y (), b.z ()),
                                       Point3 (c.x (), c.y (), c.z ()), Point3 (p.x (), p.y (), p.z ())) ==
         CGAL::ON_BOUNDED_SIDE;
}
} // namespace

bool
insideDiametralSphere (const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                       const Eigen::Vector3d& p)
{
  // With u = b - a, w = c - a, q = p - a, n = u x w, the centre of the diametral sphere is
  // a + o with o = (|w|^2 (n x u) + |u|^2 (w x n)) / (2 |n|^2), and p lies inside it exactly when
  // |q - o|^2 < |o|^2, i.e. when  D = |n|^2 |q|^2 - q . (|w|^2 (n x u) + |u|^2 (w x n))  < 0.
  const Eigen::Vector3d u = b - a, w = c - a, q = p - a; // each difference rounded once
  const Eigen::Vector3d n = u.cross (w);
  const double uu = u.squaredNorm (), ww = w.squaredNorm ();
  const double d = n.squaredNorm () * q.squaredNorm () - q.dot (ww * n.cross (u) + uu * w.cross (n));
  // Forward error bound: D has degree 6 in the differences; with U, W, Q their largest absolute
  // coordinates, the sum of the absolute values of its monomials is at most
  // 36 U^2 W^2 Q (Q + U + W), and about twenty roundings (each 2^-53, including those of the
  // differences) bound the relative error by 2.3e-15 of that. 1e-12 leaves a wide margin.
  const double U = u.cwiseAbs ().maxCoeff (), W = w.cwiseAbs ().maxCoeff (), Q = q.cwiseAbs ().maxCoeff ();
  const double bound = 1e-12 * 36.0 * U * U * W * W * Q * (Q + U + W);
  if (std::isfinite (d) && std::isfinite (bound) && bound > 1e-250 && std::abs (d) > bound)
    return d < 0;
  return exactInside (a, b, c, p);
}

} // namespace core
} // namespace pcl_flowseg

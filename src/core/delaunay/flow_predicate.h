/*
 * pcl_flowseg - internal: the exact 3D flow predicate, with a fast floating-point filter.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include <Eigen/Core>

namespace pcl_flowseg {
namespace core {

/** \brief True when \a p lies strictly inside the diametral sphere of triangle (a, b, c) (the
  * smallest sphere through a, b and c): exactly CGAL's side_of_bounded_sphere(a, b, c, p) ==
  * ON_BOUNDED_SIDE. A tetrahedron flows across the facet opposite its vertex p exactly then.
  *
  * Evaluated first in double precision with a forward error bound; only when the value is too
  * close to zero for its sign to be certain does it ask CGAL's exact predicate (about one call
  * in a thousand on surface samples). */
bool
insideDiametralSphere (const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                       const Eigen::Vector3d& p);

} // namespace core
} // namespace pcl_flowseg

/*
 * pcl_flowseg - directions spread evenly over the sphere: an icosahedron, subdivided,
 * to render the views of a model from.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include <pcl_flowseg/common/status.h>

#include <Eigen/Core>

#include <cstddef>
#include <vector>

namespace pcl_flowseg {

/** \brief The \a count unit directions of a geodesic sphere: the 12 vertices of a regular
  * icosahedron (count 12), with the midpoints of its edges pushed onto the sphere after each
  * subdivision of every triangle into four (42, 162, 642, ...: 10 4^k + 2). The same directions in
  * the same order on every platform. Fails for any other count. */
Status
viewSphereDirections (std::size_t count, std::vector<Eigen::Vector3d>& directions);

} // namespace pcl_flowseg

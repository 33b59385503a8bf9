/*
 * pcl_flowseg - the earth mover's distance between two small weighted sets (internal header).
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include <Eigen/Core>

#include <vector>

namespace pcl_flowseg {

/** \brief The least total cost of moving the weights \a from onto the weights \a to, where moving
  * one unit from i to j costs \a cost(i, j) (>= 0): the earth mover's distance. Exact (successive
  * shortest paths with potentials), for the few dozen items part matching needs: a part split in
  * two on one shape sends its weight to both halves on the other. Both weight lists are >= 0;
  * \a to is scaled to the total of \a from. Symmetric when \a cost is. */
double
transportDistance (const std::vector<double>& from, const std::vector<double>& to, const Eigen::MatrixXd& cost);

} // namespace pcl_flowseg

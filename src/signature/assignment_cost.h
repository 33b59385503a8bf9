/*
 * pcl_flowseg - the least total cost of a one-to-one assignment (internal header).
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include <cstddef>
#include <vector>

namespace pcl_flowseg {

/** \brief The least total cost of assigning each of \a rows rows to a different one of \a columns
  * columns (rows <= columns), where \a cost (row-major, rows x columns) is the cost of each pair:
  * the Hungarian method with potentials, O(rows^2 columns). 0 for no rows. */
double
leastAssignmentCost (const std::vector<double>& cost, std::size_t rows, std::size_t columns);

} // namespace pcl_flowseg

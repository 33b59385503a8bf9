/*
 * pcl_flowseg - the interior a shape description measures (internal header).
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include <vector>

namespace pcl_flowseg {

/** \brief The interior segments of a segmentation and their length unit. */
struct InteriorFrame
{
  std::vector<int> segments; ///< interior segments (indices into result.segments)
  double volume = 0.0;       ///< their total volume (area in 2D)
  double unit = 1.0;         ///< volume^(1/d)
};

} // namespace pcl_flowseg

/*
 * pcl_flowseg - a distinct colour per feature, for drawings and coloured point clouds.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include <pcl_flowseg/common/flow_result.h>

#include <array>
#include <cstdint>

namespace pcl_flowseg {

/** \brief A distinct colour for feature \a id (golden-ratio hues); grey for kNoSegment and for
  * the segment at infinity. */
std::array<std::uint8_t, 3>
segmentColour (std::uint32_t id, bool infinity = false);

} // namespace pcl_flowseg

/*
 * pcl_flowseg evaluation - 8-bit greyscale and RGB images written as PNG (libpng).
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include <pcl_flowseg/common/status.h>

#include <cstdint>
#include <string>
#include <vector>

namespace pcl_flowseg {

/** \brief Writes an 8-bit greyscale (channels = 1) or RGB (channels = 3) image as PNG (libpng).
  * Atomic. */
Status
writePng (const std::string& path, int width, int height, int channels, const std::vector<std::uint8_t>& pixels);

} // namespace pcl_flowseg

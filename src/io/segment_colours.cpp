/*
 * pcl_flowseg - a distinct colour per feature, for drawings and coloured point clouds.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include <pcl_flowseg/io/segment_colours.h>

#include <cmath>

namespace pcl_flowseg {

std::array<std::uint8_t, 3>
segmentColour (std::uint32_t id, bool infinity)
{
  if (id == kNoSegment || infinity)
    return {{160, 160, 160}};
  const double h = std::fmod (0.13 + 0.618033988749895 * id, 1.0) * 6.0;
  const double s = 0.75, v = 0.95;
  const int sector = static_cast<int> (h);
  const double f = h - sector, p = v * (1 - s), q = v * (1 - s * f), t = v * (1 - s * (1 - f));
  double r, g, b;
  switch (sector % 6)
  {
    case 0: r = v; g = t; b = p; break;
    case 1: r = q; g = v; b = p; break;
    case 2: r = p; g = v; b = t; break;
    case 3: r = p; g = q; b = v; break;
    case 4: r = t; g = p; b = v; break;
    default: r = v; g = p; b = q; break;
  }
  return {{static_cast<std::uint8_t> (r * 255), static_cast<std::uint8_t> (g * 255), static_cast<std::uint8_t> (b * 255)}};
}

} // namespace pcl_flowseg

/*
 * pcl_flowseg - internal: a PCD header, parsed and checked before any data is read.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include <pcl_flowseg/common/status.h>

#include <array>
#include <istream>
#include <string>
#include <vector>

namespace pcl_flowseg {
namespace detail {

/** \brief A PCD header as parsePcdHeader accepts it. */
struct PcdHeader
{
  std::vector<std::string> fields, sizes, types, counts;
  long long width = -1, height = 1, points = -1;
  std::string data;                                   ///< ascii, binary or binary_compressed
  std::array<double, 7> viewpoint{{0, 0, 0, 1, 0, 0, 0}}; ///< tx ty tz qw qx qy qz
  long long point_bytes = 0;                          ///< bytes per point (binary record)
};

/** \brief Reads the header of the PCD file open in \a in and checks it, leaving \a in at the first
  * byte of the data. PCL's reader crashes or allocates terabytes on many malformed headers, so the
  * header must follow the format strictly: ASCII text; known keywords, each once; VERSION 0.5 to
  * 0.7 and 7 VIEWPOINT numbers; FIELDS, SIZE, TYPE and COUNT that agree, floats of 4 or 8 bytes;
  * WIDTH, HEIGHT (at most 2e9 each) and POINTS present, consistent and not 0; points that fit in the
  * available memory and, for binary data, in the file. */
Status
parsePcdHeader (const std::string& path, std::istream& in, PcdHeader& header);

} // namespace detail
} // namespace pcl_flowseg

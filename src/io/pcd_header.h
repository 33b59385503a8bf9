/*
 * pcl_flowseg - internal: a PCD header checked before PCL's reader trusts it.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include <pcl_flowseg/common/status.h>

#include <string>

namespace pcl_flowseg {
namespace detail {

/** \brief Why the PCD file \a path must not be handed to PCL's reader, or success. PCL's reader
  * crashes or allocates terabytes on many malformed headers, so the header must follow the format
  * strictly: ASCII text; known keywords, each once; VERSION 0.5 to 0.7 and 7 VIEWPOINT numbers;
  * FIELDS, SIZE, TYPE and COUNT that agree, floats of 4 or 8 bytes; WIDTH, HEIGHT (at most 2e9
  * each) and POINTS present, consistent and not 0; points that fit in the available memory and,
  * for binary data, in the file. */
Status
checkPcdHeader (const std::string& path);

} // namespace detail
} // namespace pcl_flowseg

/*
 * pcl_flowseg - internal: a PLY header checked before PCL's reader trusts it.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include <pcl_flowseg/common/status.h>

#include "common/pcl_backend.h"

#include <string>

namespace pcl_flowseg {
namespace detail {

/** \brief Why the PLY file \a path must not be handed to PCL's reader, or success: its header
  * must start with "ply", end with "end_header" within 1 MiB, hold only format, comment,
  * obj_info, element and property lines, no list property in the vertex element, every element
  * count a whole number >= 0, and the elements it declares (at least one byte per property and
  * record) must fit in what follows the header. PCL's reader would otherwise allocate what a count
  * claims (a negative count became 51 GB) or stop on an assertion. */
Status
checkPlyHeader (const std::string& path);

/** \brief PCL's reader for the PLY file \a path once its header passed checkPlyHeader; null, with
  * \a why set, when the header fails or the PCL plugin cannot be opened. */
const PclBackend*
plyReaderFor (const std::string& path, Status& why);

} // namespace detail
} // namespace pcl_flowseg

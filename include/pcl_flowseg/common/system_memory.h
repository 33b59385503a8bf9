/*
 * pcl_flowseg - the memory the system can give a run, for refusing inputs that would not fit.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include <cstddef>

namespace pcl_flowseg {

/** \brief Memory the system reports available (Linux MemAvailable), in bytes; 0 when unknown. */
std::size_t
availableMemory ();

} // namespace pcl_flowseg

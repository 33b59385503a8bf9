/*
 * pcl_flowseg - internal: how busy the other processes keep the machine's cores right now.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

namespace pcl_flowseg {
namespace core {

/** \brief Threads of other processes that want a core right now: the system's runnable threads
  * (/proc/loadavg) minus this process's own running ones (/proc/self/task), the least of a few
  * readings over about a millisecond, so that a thread that runs only for a moment does not count
  * and one that computes does. Unlike the load average it does not remember this process's own
  * work of the last minute (a program segmenting one cloud after another would otherwise always
  * see a busy machine). Returns -1 where /proc cannot be read. */
int
otherRunnableThreads ();

} // namespace core
} // namespace pcl_flowseg

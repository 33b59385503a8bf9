/*
 * pcl_flowseg - independent jobs (one per shape, say) on a number of threads, with progress.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include <cstddef>
#include <functional>

namespace pcl_flowseg {

/** \brief Worker threads to use for \a requested: the hardware's threads for 0, else \a requested. */
unsigned
jobThreads (unsigned requested);

/** \brief Threads each of \a jobs independent jobs may use inside itself when \a requested
  * threads (0 = all cores) run them: all of them when the jobs run one at a time, else 1, since
  * the jobs already share the cores. So `-j 1` means sequential all the way down. */
unsigned
threadsPerJob (std::size_t jobs, unsigned requested);

/** \brief Calls \a job (i) for every i in [0, n) on jobThreads (\a threads) threads, each job once,
  * in no particular order; \a progress (optional) is called after each job with the number done
  * and the job's index, one call at a time. Jobs must not throw and must write only their own
  * results. */
void
runParallelJobs (std::size_t n, unsigned threads, const std::function<void (std::size_t)>& job,
                 const std::function<void (std::size_t done, std::size_t index)>& progress = {});

} // namespace pcl_flowseg

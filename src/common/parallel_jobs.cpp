/*
 * pcl_flowseg - independent jobs (one per shape, say) on a number of threads, with progress.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include <pcl_flowseg/common/parallel_jobs.h>

#include <algorithm>
#include <atomic>
#include <mutex>
#include <thread>
#include <vector>

namespace pcl_flowseg {

unsigned
jobThreads (unsigned requested)
{
  return requested > 0 ? requested : std::max (1u, std::thread::hardware_concurrency ());
}

unsigned
threadsPerJob (std::size_t jobs, unsigned requested)
{
  return jobs > 1 && jobThreads (requested) > 1 ? 1u : requested;
}

void
runParallelJobs (std::size_t n, unsigned threads, const std::function<void (std::size_t)>& job,
                 const std::function<void (std::size_t, std::size_t)>& progress)
{
  std::atomic<std::size_t> next (0);
  std::size_t done = 0;
  std::mutex report;
  auto worker = [&] () {
    for (std::size_t i; (i = next++) < n;)
    {
      job (i);
      std::lock_guard<std::mutex> lock (report);
      ++done;
      if (progress)
        progress (done, i);
    }
  };
  const unsigned count = static_cast<unsigned> (std::min<std::size_t> (jobThreads (threads), std::max<std::size_t> (n, 1)));
  std::vector<std::thread> pool;
  for (unsigned t = 1; t < count; ++t)
    pool.emplace_back (worker);
  worker (); // the calling thread works too
  for (auto& t : pool)
    t.join ();
}

} // namespace pcl_flowseg

/*
 * pcl_flowseg - internal: how busy the other processes keep the machine's cores right now.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include "core/support/system_load.h"

#include <dirent.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <string>
#include <thread>

namespace pcl_flowseg {
namespace core {

namespace {
/** Runnable threads of the whole system (the fourth field of /proc/loadavg, "running/total"), or -1. */
int
systemRunnableThreads ()
{
  std::FILE* f = std::fopen ("/proc/loadavg", "r");
  if (!f)
    return -1;
  double one, five, fifteen;
  int running = -1, total = 0;
  if (std::fscanf (f, "%lf %lf %lf %d/%d", &one, &five, &fifteen, &running, &total) != 5)
    running = -1;
  std::fclose (f);
  return running;
}

/** Threads of this process in state R (running or runnable), or -1. */
int
ownRunnableThreads ()
{
  DIR* tasks = opendir ("/proc/self/task");
  if (!tasks)
    return -1;
  int running = 0;
  while (const dirent* entry = readdir (tasks))
  {
    if (entry->d_name[0] == '.')
      continue;
    std::ifstream stat (std::string ("/proc/self/task/") + entry->d_name + "/stat");
    std::string line;
    std::getline (stat, line);
    const std::size_t close = line.rfind (')'); // the name may hold spaces and parentheses
    if (close != std::string::npos && close + 2 < line.size () && line[close + 2] == 'R')
      ++running;
  }
  closedir (tasks);
  return running;
}
} // namespace

int
otherRunnableThreads ()
{
  constexpr int kReadings = 5;
  int least = -1;
  for (int k = 0; k < kReadings; ++k)
  {
    if (k > 0)
      std::this_thread::sleep_for (std::chrono::microseconds (200));
    const int own = ownRunnableThreads ();
    const int all = systemRunnableThreads ();
    if (own < 0 || all < 0)
      return -1;
    const int others = std::max (0, all - own);
    least = least < 0 ? others : std::min (least, others);
  }
  return least;
}

} // namespace core
} // namespace pcl_flowseg

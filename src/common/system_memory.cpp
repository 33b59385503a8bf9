/*
 * pcl_flowseg - the memory the system can give a run, for refusing inputs that would not fit.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include <pcl_flowseg/common/system_memory.h>

#include <fstream>
#include <string>

namespace pcl_flowseg {

std::size_t
availableMemory ()
{
  std::ifstream meminfo ("/proc/meminfo");
  std::string key;
  std::size_t value = 0;
  std::string unit;
  while (meminfo >> key >> value >> unit)
    if (key == "MemAvailable:")
      return value * 1024;
  return 0;
}

} // namespace pcl_flowseg

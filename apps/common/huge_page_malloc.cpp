/*
 * pcl_flowseg apps - glibc's malloc asked to use transparent huge pages, by one re-execution.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include "common/huge_page_malloc.h"

#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>

#ifdef __linux__
#include <sys/auxv.h>
#include <unistd.h>
#endif

namespace flowseg_app {

bool
wantsHugePageRelaunch (const char* tunables, const char* marker, bool secure, const std::string& thp_enabled)
{
  if (secure || (marker && *marker) || (tunables && std::strstr (tunables, kHugePageTunable)))
    return false;
  return thp_enabled.find ("[madvise]") != std::string::npos;
}

std::string
withHugePageTunable (const char* tunables)
{
  std::string value = tunables ? tunables : "";
  if (!value.empty ())
    value += ':';
  return value + kHugePageTunable + "=1";
}

void
relaunchWithHugePageMalloc (char** argv)
{
#ifdef __linux__
  std::ifstream file ("/sys/kernel/mm/transparent_hugepage/enabled");
  std::ostringstream thp;
  thp << file.rdbuf ();
  const char* tunables = std::getenv ("GLIBC_TUNABLES");
  if (!wantsHugePageRelaunch (tunables, std::getenv (kRelaunchMarker), getauxval (AT_SECURE) != 0, thp.str ()))
    return;
  const bool had_tunables = tunables != nullptr;
  const std::string before = had_tunables ? tunables : "";
  if (setenv ("GLIBC_TUNABLES", withHugePageTunable (tunables).c_str (), 1) == 0 && setenv (kRelaunchMarker, "1", 1) == 0)
    execv ("/proc/self/exe", argv);
  // Not re-executed: run on as we are, with the environment as it was.
  unsetenv (kRelaunchMarker);
  if (had_tunables)
    setenv ("GLIBC_TUNABLES", before.c_str (), 1);
  else
    unsetenv ("GLIBC_TUNABLES");
#else
  (void) argv;
#endif
}

} // namespace flowseg_app

/*
 * pcl_flowseg apps - a progress line on stderr for long runs.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include "common/progress.h"

#include <cstdio>
#include <unistd.h>

namespace flowseg_app {

ProgressLine::ProgressLine (std::string label, std::size_t total, bool quiet)
  : label_ (std::move (label)), total_ (total), quiet_ (quiet), terminal_ (isatty (2) != 0)
{
}

ProgressLine::~ProgressLine ()
{
  if (quiet_)
    return;
  if (terminal_)
    std::fprintf (stderr, "\n");
  else
    std::fprintf (stderr, "%s %zu/%zu\n", label_.c_str (), done_, total_);
}

void
ProgressLine::update (std::size_t done, const std::string& detail)
{
  done_ = done;
  if (quiet_ || !terminal_)
    return;
  std::fprintf (stderr, "\r\033[K%s %zu/%zu %s", label_.c_str (), done, total_, detail.c_str ());
  std::fflush (stderr);
}

} // namespace flowseg_app

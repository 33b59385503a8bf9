/*
 * pcl_flowseg apps - a progress line on stderr for long runs.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include <cstddef>
#include <string>

namespace flowseg_app {

/** \brief "LABEL done/total detail" on stderr: rewritten in place on a terminal, once at the end
  * otherwise (logs stay readable); nothing when \a quiet. */
class ProgressLine
{
public:
  ProgressLine (std::string label, std::size_t total, bool quiet);
  ~ProgressLine ();
  ProgressLine (const ProgressLine&) = delete;
  ProgressLine& operator= (const ProgressLine&) = delete;

  void update (std::size_t done, const std::string& detail = std::string ());

private:
  std::string label_;
  std::size_t total_;
  bool quiet_, terminal_;
  std::size_t done_ = 0;
};

} // namespace flowseg_app

/*
 * pcl_flowseg - shape segmentation by flow discretization (Dey, Giesen, Goswami).
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include <string>

namespace pcl_flowseg {

/** \brief Outcome of an operation that can fail on bad input: ok, or a message for a person. */
struct Status
{
  bool ok = true;
  std::string message;

  static Status success () { return Status{}; }
  static Status error (std::string why) { return Status{false, std::move (why)}; }
  explicit operator bool () const { return ok; }
};

} // namespace pcl_flowseg

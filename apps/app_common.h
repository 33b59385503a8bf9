/*
 * pcl_flowseg apps - the small helpers every command-line app shares.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include <cmath>
#include <cstdlib>
#include <iostream>
#include <string>

namespace flowseg_app {

/** \brief Parses a finite number; false when \a text is not exactly one. */
inline bool
parseNumber (const std::string& text, double& value)
{
  char* end = nullptr;
  value = std::strtod (text.c_str (), &end);
  return !text.empty () && *end == '\0' && std::isfinite (value);
}

/** \brief Reports a usage error of \a app on stderr; returns the exit status for it (2). */
inline int
usageError (const char* app, const std::string& message)
{
  std::cerr << app << ": " << message << "\n(see " << app << " --help)\n";
  return 2;
}

} // namespace flowseg_app

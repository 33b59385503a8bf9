/*
 * pcl_flowseg - internal: the extension of a file name.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include <algorithm>
#include <cctype>
#include <string>

namespace pcl_flowseg {
namespace detail {

/** \brief Extension of \a path in lower case, without the dot ("" when there is none). */
inline std::string
lowerExtension (const std::string& path)
{
  const std::size_t slash = path.find_last_of ("/\\");
  const std::size_t dot = path.find_last_of ('.');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash))
    return "";
  std::string ext = path.substr (dot + 1);
  std::transform (ext.begin (), ext.end (), ext.begin (), [] (unsigned char c) { return std::tolower (c); });
  return ext;
}

} // namespace detail
} // namespace pcl_flowseg

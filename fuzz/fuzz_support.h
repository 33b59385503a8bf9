/*
 * pcl_flowseg fuzz targets - helpers.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include <cstdint>
#include <cstdio>
#include <string>
#include <unistd.h>

/** Writes the fuzz input to a file with the given extension (readers choose the format by it) and
  * returns its path; the same path is reused by the process. */
inline std::string
fuzzFile (const std::uint8_t* data, std::size_t size, const std::string& extension)
{
  const std::string path = "/tmp/pcl_flowseg_fuzz_" + std::to_string (::getpid ()) + "." + extension;
  FILE* f = std::fopen (path.c_str (), "wb");
  if (!f)
    return path;
  if (size)
    std::fwrite (data, 1, size, f);
  std::fclose (f);
  return path;
}

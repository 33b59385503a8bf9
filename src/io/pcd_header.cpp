/*
 * pcl_flowseg - internal: a PCD header, parsed and checked before any data is read.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include "io/pcd_header.h"

#include <pcl_flowseg/common/system_memory.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace pcl_flowseg {
namespace detail {

namespace {
std::string
where (const std::string& path, std::size_t line)
{
  return path + ":" + std::to_string (line) + ": ";
}

/** Why a VERSION or VIEWPOINT line's values are not the format's (PCL misreads the header after
  * such lines), or "". */
std::string
versionOrViewpointProblem (const std::string& key, const std::vector<std::string>& values)
{
  if (key == "VERSION")
  {
    static const std::set<std::string> known = {"0.7", ".7", "0.6", ".6", "0.5", ".5"};
    return values.size () == 1 && known.count (values[0]) ? "" : "VERSION must be one of 0.5, 0.6, 0.7";
  }
  const bool numbers = std::all_of (values.begin (), values.end (), [] (const std::string& v) {
    char* end = nullptr;
    return std::isfinite (std::strtod (v.c_str (), &end)) && *end == '\0';
  });
  return values.size () == 7 && numbers ? "" : "VIEWPOINT needs 7 numbers";
}

/** Reads the header lines up to DATA; fails on anything PCL's reader may not survive. */
Status
readPcdHeader (const std::string& path, std::istream& in, PcdHeader& h)
{
  std::string line;
  std::size_t number = 0;
  std::set<std::string> seen;
  while (h.data.empty () && std::getline (in, line))
  {
    if (++number > 64 || line.size () > 4096)
      break;
    if (!line.empty () && line.back () == '\r')
      line.pop_back ();
    // PCL splits header lines differently where control or non-ASCII bytes appear (it read "no
    // points" from such headers, then crashed): a header is ASCII text, comments included.
    if (std::any_of (line.begin (), line.end (), [] (char c) { return (c < 0x20 && c != '\t') || c == 0x7f; }))
      return Status::error (where (path, number) + "control characters in the PCD header (it must be ASCII text)");
    if (line.empty () || line[0] == '#')
      continue;
    std::istringstream words (line);
    std::string key;
    words >> key;
    std::vector<std::string> values;
    for (std::string w; words >> w;)
      values.push_back (w);
    auto integer = [&] (long long& out, const char* what) {
      char* end = nullptr;
      out = values.size () == 1 ? std::strtoll (values[0].c_str (), &end, 10) : -1;
      // At most 2e9 each, so that WIDTH x HEIGHT cannot overflow.
      return values.size () == 1 && *end == '\0' && out >= 0 && out <= 2000000000LL
                 ? Status::success ()
                 : Status::error (where (path, number) + "invalid " + what);
    };
    // PCL acts on the first of two equal keywords where this check would take the last
    // ("POINTS 0" then "POINTS 4" crashed its reader): each may appear once.
    if (!seen.insert (key).second)
      return Status::error (where (path, number) + "'" + key.substr (0, 40) + "' appears twice in the header");
    Status ok;
    if (key == "VERSION" || key == "VIEWPOINT")
    {
      if (const std::string why = versionOrViewpointProblem (key, values); !why.empty ())
        return Status::error (where (path, number) + why);
      if (key == "VIEWPOINT")
        for (std::size_t k = 0; k < 7; ++k)
          h.viewpoint[k] = std::strtod (values[k].c_str (), nullptr);
      continue;
    }
    else if (key == "FIELDS") h.fields = values;
    else if (key == "SIZE") h.sizes = values;
    else if (key == "TYPE") h.types = values;
    else if (key == "COUNT") h.counts = values;
    else if (key == "WIDTH") ok = integer (h.width, "WIDTH");
    else if (key == "HEIGHT") ok = integer (h.height, "HEIGHT");
    else if (key == "POINTS") ok = integer (h.points, "POINTS");
    else if (key == "DATA")
    {
      if (values.size () != 1 || (values[0] != "ascii" && values[0] != "binary" && values[0] != "binary_compressed"))
        return Status::error (where (path, number) + "unknown DATA type");
      h.data = values[0];
    }
    else
      return Status::error (path + ": not a PCD file (unexpected '" + key.substr (0, 40) + "' at line " +
                            std::to_string (number) + ")");
    if (!ok)
      return ok;
  }
  if (h.data.empty ())
    return Status::error (path + ": not a PCD file (no DATA line in the header)");
  return Status::success ();
}

/** Bytes per point of the header's fields; fails when the field lists or counts are inconsistent. */
Status
pcdPointBytes (const std::string& path, PcdHeader& h, long long& point_bytes)
{
  if (h.fields.empty () || h.sizes.size () != h.fields.size () || h.types.size () != h.fields.size () ||
      (!h.counts.empty () && h.counts.size () != h.fields.size ()))
    return Status::error (path + ": malformed PCD header (FIELDS, SIZE, TYPE, COUNT disagree)");
  if (h.points < 0 || h.width < 0) // PCL's reader reads "no points" without them, then crashes
    return Status::error (path + ": malformed PCD header (WIDTH or POINTS missing)");
  if (h.width * h.height != h.points) // each at most 2e9: no overflow
    return Status::error (path + ": malformed PCD header (WIDTH x HEIGHT and POINTS disagree or are missing)");
  if (h.points == 0) // PCL's reader misreads such files (a huge allocation after "No points to read")
    return Status::error (path + ": the PCD file holds no points");
  point_bytes = 0;
  for (std::size_t k = 0; k < h.fields.size (); ++k)
  {
    const std::string& size = h.sizes[k];
    const std::string& type = h.types[k];
    // Floats are 4 or 8 bytes: PCL's reader has no type for the others and crashes on them.
    if ((size != "1" && size != "2" && size != "4" && size != "8") || (type != "I" && type != "U" && type != "F") ||
        (type == "F" && size != "4" && size != "8"))
      return Status::error (path + ": malformed PCD header (field '" + h.fields[k] + "' has an invalid SIZE/TYPE " + size +
                            "/" + type + ")");
    long long count = 1;
    if (!h.counts.empty ())
    {
      char* end = nullptr;
      count = std::strtoll (h.counts[k].c_str (), &end, 10);
      if (*end != '\0' || count < 1 || count > 100000)
        return Status::error (path + ": malformed PCD header (invalid COUNT)");
    }
    point_bytes += count * std::stoll (size);
  }
  return Status::success ();
}

} // namespace

Status
parsePcdHeader (const std::string& path, std::istream& in, PcdHeader& h)
{
  if (const Status s = readPcdHeader (path, in, h); !s)
    return s;
  if (const Status s = pcdPointBytes (path, h, h.point_bytes); !s)
    return s;
  const std::size_t memory = availableMemory ();
  if (memory > 0 && static_cast<double> (h.points) * static_cast<double> (h.point_bytes + 16) > 0.5 * static_cast<double> (memory))
    return Status::error (path + ": " + std::to_string (h.points) + " points would not fit in the available memory: refused");
  if (h.data == "binary")
  {
    const std::streampos start = in.tellg ();
    in.seekg (0, std::ios::end);
    const long long available = static_cast<long long> (in.tellg () - start);
    in.seekg (start);
    if (available < h.points * h.point_bytes)
      return Status::error (path + ": truncated PCD file (" + std::to_string (available) + " data bytes, header promises " +
                            std::to_string (h.points * h.point_bytes) + ")");
  }
  return Status::success ();
}


} // namespace detail
} // namespace pcl_flowseg

/*
 * pcl_flowseg - internal: a PLY header checked before PCL's reader trusts it.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include "io/ply_header.h"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>
#include <vector>

namespace pcl_flowseg {
namespace detail {

namespace {
constexpr std::size_t kLargestHeader = 1 << 20;
constexpr unsigned long long kLargestCount = 1ULL << 40;

struct Element
{
  std::string name;
  unsigned long long count = 0;
  unsigned long long properties = 0;
};

Status
where (const std::string& path, std::size_t line, const std::string& what)
{
  return Status::error (path + ":" + std::to_string (line) + ": " + what);
}

/** A whole number >= 0 written only with digits; false otherwise. */
bool
parseCount (const std::string& text, unsigned long long& value)
{
  if (text.empty () || text.size () > 19 || text.find_first_not_of ("0123456789") != std::string::npos)
    return false;
  value = std::stoull (text);
  return value <= kLargestCount;
}
} // namespace

Status
checkPlyHeader (const std::string& path)
{
  std::ifstream in (path, std::ios::binary);
  if (!in)
    return Status::error (path + ": cannot open (" + std::strerror (errno) + ")");
  std::string line;
  if (!std::getline (in, line) || (line != "ply" && line != "ply\r"))
    return Status::error (path + ": not a PLY file (no 'ply' on the first line)");
  std::vector<Element> elements;
  for (std::size_t number = 2;; ++number)
  {
    if (!std::getline (in, line) || static_cast<std::size_t> (in.tellg ()) > kLargestHeader)
      return Status::error (path + ": PLY header without 'end_header' in its first MiB");
    if (!line.empty () && line.back () == '\r')
      line.pop_back ();
    std::istringstream words (line);
    std::string keyword, count;
    words >> keyword;
    if (keyword == "end_header")
      break;
    if (keyword == "element")
    {
      Element e;
      if (!(words >> e.name >> count) || !parseCount (count, e.count))
        return where (path, number, "element '" + e.name + "' with a count that is not a whole number from 0 to 2^40: '" +
                                        count + "'");
      elements.push_back (e);
    }
    else if (keyword == "property")
    {
      if (elements.empty ())
        return where (path, number, "property before any element");
      std::string kind;
      words >> kind;
      // PCL's reader takes lists only as faces' vertex indices; elsewhere it asserts.
      if (kind == "list" && elements.back ().name == "vertex")
        return where (path, number, "a list property of the vertex element");
      ++elements.back ().properties;
    }
    else if (keyword != "format" && keyword != "comment" && keyword != "obj_info")
      return where (path, number, "not a PLY header line: '" + line.substr (0, 40) + "'");
  }
  const std::streamoff body_start = in.tellg ();
  in.seekg (0, std::ios::end);
  const unsigned long long body = static_cast<unsigned long long> (in.tellg () - body_start);
  unsigned long long needed = 0;
  for (const Element& e : elements)
  {
    needed += e.count * std::max (1ULL, e.properties); // <= 2^40 * 2^20 per element: no overflow
    if (needed > body)
      return Status::error (path + ": the PLY header declares at least " + std::to_string (needed) +
                            " bytes of elements, the file holds " + std::to_string (body) + " after it");
  }
  return Status::success ();
}

const PclBackend*
plyReaderFor (const std::string& path, Status& why)
{
  why = checkPlyHeader (path);
  return why ? pclBackend (why) : nullptr;
}

} // namespace detail
} // namespace pcl_flowseg

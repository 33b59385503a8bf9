/*
 * pcl_flowseg - reading point samples from the file formats the apps accept.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include <pcl_flowseg/io/point_io.h>
#include <pcl_flowseg/common/system_memory.h>

#include "io/file_extension.h"
#include "io/ply_header.h"
#include "io/point_fields.h"

#include <pcl/PCLPointCloud2.h>
#include <pcl/common/io.h>
#include <pcl/io/pcd_io.h>
#include <pcl/io/ply_io.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <cmath>
#include <set>
#include <sstream>
#include <vector>

namespace pcl_flowseg {

namespace {


/** Splits a line into numbers (white space or commas); false when a token is not a number. */
bool
parseNumbers (const std::string& line, std::vector<double>& values)
{
  values.clear ();
  const char* s = line.c_str ();
  while (*s)
  {
    while (*s && (std::isspace (static_cast<unsigned char> (*s)) || *s == ','))
      ++s;
    if (!*s)
      break;
    char* end = nullptr;
    errno = 0;
    const double v = std::strtod (s, &end);
    if (end == s || (*end && !std::isspace (static_cast<unsigned char> (*end)) && *end != ','))
      return false;
    values.push_back (v);
    s = end;
  }
  return true;
}

std::string
stripComment (const std::string& line)
{
  const std::size_t hash = line.find ('#');
  return hash == std::string::npos ? line : line.substr (0, hash);
}

std::string
where (const std::string& path, std::size_t line)
{
  return path + ":" + std::to_string (line) + ": ";
}

Status
loadText (const std::string& path, std::istream& in, pcl::PointCloud<pcl::PointXYZ>& cloud, std::vector<Eigen::Vector3d>& normals)
{
  std::string line;
  std::vector<double> v;
  std::size_t number = 0, columns = 0;
  while (std::getline (in, line))
  {
    ++number;
    const std::string body = stripComment (line);
    if (!parseNumbers (body, v))
      return Status::error (where (path, number) + "not a list of numbers: '" + line.substr (0, 80) + "'");
    if (v.empty ())
      continue;
    if (v.size () < 2)
      return Status::error (where (path, number) + "expected at least 2 coordinates (x y [z])");
    if (columns == 0)
      columns = v.size ();
    else if (v.size () != columns)
      return Status::error (where (path, number) + "has " + std::to_string (v.size ()) + " columns, earlier lines " +
                            std::to_string (columns));
    cloud.push_back (pcl::PointXYZ (static_cast<float> (v[0]), static_cast<float> (v[1]),
                                    v.size () > 2 ? static_cast<float> (v[2]) : 0.0f));
    if (v.size () >= 6)
      normals.emplace_back (v[3], v[4], v[5]);
  }
  if (in.bad ())
    return Status::error (path + ": read error");
  return Status::success ();
}

/** Next line that is not empty or a comment; false at the end. */
bool
nextContentLine (std::istream& in, std::string& body, std::size_t& number)
{
  std::string line;
  while (std::getline (in, line))
  {
    ++number;
    body = stripComment (line);
    if (body.find_first_not_of (" \t\r") != std::string::npos)
      return true;
  }
  return false;
}

Status
loadOff (const std::string& path, std::istream& in, pcl::PointCloud<pcl::PointXYZ>& cloud)
{
  std::size_t number = 0;
  std::string body;
  if (!nextContentLine (in, body, number))
    return Status::error (path + ": empty file");
  std::istringstream header (body);
  std::string magic;
  header >> magic;
  if (magic.size () < 3 || magic.compare (magic.size () - 3, 3, "OFF") != 0)
    return Status::error (where (path, number) + "not an OFF file (no OFF header)");
  if (magic != "OFF" && magic != "COFF" && magic != "NOFF" && magic != "CNOFF")
    return Status::error (where (path, number) + "unsupported OFF variant '" + magic + "'");
  std::vector<double> counts;
  std::string rest;
  std::getline (header, rest);
  if (!parseNumbers (rest, counts) || counts.empty ())
  {
    if (!nextContentLine (in, body, number) || !parseNumbers (body, counts))
      return Status::error (where (path, number) + "missing vertex/face counts");
  }
  if (counts.empty () || counts[0] < 0 || counts[0] > 1e9 || counts[0] != static_cast<double> (static_cast<long long> (counts[0])))
    return Status::error (where (path, number) + "invalid vertex count");
  const std::size_t n = static_cast<std::size_t> (counts[0]);
  cloud.reserve (std::min<std::size_t> (n, 1u << 20)); // grows with the file, not with its claim
  std::vector<double> v;
  for (std::size_t k = 0; k < n; ++k)
  {
    if (!nextContentLine (in, body, number))
      return Status::error (path + ": file ends after " + std::to_string (k) + " of " + std::to_string (n) + " vertices");
    if (!parseNumbers (body, v) || v.size () < 3)
      return Status::error (where (path, number) + "expected a vertex 'x y z'");
    cloud.push_back (pcl::PointXYZ (static_cast<float> (v[0]), static_cast<float> (v[1]), static_cast<float> (v[2])));
  }
  return Status::success ();
}

Status
loadObj (const std::string& path, std::istream& in, pcl::PointCloud<pcl::PointXYZ>& cloud)
{
  std::string line;
  std::vector<double> v;
  std::size_t number = 0;
  while (std::getline (in, line))
  {
    ++number;
    if (line.size () < 2 || line[0] != 'v' || !std::isspace (static_cast<unsigned char> (line[1])))
      continue; // faces, normals, texture coordinates, groups...
    if (!parseNumbers (stripComment (line.substr (2)), v) || v.size () < 3)
      return Status::error (where (path, number) + "expected a vertex 'v x y z'");
    cloud.push_back (pcl::PointXYZ (static_cast<float> (v[0]), static_cast<float> (v[1]), static_cast<float> (v[2])));
  }
  return Status::success ();
}

/** The header of a PCD file, as far as the checks below need it. */
struct PcdHeader
{
  std::vector<std::string> fields, sizes, types, counts;
  long long width = -1, height = 1, points = -1;
  std::string data; ///< ascii, binary or binary_compressed
};

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
    if (key == "VIEWPOINT" && (values.size () != 7 || !std::all_of (values.begin (), values.end (), [] (const std::string& v) {
                                 char* end = nullptr;
                                 return std::isfinite (std::strtod (v.c_str (), &end)) && *end == '\0';
                               })))
      return Status::error (where (path, number) + "VIEWPOINT needs 7 numbers");
    if (key == "VERSION" && (values.size () != 1 || (values[0] != "0.7" && values[0] != ".7" && values[0] != "0.6" &&
                                                      values[0] != ".6" && values[0] != "0.5" && values[0] != ".5")))
      return Status::error (where (path, number) + "VERSION must be one of 0.5, 0.6, 0.7");
    if (key == "VERSION" || key == "VIEWPOINT")
      continue;
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
  if (h.points < 0 || h.points > 2000000000LL || (h.width >= 0 && h.width * h.height != h.points))
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

/** PCL's PCD reader does not survive every malformed header, so the header is checked first:
  * known keywords only, consistent field lists, a sane point count that fits in memory, and
  * enough bytes for binary data. */
Status
checkPcdHeader (const std::string& path)
{
  std::ifstream in (path, std::ios::binary);
  PcdHeader h;
  long long point_bytes = 0;
  if (const Status s = readPcdHeader (path, in, h); !s)
    return s;
  if (const Status s = pcdPointBytes (path, h, point_bytes); !s)
    return s;
  const std::size_t memory = availableMemory ();
  if (memory > 0 && static_cast<double> (h.points) * static_cast<double> (point_bytes + 16) > 0.5 * static_cast<double> (memory))
    return Status::error (path + ": " + std::to_string (h.points) + " points would not fit in the available memory: refused");
  if (h.data == "binary")
  {
    const std::streampos start = in.tellg ();
    in.seekg (0, std::ios::end);
    const long long available = static_cast<long long> (in.tellg () - start);
    if (available < h.points * point_bytes)
      return Status::error (path + ": truncated PCD file (" + std::to_string (available) + " data bytes, header promises " +
                            std::to_string (h.points * point_bytes) + ")");
  }
  return Status::success ();
}

Status
loadWithPcl (const std::string& path, bool pcd, pcl::PointCloud<pcl::PointXYZ>& cloud, std::vector<Eigen::Vector3d>& normals)
{
  if (const Status header = pcd ? checkPcdHeader (path) : detail::checkPlyHeader (path); !header)
    return header;
  pcl::PCLPointCloud2 blob;
  Eigen::Vector4f origin = Eigen::Vector4f::Zero ();
  Eigen::Quaternionf orientation = Eigen::Quaternionf::Identity ();
  const int rc = pcd ? pcl::io::loadPCDFile (path, blob, origin, orientation) : pcl::io::loadPLYFile (path, blob);
  if (rc < 0)
    return Status::error (path + ": not a readable " + std::string (pcd ? "PCD" : "PLY") + " file");
  const Status read = detail::readPointFields (blob, path, cloud, &normals);
  if (!read)
    return read;
  cloud.sensor_origin_ = origin;
  cloud.sensor_orientation_ = orientation;
  return Status::success ();
}

} // namespace

bool
isSupportedPointFile (const std::string& path)
{
  const std::string ext = detail::lowerExtension (path);
  return ext == "pcd" || ext == "ply" || ext == "xyz" || ext == "txt" || ext == "csv" || ext == "off" || ext == "obj";
}

Status
loadPointCloud (const std::string& path, pcl::PointCloud<pcl::PointXYZ>& cloud)
{
  std::vector<Eigen::Vector3d> normals;
  return loadPointCloud (path, cloud, normals);
}

Status
loadPointCloud (const std::string& path, pcl::PointCloud<pcl::PointXYZ>& cloud, std::vector<Eigen::Vector3d>& normals)
{
  cloud.clear ();
  normals.clear ();
  const std::string ext = detail::lowerExtension (path);
  if (!isSupportedPointFile (path))
    return Status::error (path + ": unknown file type '." + ext +
                          "' (expected .pcd, .ply, .xyz, .txt, .csv, .off or .obj)");
  std::ifstream in (path, std::ios::binary);
  if (!in)
    return Status::error (path + ": cannot open (" + std::strerror (errno) + ")");

  Status status;
  try
  {
  if (ext == "pcd" || ext == "ply")
  {
    in.close ();
    status = loadWithPcl (path, ext == "pcd", cloud, normals);
  }
  else if (ext == "off")
    status = loadOff (path, in, cloud);
  else if (ext == "obj")
    status = loadObj (path, in, cloud);
  else
    status = loadText (path, in, cloud, normals);
  }
  catch (const std::bad_alloc&)
  {
    status = Status::error (path + ": out of memory while reading");
  }
  catch (const std::exception& e)
  {
    status = Status::error (path + ": " + e.what ());
  }

  if (!status.ok)
  {
    cloud.clear ();
    normals.clear ();
    return status;
  }
  if (normals.size () != cloud.size ())
    normals.clear ();
  if (cloud.empty ())
    return Status::error (path + ": contains no points");
  cloud.width = static_cast<std::uint32_t> (cloud.size ());
  cloud.height = 1;
  cloud.is_dense = std::all_of (cloud.begin (), cloud.end (), [] (const pcl::PointXYZ& p) {
    return std::isfinite (p.x) && std::isfinite (p.y) && std::isfinite (p.z);
  });
  return Status::success ();
}

Status
loadPointCloud (const std::string& path, pcl::PointCloud<pcl::PointNormal>& cloud, bool& has_normals)
{
  cloud.clear ();
  pcl::PointCloud<pcl::PointXYZ> xyz;
  std::vector<Eigen::Vector3d> normals;
  const Status loaded = loadPointCloud (path, xyz, normals);
  has_normals = !normals.empty ();
  if (!loaded)
    return loaded;
  cloud.resize (xyz.size ());
  for (std::size_t i = 0; i < xyz.size (); ++i)
  {
    pcl::PointNormal& p = cloud[i];
    p.x = xyz[i].x;
    p.y = xyz[i].y;
    p.z = xyz[i].z;
    const Eigen::Vector3d n = has_normals ? normals[i] : Eigen::Vector3d::Zero ();
    p.normal_x = static_cast<float> (n.x ());
    p.normal_y = static_cast<float> (n.y ());
    p.normal_z = static_cast<float> (n.z ());
  }
  cloud.sensor_origin_ = xyz.sensor_origin_;
  cloud.sensor_orientation_ = xyz.sensor_orientation_;
  return Status::success ();
}

} // namespace pcl_flowseg

/*
 * pcl_flowseg - reading point samples from the file formats the apps accept.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include <pcl_flowseg/io/point_io.h>

#include "common/pcl_backend.h"
#include "io/file_extension.h"
#include "io/pcd_header.h"
#include "io/pcd_reader.h"
#include "io/ply_header.h"
#include "io/point_fields.h"

#include <pcl/PCLPointCloud2.h>
#include <pcl/common/io.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
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

/** The records of a PCD (its own reader) or PLY file (PCL's), with a PCD's sensor pose. */
Status
readRecords (const std::string& path, bool pcd, pcl::PCLPointCloud2& blob, Eigen::Vector4f& origin,
             Eigen::Quaternionf& orientation)
{
  origin = Eigen::Vector4f::Zero ();
  orientation = Eigen::Quaternionf::Identity ();
  if (pcd)
    return detail::readPcdFile (path, blob, origin, orientation);
  Status why;
  const detail::PclBackend* pcl_io = detail::plyReaderFor (path, why);
  if (!pcl_io)
    return why;
  if (pcl_io->load_ply_cloud (path, blob) < 0)
    return Status::error (path + ": not a readable PLY file");
  return Status::success ();
}

/** A PCD or PLY file into \a cloud: points alone, or with \a normals (a vector or the cloud's own
  * fields, by ReadArgs). */
template <class PointT, class... ReadArgs>
Status
loadPcdOrPly (const std::string& path, bool pcd, pcl::PointCloud<PointT>& cloud, ReadArgs&&... normals)
{
  pcl::PCLPointCloud2 blob;
  Eigen::Vector4f origin;
  Eigen::Quaternionf orientation;
  if (const Status read = readRecords (path, pcd, blob, origin, orientation); !read)
    return read;
  if (const Status read = detail::readPointFields (blob, path, cloud, std::forward<ReadArgs> (normals)...); !read)
    return read;
  cloud.sensor_origin_ = origin;
  cloud.sensor_orientation_ = orientation;
  return Status::success ();
}

/** An error when \a path has an extension no reader knows or cannot be opened. */
Status
checkReadable (const std::string& path)
{
  if (!isSupportedPointFile (path))
    return Status::error (path + ": unknown file type '." + detail::lowerExtension (path) +
                          "' (expected .pcd, .ply, .xyz, .txt, .csv, .off or .obj)");
  if (!std::ifstream (path, std::ios::binary))
    return Status::error (path + ": cannot open (" + std::strerror (errno) + ")");
  return Status::success ();
}

/** \a read run with its exceptions (out of memory, a reader's own) turned into errors. */
template <class Read>
Status
readGuarded (const std::string& path, Read&& read)
{
  try
  {
    return read ();
  }
  catch (const std::bad_alloc&)
  {
    return Status::error (path + ": out of memory while reading");
  }
  catch (const std::exception& e)
  {
    return Status::error (path + ": " + e.what ());
  }
}

/** Width, height and is_dense of a cloud just read; an error when it holds no points. */
template <class PointT>
Status
finishCloud (const std::string& path, pcl::PointCloud<PointT>& cloud)
{
  if (cloud.empty ())
    return Status::error (path + ": contains no points");
  cloud.width = static_cast<std::uint32_t> (cloud.size ());
  cloud.height = 1;
  cloud.is_dense = std::all_of (cloud.begin (), cloud.end (), [] (const PointT& p) {
    return std::isfinite (p.x) && std::isfinite (p.y) && std::isfinite (p.z);
  });
  return Status::success ();
}

} // namespace

bool
isSupportedPointFile (const std::string& path)
{
  const std::string ext = detail::lowerExtension (path);
  return ext == "pcd" || ext == "ply" || ext == "xyz" || ext == "txt" || ext == "csv" || ext == "off" || ext == "obj";
}

bool
carriesSensorOrigin (const std::string& path)
{
  return detail::lowerExtension (path) == "pcd";
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
  if (const Status readable = checkReadable (path); !readable)
    return readable;
  const std::string ext = detail::lowerExtension (path);
  const Status status = readGuarded (path, [&] () -> Status {
    if (ext == "pcd" || ext == "ply")
      return loadPcdOrPly (path, ext == "pcd", cloud, &normals);
    std::ifstream in (path, std::ios::binary);
    if (ext == "off")
      return loadOff (path, in, cloud);
    if (ext == "obj")
      return loadObj (path, in, cloud);
    return loadText (path, in, cloud, normals);
  });
  if (!status.ok)
  {
    cloud.clear ();
    normals.clear ();
    return status;
  }
  if (normals.size () != cloud.size ())
    normals.clear ();
  return finishCloud (path, cloud);
}

Status
loadPointCloud (const std::string& path, pcl::PointCloud<pcl::PointNormal>& cloud, bool& has_normals)
{
  cloud.clear ();
  has_normals = false;
  const std::string ext = detail::lowerExtension (path);
  if ((ext == "pcd" || ext == "ply") && checkReadable (path).ok)
  {
    // Straight into the points with normals: no intermediate cloud to fill and copy.
    const Status status = readGuarded (path, [&] () { return loadPcdOrPly (path, ext == "pcd", cloud, has_normals); });
    if (!status.ok)
    {
      cloud.clear ();
      has_normals = false;
      return status;
    }
    return finishCloud (path, cloud);
  }
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
  cloud.width = xyz.width;
  cloud.height = xyz.height;
  cloud.is_dense = xyz.is_dense;
  cloud.sensor_origin_ = xyz.sensor_origin_;
  cloud.sensor_orientation_ = xyz.sensor_orientation_;
  return Status::success ();
}

} // namespace pcl_flowseg

/*
 * pcl_flowseg - triangle meshes: reading, and area-uniform surface sampling with noise.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include <pcl_flowseg/io/mesh_io.h>

#include "common/pcl_backend.h"
#include "io/file_extension.h"
#include "io/ply_header.h"
#include "io/point_fields.h"

#include <pcl/PolygonMesh.h>
#include <pcl/common/io.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <random>
#include <sstream>

namespace pcl_flowseg {

namespace {

bool
nextLine (std::istream& in, std::string& line, std::size_t& number)
{
  while (std::getline (in, line))
  {
    ++number;
    const std::size_t hash = line.find ('#');
    if (hash != std::string::npos)
      line.resize (hash);
    if (line.find_first_not_of (" \t\r") != std::string::npos)
      return true;
  }
  return false;
}

/** Adds the polygon \a ids as a triangle fan; false when an index is out of range. */
bool
addPolygon (const std::vector<long long>& ids, TriangleMesh& mesh)
{
  for (long long id : ids)
    if (id < 0 || id >= static_cast<long long> (mesh.vertices.size ()))
      return false;
  for (std::size_t k = 2; k < ids.size (); ++k)
    mesh.faces.push_back ({{static_cast<int> (ids[0]), static_cast<int> (ids[k - 1]), static_cast<int> (ids[k])}});
  return true;
}

Status
loadOff (const std::string& path, std::istream& in, TriangleMesh& mesh)
{
  std::string line;
  std::size_t number = 0;
  if (!nextLine (in, line, number))
    return Status::error (path + ": empty file");
  std::istringstream header (line);
  std::string magic;
  header >> magic;
  if (magic != "OFF" && magic != "COFF" && magic != "NOFF")
    return Status::error (path + ": not an OFF file");
  long long nv = -1, nf = -1;
  if (!(header >> nv >> nf))
  {
    if (!nextLine (in, line, number))
      return Status::error (path + ": missing counts");
    std::istringstream counts (line);
    counts >> nv >> nf;
  }
  if (nv < 0 || nf < 0 || nv > 100000000 || nf > 200000000)
    return Status::error (path + ": invalid vertex/face counts");
  mesh.vertices.reserve (std::min<std::size_t> (static_cast<std::size_t> (nv), 1u << 20));
  for (long long k = 0; k < nv; ++k)
  {
    double x, y, z;
    if (!nextLine (in, line, number) || !(std::istringstream (line) >> x >> y >> z))
      return Status::error (path + ":" + std::to_string (number) + ": expected a vertex");
    mesh.vertices.emplace_back (x, y, z);
  }
  for (long long k = 0; k < nf; ++k)
  {
    if (!nextLine (in, line, number))
      return Status::error (path + ": file ends after " + std::to_string (k) + " faces");
    std::istringstream face (line);
    long long n = 0;
    face >> n;
    std::vector<long long> ids (static_cast<std::size_t> (std::max (0LL, std::min (n, 1000LL))));
    for (auto& id : ids)
      face >> id;
    if (n < 3 || n > 1000 || !face || !addPolygon (ids, mesh))
      return Status::error (path + ":" + std::to_string (number) + ": invalid face");
  }
  return Status::success ();
}

Status
loadObj (const std::string& path, std::istream& in, TriangleMesh& mesh)
{
  std::string line;
  std::size_t number = 0;
  while (nextLine (in, line, number))
  {
    std::istringstream words (line);
    std::string kind;
    words >> kind;
    if (kind == "v")
    {
      double x, y, z;
      if (!(words >> x >> y >> z))
        return Status::error (path + ":" + std::to_string (number) + ": expected 'v x y z'");
      mesh.vertices.emplace_back (x, y, z);
    }
    else if (kind == "f")
    {
      std::vector<long long> ids;
      for (std::string corner; words >> corner;)
      {
        const long long id = std::atoll (corner.c_str ()); // "v", "v/vt", "v//vn", "v/vt/vn"
        ids.push_back (id < 0 ? static_cast<long long> (mesh.vertices.size ()) + id : id - 1);
      }
      if (ids.size () < 3 || !addPolygon (ids, mesh))
        return Status::error (path + ":" + std::to_string (number) + ": invalid face");
    }
  }
  return Status::success ();
}

Status
loadPly (const std::string& path, TriangleMesh& mesh)
{
  Status why;
  const detail::PclBackend* pcl_io = detail::plyReaderFor (path, why);
  if (!pcl_io)
    return why;
  pcl::PolygonMesh poly;
  if (pcl_io->load_ply_mesh (path, poly) < 0)
    return Status::error (path + ": not a readable PLY file");
  pcl::PointCloud<pcl::PointXYZ> cloud;
  const Status read = detail::readPointFields (poly.cloud, path, cloud, nullptr);
  if (!read)
    return read;
  for (const auto& p : cloud)
    mesh.vertices.emplace_back (p.x, p.y, p.z);
  for (const auto& v : poly.polygons)
  {
    std::vector<long long> ids (v.vertices.begin (), v.vertices.end ());
    if (ids.size () < 3 || !addPolygon (ids, mesh))
      return Status::error (path + ": invalid face");
  }
  return Status::success ();
}

} // namespace

double
TriangleMesh::area () const
{
  double a = 0.0;
  for (const auto& f : faces)
    a += 0.5 * (vertices[static_cast<std::size_t> (f[1])] - vertices[static_cast<std::size_t> (f[0])])
                   .cross (vertices[static_cast<std::size_t> (f[2])] - vertices[static_cast<std::size_t> (f[0])])
                   .norm ();
  return a;
}

double
TriangleMesh::diagonal () const
{
  if (vertices.empty ())
    return 0.0;
  Eigen::Vector3d lo = vertices.front (), hi = vertices.front ();
  for (const auto& v : vertices)
  {
    lo = lo.cwiseMin (v);
    hi = hi.cwiseMax (v);
  }
  return (hi - lo).norm ();
}

Status
loadTriangleMesh (const std::string& path, TriangleMesh& mesh)
{
  mesh = TriangleMesh ();
  const std::string ext = detail::lowerExtension (path);
  if (ext != "off" && ext != "obj" && ext != "ply")
    return Status::error (path + ": unknown mesh type '." + ext + "' (expected .off, .obj or .ply)");
  std::ifstream in (path);
  if (!in)
    return Status::error (path + ": cannot open (" + std::strerror (errno) + ")");
  Status s;
  try
  {
    s = ext == "off" ? loadOff (path, in, mesh) : ext == "obj" ? loadObj (path, in, mesh) : loadPly (path, mesh);
  }
  catch (const std::bad_alloc&)
  {
    s = Status::error (path + ": out of memory while reading");
  }
  if (s.ok && mesh.faces.empty ())
    s = Status::error (path + ": the mesh has no faces");
  if (!s.ok)
    mesh = TriangleMesh ();
  return s;
}

std::vector<Eigen::Vector3d>
sampleMeshSurface (const TriangleMesh& mesh, std::size_t count, double noise_sigma, std::uint32_t seed)
{
  std::vector<Eigen::Vector3d> out;
  if (mesh.faces.empty () || count == 0)
    return out;
  std::vector<double> cumulative (mesh.faces.size ());
  double total = 0.0;
  for (std::size_t k = 0; k < mesh.faces.size (); ++k)
  {
    const auto& f = mesh.faces[k];
    const Eigen::Vector3d& a = mesh.vertices[static_cast<std::size_t> (f[0])];
    total += 0.5 * (mesh.vertices[static_cast<std::size_t> (f[1])] - a).cross (mesh.vertices[static_cast<std::size_t> (f[2])] - a).norm ();
    cumulative[k] = total;
  }
  std::mt19937_64 rng (seed);
  std::uniform_real_distribution<double> u (0.0, 1.0);
  std::normal_distribution<double> gauss (0.0, 1.0);
  out.reserve (count);
  for (std::size_t i = 0; i < count; ++i)
  {
    const double pick = u (rng) * total;
    const std::size_t k = std::min (static_cast<std::size_t> (std::lower_bound (cumulative.begin (), cumulative.end (), pick) - cumulative.begin ()),
                                    mesh.faces.size () - 1);
    const auto& f = mesh.faces[k];
    double r1 = u (rng), r2 = u (rng);
    if (r1 + r2 > 1.0)
    {
      r1 = 1.0 - r1;
      r2 = 1.0 - r2;
    }
    const Eigen::Vector3d& a = mesh.vertices[static_cast<std::size_t> (f[0])];
    Eigen::Vector3d p = a + r1 * (mesh.vertices[static_cast<std::size_t> (f[1])] - a) + r2 * (mesh.vertices[static_cast<std::size_t> (f[2])] - a);
    if (noise_sigma > 0.0)
      p += noise_sigma * Eigen::Vector3d (gauss (rng), gauss (rng), gauss (rng));
    out.push_back (p);
  }
  return out;
}

} // namespace pcl_flowseg

/*
 * pcl_flowseg - one way in for shape files: point clouds as they are, meshes sampled on their faces.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include <pcl_flowseg/io/shape_input.h>

#include "io/file_extension.h"

#include <pcl_flowseg/io/mesh_io.h>
#include <pcl_flowseg/io/point_io.h>
#include <pcl_flowseg/io/silhouette.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <dirent.h>
#include <sys/stat.h>

namespace pcl_flowseg {

Status
checkShapeInputOptions (const ShapeInputOptions& options)
{
  if (options.mesh_points < 4 || options.mesh_points > 100000000)
    return Status::error ("the points sampled on a mesh must number from 4 to 100000000, got " +
                          std::to_string (options.mesh_points));
  return Status::success ();
}

bool
isShapeFile (const std::string& path)
{
  return isSupportedPointFile (path) || isSilhouetteFile (path);
}

Status
loadShapeSample (const std::string& path, const ShapeInputOptions& options, std::vector<Eigen::Vector3d>& points,
                 std::optional<Eigen::Vector3d>* sensor_origin)
{
  points.clear ();
  if (sensor_origin)
    sensor_origin->reset ();
  if (const Status o = checkShapeInputOptions (options); !o)
    return o;
  // Checked before reading: a mesh or an image is not a single view from a known place.
  const bool has_origin = carriesSensorOrigin (path);
  if (options.use_sensor_origin && !has_origin)
    return Status::error (path + ": the file carries no sensor origin to take the viewpoint from (only PCD files do, "
                                 "in their VIEWPOINT line)");
  const std::string ext = detail::lowerExtension (path);
  if (isSilhouetteFile (path))
  {
    GreyImage image;
    const Status s = loadGreyImage (path, image);
    if (!s.ok)
      return s;
    points = silhouetteBoundary (image);
    if (points.empty ())
      return Status::error (path + ": the image holds no silhouette");
    return Status::success ();
  }
  if (ext == "off" || ext == "obj" || ext == "ply")
  {
    TriangleMesh mesh;
    const Status m = loadTriangleMesh (path, mesh);
    if (m.ok)
    {
      points = sampleMeshSurface (mesh, options.mesh_points, 0.0, options.seed);
      return Status::success ();
    }
    if (ext != "ply") // a PLY without faces is a point cloud
      return m;
  }
  pcl::PointCloud<pcl::PointXYZ> cloud;
  const Status s = loadPointCloud (path, cloud);
  if (!s.ok)
    return s;
  points.reserve (cloud.size ());
  for (const auto& p : cloud)
    points.emplace_back (p.x, p.y, p.z);
  if (sensor_origin && has_origin)
    *sensor_origin = cloud.sensor_origin_.head<3> ().cast<double> ();
  return Status::success ();
}

namespace {
Status
walk (const std::string& root, const std::string& relative, std::vector<std::string>& out, int depth)
{
  if (depth > 32)
    return Status::error (root + "/" + relative + ": folders nested too deeply");
  const std::string dir = relative.empty () ? root : root + "/" + relative;
  DIR* d = opendir (dir.c_str ());
  if (!d)
    return Status::error (dir + ": cannot open folder (" + std::strerror (errno) + ")");
  std::vector<std::string> names;
  while (dirent* e = readdir (d))
  {
    const std::string name = e->d_name;
    if (name != "." && name != "..")
      names.push_back (name);
  }
  closedir (d);
  std::sort (names.begin (), names.end ());
  for (const auto& name : names)
  {
    const std::string rel = relative.empty () ? name : relative + "/" + name;
    struct stat st;
    if (stat ((root + "/" + rel).c_str (), &st) != 0)
      continue;
    if (S_ISDIR (st.st_mode))
    {
      const Status s = walk (root, rel, out, depth + 1);
      if (!s.ok)
        return s;
    }
    else if (S_ISREG (st.st_mode) && isShapeFile (name))
      out.push_back (rel);
  }
  return Status::success ();
}
} // namespace

Status
listShapeFiles (const std::string& root, std::vector<std::string>& relative_paths)
{
  relative_paths.clear ();
  return walk (root, "", relative_paths, 0);
}

std::string
shapeLabel (const std::string& relative_path)
{
  const std::size_t slash = relative_path.find_last_of ('/');
  if (slash == std::string::npos)
    return "";
  const std::size_t before = relative_path.find_last_of ('/', slash - 1);
  return relative_path.substr (before == std::string::npos ? 0 : before + 1, slash - (before == std::string::npos ? 0 : before + 1));
}

} // namespace pcl_flowseg

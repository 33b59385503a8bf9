/*
 * pcl_flowseg Python bindings - reading point files and shape files, listing shape collections.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include "bindings.h"
#include "python_values.h"

#include <pcl_flowseg/io/point_io.h>
#include <pcl_flowseg/io/shape_input.h>

#include <pybind11/stl.h>

namespace pcl_flowseg_python {
namespace {

/** (points, normals or None) of a point file, as flowseg_segment reads it. */
py::tuple
readPoints (const std::string& path)
{
  pcl::PointCloud<pcl::PointNormal> cloud;
  bool has_normals = false;
  pcl_flowseg::Status s;
  {
    py::gil_scoped_release release;
    s = pcl_flowseg::loadPointCloud (path, cloud, has_normals);
  }
  raiseOsErrorIfFailed (s);
  std::vector<Eigen::Vector3d> points, normals;
  for (const auto& p : cloud)
  {
    points.emplace_back (p.x, p.y, p.z);
    normals.emplace_back (p.normal_x, p.normal_y, p.normal_z);
  }
  return py::make_tuple (rowsToArray (points), has_normals ? py::object (rowsToArray (normals)) : py::object (py::none ()));
}

py::array_t<double>
readShape (const std::string& path, const py::kwargs& kwargs)
{
  CallParameters call;
  pcl_flowseg::MatchParameters unused;
  applyKwargs (kwargs, kShapeInputArguments, call, unused);
  std::vector<Eigen::Vector3d> points;
  pcl_flowseg::Status s;
  {
    py::gil_scoped_release release;
    s = pcl_flowseg::loadShapeSample (path, call.input, points);
  }
  raiseOsErrorIfFailed (s);
  return rowsToArray (points);
}

} // namespace

void
bindIo (py::module_& m)
{
  m.def ("read_points", &readPoints, py::arg ("path"),
         "Reads a point file (.pcd .ply .xyz .txt .csv, vertices of .off .obj) as flowseg_segment does: returns "
         "(points, normals), an (n, 3) float64 array and the (n, 3) normals or None. OSError on a missing, "
         "unreadable or malformed file.");
  m.def ("read_shape", &readShape, py::arg ("path"),
         "Reads any shape file as points: meshes sampled on their faces (keywords mesh_points, seed), point files "
         "as they are, silhouette images (.png .bmp .pgm) as their boundary (2D, z = 0).");
  m.def ("list_shape_files", [] (const std::string& root) {
           std::vector<std::string> files;
           raiseOsErrorIfFailed (pcl_flowseg::listShapeFiles (root, files));
           return files;
         }, py::arg ("root"), "The shape files below root (recursively, sorted), relative to root: what flowseg_db build indexes.");
  m.def ("shape_label", &pcl_flowseg::shapeLabel, py::arg ("relative_path"),
         "The class of a shape file: the name of its folder ('' at the top level).");
}

} // namespace pcl_flowseg_python

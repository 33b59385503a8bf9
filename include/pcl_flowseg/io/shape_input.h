/*
 * pcl_flowseg - one way in for shape files: point clouds as they are, meshes sampled on their faces.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include <pcl_flowseg/common/status.h>

#include <Eigen/Core>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace pcl_flowseg {

/** \brief How shape files become point samples. */
struct ShapeInputOptions
{
  std::size_t mesh_points = 5000; ///< points sampled on a mesh's faces (area-uniform; 4 to 10^8)
  std::uint32_t seed = 1;          ///< sampling seed
  /** Point files: the viewpoint of a single-view scan is the file's sensor origin (PCD VIEWPOINT);
    * reading a file that carries none (meshes, PLY, text, images) then fails. */
  bool use_sensor_origin = false;
};

/** \brief Why \a options cannot be used, or success. */
Status
checkShapeInputOptions (const ShapeInputOptions& options);

/** \brief True for the files loadShapeSample reads (.pcd .ply .xyz .txt .csv .off .obj, and the
  * silhouette images .png .bmp .pgm). */
bool
isShapeFile (const std::string& path);

/** \brief Reads a shape as points: meshes (.off, .obj, and .ply files with faces) are sampled on
  * their faces, point files are read as they are, silhouette images give their boundary (2D).
  * \param[out] sensor_origin (optional) the file's sensor origin, or none when the file carries
  *             none (see carriesSensorOrigin); with options.use_sensor_origin such a file fails,
  *             with a message naming it. */
Status
loadShapeSample (const std::string& path, const ShapeInputOptions& options, std::vector<Eigen::Vector3d>& points,
                 std::optional<Eigen::Vector3d>* sensor_origin = nullptr);

/** \brief The shape files below \a root (recursively, sorted), as paths relative to \a root. */
Status
listShapeFiles (const std::string& root, std::vector<std::string>& relative_paths);

/** \brief The class of a shape file: the name of the folder holding it ("" at the top level). */
std::string
shapeLabel (const std::string& relative_path);

} // namespace pcl_flowseg

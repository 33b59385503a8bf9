/*
 * pcl_flowseg - a virtual range scanner: the points of a mesh that a sensor at a viewpoint sees.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include <pcl_flowseg/common/status.h>
#include <pcl_flowseg/io/mesh_io.h>

#include <Eigen/Core>

#include <cstdint>
#include <vector>

namespace pcl_flowseg {

/** \brief How a virtual range scanner looks at a mesh. */
struct RangeScanOptions
{
  /** Sensor position, in the mesh's units; must lie outside the mesh's bounding sphere (the
    * smallest ball around the bounding-box centre that holds every vertex). */
  Eigen::Vector3d viewpoint = Eigen::Vector3d::Zero ();
  /** Returns wanted: the image grid is chosen so that about this many rays hit the mesh, then
    * surplus returns are dropped at random. */
  std::size_t points = 10000;
  /** Depth noise: standard deviation along the ray, as a share of the bounding-box diagonal, at the
    * distance of the bounding-box centre; it grows with the squared range, as in structured-light
    * and time-of-flight depth cameras. 0 = exact depths. */
  double depth_noise = 0.0;
  /** Seed of the noise and of the choice of returns. */
  std::uint32_t seed = 1;
};

/** \brief Checks \a options against \a mesh: finite viewpoint outside the bounding sphere, at
  * least 4 points (at most 10^8), depth noise finite in [0, 1]. */
Status
checkRangeScanOptions (const TriangleMesh& mesh, const RangeScanOptions& options);

/** \brief The points of \a mesh visible from options.viewpoint: a pinhole camera aimed at the
  * bounding-box centre whose square image just covers the bounding sphere casts one ray per pixel;
  * each ray returns its first hit on the mesh, moved along the ray by the depth noise. Fails on
  * bad options or when the mesh shows no face to the sensor. */
Status
scanMesh (const TriangleMesh& mesh, const RangeScanOptions& options, std::vector<Eigen::Vector3d>& points);

/** \brief scanMesh, also giving the face of \a mesh each point was measured on. */
Status
scanMesh (const TriangleMesh& mesh, const RangeScanOptions& options, std::vector<Eigen::Vector3d>& points,
          std::vector<int>& face_of_point);

} // namespace pcl_flowseg

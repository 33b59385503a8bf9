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

/** \brief How the depth noise of a scan depends on the range. */
enum class DepthNoiseModel
{
  /** Grows with the squared range, as in structured-light and time-of-flight depth cameras:
    * RangeScanOptions::depth_noise holds at the range of the bounding-box centre. */
  kGrowsWithSquaredRange,
  /** The same standard deviation along every ray, whatever its range. */
  kConstant
};

/** \brief The largest image side, in pixels, of a scan with a fixed image. */
constexpr std::size_t kMaxScanImagePixels = 10000;

/** \brief How a virtual range scanner looks at a mesh. The defaults choose the image grid from
  * the number of points wanted; a fixed image_pixels makes the scanner a camera whose every
  * pixel returns its first hit. */
struct RangeScanOptions
{
  /** Sensor position, in the mesh's units; must lie outside the mesh's bounding sphere (the
    * smallest ball around the bounding-box centre that holds every vertex). */
  Eigen::Vector3d viewpoint = Eigen::Vector3d::Zero ();
  /** Returns wanted: the image grid is chosen so that about this many rays hit the mesh, then
    * surplus returns are dropped at random. Ignored when image_pixels is set. */
  std::size_t points = 10000;
  /** Depth noise: standard deviation along the ray, as a share of the bounding-box diagonal; how
    * it depends on the range is noise_model's. 0 = exact depths. */
  double depth_noise = 0.0;
  /** How the depth noise depends on the range; by default it grows with the squared range. */
  DepthNoiseModel noise_model = DepthNoiseModel::kGrowsWithSquaredRange;
  /** Side of the square image in pixels (at most kMaxScanImagePixels): one ray per pixel, each
    * returning its first hit, none dropped, so a scan holds at most image_pixels^2 points.
    * 0 = the side is chosen from `points`. */
  std::size_t image_pixels = 0;
  /** Field of view in degrees, in (0, 180): the angle the square image spans, horizontally and
    * vertically alike, around the axis from the viewpoint to the bounding-box centre. 0 = the
    * image just covers the bounding sphere. */
  double field_of_view = 0.0;
  /** Seed of the noise and of the choice of returns. */
  std::uint32_t seed = 1;
};

/** \brief Checks \a options against \a mesh: finite viewpoint outside the bounding sphere, at
  * least 4 points (at most 10^8; not checked with a fixed image), depth noise finite in [0, 1],
  * image side at most kMaxScanImagePixels, field of view 0 or in (0, 180) degrees. */
Status
checkRangeScanOptions (const TriangleMesh& mesh, const RangeScanOptions& options);

/** \brief The points of \a mesh visible from options.viewpoint: a pinhole camera aimed at the
  * bounding-box centre, whose square image just covers the bounding sphere or spans the field of
  * view, casts one ray through the centre of each pixel; each ray returns its first hit on the
  * mesh, moved along the ray by the depth noise. The image's up direction is the part of the z
  * axis across the viewing axis (of the x axis when the viewing axis lies within 26 degrees of z).
  * Points come in image order. Fails on bad options or when the
  * mesh shows no face to the sensor. */
Status
scanMesh (const TriangleMesh& mesh, const RangeScanOptions& options, std::vector<Eigen::Vector3d>& points);

/** \brief scanMesh, also giving the face of \a mesh each point was measured on. */
Status
scanMesh (const TriangleMesh& mesh, const RangeScanOptions& options, std::vector<Eigen::Vector3d>& points,
          std::vector<int>& face_of_point);

} // namespace pcl_flowseg

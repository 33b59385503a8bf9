/*
 * pcl_flowseg - a shape as a depth camera sees it: the visible points of one view, in a frame of
 * their own, and a roll-invariant histogram of them.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include <pcl_flowseg/common/status.h>

#include <Eigen/Core>

#include <array>
#include <cstddef>
#include <optional>
#include <vector>

namespace pcl_flowseg {

/** \brief Points kept per view (farthest-point sampled from the visible points). */
constexpr std::size_t kViewPoints = 128;
/** \brief Bins of a view's histogram: kViewRadiusBins x kViewDepthBins of (distance from the view
  * axis, depth), then kViewPairBins of the distances between point pairs. */
constexpr std::size_t kViewRadiusBins = 8;
constexpr std::size_t kViewDepthBins = 8;
constexpr std::size_t kViewPairBins = 16;
constexpr std::size_t kViewHistogramBins = kViewRadiusBins * kViewDepthBins + kViewPairBins;
/** \brief Points of a complete shape kept for aligning scans with it (farthest-point sampled). */
constexpr std::size_t kShapePoints = 512;
/** \brief Views rendered of each complete 3D shape (a geodesic sphere: 12, 42, 162, ...). */
constexpr std::size_t kDefaultViewCount = 42;
/** \brief Points a kept point's normal is fitted to. */
constexpr std::size_t kNormalNeighbours = 12;
/** \brief Fewest visible points a view needs to be described. */
constexpr std::size_t kMinViewPoints = 16;

/** \brief One view of a shape. The view frame: origin at the visible points' centroid, z along the
  * line of sight (from the camera to the centroid), x along the points' widest spread across it,
  * lengths divided by the points' RMS distance from the centroid. So a view does not change with the
  * shape's position, orientation or scale, nor with the camera's roll; the roll between two views
  * is found when they are compared. */
struct ViewDescription
{
  /** Unit direction from the visible points' centroid towards the camera, input coordinates: the
    * view frame's -z. */
  Eigen::Vector3f direction = Eigen::Vector3f::UnitZ ();
  /** The view frame's x: viewFrameAxes (-direction) turned by this angle about z (radians). */
  float roll = 0.0f;
  Eigen::Vector3f centre = Eigen::Vector3f::Zero (); ///< the view frame's origin, input coordinates
  float scale = 1.0f; ///< the view frame's length unit (RMS radius of the visible points), input units
  std::array<float, kViewHistogramBins> histogram{}; ///< sums to 2 (two blocks of 1)
  std::vector<Eigen::Vector3f> points;               ///< at most kViewPoints, view frame
  /** Unit surface normal at each point (unoriented, fitted to its kNormalNeighbours nearest
    * visible points), view frame: distances to the surface are measured along them. */
  std::vector<Eigen::Vector3f> normals;
};

/** \brief The views of a shape: of a complete shape, kDefaultViewCount rendered ones; of a
  * single-view scan, the one its camera saw. */
struct ViewSet
{
  bool single_view = false;
  std::vector<ViewDescription> views;
  /** A complete shape: at most kShapePoints of its sample spread evenly, input coordinates (a scan
    * aligned with one of the views is refined against the whole surface). Empty for a scan. */
  std::vector<Eigen::Vector3f> shape_points;
  std::vector<Eigen::Vector3f> shape_normals; ///< unit normal at each shape point (unoriented)
};

/** \brief The x, y and z axes (columns) of a frame whose z is \a sight (unit), x and y across it
  * by a fixed rule. */
Eigen::Matrix3d
viewFrameAxes (const Eigen::Vector3d& sight);

/** \brief The axes (columns) of \a view's frame, input coordinates. */
Eigen::Matrix3d
viewAxes (const ViewDescription& view);

/** \brief Describes the points a camera at \a viewpoint saw (a single-view scan): fails when the
  * viewpoint is not finite, lies inside the points' bounding box (a camera inside the object) or
  * more than 10^6 box diagonals away, or fewer than kMinViewPoints points are finite. */
Status
describeScanView (const std::vector<Eigen::Vector3d>& points, const Eigen::Vector3d& viewpoint, ViewDescription& view);

/** \brief Renders \a count views of a complete 3D point sample (cameras on a geodesic sphere
  * turned to the sample's principal axes, at twice the diagonal of its bounding box along those
  * axes from the box's centre, looking at the centre: the same views however the sample is turned
  * or shifted) and describes
  * each: the points a view sees are those nearest the camera in their image cell (a depth buffer
  * whose cells match the sample's spacing), and keeps kShapePoints of the sample. Views seeing
  * fewer than kMinViewPoints are left out. */
Status
describeShapeViews (const std::vector<Eigen::Vector3d>& points, std::size_t count, ViewSet& set);

/** \brief True when \a points look like a single view seen from \a origin: it lies outside their
  * bounding box and at least kSingleViewShare of them are seen from it (a complete shape hides
  * about half of its points from any place). Matching such points as a complete shape ranks them
  * poorly: callers warn that single-view matching needs the viewpoint. */
bool
looksLikeSingleView (const std::vector<Eigen::Vector3d>& points, const Eigen::Vector3d& origin);

/** \brief Share of the points a camera must see for them to look like its single view. */
constexpr double kSingleViewShare = 0.9;

/** \brief The views of a shape file's sample for its signature: the scan's own view when
  * \a viewpoint is given, the rendered ones otherwise; 2D shapes have none. */
Status
describeViewSet (const std::vector<Eigen::Vector3d>& points, int dimension, const std::optional<Eigen::Vector3d>& viewpoint,
                 ViewSet& set);

/** \brief Why \a set is not one these functions could have made, or success: unit directions,
  * finite centres, scales > 0, histogram bins in [0, 1], 2 to kViewPoints finite points per view with as
  * many unit normals, at most kShapePoints finite shape points with as many unit normals, a
  * single-view set with exactly one view. */
Status
checkViewSet (const ViewSet& set);

} // namespace pcl_flowseg

/*
 * pcl_flowseg - the views of a point sample: of a complete one, cameras on a geodesic sphere and a
 * depth buffer sized to its spacing; of a scan, its own camera's.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include "view_rendering.h"
#include "view_points.h"

#include <pcl_flowseg/signature/view_sphere.h>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>

namespace pcl_flowseg {

namespace {

/** Distance of the cameras from the shape's centre, in bounding-box diagonals (the scan protocol's). */
constexpr double kCameraDistance = 2.0;
/** Points whose nearest neighbour distance estimates the spacing. */
constexpr std::size_t kSpacingProbes = 256;
/** Image cell width in sample spacings: wide enough that a surface facing the camera leaves no
  * empty cell for the far side to show through. */
constexpr double kCellSpacings = 1.5;
/** Depth, in image cells, by which a point must lie behind the nearest of its cell to count as
  * hidden when telling single views (looksLikeSingleView). */
constexpr double kSingleViewDepthCells = 4.0;
/** Farthest a scan's viewpoint may lie from its points' bounding-box centre, in box diagonals. */
constexpr double kFarthestViewpoint = 1e6;
/** Most image cells along a side (a sample of a few far outliers must not allocate much). */
constexpr long kMaxCells = 2048;

/** The median distance from a point of \a points to its nearest other point (a subset probed). */
double
sampleSpacing (const std::vector<Eigen::Vector3d>& points)
{
  const std::size_t step = std::max<std::size_t> (1, points.size () / kSpacingProbes);
  std::vector<double> nearest;
  for (std::size_t i = 0; i < points.size (); i += step)
  {
    double best = std::numeric_limits<double>::infinity ();
    for (std::size_t j = 0; j < points.size (); ++j)
      if (j != i)
      {
        const double d = (points[i] - points[j]).squaredNorm ();
        if (d > 0.0)
          best = std::min (best, d);
      }
    if (std::isfinite (best))
      nearest.push_back (std::sqrt (best));
  }
  if (nearest.empty ())
    return 0.0;
  std::nth_element (nearest.begin (), nearest.begin () + static_cast<std::ptrdiff_t> (nearest.size () / 2), nearest.end ());
  return nearest[nearest.size () / 2];
}

/** The shape's principal axes (columns), and the centre and diagonal of its bounding box along them:
  * the cameras placed in this frame see the same views of a turned or shifted shape. (The view
  * sphere is symmetric under the axes' sign changes, so their signs do not matter.) */
struct ShapeFrame
{
  Eigen::Matrix3d axes = Eigen::Matrix3d::Identity ();
  Eigen::Vector3d centre = Eigen::Vector3d::Zero ();
  double diagonal = 0.0;
};

ShapeFrame
principalFrame (const std::vector<Eigen::Vector3d>& points)
{
  Eigen::Vector3d mean = Eigen::Vector3d::Zero ();
  for (const auto& p : points)
    mean += p;
  mean /= static_cast<double> (points.size ());
  Eigen::Matrix3d scatter = Eigen::Matrix3d::Zero ();
  for (const auto& p : points)
    scatter += (p - mean) * (p - mean).transpose ();
  ShapeFrame frame;
  frame.axes = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> (scatter).eigenvectors ();
  Eigen::AlignedBox3d box;
  for (const auto& p : points)
    box.extend (frame.axes.transpose () * (p - mean));
  frame.centre = mean + frame.axes * box.center ();
  frame.diagonal = box.diagonal ().norm ();
  return frame;
}

/** The finite ones of \a points, and their bounding \a box. */
std::vector<Eigen::Vector3d>
finitePoints (const std::vector<Eigen::Vector3d>& points, Eigen::AlignedBox3d& box)
{
  std::vector<Eigen::Vector3d> finite;
  finite.reserve (points.size ());
  for (const auto& p : points)
    if (p.allFinite ())
    {
      finite.push_back (p);
      box.extend (p);
    }
  return finite;
}

/** Image coordinates (scaled to the target's distance) and depth of a point. */
struct Projected
{
  double u = 0.0, v = 0.0, depth = 0.0;
};

} // namespace

namespace internal {

std::vector<Eigen::Vector3d>
visiblePoints (const std::vector<Eigen::Vector3d>& points, const Eigen::Vector3d& camera, const Eigen::Vector3d& target,
               double spacing, long reach, double tolerance)
{
  const Eigen::Vector3d axis = (target - camera).normalized ();
  const Eigen::Vector3d helper = std::abs (axis.x ()) < 0.9 ? Eigen::Vector3d::UnitX () : Eigen::Vector3d::UnitY ();
  const Eigen::Vector3d right = helper.cross (axis).normalized ();
  const Eigen::Vector3d up = axis.cross (right);
  const double focal = (target - camera).norm ();
  std::vector<Projected> image (points.size ());
  double low_u = std::numeric_limits<double>::infinity (), low_v = low_u, high_u = -low_u, high_v = -low_u;
  for (std::size_t i = 0; i < points.size (); ++i)
  {
    const Eigen::Vector3d d = points[i] - camera;
    const double depth = std::max (d.dot (axis), 1e-12 * focal);
    image[i] = {d.dot (right) / depth * focal, d.dot (up) / depth * focal, depth};
    low_u = std::min (low_u, image[i].u), high_u = std::max (high_u, image[i].u);
    low_v = std::min (low_v, image[i].v), high_v = std::max (high_v, image[i].v);
  }
  const double cell = std::max ({kCellSpacings * spacing, (high_u - low_u) / kMaxCells, (high_v - low_v) / kMaxCells, 1e-300});
  const long width = static_cast<long> ((high_u - low_u) / cell) + 1, height = static_cast<long> ((high_v - low_v) / cell) + 1;
  auto cellOf = [&] (const Projected& p, long& cu, long& cv) {
    cu = std::min (width - 1, static_cast<long> ((p.u - low_u) / cell));
    cv = std::min (height - 1, static_cast<long> ((p.v - low_v) / cell));
  };
  std::vector<double> nearest (static_cast<std::size_t> (width * height), std::numeric_limits<double>::infinity ());
  for (const Projected& p : image)
  {
    long cu, cv;
    cellOf (p, cu, cv);
    double& depth = nearest[static_cast<std::size_t> (cv * width + cu)];
    depth = std::min (depth, p.depth);
  }
  std::vector<Eigen::Vector3d> visible;
  for (std::size_t i = 0; i < points.size (); ++i)
  {
    long cu, cv;
    cellOf (image[i], cu, cv);
    double front = std::numeric_limits<double>::infinity ();
    for (long y = std::max (0L, cv - reach); y <= std::min (height - 1, cv + reach); ++y)
      for (long x = std::max (0L, cu - reach); x <= std::min (width - 1, cu + reach); ++x)
        front = std::min (front, nearest[static_cast<std::size_t> (y * width + x)]);
    if (image[i].depth <= front + tolerance * cell * image[i].depth / focal)
      visible.push_back (points[i]);
  }
  return visible;
}

} // namespace internal

bool
looksLikeSingleView (const std::vector<Eigen::Vector3d>& points, const Eigen::Vector3d& origin)
{
  Eigen::AlignedBox3d box;
  const std::vector<Eigen::Vector3d> finite = finitePoints (points, box);
  if (finite.size () < kMinViewPoints || !origin.allFinite () || box.contains (origin))
    return false;
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero ();
  for (const auto& p : finite)
    centroid += p;
  centroid /= static_cast<double> (finite.size ());
  const double spacing = sampleSpacing (finite);
  if (!(spacing > 0.0))
    return false;
  // Only points straight behind others are hidden: a scan's steep surfaces are seen, a complete
  // shape's far side is not.
  const std::size_t seen = internal::visiblePoints (finite, origin, centroid, spacing, 0, kSingleViewDepthCells).size ();
  return static_cast<double> (seen) >= kSingleViewShare * static_cast<double> (finite.size ());
}

Status
describeShapeViews (const std::vector<Eigen::Vector3d>& points, std::size_t count, ViewSet& set)
{
  set = ViewSet ();
  std::vector<Eigen::Vector3d> directions;
  if (const Status s = viewSphereDirections (count, directions); !s)
    return s;
  Eigen::AlignedBox3d box;
  const std::vector<Eigen::Vector3d> finite = finitePoints (points, box);
  if (finite.size () < kMinViewPoints)
    return Status::error ("views need at least " + std::to_string (kMinViewPoints) + " finite points");
  const ShapeFrame frame = principalFrame (finite);
  const double spacing = sampleSpacing (finite);
  if (!(frame.diagonal > 0.0) || !(spacing > 0.0))
    return Status::error ("views need points that are not all equal");
  for (const Eigen::Vector3d& d : directions)
  {
    const Eigen::Vector3d camera = frame.centre + kCameraDistance * frame.diagonal * (frame.axes * d);
    ViewDescription view;
    if (internal::describeVisiblePoints (internal::visiblePoints (finite, camera, frame.centre, spacing), camera, view))
      set.views.push_back (std::move (view));
  }
  if (set.views.empty ())
    return Status::error ("no view of the shape sees enough points");
  set.shape_points = internal::farthestPoints (finite, kShapePoints);
  set.shape_normals = internal::pointNormals (finite, set.shape_points);
  return Status::success ();
}

Status
describeScanView (const std::vector<Eigen::Vector3d>& points, const Eigen::Vector3d& viewpoint, ViewDescription& view)
{
  if (!viewpoint.allFinite ())
    return Status::error ("the viewpoint is not finite");
  Eigen::AlignedBox3d box;
  const std::vector<Eigen::Vector3d> finite = finitePoints (points, box);
  if (finite.size () >= kMinViewPoints && box.contains (viewpoint))
    return Status::error ("the viewpoint lies inside the scanned points' bounding box: a single view is seen from "
                          "outside the object");
  if (finite.size () >= kMinViewPoints &&
      !((viewpoint - box.center ()).norm () <= kFarthestViewpoint * std::max (box.diagonal ().norm (), 1e-300)))
    return Status::error ("the viewpoint lies absurdly far from the scanned points (more than 10^6 times their size)");
  return internal::describeVisiblePoints (finite, viewpoint, view);
}

Status
describeViewSet (const std::vector<Eigen::Vector3d>& points, int dimension, const std::optional<Eigen::Vector3d>& viewpoint,
                 ViewSet& set)
{
  set = ViewSet ();
  if (dimension != 3)
    return Status::success ();
  if (!viewpoint)
    return describeShapeViews (points, kDefaultViewCount, set);
  set.single_view = true;
  set.views.resize (1);
  return describeScanView (points, *viewpoint, set.views[0]);
}

} // namespace pcl_flowseg

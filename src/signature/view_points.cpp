/*
 * pcl_flowseg - internal: the description of the points one view sees (frame, histogram, kept points, normals).
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include "view_points.h"

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>

namespace pcl_flowseg {
namespace internal {

namespace {

/** Largest distance from the view axis and depth (in RMS radii) the histogram covers; farther
  * points fall in the last bins. */
constexpr double kHistogramRadius = 2.5;
constexpr double kHistogramDepth = 1.5;
/** Largest pair distance the pair block covers, in RMS radii. */
constexpr double kHistogramPairDistance = 4.0;

/** The angle about z that turns x onto the widest spread of \a local across z. */
double
widestRoll (const std::vector<Eigen::Vector3d>& local)
{
  Eigen::Matrix2d scatter = Eigen::Matrix2d::Zero ();
  for (const auto& p : local)
    scatter += p.head<2> () * p.head<2> ().transpose ();
  const Eigen::Vector2d widest = Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> (scatter).eigenvectors ().col (1);
  return std::atan2 (widest.y (), widest.x ());
}

/** \a points in the view frame of a camera at \a camera (see ViewDescription), whose origin,
  * direction, roll and scale it sets in \a view. */
std::vector<Eigen::Vector3d>
toViewFrame (const std::vector<Eigen::Vector3d>& points, const Eigen::Vector3d& camera, ViewDescription& view)
{
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero ();
  for (const auto& p : points)
    centroid += p;
  centroid /= static_cast<double> (points.size ());
  const Eigen::Matrix3d axes = viewFrameAxes ((centroid - camera).normalized ());
  std::vector<Eigen::Vector3d> local;
  local.reserve (points.size ());
  double squares = 0.0;
  for (const auto& p : points)
  {
    local.push_back (axes.transpose () * (p - centroid));
    squares += (p - centroid).squaredNorm ();
  }
  const double roll = widestRoll (local);
  const Eigen::Matrix3d unroll = Eigen::AngleAxisd (-roll, Eigen::Vector3d::UnitZ ()).toRotationMatrix ();
  double radius = std::sqrt (squares / static_cast<double> (points.size ()));
  radius = radius > 0.0 ? radius : 1.0;
  for (auto& p : local)
    p = unroll * p / radius;
  view.direction = -axes.col (2).cast<float> ();
  view.roll = static_cast<float> (roll);
  view.centre = centroid.cast<float> ();
  view.scale = static_cast<float> (radius);
  return local;
}

std::size_t
binOf (double value, double low, double high, std::size_t bins)
{
  const double t = (value - low) / (high - low) * static_cast<double> (bins);
  return static_cast<std::size_t> (std::clamp (t, 0.0, static_cast<double> (bins) - 1.0));
}

/** The (axis distance, depth) block and the pair-distance block, each summing to 1, of the kept
  * points (spread evenly, so neither block depends on the sampling density). */
void
fillHistogram (ViewDescription& view)
{
  view.histogram.fill (0.0f);
  const float point_share = 1.0f / static_cast<float> (view.points.size ());
  for (const auto& p : view.points)
  {
    const std::size_t r = binOf (std::hypot (p.x (), p.y ()), 0.0, kHistogramRadius, kViewRadiusBins);
    const std::size_t d = binOf (p.z (), -kHistogramDepth, kHistogramDepth, kViewDepthBins);
    view.histogram[r * kViewDepthBins + d] += point_share;
  }
  const std::size_t n = view.points.size ();
  const float pair_share = 2.0f / static_cast<float> (n * (n - 1));
  float* pairs = view.histogram.data () + kViewRadiusBins * kViewDepthBins;
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j)
      pairs[binOf ((view.points[i] - view.points[j]).norm (), 0.0, kHistogramPairDistance, kViewPairBins)] += pair_share;
}

} // namespace

std::vector<Eigen::Vector3f>
farthestPoints (const std::vector<Eigen::Vector3d>& local, std::size_t count)
{
  std::vector<double> nearest (local.size (), std::numeric_limits<double>::infinity ());
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero ();
  for (const auto& p : local)
    centroid += p;
  centroid /= static_cast<double> (std::max<std::size_t> (1, local.size ()));
  std::size_t next = 0;
  for (std::size_t i = 1; i < local.size (); ++i)
    if ((local[i] - centroid).squaredNorm () < (local[next] - centroid).squaredNorm ())
      next = i;
  std::vector<Eigen::Vector3f> kept;
  const std::size_t wanted = std::min (count, local.size ());
  while (kept.size () < wanted)
  {
    const Eigen::Vector3d newest = local[next];
    kept.push_back (newest.cast<float> ());
    double farthest = -1.0;
    for (std::size_t i = 0; i < local.size (); ++i)
    {
      nearest[i] = std::min (nearest[i], (local[i] - newest).squaredNorm ());
      if (nearest[i] > farthest)
      {
        farthest = nearest[i];
        next = i;
      }
    }
  }
  return kept;
}

std::vector<Eigen::Vector3f>
pointNormals (const std::vector<Eigen::Vector3d>& cloud, const std::vector<Eigen::Vector3f>& at)
{
  std::vector<Eigen::Vector3f> normals;
  normals.reserve (at.size ());
  std::vector<std::pair<double, std::size_t>> near (cloud.size ());
  const std::size_t k = std::min (kNormalNeighbours, cloud.size ());
  for (const Eigen::Vector3f& centre : at)
  {
    const Eigen::Vector3d c = centre.cast<double> ();
    for (std::size_t i = 0; i < cloud.size (); ++i)
      near[i] = {(cloud[i] - c).squaredNorm (), i};
    std::nth_element (near.begin (), near.begin () + static_cast<std::ptrdiff_t> (k - 1), near.end ());
    Eigen::Vector3d mean = Eigen::Vector3d::Zero ();
    for (std::size_t j = 0; j < k; ++j)
      mean += cloud[near[j].second];
    mean /= static_cast<double> (k);
    Eigen::Matrix3d scatter = Eigen::Matrix3d::Zero ();
    for (std::size_t j = 0; j < k; ++j)
    {
      const Eigen::Vector3d d = cloud[near[j].second] - mean;
      scatter += d * d.transpose ();
    }
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver (scatter);
    normals.push_back (solver.eigenvectors ().col (0).normalized ().cast<float> ());
  }
  return normals;
}

Status
describeVisiblePoints (const std::vector<Eigen::Vector3d>& visible, const Eigen::Vector3d& camera, ViewDescription& view)
{
  if (visible.size () < kMinViewPoints)
    return Status::error ("a view needs at least " + std::to_string (kMinViewPoints) + " visible points, this one has " +
                          std::to_string (visible.size ()));
  const std::vector<Eigen::Vector3d> local = toViewFrame (visible, camera, view);
  view.points = farthestPoints (local, kViewPoints);
  view.normals = pointNormals (local, view.points);
  fillHistogram (view);
  return Status::success ();
}

} // namespace internal
} // namespace pcl_flowseg

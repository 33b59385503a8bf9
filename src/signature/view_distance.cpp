/*
 * pcl_flowseg - how far apart two views are: roll search, then iterative closest points; a scan
 * against a complete shape: aligned with its nearest views, refined against its whole surface.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include "view_distance.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>

namespace pcl_flowseg {
namespace internal {

namespace {

/** Rolls about the line of sight tried before the alignment is refined. */
constexpr int kRolls = 12;
/** Points of the moving view the rolls are tried with (a farthest-point prefix: spread evenly). */
constexpr Eigen::Index kRollPoints = 32;
/** Iterations of each closest-point refinement. */
constexpr int kRefinements = 5;
/** Rolls kept per view, refined coarsely: kCoarseRefinements iterations with the first
  * kCoarsePoints of the scan. */
constexpr std::size_t kRollsPerView = 2;
constexpr int kCoarseRefinements = 4;
constexpr Eigen::Index kCoarsePoints = 64;
/** Best coarse starts refined in full, on the view and then on the whole surface. */
constexpr std::size_t kFinishedStarts = 2;


using Points = Eigen::Matrix3Xd;

Points
asMatrix (const std::vector<Eigen::Vector3f>& points)
{
  Points m (3, static_cast<Eigen::Index> (points.size ()));
  for (std::size_t i = 0; i < points.size (); ++i)
    m.col (static_cast<Eigen::Index> (i)) = points[i].cast<double> ();
  return m;
}

/** Share of the squared offset along the surface counted in a distance to a sampled surface: the
  * offset across it counts in full, the offset along it mostly comes from the sampling. */
constexpr double kTangentialShare = 0.1;

/** Points with their unit normals. */
struct Surface
{
  Points points, normals;
};

Surface
asSurface (const std::vector<Eigen::Vector3f>& points, const std::vector<Eigen::Vector3f>& normals)
{
  return {asMatrix (points), asMatrix (normals)};
}

/** For each column of \a from the index of its nearest column of \a to; returns the mean distance,
  * measured across the surface when \a normals (of \a to) are given (see kTangentialShare). */
double
nearestColumns (const Points& from, const Points& to, std::vector<Eigen::Index>& index, const Points* normals = nullptr)
{
  index.resize (static_cast<std::size_t> (from.cols ()));
  double sum = 0.0;
  const double* candidates = to.data (); // x, y, z of each column in turn
  for (Eigen::Index i = 0; i < from.cols (); ++i)
  {
    const double px = from (0, i), py = from (1, i), pz = from (2, i);
    double best = std::numeric_limits<double>::infinity ();
    Eigen::Index nearest = 0;
    for (Eigen::Index j = 0; j < to.cols (); ++j)
    {
      const double dx = candidates[3 * j] - px, dy = candidates[3 * j + 1] - py, dz = candidates[3 * j + 2] - pz;
      const double d = dx * dx + dy * dy + dz * dz;
      if (d < best)
      {
        best = d;
        nearest = j;
      }
    }
    const Eigen::Vector3d p (px, py, pz);
    index[static_cast<std::size_t> (i)] = nearest;
    if (normals)
    {
      const double across = normals->col (nearest).dot (p - to.col (nearest));
      best = across * across + kTangentialShare * (best - across * across);
    }
    sum += std::sqrt (std::max (best, 0.0));
  }
  return from.cols () > 0 ? sum / static_cast<double> (from.cols ()) : 0.0;
}

/** Mean distance from each point of \a moving to the nearest of \a surface plus from each of
  * \a seen to the nearest of \a moving (point to point: for comparing starts). */
double
coverDistance (const Points& moving, const Points& surface, const Points& seen)
{
  std::vector<Eigen::Index> index;
  return nearestColumns (moving, surface, index) + nearestColumns (seen, moving, index);
}

/** Mean distance from each point of \a moving to \a surface, plus from each point of \a seen (the
  * part of the surface the camera saw) to \a moving (along \a moving_normals), both measured
  * across the surfaces. */
double
coverDistance (const Points& moving, const Points& moving_normals, const Surface& surface, const Points& seen)
{
  std::vector<Eigen::Index> index;
  return nearestColumns (moving, surface.points, index, &surface.normals) + nearestColumns (seen, moving, index, &moving_normals);
}

/** \a moving brought onto the surface by closest-point iterations with rotation, translation and
  * scale: each of its points is paired with the nearest of \a surface, each point of \a seen with
  * the nearest of \a moving (so that the scan cannot leave seen parts uncovered). */
Points
refine (Points moving, const Points& surface, const Points& seen, int iterations)
{
  std::vector<Eigen::Index> forward, backward;
  const Eigen::Index n = moving.cols (), m = seen.cols ();
  Points source (3, n + m), target (3, n + m);
  for (int iteration = 0; iteration < iterations; ++iteration)
  {
    nearestColumns (moving, surface, forward);
    nearestColumns (seen, moving, backward);
    for (Eigen::Index i = 0; i < n; ++i)
    {
      source.col (i) = moving.col (i);
      target.col (i) = surface.col (forward[static_cast<std::size_t> (i)]);
    }
    for (Eigen::Index j = 0; j < m; ++j)
    {
      source.col (n + j) = moving.col (backward[static_cast<std::size_t> (j)]);
      target.col (n + j) = seen.col (j);
    }
    const Eigen::Matrix4d transform = Eigen::umeyama (source, target, true);
    moving = (transform.topLeftCorner<3, 3> () * moving).colwise () + transform.topRightCorner<3, 1> ();
  }
  return moving;
}

/** A way to start aligning a scan with a view: a roll about the line of sight (maybe mirrored),
  * and how well it lays the scan on the view (smaller is better). */
struct Start
{
  double distance = std::numeric_limits<double>::infinity ();
  Eigen::Matrix3d roll = Eigen::Matrix3d::Identity ();
  std::size_t view = 0;
};

/** The \a count rolls about the line of sight (and their mirror images) that best lay \a moving
  * onto \a fixed, tried with the first kRollPoints of each, best first. */
std::vector<Start>
bestRolls (const Points& moving, const Points& fixed, std::size_t count)
{
  const Points few = moving.leftCols (std::min (kRollPoints, moving.cols ()));
  const Points few_fixed = fixed.leftCols (std::min (kRollPoints, fixed.cols ()));
  std::vector<Start> starts;
  std::vector<Eigen::Index> index;
  for (int mirror = 0; mirror < 2; ++mirror)
    for (int roll = 0; roll < kRolls; ++roll)
    {
      Start s;
      s.roll = Eigen::AngleAxisd (2.0 * M_PI * roll / kRolls, Eigen::Vector3d::UnitZ ()).toRotationMatrix ();
      if (mirror)
        s.roll.col (1) *= -1.0;
      s.distance = nearestColumns (s.roll * few, fixed, index) + nearestColumns (few_fixed, s.roll * moving, index);
      starts.push_back (s);
    }
  count = std::min (count, starts.size ());
  std::partial_sort (starts.begin (), starts.begin () + static_cast<std::ptrdiff_t> (count), starts.end (),
                     [] (const Start& a, const Start& b) { return a.distance < b.distance; });
  starts.resize (count);
  return starts;
}

/** \a shape's points and normals (input coordinates) in the frame of \a view. */
Surface
inViewFrame (const ViewSet& shape, const ViewDescription& view)
{
  const Eigen::Matrix3d axes = viewAxes (view);
  Surface s = asSurface (shape.shape_points, shape.shape_normals);
  s.points.colwise () -= view.centre.cast<double> ();
  s.points = axes.transpose () * s.points / static_cast<double> (view.scale);
  s.normals = axes.transpose () * s.normals;
  return s;
}

/** The rotation that took \a original to \a aligned (their best fit: the refinements turn, shift
  * and scale, never mirror). */
Eigen::Matrix3d
turnOf (const Points& original, const Points& aligned)
{
  const Eigen::Matrix4d fit = Eigen::umeyama (original, aligned, true);
  Eigen::Matrix3d rotation = fit.topLeftCorner<3, 3> ();
  return rotation / std::cbrt (std::abs (rotation.determinant ()));
}

} // namespace

double
viewHistogramDistance (const ViewDescription& a, const ViewDescription& b)
{
  double sum = 0.0;
  for (std::size_t i = 0; i < kViewHistogramBins; ++i)
    sum += std::abs (static_cast<double> (a.histogram[i]) - b.histogram[i]);
  return sum;
}

double
viewDistance (const ViewDescription& a, const ViewDescription& b)
{
  if (a.points.empty () || b.points.empty ())
    return std::numeric_limits<double>::infinity ();
  const Points moving = asMatrix (a.points), fixed = asMatrix (b.points);
  const Eigen::Matrix3d roll = bestRolls (moving, fixed, 1).front ().roll;
  const Points start = roll * moving;
  const Points aligned = refine (start, fixed, fixed, kRefinements);
  const Points normals = turnOf (start, aligned) * roll * asMatrix (a.normals);
  return coverDistance (aligned, normals, {fixed, asMatrix (b.normals)}, fixed);
}

double
singleViewDistance (const ViewDescription& scan, const ViewSet& shape)
{
  if (scan.points.empty () || shape.views.empty ())
    return std::numeric_limits<double>::infinity ();
  std::vector<std::pair<double, std::size_t>> order;
  order.reserve (shape.views.size ());
  for (std::size_t i = 0; i < shape.views.size (); ++i)
    order.emplace_back (viewHistogramDistance (scan, shape.views[i]), i);
  const std::size_t tried = std::min (kAlignedViews, order.size ());
  std::partial_sort (order.begin (), order.begin () + static_cast<std::ptrdiff_t> (tried), order.end ());
  const Points moving = asMatrix (scan.points), moving_normals = asMatrix (scan.normals);
  // Coarse: the best rolls onto each of the nearest views, each refined a little on its view.
  std::vector<Start> starts;
  const Points coarse = moving.leftCols (std::min (kCoarsePoints, moving.cols ()));
  for (std::size_t k = 0; k < tried; ++k)
  {
    const Points seen = asMatrix (shape.views[order[k].second].points);
    for (Start s : bestRolls (moving, seen, kRollsPerView))
    {
      s.view = order[k].second;
      const Points aligned = refine (s.roll * coarse, seen, seen, kCoarseRefinements);
      s.distance = coverDistance (aligned, seen, seen);
      starts.push_back (s);
    }
  }
  const std::size_t finished = std::min (kFinishedStarts, starts.size ());
  std::partial_sort (starts.begin (), starts.begin () + static_cast<std::ptrdiff_t> (finished), starts.end (),
                     [] (const Start& a, const Start& b) { return a.distance < b.distance; });
  // Fine: the best starts refined on the view, then on the whole surface (the view was rendered
  // from a direction near the scan's, not from it).
  double best = std::numeric_limits<double>::infinity ();
  for (std::size_t k = 0; k < finished; ++k)
  {
    const ViewDescription& view = shape.views[starts[k].view];
    const Surface seen = asSurface (view.points, view.normals);
    const Surface surface = shape.shape_points.empty () ? seen : inViewFrame (shape, view);
    const Points start = starts[k].roll * moving;
    const Points aligned = refine (refine (start, seen.points, seen.points, kRefinements), surface.points, seen.points, kRefinements);
    best = std::min (best, coverDistance (aligned, turnOf (start, aligned) * starts[k].roll * moving_normals, surface, seen.points));
  }
  return best;
}

} // namespace internal
} // namespace pcl_flowseg

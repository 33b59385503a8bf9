/*
 * Outlier removal: isolated points (NoiseEstimate::isolated_share) and points detached from the
 * surface (::detached_share) are found, left out when asked or when the sample shows them, counted,
 * and labelled no segment; clean and noisy samples are left alone.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include "core/preparation/detached_points.h"
#include "test_support.h"

#include <pcl_flowseg/common/feature_significance.h>
#include <pcl_flowseg/io/sample_outliers.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <random>

using namespace pcl_flowseg;
using flowseg_test::shapeSample;

namespace {

/** \a count points uniform in a box three times the size of the sample's bounding box, same centre. */
std::vector<Eigen::Vector3d>
farPoints (const std::vector<Eigen::Vector3d>& sample, std::size_t count, bool planar)
{
  Eigen::Vector3d lo = sample.front (), hi = sample.front ();
  for (const auto& p : sample)
  {
    lo = lo.cwiseMin (p);
    hi = hi.cwiseMax (p);
  }
  const Eigen::Vector3d centre = 0.5 * (lo + hi), half = 1.5 * (hi - lo);
  std::mt19937 rng (11);
  std::uniform_real_distribution<double> u (-1.0, 1.0);
  std::vector<Eigen::Vector3d> out;
  while (out.size () < count)
  {
    const Eigen::Vector3d p = centre + Eigen::Vector3d (u (rng) * half.x (), u (rng) * half.y (), planar ? 0.0 : u (rng) * half.z ());
    if (((p - centre).array ().abs () > 0.5 * (hi - lo).array () + 1e-9).any ()) // outside the sample's box
      out.push_back (p);
  }
  return out;
}

/** \a clean followed by \a count far points (farPoints). */
std::vector<Eigen::Vector3d>
withFarPoints (const std::vector<Eigen::Vector3d>& clean, std::size_t count, bool planar)
{
  std::vector<Eigen::Vector3d> pts = clean;
  const std::vector<Eigen::Vector3d> far = farPoints (clean, count, planar);
  pts.insert (pts.end (), far.begin (), far.end ());
  return pts;
}

FlowResult
segmentWith (const std::vector<Eigen::Vector3d>& pts, OutlierRemoval mode)
{
  return flowseg_test::segmentWith (pts, [mode] (FlowParameters& p) { p.preparation.outliers = mode; });
}

/** Input points from \a first on labelled no segment. */
std::size_t
unlabelledFrom (const FlowResult& r, std::size_t first)
{
  std::size_t n = 0;
  for (std::size_t i = first; i < r.point_labels.size (); ++i)
    n += r.point_labels[i] == kNoSegment;
  return n;
}

/** Distance from \a p to the nearest of \a points other than \a p itself (brute force). */
double
nearestDistance (const Eigen::Vector3d& p, const std::vector<Eigen::Vector3d>& points)
{
  double best = std::numeric_limits<double>::infinity ();
  for (const auto& q : points)
    if (q != p)
      best = std::min (best, (q - p).norm ());
  return best;
}

/** The median over \a points of the distance to the nearest other point. */
double
medianSpacing (const std::vector<Eigen::Vector3d>& points)
{
  std::vector<double> d;
  for (const auto& p : points)
    d.push_back (nearestDistance (p, points));
  std::nth_element (d.begin (), d.begin () + static_cast<long> (d.size () / 2), d.end ());
  return d[d.size () / 2];
}

/** A square grid of \a side x \a side points, spacing 1, in the plane z = 0. */
std::vector<Eigen::Vector3d>
gridPlane (int side)
{
  std::vector<Eigen::Vector3d> pts;
  for (int i = 0; i < side; ++i)
    for (int j = 0; j < side; ++j)
      pts.emplace_back (i, j, 0.0);
  return pts;
}

} // namespace

TEST (OutlierRemoval, PointsOffAPlaneAreDetachedAndPointsOnItAreNot)
{
  std::vector<Eigen::Vector3d> pts = gridPlane (30);
  pts.emplace_back (14.5, 14.5, 2.5);  // 2.5 spacings above the plane
  pts.emplace_back (5.5, 20.5, -1.5);  // 1.5 below
  pts.emplace_back (20.5, 5.5, 0.4);   // within the plane's noise band: kept
  const std::vector<char> detached = core::detachedPoints (pts, 3);
  const std::size_t grid = 900;
  EXPECT_EQ (std::count (detached.begin (), detached.begin () + grid, 1), 0) << "no grid point";
  EXPECT_EQ (detached[grid], 1);
  EXPECT_EQ (detached[grid + 1], 1);
  EXPECT_EQ (detached[grid + 2], 0);
}

TEST (OutlierRemoval, CurvePointsAndCornersAreNotDetached)
{
  std::vector<Eigen::Vector3d> pts; // the outline of a 50 x 50 square, spacing 1
  for (int i = 0; i < 50; ++i)
  {
    pts.emplace_back (i, 0, 0);
    pts.emplace_back (50, i, 0);
    pts.emplace_back (50 - i, 50, 0);
    pts.emplace_back (0, 50 - i, 0);
  }
  pts.emplace_back (25, 3, 0); // 3 spacings inside, next to the bottom side
  const std::vector<char> detached = core::detachedPoints (pts, 2);
  EXPECT_EQ (std::count (detached.begin (), detached.end () - 1, 1), 0) << "corners included";
  EXPECT_EQ (detached.back (), 1);
}

TEST (OutlierRemoval, CleanSampleIsLeftAlone)
{
  const FlowResult r = segmentWith (shapeSample ("snowman3d", 3000), OutlierRemoval::Automatic);
  EXPECT_LE (r.noise.isolated_share, kIsolatedShare);
  EXPECT_EQ (r.noise.detached_share, 0.0);
  EXPECT_EQ (r.outlier_points, 0u);
  EXPECT_EQ (r.vertices.size (), 3000u);
}

TEST (OutlierRemoval, AutomaticModeRemovesIsolatedPointsAndKeepsTheParts)
{
  const std::vector<Eigen::Vector3d> clean = shapeSample ("snowman3d", 3000);
  std::vector<Eigen::Vector3d> pts = withFarPoints (clean, 30, false);
  pts.push_back (pts[clean.size ()]); // a duplicate of an outlier: left out with it

  const FlowResult kept = segmentWith (pts, OutlierRemoval::Off);
  EXPECT_GT (kept.noise.isolated_share, kIsolatedShare);
  EXPECT_EQ (kept.outlier_points, 0u);
  EXPECT_EQ (kept.vertices.size (), 3030u);

  const FlowResult removed = segmentWith (pts, OutlierRemoval::Automatic);
  EXPECT_EQ (removed.noise.isolated_share, kept.noise.isolated_share);
  EXPECT_GE (unlabelledFrom (removed, clean.size ()), 26u) << "most far points left out";
  EXPECT_EQ (removed.point_labels.back (), kNoSegment);
  EXPECT_LE (removed.outlier_points, 31u + 30u) << "few surface points taken with them";
  EXPECT_EQ (removed.vertices.size () + removed.outlier_points, kept.vertices.size () + 1) << "the duplicate counts as a point";
  const FlowResult reference = segmentWith (clean, OutlierRemoval::Off);
  EXPECT_EQ (significantSegments (removed, removed.features, 0.01).size (),
             significantSegments (reference, reference.features, 0.01).size ());
}

TEST (OutlierRemoval, OutliersInsideAndNearTheShapeAreLeftOut)
{
  const std::vector<Eigen::Vector3d> clean = shapeSample ("snowman3d", 3000);
  std::vector<Eigen::Vector3d> pts = clean;
  replaceWithOutliers (pts, 0.02, 3); // 60 points uniform in the bounding box, many inside the snowman
  std::vector<Eigen::Vector3d> surface;
  std::vector<std::size_t> outliers;
  for (std::size_t i = 0; i < pts.size (); ++i)
    if (pts[i] == clean[i])
      surface.push_back (pts[i]);
    else
      outliers.push_back (i);
  ASSERT_EQ (outliers.size (), 60u);

  const FlowResult kept = segmentWith (pts, OutlierRemoval::Off);
  EXPECT_GT (kept.noise.detached_share, kDetachedShare);
  const FlowResult r = segmentWith (pts, OutlierRemoval::Automatic);
  const double spacing = medianSpacing (surface);
  std::size_t off_surface = 0, kept_off_surface = 0; // more than 3 spacings (nearest neighbour) off
  for (std::size_t i : outliers)
  {
    const double off = nearestDistance (pts[i], surface) / spacing;
    if (off > 3.0)
    {
      ++off_surface;
      kept_off_surface += r.point_labels[i] != kNoSegment;
    }
    if (off > 5.0)
      EXPECT_EQ (r.point_labels[i], kNoSegment) << "outlier " << i << " lies " << off << " spacings off the surface";
  }
  EXPECT_GE (off_surface, 40u);
  // PCL's statistical filter alone keeps 6 of the 42 here (most within 5 spacings, inside the snowman).
  EXPECT_LE (kept_off_surface, off_surface / 20) << "outliers near the surface, inside and out, left out too";
  std::size_t surface_left_out = 0;
  for (std::size_t i = 0; i < pts.size (); ++i)
    surface_left_out += pts[i] == clean[i] && r.point_labels[i] == kNoSegment;
  EXPECT_LE (surface_left_out, 10u) << "few surface points taken with them";
  const FlowResult reference = segmentWith (clean, OutlierRemoval::Off);
  EXPECT_EQ (significantSegments (r, r.features, 0.01).size (), significantSegments (reference, reference.features, 0.01).size ());
}

TEST (OutlierRemoval, NoisySampleIsLeftAlone)
{
  std::vector<Eigen::Vector3d> pts = shapeSample ("snowman3d", 3000);
  Eigen::Vector3d lo = pts.front (), hi = pts.front ();
  for (const auto& p : pts)
    lo = lo.cwiseMin (p), hi = hi.cwiseMax (p);
  std::mt19937 rng (5);
  std::normal_distribution<double> g (0.0, 0.005 * (hi - lo).norm ());
  for (auto& p : pts)
    p += Eigen::Vector3d (g (rng), g (rng), g (rng));
  const FlowResult r = segmentWith (pts, OutlierRemoval::Automatic);
  EXPECT_LE (r.noise.detached_share, kDetachedShare);
  EXPECT_EQ (r.outlier_points, 0u);
}

TEST (OutlierRemoval, PlanarSampleCompactsItsPlaneCoordinates)
{
  const std::vector<Eigen::Vector3d> clean = shapeSample ("dumbbell2d", 1500);
  const std::vector<Eigen::Vector3d> pts = withFarPoints (clean, 15, true);
  const FlowResult r = segmentWith (pts, OutlierRemoval::Always);
  EXPECT_EQ (r.dimension, 2);
  EXPECT_GE (unlabelledFrom (r, clean.size ()), 13u);
  EXPECT_EQ (r.vertices.size () + r.outlier_points, pts.size ());
  for (const FlowCell& cell : r.cells)
    for (int i = 0; i < 3; ++i)
      ASSERT_LT (static_cast<std::size_t> (cell.vertices[i]), r.vertices.size ());
}

TEST (OutlierRemoval, AutomaticModeNeedsMoreThanOneOrTwoIsolatedPoints)
{
  const std::vector<Eigen::Vector3d> clean = shapeSample ("dumbbell2d", 600);
  const std::vector<Eigen::Vector3d> pts = withFarPoints (clean, 2, true);
  const FlowResult automatic = segmentWith (pts, OutlierRemoval::Automatic);
  EXPECT_GT (automatic.noise.isolated_share, kIsolatedShare) << "seen";
  EXPECT_EQ (automatic.outlier_points, 0u) << "but too few to act on";
  const FlowResult forced = segmentWith (pts, OutlierRemoval::Always);
  EXPECT_GE (forced.outlier_points, 2u);
}

TEST (OutlierRemoval, UnknownModeIsRefused)
{
  FlowParameters params;
  params.preparation.outliers = static_cast<OutlierRemoval> (7);
  const Status s = checkParameters (params);
  EXPECT_FALSE (s.ok);
  EXPECT_NE (s.message.find ("outlier"), std::string::npos);
}

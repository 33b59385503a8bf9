/*
 * Outlier removal: isolated points are found (NoiseEstimate::isolated_share), left out when asked or
 * when the sample shows them, counted, and labelled no segment; clean samples are left alone.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include "test_support.h"

#include <pcl_flowseg/common/feature_significance.h>

#include <gtest/gtest.h>

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

} // namespace

TEST (OutlierRemoval, CleanSampleIsLeftAlone)
{
  const FlowResult r = segmentWith (shapeSample ("snowman3d", 3000), OutlierRemoval::Automatic);
  EXPECT_LE (r.noise.isolated_share, kIsolatedShare);
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

/*
 * Smoothing before the triangulation (PreparationParameters::smoothing): automatic on rough samples
 * only, fewer noise maxima with the parts kept, thin walls keep their two sides, 2D samples left
 * alone, absurd settings refused.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include "core/geometry/point_neighbourhoods.h"
#include "core/interior/denoising.h"
#include "core/preparation/noise_estimate.h"
#include "core/preparation/sample_smoothing.h"
#include "test_support.h"

#include <pcl_flowseg/common/feature_significance.h>

#include <gtest/gtest.h>

#include <random>

using namespace pcl_flowseg;
using flowseg_test::shapeSample;

namespace {

/** \a pts with Gaussian noise of \a share of their bounding-box diagonal added to every coordinate. */
std::vector<Eigen::Vector3d>
withNoise (std::vector<Eigen::Vector3d> pts, double share)
{
  Eigen::Vector3d lo = pts.front (), hi = pts.front ();
  for (const auto& p : pts)
  {
    lo = lo.cwiseMin (p);
    hi = hi.cwiseMax (p);
  }
  std::mt19937 rng (5);
  std::normal_distribution<double> g (0.0, share * (hi - lo).norm ());
  for (auto& p : pts)
    p += Eigen::Vector3d (g (rng), g (rng), g (rng));
  return pts;
}

FlowResult
segmentWithSmoothing (const std::vector<Eigen::Vector3d>& pts, Smoothing mode, unsigned passes = 6)
{
  return flowseg_test::segmentWith (pts, [mode, passes] (FlowParameters& p) {
    p.preparation.smoothing = mode;
    p.preparation.smoothing_passes = passes;
  });
}

/** The two large faces of a thin closed slab [0,1]^2 x [0, thickness]: \a n points on each, with
  * Gaussian noise of \a sigma along the normal. */
std::vector<Eigen::Vector3d>
noisySlabFaces (std::size_t n, double thickness, double sigma)
{
  std::mt19937 rng (11);
  std::uniform_real_distribution<double> u (0.0, 1.0);
  std::normal_distribution<double> g (0.0, sigma);
  std::vector<Eigen::Vector3d> pts;
  for (std::size_t i = 0; i < 2 * n; ++i)
    pts.emplace_back (u (rng), u (rng), (i < n ? 0.0 : thickness) + g (rng));
  return pts;
}

/** Mean z of the second half of \a pts minus that of the first half (the slab's two faces). */
double
faceDistance (const std::vector<Eigen::Vector3d>& pts)
{
  const std::size_t n = pts.size () / 2;
  double bottom = 0.0, top = 0.0;
  for (std::size_t i = 0; i < n; ++i)
  {
    bottom += pts[i].z ();
    top += pts[n + i].z ();
  }
  return (top - bottom) / static_cast<double> (n);
}

} // namespace

TEST (Presmoothing, NoisySampleIsSmoothedAutomaticallyAndKeepsItsParts)
{
  const std::vector<Eigen::Vector3d> clean = shapeSample ("snowman3d", 3000);
  const std::vector<Eigen::Vector3d> noisy = withNoise (clean, 0.005);
  const FlowResult reference = segmentWithSmoothing (clean, Smoothing::Off);
  const FlowResult raw = segmentWithSmoothing (noisy, Smoothing::Off);
  const FlowResult smoothed = segmentWithSmoothing (noisy, Smoothing::Automatic);
  EXPECT_GT (smoothed.noise.roughness, kRoughSample);
  EXPECT_GE (smoothed.smoothing_passes, 1u);
  EXPECT_LE (smoothed.smoothing_passes, 6u);
  EXPECT_EQ (raw.smoothing_passes, 0u);
  EXPECT_LT (2 * smoothed.maxima.size (), raw.maxima.size ());
  EXPECT_EQ (significantSegments (smoothed, smoothed.features, 0.02).size (),
             significantSegments (reference, reference.features, 0.02).size ());
  ASSERT_EQ (smoothed.vertices.size (), raw.vertices.size ());
  EXPECT_NE (smoothed.vertices, raw.vertices) << "the vertices are the smoothed positions";
}

TEST (Presmoothing, CleanSamplesAreNotSmoothedAutomatically)
{
  for (const char* shape : {"snowman3d", "animal3d", "dumbbell3d"})
  {
    const std::vector<Eigen::Vector3d> pts = shapeSample (shape, 3000);
    const FlowResult automatic = segmentWithSmoothing (pts, Smoothing::Automatic);
    const FlowResult off = segmentWithSmoothing (pts, Smoothing::Off);
    EXPECT_LT (automatic.noise.roughness, kRoughSample) << shape;
    EXPECT_EQ (automatic.smoothing_passes, 0u) << shape;
    EXPECT_EQ (automatic.vertices, off.vertices) << shape;
  }
}

TEST (Presmoothing, AlwaysMakesExactlyThePassesAsked)
{
  const std::vector<Eigen::Vector3d> noisy = withNoise (shapeSample ("snowman3d", 2000), 0.005);
  const FlowResult one = segmentWithSmoothing (noisy, Smoothing::Always, 1);
  const FlowResult eight = segmentWithSmoothing (noisy, Smoothing::Always, kMaxSmoothingPasses);
  EXPECT_EQ (one.smoothing_passes, 1u);
  EXPECT_EQ (eight.smoothing_passes, kMaxSmoothingPasses);
  EXPECT_EQ (eight.parameters.preparation.smoothing, Smoothing::Always);
}

TEST (Presmoothing, ThinWallKeepsItsTwoSides)
{
  // Faces 2.3 sample spacings apart: a 16-point neighbourhood reaches across the wall.
  const double thickness = 0.05, sigma = 0.003;
  std::vector<Eigen::Vector3d> pts = noisySlabFaces (2000, thickness, sigma);
  const NoiseEstimate noise = core::estimateNoise (pts, 3);
  std::vector<Eigen::Vector3d> projected = pts;
  const core::Neighbourhoods hoods = core::nearestNeighbourhoods (projected);
  for (int pass = 0; pass < 3; ++pass)
    projected = core::smoothPoints (projected, hoods, 3);
  PreparationParameters params;
  params.smoothing = Smoothing::Always;
  params.smoothing_passes = 3;
  ASSERT_EQ (core::smoothSample (pts, noise, params), 3u);
  EXPECT_LT (faceDistance (projected), 0.8 * thickness) << "a plain projection pulls the faces together";
  EXPECT_GT (faceDistance (pts), 0.9 * thickness);
  double spread = 0.0;
  for (std::size_t i = 2000; i < pts.size (); ++i)
    spread += (pts[i].z () - thickness) * (pts[i].z () - thickness);
  EXPECT_LT (std::sqrt (spread / 2000.0), 0.8 * sigma) << "the noise is reduced";
}

TEST (Presmoothing, TinyNoiseScaleLeavesTheVerticesFinite)
{
  std::vector<Eigen::Vector3d> pts = noisySlabFaces (500, 0.05, 0.003);
  NoiseEstimate noise;
  noise.sigma = 1e-300;
  PreparationParameters params;
  params.smoothing = Smoothing::Always;
  params.smoothing_passes = 2;
  const std::vector<Eigen::Vector3d> before = pts;
  ASSERT_EQ (core::smoothSample (pts, noise, params), 2u);
  for (std::size_t i = 0; i < pts.size (); ++i)
  {
    ASSERT_TRUE (pts[i].allFinite ()) << i;
    EXPECT_LT ((pts[i] - before[i]).norm (), 1e-12) << "offsets far beyond the scale weigh nothing";
  }
}

TEST (Presmoothing, PlanarSampleIsNotSmoothedAndSaysSoWhenAsked)
{
  const std::vector<Eigen::Vector3d> pts = shapeSample ("hand2d", 800);
  const FlowResult automatic = segmentWithSmoothing (pts, Smoothing::Automatic);
  const FlowResult asked = segmentWithSmoothing (pts, Smoothing::Always, 2);
  EXPECT_EQ (asked.dimension, 2);
  EXPECT_EQ (asked.vertices, automatic.vertices);
  EXPECT_EQ (asked.smoothing_passes, 0u);
  const auto warns = [] (const FlowResult& r) {
    for (const std::string& w : r.warnings)
      if (w.find ("3D samples only") != std::string::npos)
        return true;
    return false;
  };
  EXPECT_TRUE (warns (asked));
  EXPECT_FALSE (warns (automatic));
}

TEST (Presmoothing, AbsurdSettingsAreRefused)
{
  for (unsigned passes : {0u, kMaxSmoothingPasses + 1})
  {
    FlowParameters params;
    params.preparation.smoothing_passes = passes;
    const Status s = checkParameters (params);
    EXPECT_FALSE (s.ok) << passes;
    EXPECT_NE (s.message.find ("smoothing passes"), std::string::npos);
  }
  FlowParameters params;
  params.preparation.smoothing = static_cast<Smoothing> (5);
  EXPECT_FALSE (checkParameters (params).ok);
}

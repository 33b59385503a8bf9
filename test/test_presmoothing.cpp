/*
 * Smoothing before the triangulation (PreparationParameters::smoothing_passes): fewer noise maxima,
 * the parts kept, 2D samples left alone with a warning, absurd counts refused.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
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
segmentWithPasses (const std::vector<Eigen::Vector3d>& pts, unsigned passes)
{
  return flowseg_test::segmentWith (pts, [passes] (FlowParameters& p) { p.preparation.smoothing_passes = passes; });
}

} // namespace

TEST (Presmoothing, NoisySampleLosesItsNoiseMaximaAndKeepsItsParts)
{
  const std::vector<Eigen::Vector3d> clean = shapeSample ("snowman3d", 3000);
  const std::vector<Eigen::Vector3d> noisy = withNoise (clean, 0.005);
  const FlowResult reference = segmentWithPasses (clean, 0);
  const FlowResult raw = segmentWithPasses (noisy, 0);
  const FlowResult smoothed = segmentWithPasses (noisy, 2);
  EXPECT_LT (2 * smoothed.maxima.size (), raw.maxima.size ());
  EXPECT_EQ (significantSegments (smoothed, smoothed.features, 0.02).size (),
             significantSegments (reference, reference.features, 0.02).size ());
  EXPECT_EQ (smoothed.parameters.preparation.smoothing_passes, 2u);
  ASSERT_EQ (smoothed.vertices.size (), raw.vertices.size ());
  EXPECT_NE (smoothed.vertices, raw.vertices) << "the vertices are the smoothed positions";
}

TEST (Presmoothing, PlanarSampleIsNotSmoothedAndSaysSo)
{
  const std::vector<Eigen::Vector3d> pts = shapeSample ("hand2d", 800);
  const FlowResult plain = segmentWithPasses (pts, 0);
  const FlowResult asked = segmentWithPasses (pts, 2);
  EXPECT_EQ (asked.dimension, 2);
  EXPECT_EQ (asked.vertices, plain.vertices);
  bool warned = false;
  for (const std::string& w : asked.warnings)
    warned = warned || w.find ("3D samples only") != std::string::npos;
  EXPECT_TRUE (warned);
}

TEST (Presmoothing, TooManyPassesAreRefused)
{
  FlowParameters params;
  params.preparation.smoothing_passes = kMaxSmoothingPasses + 1;
  const Status s = checkParameters (params);
  EXPECT_FALSE (s.ok);
  EXPECT_NE (s.message.find ("smoothing passes"), std::string::npos);
}

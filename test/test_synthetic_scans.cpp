/*
 * Synthetic sensor input: the virtual range scanner, outliers, and the noise estimate of a run.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include "test_support.h"

#include <pcl_flowseg/io/range_scan.h>
#include <pcl_flowseg/io/sample_outliers.h>
#include <pcl_flowseg/segmentation/flow_pipeline.h>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

using namespace pcl_flowseg;
using V = Eigen::Vector3d;

namespace {

/** Appends the 12 triangles of the axis-aligned cube of half side \a half around \a centre. */
void
addCube (TriangleMesh& mesh, const V& centre, double half)
{
  const int base = static_cast<int> (mesh.vertices.size ());
  for (int i = 0; i < 8; ++i)
    mesh.vertices.push_back (centre + half * V (i & 1 ? 1 : -1, i & 2 ? 1 : -1, i & 4 ? 1 : -1));
  const int quads[6][4] = {{0, 1, 3, 2}, {4, 6, 7, 5}, {0, 4, 5, 1}, {2, 3, 7, 6}, {0, 2, 6, 4}, {1, 5, 7, 3}};
  for (const auto& q : quads)
  {
    mesh.faces.push_back ({base + q[0], base + q[1], base + q[2]});
    mesh.faces.push_back ({base + q[0], base + q[2], base + q[3]});
  }
}

RangeScanOptions
scanFrom (const V& viewpoint, std::size_t points, double depth_noise = 0.0)
{
  RangeScanOptions o;
  o.viewpoint = viewpoint;
  o.points = points;
  o.depth_noise = depth_noise;
  return o;
}

} // namespace

TEST (RangeScan, SeesOnlyTheFacesTurnedToTheSensor)
{
  TriangleMesh cube;
  addCube (cube, V::Zero (), 1.0);
  for (const V& axis : {V (0, 0, 1), V (-1, 0, 0), V (0, 1, 0)})
  {
    std::vector<V> pts;
    ASSERT_TRUE (scanMesh (cube, scanFrom (10.0 * axis, 2000), pts).ok);
    EXPECT_EQ (pts.size (), 2000u);
    for (const V& p : pts)
    {
      EXPECT_NEAR (p.dot (axis), 1.0, 1e-9) << p.transpose ();
      EXPECT_LE (p.cwiseAbs ().maxCoeff (), 1.0 + 1e-9);
    }
  }
}

TEST (RangeScan, NearerSurfacesHideFartherOnes)
{
  TriangleMesh mesh;
  addCube (mesh, V::Zero (), 1.0);
  addCube (mesh, V (0, 0, 3), 0.5);
  std::vector<V> pts;
  ASSERT_TRUE (scanMesh (mesh, scanFrom (V (0, 0, 12), 5000), pts).ok);
  std::size_t on_small = 0;
  for (const V& p : pts)
    if (std::abs (p.x ()) < 0.45 && std::abs (p.y ()) < 0.45)
    {
      EXPECT_NEAR (p.z (), 3.5, 1e-9) << "the small cube hides the big one's top here";
      ++on_small;
    }
    else if (std::abs (p.x ()) > 0.55 || std::abs (p.y ()) > 0.55)
      EXPECT_NEAR (p.z (), 1.0, 1e-9);
  EXPECT_GT (on_small, 100u);
}

TEST (RangeScan, DepthNoiseMovesPointsAlongTheRays)
{
  TriangleMesh cube;
  addCube (cube, V::Zero (), 1.0);
  const double share = 0.002, diagonal = cube.diagonal ();
  std::vector<V> pts;
  ASSERT_TRUE (scanMesh (cube, scanFrom (V (0, 0, 10), 4000, share), pts).ok);
  double sum = 0.0, sum2 = 0.0;
  for (const V& p : pts)
  {
    sum += p.z () - 1.0;
    sum2 += (p.z () - 1.0) * (p.z () - 1.0);
  }
  const double n = static_cast<double> (pts.size ()), sd = std::sqrt (sum2 / n - (sum / n) * (sum / n));
  // Range about 9 against 10 to the centre: sigma about 0.81 of share * diagonal.
  EXPECT_GT (sd, 0.7 * share * diagonal);
  EXPECT_LT (sd, 0.95 * share * diagonal);
  EXPECT_NEAR (sum / n, 0.0, 0.1 * share * diagonal);
}

TEST (RangeScan, BadOptionsAreRefused)
{
  TriangleMesh cube;
  addCube (cube, V::Zero (), 1.0);
  std::vector<V> pts{V::Zero ()};
  const double nan = std::numeric_limits<double>::quiet_NaN ();
  const Status inside = scanMesh (cube, scanFrom (V (0.5, 0, 0), 100), pts);
  EXPECT_FALSE (inside.ok);
  EXPECT_NE (inside.message.find ("outside"), std::string::npos) << inside.message;
  EXPECT_TRUE (pts.empty ());
  EXPECT_FALSE (scanMesh (cube, scanFrom (V (nan, 0, 10), 100), pts).ok);
  EXPECT_FALSE (scanMesh (cube, scanFrom (V (0, 0, 10), 3), pts).ok);
  EXPECT_FALSE (scanMesh (cube, scanFrom (V (0, 0, 10), 100, -0.1), pts).ok);
  EXPECT_FALSE (scanMesh (TriangleMesh (), scanFrom (V (0, 0, 10), 100), pts).ok);
}

TEST (Outliers, ReplaceTheGivenShareInsideTheBox)
{
  const auto clean = flowseg_test::randomPoints (1000, 3, 4);
  auto pts = clean;
  EXPECT_EQ (replaceWithOutliers (pts, 0.02, 9), 20u);
  std::size_t changed = 0;
  for (std::size_t i = 0; i < pts.size (); ++i)
  {
    changed += pts[i] != clean[i];
    EXPECT_LE (pts[i].cwiseAbs ().maxCoeff (), 1.0);
  }
  EXPECT_EQ (changed, 20u);
  EXPECT_EQ (replaceWithOutliers (pts, 0.0, 9), 0u);
}

TEST (NoiseEstimate, ReadsTheNoiseOfASphereSample)
{
  std::mt19937 rng (3);
  std::normal_distribution<double> gauss (0.0, 1.0);
  const double sigma = 0.01;
  std::vector<V> clean, noisy;
  for (int i = 0; i < 6000; ++i)
  {
    const V p = V (gauss (rng), gauss (rng), gauss (rng)).normalized ();
    clean.push_back (p);
    noisy.push_back (p + sigma * V (gauss (rng), gauss (rng), gauss (rng)));
  }
  FlowParameters params;
  params.interior.separate = false;
  FlowResult a, b;
  ASSERT_TRUE (runFlowSegmentation (clean, params, a).ok);
  ASSERT_TRUE (runFlowSegmentation (noisy, params, b).ok);
  EXPECT_LT (a.noise.sigma, 0.2 * sigma);
  EXPECT_GT (b.noise.sigma, 0.6 * sigma);
  EXPECT_LT (b.noise.sigma, 1.3 * sigma);
  // The bounding box of a unit sphere sample: diagonal about 2 sqrt 3.
  EXPECT_NEAR (b.noise.share * 2.0 * std::sqrt (3.0), b.noise.sigma, 0.05 * b.noise.sigma);
  EXPECT_EQ (b.noise.points_used, 3000u) << "every second of the 6000 vertices: at most kNoiseEstimatePoints";
}

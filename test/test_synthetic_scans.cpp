/*
 * Synthetic sensor input: the virtual range scanner (and its camera mode, the single-view protocol),
 * outliers, and the noise estimate of a run.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include "test_support.h"

#include <pcl_flowseg/io/range_scan.h>
#include <pcl_flowseg/io/sample_outliers.h>
#include <pcl_flowseg/io/scan_protocol.h>
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

namespace {

/** A camera-mode scan of \a mesh: \a pixels x \a pixels, \a fov degrees, from \a viewpoint. */
RangeScanOptions
cameraAt (const V& viewpoint, std::size_t pixels, double fov, double depth_noise = 0.0,
          DepthNoiseModel model = DepthNoiseModel::kConstant)
{
  RangeScanOptions o = scanFrom (viewpoint, 10000, depth_noise);
  o.image_pixels = pixels;
  o.field_of_view = fov;
  o.noise_model = model;
  return o;
}

/** The standard deviation and mean of each point's range minus the range of its ray's hit on
  * the plane z = \a plane_z (the camera above it, at \a eye). */
std::pair<double, double>
rangeResiduals (const std::vector<V>& pts, const V& eye, double plane_z)
{
  double sum = 0.0, sum2 = 0.0;
  for (const V& p : pts)
  {
    const V dir = (p - eye).normalized ();
    const double r = (p - eye).norm () - (plane_z - eye.z ()) / dir.z ();
    sum += r;
    sum2 += r * r;
  }
  const double n = static_cast<double> (pts.size ());
  return {std::sqrt (sum2 / n - (sum / n) * (sum / n)), sum / n};
}

} // namespace

TEST (RangeScanCamera, EveryPixelReturnsItsFirstHit)
{
  TriangleMesh cube;
  addCube (cube, V::Zero (), 1.0);
  // A 5-degree view from 10 above sees only the top face, which fills the whole image.
  std::vector<V> pts;
  ASSERT_TRUE (scanMesh (cube, cameraAt (V (0, 0, 10), 240, 5.0), pts).ok);
  ASSERT_EQ (pts.size (), 240u * 240u);
  const double half = 9.0 * std::tan (2.5 * M_PI / 180.0);
  double reach = 0.0;
  for (const V& p : pts)
  {
    EXPECT_NEAR (p.z (), 1.0, 1e-9);
    reach = std::max (reach, p.head<2> ().cwiseAbs ().maxCoeff ());
  }
  EXPECT_LE (reach, half);
  EXPECT_GT (reach, half * (1.0 - 2.0 / 240.0)) << "the outermost pixel centres lie half a pixel inside the image";
  // Points are ignored in camera mode; the field of view alone still chooses the grid from them.
  RangeScanOptions o = cameraAt (V (0, 0, 10), 100, 5.0);
  o.points = 0;
  ASSERT_TRUE (scanMesh (cube, o, pts).ok);
  EXPECT_EQ (pts.size (), 100u * 100u);
  o.image_pixels = 0;
  o.points = 2000;
  ASSERT_TRUE (scanMesh (cube, o, pts).ok);
  EXPECT_EQ (pts.size (), 2000u);
}

TEST (RangeScanCamera, NearerSurfacesHideFartherOnes)
{
  TriangleMesh mesh;
  addCube (mesh, V::Zero (), 1.0);
  addCube (mesh, V (0, 0, 3), 0.5);
  std::vector<V> pts;
  ASSERT_TRUE (scanMesh (mesh, cameraAt (V (0, 0, 12), 240, 30.0), pts).ok);
  EXPECT_LT (pts.size (), 240u * 240u);
  std::size_t on_small = 0;
  for (const V& p : pts)
    if (std::abs (p.x ()) < 0.45 && std::abs (p.y ()) < 0.45)
    {
      EXPECT_NEAR (p.z (), 3.5, 1e-9);
      ++on_small;
    }
  EXPECT_GT (on_small, 1000u);
}

TEST (RangeScanCamera, TheProtocolScanSeesOnlyWhatLiesInItsViewAndFacesIt)
{
  TriangleMesh cube;
  addCube (cube, V (3, -1, 2), 1.0);
  const V centre (3, -1, 2);
  const double diagonal = cube.diagonal ();
  // The image is square: its corners lie atan (sqrt 2 tan 25 degrees) off the axis.
  const double widest = std::atan (std::sqrt (2.0) * std::tan (25.0 * M_PI / 180.0));
  for (std::uint32_t seed : {1u, 2u, 3u, 4u, 5u})
  {
    const RangeScanOptions o = singleViewProtocolScan (cube, 0.0, seed);
    EXPECT_NEAR ((o.viewpoint - centre).norm (), 2.0 * diagonal, 1e-9 * diagonal);
    EXPECT_EQ (o.image_pixels, 240u);
    EXPECT_EQ (o.field_of_view, 50.0);
    EXPECT_EQ (o.noise_model, DepthNoiseModel::kConstant);
    std::vector<V> pts;
    std::vector<int> faces;
    ASSERT_TRUE (scanMesh (cube, o, pts, faces).ok);
    EXPECT_GT (pts.size (), 1000u);
    EXPECT_LE (pts.size (), 240u * 240u);
    const V axis = (centre - o.viewpoint).normalized ();
    for (std::size_t i = 0; i < pts.size (); ++i)
    {
      const V ray = pts[i] - o.viewpoint;
      ASSERT_GT (ray.dot (axis), 0.0);
      EXPECT_LE (std::acos (std::min (1.0, ray.normalized ().dot (axis))), widest + 1e-12);
      const auto& f = cube.faces[static_cast<std::size_t> (faces[i])];
      const V middle = (cube.vertices[f[0]] + cube.vertices[f[1]] + cube.vertices[f[2]]) / 3.0 - centre;
      Eigen::Index k = 0;
      middle.cwiseAbs ().maxCoeff (&k); // the face's outward normal is this axis, signed as middle[k]
      EXPECT_LT (middle[k] > 0.0 ? ray[k] : -ray[k], 0.0) << "a convex mesh shows the sensor only the faces turned to it";
      EXPECT_NEAR ((pts[i] - centre).cwiseAbs ().maxCoeff (), 1.0, 1e-9);
    }
  }
}

TEST (RangeScanCamera, ProtocolViewpointFollowsItsRecipe)
{
  TriangleMesh cube;
  addCube (cube, V (3, -1, 2), 1.0);
  const V centre (3, -1, 2);
  const double diagonal = cube.diagonal ();
  V mean = V::Zero ();
  double upper = 0.0, z2 = 0.0;
  const int n = 4000;
  for (int seed = 0; seed < n; ++seed)
  {
    const V vp = protocolViewpoint (cube, 2.0, static_cast<std::uint32_t> (seed));
    const V d = (vp - centre) / (2.0 * diagonal);
    ASSERT_NEAR (d.norm (), 1.0, 1e-12);
    mean += d / n;
    upper += d.z () > 0.0 ? 1.0 / n : 0.0;
    z2 += d.z () * d.z () / n;
  }
  // Uniform on the sphere: mean 0, half above the equator, E[z^2] = 1/3 (4000 draws: sd about 0.01).
  EXPECT_LT (mean.norm (), 0.05);
  EXPECT_NEAR (upper, 0.5, 0.03);
  EXPECT_NEAR (z2, 1.0 / 3.0, 0.02);
  // The documented recipe, step by step.
  std::mt19937 rng (7);
  const double u = (static_cast<double> (rng ()) + 0.5) / 4294967296.0, v = (static_cast<double> (rng ()) + 0.5) / 4294967296.0;
  const double z = 1.0 - 2.0 * u, r = std::sqrt (1.0 - z * z);
  const V expected = centre + 3.0 * diagonal * V (r * std::cos (2.0 * M_PI * v), r * std::sin (2.0 * M_PI * v), z);
  EXPECT_LT ((protocolViewpoint (cube, 3.0, 7) - expected).norm (), 1e-12 * diagonal);
}

TEST (RangeScanCamera, ConstantNoiseHasTheSameDeviationAtEveryRange)
{
  TriangleMesh cube;
  addCube (cube, V::Zero (), 1.0);
  const double share = 0.005, diagonal = cube.diagonal ();
  for (double height : {6.0, 20.0})
  {
    std::vector<V> pts;
    const V eye (0, 0, height);
    ASSERT_TRUE (scanMesh (cube, cameraAt (eye, 240, 4.0, share), pts).ok);
    ASSERT_EQ (pts.size (), 240u * 240u);
    const auto [sd, mean] = rangeResiduals (pts, eye, 1.0);
    EXPECT_NEAR (sd, share * diagonal, 0.02 * share * diagonal) << "from " << height;
    EXPECT_NEAR (mean, 0.0, 0.02 * share * diagonal);
    // The range model at the same place: (range / centre range)^2 of it.
    ASSERT_TRUE (scanMesh (cube, cameraAt (eye, 240, 4.0, share, DepthNoiseModel::kGrowsWithSquaredRange), pts).ok);
    const double shrink = std::pow ((height - 1.0) / height, 2.0);
    EXPECT_NEAR (rangeResiduals (pts, eye, 1.0).first, shrink * share * diagonal, 0.03 * share * diagonal);
  }
}

TEST (RangeScanCamera, TheSameSeedGivesTheSameScanAndNoiseKeepsTheRays)
{
  TriangleMesh mesh;
  addCube (mesh, V::Zero (), 1.0);
  addCube (mesh, V (0.5, 0.5, 1.5), 0.5);
  std::vector<V> a, b, clean;
  ASSERT_TRUE (scanMesh (mesh, singleViewProtocolScan (mesh, 0.005, 11), a).ok);
  ASSERT_TRUE (scanMesh (mesh, singleViewProtocolScan (mesh, 0.005, 11), b).ok);
  EXPECT_EQ (a, b);
  ASSERT_TRUE (scanMesh (mesh, singleViewProtocolScan (mesh, 0.005, 12), b).ok);
  EXPECT_NE (a, b);
  const RangeScanOptions o = singleViewProtocolScan (mesh, 0.0, 11);
  ASSERT_TRUE (scanMesh (mesh, o, clean).ok);
  ASSERT_EQ (clean.size (), a.size ()) << "noise moves points along their rays; it adds or drops none";
  for (std::size_t i = 0; i < a.size (); ++i)
    EXPECT_LT ((a[i] - o.viewpoint).normalized ().cross ((clean[i] - o.viewpoint).normalized ()).norm (), 1e-9);
}

TEST (RangeScanCamera, BadCameraOptionsAreRefused)
{
  TriangleMesh cube;
  addCube (cube, V::Zero (), 1.0);
  std::vector<V> pts{V::Zero ()};
  const auto refused = [&] (const RangeScanOptions& o, const std::string& word) {
    const Status s = scanMesh (cube, o, pts);
    EXPECT_FALSE (s.ok);
    EXPECT_NE (s.message.find (word), std::string::npos) << s.message;
    EXPECT_TRUE (pts.empty ());
  };
  for (double fov : {-1.0, 180.0, 250.0, std::numeric_limits<double>::quiet_NaN (), std::numeric_limits<double>::infinity ()})
    refused (cameraAt (V (0, 0, 10), 240, fov), "field of view");
  refused (cameraAt (V (0, 0, 10), kMaxScanImagePixels + 1, 50.0), "pixels");
  refused (cameraAt (V (0, 0, 10), 1000000000, 50.0), "pixels");
  refused (cameraAt (V (0, 0, 1.2), 240, 50.0), "outside");
  RangeScanOptions inside = singleViewProtocolScan (cube);
  inside.viewpoint = protocolViewpoint (cube, 0.4, 1);
  refused (inside, "outside");
  RangeScanOptions model = singleViewProtocolScan (cube);
  model.noise_model = static_cast<DepthNoiseModel> (7);
  refused (model, "noise model");
  EXPECT_TRUE (scanMesh (cube, cameraAt (V (0, 0, 2), kMaxScanImagePixels / 10, 170.0), pts).ok);
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

/*
 * Signatures and their matching: invariances, symmetry, ranking, degenerate signatures.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include "test_support.h"

#include <pcl_flowseg/io/point_cloud_writer.h>
#include <pcl_flowseg/io/range_scan.h>
#include <pcl_flowseg/signature/feature_signature.h>
#include <pcl_flowseg/signature/shape_signature.h>
#include <pcl_flowseg/signature/signature_matcher.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <map>
#include <unistd.h>

using namespace pcl_flowseg;
using V = Eigen::Vector3d;

namespace {

using flowseg_test::signatureOf;

std::vector<V>
transformed (const std::vector<V>& pts, double angle, const V& axis, double scale, bool mirror, const V& shift)
{
  const Eigen::Matrix3d r = Eigen::AngleAxisd (angle, axis.normalized ()).toRotationMatrix ();
  std::vector<V> out;
  for (V p : pts)
  {
    if (mirror)
      p.y () = -p.y ();
    out.push_back (scale * (r * p) + shift);
  }
  return out;
}

pcl::SignatureMatcher
paperMatcher ()
{
  pcl::SignatureMatcher matcher;
  matcher.setMethod (MatchMethod::Paper);
  return matcher;
}

/** Two balls side by side (radii 1 and 0.6, 32 x 16 quads each): two parts, both seen from the
  * front and from above. */
TriangleMesh
twoBalls ()
{
  TriangleMesh mesh;
  flowseg_test::addSphere (mesh, V::Zero (), 1.0, 32, 16);
  flowseg_test::addSphere (mesh, V (1.5, 0, 0), 0.6, 32, 16);
  return mesh;
}

/** A scan of \a mesh from \a sensor written to \a path: a PCD file carries the sensor as its
  * VIEWPOINT, any other format (.xyz) only the points. */
void
writeScan (const TriangleMesh& mesh, const V& sensor, const std::string& path)
{
  RangeScanOptions o;
  o.viewpoint = sensor;
  o.points = 3000;
  std::vector<V> pts;
  ASSERT_TRUE (scanMesh (mesh, o, pts));
  pcl::PointCloud<pcl::PointXYZ> cloud;
  for (const V& p : pts)
    cloud.push_back (pcl::PointXYZ (static_cast<float> (p.x ()), static_cast<float> (p.y ()), static_cast<float> (p.z ())));
  cloud.sensor_origin_ = Eigen::Vector4f (static_cast<float> (sensor.x ()), static_cast<float> (sensor.y ()),
                                          static_cast<float> (sensor.z ()), 0.0f);
  if (path.size () > 4 && path.substr (path.size () - 4) == ".pcd")
  {
    ASSERT_TRUE (writePointCloud (path, cloud, false));
    return;
  }
  std::ofstream out (path);
  for (const auto& p : cloud)
    out << p.x << " " << p.y << " " << p.z << "\n";
}

void
expectSameSignature (const Signature& a, const Signature& b, const std::string& what)
{
  EXPECT_EQ (a.interior_volume, b.interior_volume) << what;
  ASSERT_EQ (a.points.size (), b.points.size ()) << what;
  for (std::size_t k = 0; k < a.points.size (); ++k)
  {
    EXPECT_EQ (a.points[k].position, b.points[k].position) << what;
    EXPECT_EQ (a.points[k].weight, b.points[k].weight) << what;
  }
}

} // namespace

TEST (Signature, FeaturesOfTheAnimal)
{
  const Signature s = signatureOf (flowseg_test::shapeSample ("animal3d", 4000));
  ASSERT_GE (s.points.size (), 6u); // body, head, four legs (neck and tail may be smaller than 2%)
  double sum = 0;
  for (std::size_t k = 0; k < s.points.size (); ++k)
  {
    sum += s.points[k].weight;
    if (k > 0)
      EXPECT_LE (s.points[k].weight, s.points[k - 1].weight);
  }
  EXPECT_NEAR (sum, 1.0, 1e-12);
  EXPECT_GT (s.points[0].weight, 0.5); // the body
}

TEST (Signature, RequiresInteriorAndSaneSignificance)
{
  FlowParameters params;
  params.interior.separate = false;
  FlowResult r;
  ASSERT_TRUE (runFlowSegmentation (flowseg_test::shapeSample ("snowman3d", 1000), params, r).ok);
  Signature s;
  EXPECT_FALSE (signatureFromSegmentation (r, 0.02, s).ok);
  params.interior.separate = true;
  ASSERT_TRUE (runFlowSegmentation (flowseg_test::shapeSample ("snowman3d", 1000), params, r).ok);
  EXPECT_FALSE (signatureFromSegmentation (r, -0.1, s).ok);
  EXPECT_FALSE (signatureFromSegmentation (r, 1.0, s).ok);
  EXPECT_TRUE (signatureFromSegmentation (r, 0.0, s).ok);
}

class MatchInvariance : public ::testing::TestWithParam<const char*> {};

TEST_P (MatchInvariance, ATransformedResampledCopyScoresAtTheTop)
{
  const std::string name = GetParam ();
  const int n = name.find ("2d") != std::string::npos ? 1500 : 4000;
  const Signature query = signatureOf (flowseg_test::shapeSample (name, n, 1));
  // The copy: another sample (seed), rotated, mirrored, scaled and moved.
  const auto copy_pts = transformed (flowseg_test::shapeSample (name, n, 99), 1.1,
                                     name.find ("2d") != std::string::npos ? V (0, 0, 1) : V (1, -2, 0.5), 3.5, true, V (4, -7, 2));
  const Signature copy = signatureOf (copy_pts);
  pcl::SignatureMatcher matcher = paperMatcher ();
  const auto self = matcher.match (query, copy);
  EXPECT_GT (self.paper_score, 0.8 * static_cast<double> (query.points.size ()) - 0.2) << name;
  // Every other shape of the same dimension scores lower.
  for (const auto& other : sampleShapes ())
  {
    if (other.name == name || (other.dimension == 2) != (name.find ("2d") != std::string::npos))
      continue;
    const Signature o = signatureOf (sampleBoundary (other, n, 5));
    EXPECT_LT (matcher.match (query, o).paper_score, self.paper_score) << name << " vs " << other.name;
  }
}

INSTANTIATE_TEST_SUITE_P (Shapes, MatchInvariance,
                          ::testing::Values ("star2d", "hand2d", "dumbbell3d", "snowman3d", "animal3d"));

TEST (Match, SymmetricAndTheTransformMapsPartners)
{
  const Signature a = signatureOf (flowseg_test::shapeSample ("animal3d", 3000, 1));
  const Signature b = signatureOf (transformed (flowseg_test::shapeSample ("animal3d", 3000, 2), 0.7, V (0, 0, 1), 2.0, false, V::Zero ()));
  pcl::SignatureMatcher matcher = paperMatcher ();
  const auto ab = matcher.match (a, b);
  const auto ba = matcher.match (b, a);
  EXPECT_DOUBLE_EQ (ab.paper_score, ba.paper_score);
  ASSERT_FALSE (ab.pairs.empty ());
  for (const auto& p : ab.pairs)
  {
    const V mapped = ab.linear * b.points[static_cast<std::size_t> (p.second)].position + ab.translation;
    EXPECT_LT ((mapped - a.points[static_cast<std::size_t> (p.first)].position).norm (), matcher.getParameters ().paper.threshold + 1e-9);
  }
  EXPECT_NEAR (std::abs (ab.linear.determinant ()), 1.0, 1e-9);
  EXPECT_NEAR ((ab.linear * ab.linear.transpose () - Eigen::Matrix3d::Identity ()).norm (), 0.0, 1e-9);
}

TEST (Match, MirroringIsFoundOnlyWhenAllowed)
{
  // A chiral arrangement of weighted points and its mirror image.
  Signature a;
  a.points = {{V (0, 0, 0), 0.4}, {V (1, 0, 0), 0.25}, {V (0, 1.5, 0), 0.2}, {V (0, 0, 0.7), 0.15}};
  Signature b = a;
  for (auto& p : b.points)
    p.position.z () = -p.position.z ();
  pcl::SignatureMatcher matcher = paperMatcher ();
  const auto with = matcher.match (a, b);
  EXPECT_NEAR (with.paper_score, 4.0, 1e-9);
  EXPECT_TRUE (with.mirrored);
  MatchParameters no_mirror = matcher.getParameters ();
  no_mirror.paper.allow_mirror = false;
  matcher.setParameters (no_mirror);
  EXPECT_LT (matcher.match (a, b).paper_score, 4.0 - 0.1);
  EXPECT_NEAR (matcher.match (a, a).paper_score, 4.0, 1e-9);
}

TEST (Match, DegenerateSignatures)
{
  Signature empty, one, two;
  one.points = {{V::Zero (), 1.0}};
  two.points = {{V::Zero (), 0.6}, {V (1, 0, 0), 0.4}};
  pcl::SignatureMatcher matcher = paperMatcher ();
  EXPECT_EQ (matcher.match (empty, empty).paper_score, 0.0);
  EXPECT_EQ (matcher.match (empty, one).paper_score, -1.0);
  EXPECT_EQ (matcher.match (one, empty).paper_score, -1.0);
  EXPECT_NEAR (matcher.match (one, one).paper_score, 1.0, 1e-12);
  // One point against two: the heavy ones pair up, the light one is unmatched.
  const double expected = 1.0 - 0.4 / 1.6 - 0.4;
  EXPECT_NEAR (matcher.match (one, two).paper_score, expected, 1e-12);
  EXPECT_NEAR (matcher.match (two, one).paper_score, expected, 1e-12);
  EXPECT_NEAR (matcher.match (two, two).paper_score, 2.0, 1e-12);
}

TEST (FeatureSignature, PclStyle)
{
  pcl::PointCloud<pcl::PointXYZ>::Ptr cloud (new pcl::PointCloud<pcl::PointXYZ>);
  for (const auto& p : flowseg_test::shapeSample ("snowman3d", 3000))
    cloud->push_back (pcl::PointXYZ (static_cast<float> (p.x ()), static_cast<float> (p.y ()), static_cast<float> (p.z ())));
  pcl::FeatureSignature<pcl::PointXYZ> fs;
  fs.setInputCloud (cloud);
  Signature s;
  ASSERT_TRUE (fs.compute (s)) << fs.getLastError ();
  EXPECT_EQ (s.points.size (), 3u); // three balls
  pcl::PointCloud<pcl::PointXYZ>::Ptr tiny (new pcl::PointCloud<pcl::PointXYZ>);
  tiny->push_back (pcl::PointXYZ (0, 0, 0));
  fs.setInputCloud (tiny);
  EXPECT_FALSE (fs.compute (s));
  EXPECT_FALSE (fs.getLastError ().empty ());
}

TEST (Match, ParametersRoundTripAndAreChecked)
{
  EXPECT_EQ (pcl::SignatureMatcher ().getMethod (), MatchMethod::Combined); // the default
  pcl::SignatureMatcher matcher = paperMatcher ();
  EXPECT_EQ (matcher.getParameters ().paper.threshold, PaperMatchParameters ().threshold);
  MatchParameters p;
  p.paper.threshold = 0.25;
  p.paper.allow_mirror = false;
  p.paper.alignment_points = 6;
  p.method = MatchMethod::Paper;
  matcher.setParameters (p);
  EXPECT_EQ (matcher.getParameters ().paper.threshold, 0.25);
  EXPECT_FALSE (matcher.getParameters ().paper.allow_mirror);
  EXPECT_EQ (matcher.getParameters ().paper.alignment_points, 6);
  EXPECT_TRUE (checkMatchParameters (p));
  for (double t : {0.0, -1.0, std::nan ("")})
  {
    MatchParameters bad;
    bad.paper.threshold = t;
    const Status s = checkMatchParameters (bad);
    EXPECT_FALSE (s);
    EXPECT_NE (s.message.find ("threshold"), std::string::npos) << s.message;
  }
  MatchParameters bad;
  bad.paper.alignment_points = 0;
  EXPECT_FALSE (checkMatchParameters (bad));
  // The matcher refuses them too, rather than clamping them into something it did not get.
  Signature two;
  two.points = {{V::Zero (), 0.6}, {V (1, 0, 0), 0.4}};
  EXPECT_TRUE (matcher.match (two, two).status);
  matcher.setParameters (bad);
  const pcl::SignatureMatcher::Result refused = matcher.match (two, two);
  EXPECT_FALSE (refused.status);
  EXPECT_NE (refused.status.message.find ("alignment"), std::string::npos) << refused.status.message;
  EXPECT_EQ (refused.alignments, 0u);
  EXPECT_LT (refused.similarity, -1e300);
}

TEST (Signature, SignificanceIsDecidedInOnePlace)
{
  const FlowResult r = flowseg_test::segmentOrDie (flowseg_test::shapeSample ("animal3d", 2500), flowseg_test::kDefaultMerge.rho,
                                                   DimensionMode::Automatic, true);
  const std::vector<int> interior = segmentsOnSide (r, FeatureSide::Interior);
  EXPECT_EQ (interior, r.features); // the result reports the interior by default
  double total = 0.0;
  for (int k : interior)
  {
    EXPECT_EQ (r.segments[static_cast<std::size_t> (k)].interior, 1);
    total += r.segments[static_cast<std::size_t> (k)].volume;
  }
  const std::vector<int> significant = significantSegments (r, interior, 0.05);
  std::size_t expected = 0;
  for (int k : interior)
    expected += r.segments[static_cast<std::size_t> (k)].volume > 0.05 * total;
  EXPECT_EQ (significant.size (), expected);
  EXPECT_LT (significant.size (), interior.size ());
  Signature s;
  ASSERT_TRUE (signatureFromSegmentation (r, 0.05, s));
  EXPECT_EQ (s.points.size (), significant.size ()); // the signature keeps exactly those
  EXPECT_EQ (significantSegments (r, interior, 0.0).size (), interior.size ());
  EXPECT_FALSE (checkSignificance (1.0));
  EXPECT_FALSE (checkSignificance (-0.01));
  EXPECT_TRUE (checkSignificance (0.0));
}

TEST (Signature, ManyFilesInParallelEqualOneByOne)
{
  const std::string samples = std::string (PCL_FLOWSEG_SOURCE_DIR) + "/samples/";
  const std::vector<std::string> paths = {samples + "snowman3d.pcd", samples + "missing.pcd", samples + "hand2d.pcd",
                                          samples + "dumbbell3d.pcd"};
  const FlowParameters params;
  std::vector<Signature> signatures;
  std::vector<Status> statuses;
  std::size_t reports = 0, last_done = 0;
  signaturesOfShapeFiles (paths, ShapeInputOptions (), params, kDefaultSignificance, 2, signatures, statuses,
                          [&] (std::size_t done, const std::string& path, const Status&) {
                            ++reports;
                            EXPECT_GT (done, last_done);
                            last_done = done;
                            EXPECT_NE (std::find (paths.begin (), paths.end (), path), paths.end ());
                          });
  ASSERT_EQ (signatures.size (), paths.size ());
  EXPECT_EQ (reports, paths.size ());
  EXPECT_FALSE (statuses[1].ok);
  EXPECT_NE (statuses[1].message.find ("missing.pcd"), std::string::npos) << statuses[1].message;
  for (std::size_t i : {0u, 2u, 3u})
  {
    EXPECT_TRUE (statuses[i].ok) << statuses[i].message;
    Signature one;
    ASSERT_TRUE (signatureOfShapeFile (paths[i], ShapeInputOptions (), params, kDefaultSignificance, one));
    ASSERT_EQ (one.points.size (), signatures[i].points.size ()) << paths[i];
    for (std::size_t k = 0; k < one.points.size (); ++k)
    {
      EXPECT_EQ (one.points[k].position, signatures[i].points[k].position);
      EXPECT_EQ (one.points[k].weight, signatures[i].points[k].weight);
    }
  }
}

TEST (Signature, EachScanFileSegmentedFromItsOwnSensorOrigin)
{
  char folder[] = "/tmp/flowseg_scans_XXXXXX";
  ASSERT_NE (::mkdtemp (folder), nullptr);
  const std::string dir = folder;
  const TriangleMesh mesh = twoBalls ();
  const std::vector<V> sensors = {V (0.5, 0, 12), V (0, 12, 1)}; // exact in the PCD's floats
  const std::vector<std::string> paths = {dir + "/front.pcd", dir + "/above.pcd"};
  for (std::size_t i = 0; i < paths.size (); ++i)
    writeScan (mesh, sensors[i], paths[i]);
  writeScan (mesh, sensors[0], dir + "/front.xyz");

  ShapeInputOptions own;
  own.use_sensor_origin = true;
  const FlowParameters plain;
  std::vector<Signature> signatures;
  std::vector<Status> statuses;
  signaturesOfShapeFiles (paths, own, plain, kDefaultSignificance, 2, signatures, statuses);
  for (std::size_t i = 0; i < paths.size (); ++i)
  {
    ASSERT_TRUE (statuses[i]) << statuses[i].message;
    FlowParameters given;
    given.interior.viewpoint = sensors[i];
    Signature explicit_viewpoint, none;
    ASSERT_TRUE (signatureOfShapeFile (paths[i], ShapeInputOptions (), given, kDefaultSignificance, explicit_viewpoint));
    expectSameSignature (signatures[i], explicit_viewpoint, paths[i]);
    // Without the viewpoint the seen shells close into one part; from it the balls are two.
    ASSERT_TRUE (signatureOfShapeFile (paths[i], ShapeInputOptions (), plain, kDefaultSignificance, none));
    EXPECT_GE (signatures[i].points.size (), 2u) << paths[i];
    EXPECT_NE (signatures[i].interior_volume, none.interior_volume) << paths[i];
  }

  Signature s;
  const Status no_origin = signatureOfShapeFile (dir + "/front.xyz", own, plain, kDefaultSignificance, s);
  EXPECT_FALSE (no_origin.ok);
  EXPECT_NE (no_origin.message.find (dir + "/front.xyz: the file carries no sensor origin"), std::string::npos) << no_origin.message;
  FlowParameters given;
  given.interior.viewpoint = sensors[0];
  const Status both = signatureOfShapeFile (paths[0], own, given, kDefaultSignificance, s);
  EXPECT_FALSE (both.ok);
  EXPECT_NE (both.message.find ("exclude each other"), std::string::npos) << both.message;
  std::system (("rm -rf '" + dir + "'").c_str ());
}

/*
 * Single-view recognition: a scan of a stored shape finds it, turning and shifting everything
 * together changes nothing, bad viewpoints are refused, views survive the database file.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include <pcl_flowseg/io/mesh_io.h>
#include <pcl_flowseg/io/range_scan.h>
#include <pcl_flowseg/io/scan_protocol.h>
#include <pcl_flowseg/segmentation/flow_pipeline.h>
#include <pcl_flowseg/signature/signature_database.h>
#include <pcl_flowseg/signature/view_description.h>

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <string>
#include <unistd.h>

using namespace pcl_flowseg;

namespace {

/** An axis-aligned box from \a low to \a high, as twelve triangles appended to \a m. */
void
addBox (TriangleMesh& m, const Eigen::Vector3d& low, const Eigen::Vector3d& high)
{
  const int first = static_cast<int> (m.vertices.size ());
  for (int k = 0; k < 8; ++k)
    m.vertices.emplace_back (k & 1 ? high.x () : low.x (), k & 2 ? high.y () : low.y (), k & 4 ? high.z () : low.z ());
  const int faces[12][3] = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                            {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
  for (const auto& f : faces)
    m.faces.push_back ({first + f[0], first + f[1], first + f[2]});
}

/** Four shapes a camera tells apart: a slab, a rod, an L and a T. */
std::vector<TriangleMesh>
testShapes ()
{
  std::vector<TriangleMesh> shapes (4);
  addBox (shapes[0], {0, 0, 0}, {2, 1.5, 0.4});
  addBox (shapes[1], {0, 0, 0}, {4, 0.5, 0.5});
  addBox (shapes[2], {0, 0, 0}, {3, 0.6, 0.6});
  addBox (shapes[2], {0, 0.6, 0}, {0.6, 2.5, 0.6});
  addBox (shapes[3], {0, 0, 0}, {3, 0.6, 0.6});
  addBox (shapes[3], {1.2, 0.6, 0}, {1.8, 2.5, 0.6});
  return shapes;
}

TriangleMesh
moved (TriangleMesh mesh, const Eigen::Isometry3d& motion)
{
  for (auto& v : mesh.vertices)
    v = motion * v;
  return mesh;
}

/** The signature of \a points segmented with default parameters (seen from \a viewpoint, if any). */
Signature
signatureOf (const std::vector<Eigen::Vector3d>& points, const std::optional<Eigen::Vector3d>& viewpoint)
{
  FlowParameters params;
  params.interior.viewpoint = viewpoint;
  FlowResult result;
  Signature signature;
  EXPECT_TRUE (runFlowSegmentation (points, params, result));
  const Status s = signatureFromSegmentation (result, kDefaultSignificance, signature);
  EXPECT_TRUE (s) << s.message;
  return signature;
}

/** A database of the complete shapes (3000-point samples), each named by its index. */
SignatureDatabase
databaseOf (const std::vector<TriangleMesh>& shapes)
{
  SignatureDatabase db;
  for (std::size_t i = 0; i < shapes.size (); ++i)
    db.add (ShapeEntry{std::to_string (i), "c" + std::to_string (i), signatureOf (sampleMeshSurface (shapes[i], 3000, 0.0, 7), {})});
  return db;
}

/** The protocol's scan of \a mesh from \a direction, with its viewpoint. */
std::vector<Eigen::Vector3d>
protocolScan (const TriangleMesh& mesh, const Eigen::Vector3d& direction, Eigen::Vector3d& viewpoint)
{
  const RangeScanOptions options = singleViewProtocolScanAlong (mesh, direction.normalized ());
  viewpoint = options.viewpoint;
  std::vector<Eigen::Vector3d> points;
  EXPECT_TRUE (scanMesh (mesh, options, points));
  return points;
}

} // namespace

// From oblique directions: end-on, a rod and the long bar of an L look alike (docs/method.md).
TEST (SingleView, AScanOfAStoredShapeFindsItFirst)
{
  const std::vector<TriangleMesh> shapes = testShapes ();
  const SignatureDatabase db = databaseOf (shapes);
  for (std::size_t i = 0; i < shapes.size (); ++i)
    for (const Eigen::Vector3d& direction : {Eigen::Vector3d (1, 2, 3), Eigen::Vector3d (-2, 1, -1.5)})
    {
      Eigen::Vector3d viewpoint;
      const std::vector<Eigen::Vector3d> scan = protocolScan (shapes[i], direction, viewpoint);
      const Signature query = signatureOf (scan, viewpoint);
      ASSERT_TRUE (query.views.single_view);
      const auto hits = db.query (query, 0, pcl::SignatureMatcher ());
      ASSERT_EQ (hits.size (), shapes.size ());
      EXPECT_EQ (hits[0].name, std::to_string (i)) << "from " << direction.transpose ();
      EXPECT_LT (hits[0].distance, hits[1].distance);
      EXPECT_TRUE (hits[0].compared);
    }
}

TEST (SingleView, TurningAndShiftingScanAndDatabaseTogetherChangesNothing)
{
  const std::vector<TriangleMesh> shapes = testShapes ();
  const Eigen::Isometry3d motion =
      Eigen::Translation3d (5.0, -3.0, 12.0) * Eigen::AngleAxisd (1.1, Eigen::Vector3d (1, 2, 3).normalized ());
  std::vector<TriangleMesh> turned;
  for (const auto& s : shapes)
    turned.push_back (moved (s, motion));
  const SignatureDatabase db = databaseOf (shapes), turned_db = databaseOf (turned);
  Eigen::Vector3d viewpoint;
  std::vector<Eigen::Vector3d> scan = protocolScan (shapes[2], Eigen::Vector3d (2, -1, 1), viewpoint);
  const auto hits = db.query (signatureOf (scan, viewpoint), 0, pcl::SignatureMatcher ());
  for (auto& p : scan)
    p = motion * p;
  const auto turned_hits = turned_db.query (signatureOf (scan, motion * viewpoint), 0, pcl::SignatureMatcher ());
  // The views are rendered through image cells laid along the input's axes, so distances may
  // move by a few percent: the best shape and every clear gap stay.
  ASSERT_EQ (hits.size (), turned_hits.size ());
  EXPECT_EQ (turned_hits[0].name, hits[0].name);
  std::map<std::string, double> turned_distance;
  for (const auto& h : turned_hits)
    turned_distance[h.name] = h.distance;
  for (const auto& h : hits)
    EXPECT_NEAR (turned_distance[h.name], h.distance, 0.01 + 0.1 * h.distance) << "shape " << h.name;
  EXPECT_LT (2.0 * hits[0].distance, hits[1].distance);
  EXPECT_EQ (hits[0].name, "2");
}

TEST (SingleView, BadViewpointsAreRefused)
{
  const TriangleMesh slab = testShapes ()[0];
  Eigen::Vector3d viewpoint;
  const std::vector<Eigen::Vector3d> scan = protocolScan (slab, Eigen::Vector3d (1, 1, 1), viewpoint);
  ViewDescription view;
  const double nan = std::numeric_limits<double>::quiet_NaN ();
  Status s = describeScanView (scan, Eigen::Vector3d (nan, 0, 0), view);
  EXPECT_FALSE (s);
  EXPECT_NE (s.message.find ("not finite"), std::string::npos) << s.message;
  s = describeScanView (scan, Eigen::Vector3d (1.0, 0.75, 0.2), view); // inside the slab
  EXPECT_FALSE (s);
  EXPECT_NE (s.message.find ("inside"), std::string::npos) << s.message;
  s = describeScanView (scan, Eigen::Vector3d (1e300, 0, 0), view);
  EXPECT_FALSE (s);
  EXPECT_NE (s.message.find ("absurdly far"), std::string::npos) << s.message;
  s = describeScanView ({scan.begin (), scan.begin () + 5}, viewpoint, view);
  EXPECT_FALSE (s);
  EXPECT_NE (s.message.find ("at least"), std::string::npos) << s.message;
  EXPECT_TRUE (describeScanView (scan, viewpoint, view));
  // Through the segmentation, as the apps and Python take it: refused, never a signature.
  FlowParameters params;
  params.interior.viewpoint = Eigen::Vector3d (1.0, 0.75, 0.2);
  FlowResult result;
  Signature signature;
  s = runFlowSegmentation (scan, params, result);
  if (s)
    s = signatureFromSegmentation (result, kDefaultSignificance, signature);
  EXPECT_FALSE (s);
}

TEST (SingleView, AScanSignatureWithoutItsViewFindsNothing)
{
  const SignatureDatabase db = databaseOf ({testShapes ()[0]});
  Signature broken;
  broken.views.single_view = true; // no view: checkViewSet refuses it, a query finds nothing
  EXPECT_FALSE (checkViewSet (broken.views));
  EXPECT_TRUE (db.query (broken, 0, pcl::SignatureMatcher ()).empty ());
}

TEST (SingleView, ViewsSurviveTheDatabaseFile)
{
  const std::vector<TriangleMesh> shapes = testShapes ();
  const SignatureDatabase db = databaseOf (shapes);
  const std::string path = "/tmp/flowseg_single_view_" + std::to_string (getpid ()) + ".db";
  ASSERT_TRUE (db.save (path));
  SignatureDatabase loaded;
  ASSERT_TRUE (loaded.load (path));
  std::remove (path.c_str ());
  std::remove ((path + ".lock").c_str ());
  ASSERT_EQ (loaded.size (), db.size ());
  for (std::size_t i = 0; i < db.size (); ++i)
  {
    const ViewSet& a = db.entries ()[i].signature.views;
    const ViewSet& b = loaded.entries ()[i].signature.views;
    EXPECT_FALSE (a.single_view);
    EXPECT_EQ (a.views.size (), kDefaultViewCount);
    ASSERT_EQ (a.views.size (), b.views.size ());
    EXPECT_EQ (a.shape_points.size (), b.shape_points.size ());
    EXPECT_NEAR ((a.views[0].points[0] - b.views[0].points[0]).norm (), 0.0, 1e-3);
  }
  Eigen::Vector3d viewpoint;
  const std::vector<Eigen::Vector3d> scan = protocolScan (shapes[3], Eigen::Vector3d (-1, 2, 2), viewpoint);
  const Signature query = signatureOf (scan, viewpoint); // the scan first: it sets the viewpoint
  const auto before = db.query (query, 0, pcl::SignatureMatcher ());
  const auto after = loaded.query (query, 0, pcl::SignatureMatcher ());
  ASSERT_EQ (before.size (), after.size ());
  for (std::size_t r = 0; r < before.size (); ++r)
  {
    EXPECT_EQ (before[r].name, after[r].name);
    EXPECT_NEAR (before[r].distance, after[r].distance, 0.01);
  }
}

TEST (SingleView, AScanLooksLikeASingleViewAndACompleteSampleDoesNot)
{
  for (const TriangleMesh& shape : testShapes ())
  {
    Eigen::Vector3d viewpoint;
    const std::vector<Eigen::Vector3d> scan = protocolScan (shape, Eigen::Vector3d (1, -2, 1.5), viewpoint);
    EXPECT_TRUE (looksLikeSingleView (scan, viewpoint));
    EXPECT_FALSE (looksLikeSingleView (sampleMeshSurface (shape, 3000, 0.0, 3), viewpoint));
    EXPECT_FALSE (looksLikeSingleView (scan, Eigen::Vector3d (1.0, 0.3, 0.3))); // from inside: no view
  }
}

TEST (SingleView, A2DShapeHasNoViewsAndAScanSkipsIt)
{
  ViewSet set;
  EXPECT_TRUE (describeViewSet ({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, 2, std::nullopt, set));
  EXPECT_TRUE (set.views.empty ());
  EXPECT_FALSE (set.single_view);
}

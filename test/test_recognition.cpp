/*
 * Single-view recognition: its scores on hand-made similarity matrices, the pairing of queries with
 * their models, the view sphere, the methods by name, the protocol camera's rendered views.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include <pcl_flowseg/evaluation/query_models.h>
#include <pcl_flowseg/evaluation/recognition_method.h>
#include <pcl_flowseg/evaluation/recognition_scores.h>
#include <pcl_flowseg/evaluation/rendered_views.h>
#include <pcl_flowseg/signature/view_sphere.h>
#include <pcl_flowseg/io/scan_protocol.h>

#include <gtest/gtest.h>

#include <cmath>

using namespace pcl_flowseg;

namespace {

/** A box of sides 2, 1 and 0.5: twelve triangles. */
TriangleMesh
boxMesh ()
{
  TriangleMesh m;
  for (int k = 0; k < 8; ++k)
    m.vertices.emplace_back (k & 1 ? 2.0 : 0.0, k & 2 ? 1.0 : 0.0, k & 4 ? 0.5 : 0.0);
  m.faces = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
             {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
  return m;
}

} // namespace

// Models a/0 a/1 a/2 b/0 b/1 (indices 0 to 4); three queries, worked by hand.
TEST (RecognitionScores, CategoryAndInstanceOfAHandMadeMatrix)
{
  const std::vector<std::string> labels = {"a", "a", "a", "b", "b"};
  const std::vector<std::vector<double>> similarity = {
      // own model 0: kept in, it is the best (instance); left out, b/0 comes first (NN missed) and
      // the top 2 hold one of a's two others (FT 0.5).
      {0.9, 0.8, 0.1, 0.85, 0.2},
      // own model 3: b/1 beats it (instance missed); left out, b/1 is first (NN) and is b's only
      // other model (FT 1).
      {0.5, 0.4, 0.3, 0.6, 0.7},
      // own model 1: a/0 ties with it, which counts against it (instance missed); left out, a/0 is
      // first and a/2 wins the tie at 0 by database order (FT 1).
      {0.9, 0.9, 0.0, 0.0, 0.0}};
  RecognitionScores all;
  std::vector<ClassRecognitionScores> per_class;
  ASSERT_TRUE (scoreRecognition (similarity, {0, 3, 1}, labels, all, per_class));
  EXPECT_EQ (all.queries, 3u);
  EXPECT_EQ (all.category_queries, 3u);
  EXPECT_NEAR (all.instance_top1, 1.0 / 3.0, 1e-12);
  EXPECT_NEAR (all.nearest_neighbour, 2.0 / 3.0, 1e-12);
  EXPECT_NEAR (all.first_tier, 2.5 / 3.0, 1e-12);
  ASSERT_EQ (per_class.size (), 2u);
  EXPECT_EQ (per_class[0].label, "a");
  EXPECT_EQ (per_class[0].scores.queries, 2u);
  EXPECT_NEAR (per_class[0].scores.instance_top1, 0.5, 1e-12);
  EXPECT_NEAR (per_class[0].scores.nearest_neighbour, 0.5, 1e-12);
  EXPECT_NEAR (per_class[0].scores.first_tier, 0.75, 1e-12);
  EXPECT_EQ (per_class[1].label, "b");
  EXPECT_NEAR (per_class[1].scores.instance_top1, 0.0, 1e-12);
  EXPECT_NEAR (per_class[1].scores.nearest_neighbour, 1.0, 1e-12);
  EXPECT_NEAR (per_class[1].scores.first_tier, 1.0, 1e-12);
}

TEST (RecognitionScores, AClassOfOneModelCountsForTheInstanceOnly)
{
  RecognitionScores all;
  std::vector<ClassRecognitionScores> per_class;
  // Query of c/0, the only model of c: no category ranking; its own model is the best.
  ASSERT_TRUE (scoreRecognition ({{0.2, 0.1, 0.9}, {0.3, 0.8, 0.1}}, {2, 0}, {"a", "a", "c"}, all, per_class));
  EXPECT_EQ (all.queries, 2u);
  EXPECT_EQ (all.category_queries, 1u);
  EXPECT_NEAR (all.instance_top1, 0.5, 1e-12);
  EXPECT_NEAR (all.nearest_neighbour, 1.0, 1e-12); // the query of a/0: a/1 first
  EXPECT_NEAR (all.first_tier, 1.0, 1e-12);
  ASSERT_EQ (per_class.size (), 2u);
  EXPECT_EQ (per_class[1].label, "c");
  EXPECT_EQ (per_class[1].scores.category_queries, 0u);
  EXPECT_NEAR (per_class[1].scores.instance_top1, 1.0, 1e-12);
}

TEST (RecognitionScores, RefusesWhatDoesNotFit)
{
  RecognitionScores all;
  std::vector<ClassRecognitionScores> per_class;
  EXPECT_FALSE (scoreRecognition ({{0.1, 0.2}}, {0, 1}, {"a", "b"}, all, per_class));          // rows != queries
  EXPECT_FALSE (scoreRecognition ({{0.1}}, {0}, {"a", "b"}, all, per_class));                  // short row
  EXPECT_FALSE (scoreRecognition ({{0.1, 0.2}}, {2}, {"a", "b"}, all, per_class));             // no model 2
  EXPECT_FALSE (scoreRecognition ({{0.1, std::nan ("")}}, {0}, {"a", "b"}, all, per_class));   // NaN
  EXPECT_TRUE (scoreRecognition ({}, {}, {"a", "b"}, all, per_class));
  EXPECT_EQ (all.queries, 0u);
}

TEST (QueryModels, PairsByRelativePathWithoutExtension)
{
  EXPECT_EQ (withoutExtension ("chair/3.off"), "chair/3");
  EXPECT_EQ (withoutExtension ("v1.2/3"), "v1.2/3");
  EXPECT_EQ (withoutExtension ("a/.hidden"), "a/.hidden");
  std::vector<std::size_t> model_of;
  ASSERT_TRUE (modelsOfQueries ({"chair/3.off", "cup/1.obj", "cup/2.off"}, {"cup/2.pcd", "chair/3.pcd", "cup/2.ply"}, model_of));
  EXPECT_EQ (model_of, (std::vector<std::size_t>{2, 0, 2}));
  const Status missing = modelsOfQueries ({"chair/3.off"}, {"chair/4.pcd"}, model_of);
  EXPECT_FALSE (missing);
  EXPECT_NE (missing.message.find ("chair/4.pcd"), std::string::npos);
  EXPECT_TRUE (model_of.empty ());
  EXPECT_FALSE (modelsOfQueries ({"chair/3.off", "chair/3.ply"}, {"chair/3.pcd"}, model_of));
}

TEST (ViewSphere, IcosahedronAndItsSubdivisions)
{
  for (std::size_t count : {12u, 42u, 162u})
  {
    std::vector<Eigen::Vector3d> d;
    ASSERT_TRUE (viewSphereDirections (count, d));
    ASSERT_EQ (d.size (), count);
    double closest = 4.0;
    Eigen::Vector3d sum = Eigen::Vector3d::Zero ();
    for (std::size_t i = 0; i < d.size (); ++i)
    {
      EXPECT_NEAR (d[i].norm (), 1.0, 1e-12);
      sum += d[i];
      for (std::size_t j = 0; j < i; ++j)
        closest = std::min (closest, (d[i] - d[j]).norm ());
    }
    EXPECT_LT (sum.norm (), 1e-9) << count; // symmetric under x -> -x
    // Spread: the icosahedron's edge is 1.05 on the unit sphere; each subdivision about halves it.
    EXPECT_GT (closest, (count == 12 ? 1.0 : count == 42 ? 0.5 : 0.25)) << count;
  }
  std::vector<Eigen::Vector3d> d;
  EXPECT_FALSE (viewSphereDirections (13, d));
  EXPECT_FALSE (viewSphereDirections (0, d));
  EXPECT_TRUE (d.empty ());
}

TEST (RecognitionMethod, ByName)
{
  std::vector<RecognitionMethod> m;
  ASSERT_TRUE (parseRecognitionMethods ("flowseg,esf,esf-views,parts", m));
  ASSERT_EQ (m.size (), 4u);
  EXPECT_EQ (m[0].kind, RecognitionMethodKind::kSignature);
  EXPECT_EQ (m[0].match, MatchMethod::Combined);
  EXPECT_EQ (m[1].kind, RecognitionMethodKind::kEsf);
  EXPECT_EQ (m[2].kind, RecognitionMethodKind::kEsfViews);
  EXPECT_EQ (m[3].match, MatchMethod::Parts);
  EXPECT_FALSE (parseRecognitionMethods ("esf,esf", m));
  const Status unknown = parseRecognitionMethods ("esf,d2", m);
  EXPECT_FALSE (unknown);
  EXPECT_NE (unknown.message.find ("esf-views"), std::string::npos);
  EXPECT_FALSE (parseRecognitionMethods ("", m));
}

TEST (RenderedViews, TheProtocolCameraFromEachDirection)
{
  const TriangleMesh box = boxMesh ();
  // The protocol's scan along a direction is the protocol's scan: the same camera.
  const RangeScanOptions random = singleViewProtocolScan (box, 0.01, 5);
  const Eigen::Vector3d centre (1.0, 0.5, 0.25);
  const Eigen::Vector3d direction = (random.viewpoint - centre).normalized ();
  const RangeScanOptions along = singleViewProtocolScanAlong (box, direction, 0.01, 5);
  EXPECT_LT ((along.viewpoint - random.viewpoint).norm (), 1e-9);
  EXPECT_NEAR ((random.viewpoint - centre).norm (), 2.0 * box.diagonal (), 1e-9);
  EXPECT_EQ (along.image_pixels, random.image_pixels);
  EXPECT_EQ (along.field_of_view, random.field_of_view);
  EXPECT_EQ (along.noise_model, random.noise_model);

  std::vector<Eigen::Vector3d> directions;
  ASSERT_TRUE (viewSphereDirections (12, directions));
  std::vector<std::vector<Eigen::Vector3d>> views;
  ASSERT_TRUE (renderProtocolViews (box, directions, views));
  ASSERT_EQ (views.size (), 12u);
  for (std::size_t k = 0; k < views.size (); ++k)
  {
    ASSERT_GT (views[k].size (), 100u) << k;
    // A convex shape shows its near side: the points' mean lies towards the camera.
    Eigen::Vector3d mean = Eigen::Vector3d::Zero ();
    for (const auto& p : views[k])
      mean += p / static_cast<double> (views[k].size ());
    EXPECT_GT ((mean - centre).dot (directions[k]), 0.05) << k;
  }
  std::vector<std::vector<double>> esf;
  ASSERT_TRUE (esfOfProtocolViews (box, directions, esf));
  ASSERT_EQ (esf.size (), 12u);
  for (const auto& h : esf)
    EXPECT_EQ (h.size (), 640u);
}

TEST (RenderedViews, TheNearestViewCounts)
{
  const std::vector<double> query = {0.5, 0.5, 0.0};
  EXPECT_EQ (bestViewSimilarity (query, {}), 0.0);
  EXPECT_NEAR (bestViewSimilarity (query, {{0.0, 0.0, 1.0}, {0.5, 0.25, 0.25}, {0.0, 1.0, 0.0}}), 0.75, 1e-12);
  EXPECT_NEAR (bestViewSimilarity (query, {{0.0, 0.0, 1.0}, {0.5, 0.5, 0.0}}), 1.0, 1e-12);
}

/*
 * Signature database file, queries, retrieval scores and the PNG writer.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include "test_support.h"

#include <pcl_flowseg/common/parallel_jobs.h>
#include <pcl_flowseg/evaluation/png_writer.h>
#include <pcl_flowseg/evaluation/retrieval_figures.h>
#include <pcl_flowseg/evaluation/retrieval_report.h>
#include <pcl_flowseg/evaluation/retrieval_scores.h>
#include <pcl_flowseg/evaluation/shape_distributions.h>
#include <pcl_flowseg/signature/signature_database.h>

#include <gtest/gtest.h>

#include <atomic>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <sstream>
#include <unistd.h>

using namespace pcl_flowseg;
using V = Eigen::Vector3d;

namespace {
std::string
tempPath (const std::string& name)
{
  return "/tmp/flowseg_db_test_" + std::to_string (::getpid ()) + "_" + name;
}

ShapeEntry
entry (const std::string& name, const std::string& label, const std::vector<WeightedPoint>& points)
{
  ShapeEntry e;
  e.name = name;
  e.label = label;
  e.signature.points = points;
  return e;
}
} // namespace

TEST (Database, SaveLoadAddQuery)
{
  SignatureDatabase db;
  EXPECT_TRUE (db.add (entry ("a b/one.pcd", "a", {{V (0, 0, 0), 0.6}, {V (1, 0, 0), 0.4}})));
  EXPECT_TRUE (db.add (entry ("two.pcd", "b", {{V (0, 0, 0), 0.5}, {V (0, 2, 0), 0.3}, {V (0, 0, 1), 0.2}})));
  EXPECT_FALSE (db.add (entry ("two.pcd", "b", {{V (0, 0, 0), 1.0}}))) << "same name replaces";
  EXPECT_EQ (db.size (), 2u);
  const std::string path = tempPath ("ok.db");
  ASSERT_TRUE (db.save (path).ok);
  SignatureDatabase back;
  ASSERT_TRUE (back.load (path).ok);
  ASSERT_EQ (back.size (), 2u);
  EXPECT_EQ (back.entries ()[0].name, "a b/one.pcd");
  EXPECT_EQ (back.entries ()[1].signature.points.size (), 1u);
  EXPECT_DOUBLE_EQ (back.entries ()[0].signature.points[1].weight, 0.4);

  Signature q;
  q.points = {{V (5, 5, 5), 0.61}, {V (5, 5, 6), 0.39}}; // the first shape, moved and turned
  pcl::SignatureMatcher matcher;
  matcher.setMethod (MatchMethod::Paper); // hand-made signatures have no descriptions
  const auto hits = back.query (q, 1, matcher);
  ASSERT_EQ (hits.size (), 1u);
  EXPECT_EQ (back.entries ()[hits[0].entry].name, "a b/one.pcd");
  EXPECT_GT (hits[0].similarity, 0.95);
  std::remove (path.c_str ());
}

TEST (Database, CorruptOrForeignFilesAreRejectedWithTheLine)
{
  SignatureDatabase db;
  auto write = [] (const std::string& name, const std::string& text) {
    const std::string p = tempPath (name);
    std::ofstream (p) << text;
    return p;
  };
  const std::string head = "pcl_flowseg signature database 7\nshapes 1\n";
  const std::string no_views = "views 0 0\no 0\n"; // a shape's views line and its empty shape points
  const auto view_line = [] (const std::string& direction, const std::string& scale) { // a view: direction, centre, scale, histogram
    std::string line = "v " + direction + " 0 0 0 0 " + scale;
    for (std::size_t k = 0; k < kViewHistogramBins; ++k)
      line += " 0";
    return line + "\n";
  };
  const std::string two_points = "u 2 0 0 0 0 0 1 1 0 0 0 0 1\n"; // two view points with their normals
  const auto bins = [] (const std::string& tag) { // a distribution line: all in the first bin
    std::string line = tag + " 1";
    for (std::size_t k = 1; k < kDistributionBins; ++k)
      line += " 0";
    return line + "\n";
  };
  std::string profiles, thickness_profile = "h"; // the 16 rows of inner-distance profiles, the thickness profile
  for (std::size_t r = 0; r < kProfileRows; ++r)
  {
    profiles += bins ("r");
    thickness_profile += " -1";
  }
  thickness_profile += "\n";
  std::string contour_row = "c 1"; // a contour histogram: all in the first bin
  for (std::size_t k = 1; k < kContourBins; ++k)
    contour_row += " 0";
  contour_row += "\n";
  std::string context_row = "x -1 1"; // an inner context: all in the first bin
  for (std::size_t k = 1; k < kContextBins; ++k)
    context_row += " 0";
  context_row += "\n";
  const std::string description = bins ("t") + bins ("i") + bins ("s") + profiles + thickness_profile;
  struct Case { std::string text, expected; };
  const std::vector<Case> cases = {
      {"hello world\n", "not a pcl_flowseg signature database"},
      {"pcl_flowseg signature database 8\nshapes 0\n", "version"},
      {"pcl_flowseg signature database 7\nshapes x\n", ":2:"},
      // Version 1 (no descriptions) is refused with what to do, never misread.
      {"pcl_flowseg signature database 1\nshapes 1\nshape a 3 1 1 0.02 1 name\np 0 0 0 1\n", ":1: a version 1 database"},
      {"pcl_flowseg signature database 2\nshapes 0\n", ":1: a version 2 database (signatures without inner-distance and thickness profiles"},
      {"pcl_flowseg signature database 3\nshapes 0\n", ":1: a version 3 database (signatures without 2D contours"},
      {"pcl_flowseg signature database 4\nshapes 0\n", ":1: a version 4 database (signatures without inner-distance contexts"},
      {"pcl_flowseg signature database 5\nshapes 0\n", ":1: a version 5 database (signatures without the parts' remoteness"},
      {"pcl_flowseg signature database 6\nshapes 0\n", ":1: a version 6 database (signatures without views for single-view scans"},
      // A count the file cannot hold is refused before anything is allocated (fuzzing: 44 million
      // shapes in a 49-byte file asked for 4 GB).
      {"pcl_flowseg signature database 7\nshapes 44204242\n", ":2: 44204242 shapes cannot fit"},
      {"pcl_flowseg signature database 7\nshapes -1\n", ":2:"},
      {head + "shape a 3 1 1 0.02 2 0 0 0 name\np 0 0 0 0.5\n", ":5:"},
      {head + "shape a 3 1 1 0.02 1 0 0 0 name\np 0 0 nan 0.5\n", ":4:"},
      {head + "shape a 4 1 1 0.02 1 0 0 0 name\np 0 0 0 1\n", ":3:"},
      {head + "shape a 3 1 1 0.02 1 0 0 0\np 0 0 0 1\n", "name"},
      // Numbers that parse but are absurd: refused at their line, never handed to a query.
      {head + "shape a 3 1 1 0.02 1 0 0 0 name\np 0 0 1 88888888888888888888888888888880.6\n", ":4: the weight"},
      {head + "shape a 3 1 1 0.02 1 0 0 0 name\np 1e300 0 0 1\n", ":4: coordinates"},
      {head + "shape a 3 1 1 0.02 1 0 0 0 name\np 0 0 0 -0.5\n", ":4: the weight"},
      {head + "shape a 3 0 1 0.02 1 0 0 0 name\np 0 0 0 1\n" + no_views, ":3: shape 'name': the unit"},
      {head + "shape a 3 1 1 0.02 2 0 0 0 name\np 0 0 0 0.5\np 1 0 0 0.2\n" + no_views, ":3: shape 'name': the weights sum"},
      {head + "shape a 3 1 1 0.02 2 0 0 0 name\np 0 0 0 0.4\np 1 0 0 0.6\n" + no_views, ":3: shape 'name': the points are not ordered"},
      {head + "shape a 3 1 1 1.5 1 0 0 0 name\np 0 0 0 1\n" + no_views, ":3: shape 'name': "},
      // Descriptions: every line and number checked.
      {head + "shape a 3 1 1 0.02 1 17 0 0 name\np 0 0 0 1\n", ":3: expected 'shape"},
      {head + "shape a 3 1 1 0.02 1 1 0 0 name\np 0 0 0 1\nq 1 0.5 0.5 0.5\n", ":5: expected 'q"},
      {head + "shape a 3 1 1 0.02 1 1 0 0 name\np 0 0 0 1\nq 1 0.5 0.5 0.5 0.5 0\nt 1 0 0\n", ":6: expected 't' and 32 numbers"},
      {head + "shape a 3 1 1 0.02 1 1 0 0 name\np 0 0 0 1\nq 0.5 0.5 0.5 0.5 0.5 0\n" + bins ("t") + bins ("i") + bins ("s") + profiles + thickness_profile + no_views,
       ":3: shape 'name': the part weights sum"},
      {head + "shape a 3 1 1 0.02 1 1 0 0 name\np 0 0 0 1\nq 1 0 0.5 0.5 0.5 0\n" + bins ("t") + bins ("i") + bins ("s") + profiles + thickness_profile + no_views,
       ":3: shape 'name': part 1 has a thickness"},
      // Version 2 descriptions have no inner-distance profiles: refused at their first missing row.
      {head + "shape a 3 1 1 0.02 1 1 0 0 name\np 0 0 0 1\nq 1 0.5 0.5 0.5 0.5 0\n" + bins ("t") + bins ("i") + bins ("s"),
       ":9: expected 'r' and 32 numbers"},
      {head + "shape a 3 1 1 0.02 1 1 0 0 name\np 0 0 0 1\nq 1 0.5 0.5 0.5 0.5 0\n" + bins ("t") + bins ("i") + bins ("s") +
           profiles.substr (0, profiles.size () / kProfileRows * (kProfileRows - 1)) + "r 0.5 0.4" + bins ("").substr (4) +
           thickness_profile + no_views,
       ":3: shape 'name': the inner-distance profile distribution sums to 0.9"},
      {head + "shape a 3 1 1 0.02 1 1 0 0 name\np 0 0 0 1\nq 1 0.5 0.5 0.5 0.5 0\n" + bins ("t") + bins ("i") + bins ("s") + profiles +
           "h -1 -1\n",
       ":25: expected 'h' and 16 numbers"},
      {head + "shape a 3 1 1 0.02 1 1 0 0 name\np 0 0 0 1\nq 1 0.5 0.5 0.5 0.5 0\n" + bins ("t") + bins ("i") + bins ("s") + profiles +
           "h 7" + thickness_profile.substr (4) + no_views,
       ":3: shape 'name': the thickness profile has an entry outside"},
      {head + "shape a 3 1 1 0.02 1 1 0 0 name\np 0 0 0 1\nq 1 0.5 0.5 0.5 0.5 0\n" + bins ("t") + bins ("i") + "s 0.5 0.5 0.5\n",
       ":8: expected 's'"},
      // Contours: a count above kContourPoints, a short line, a count other than 0 or kContourPoints.
      {head + "shape a 2 1 1 0.02 1 1 65 0 name\np 0 0 0 1\n", ":3: expected 'shape"},
      {head + "shape a 2 1 1 0.02 1 1 1 0 name\np 0 0 0 1\nq 1 0.5 0.5 0.5 0.5 0\n" + bins ("t") + bins ("i") + bins ("s") + profiles +
           thickness_profile + "c 1 0 0\n",
       ":26: expected 'c' and 60 numbers"},
      {head + "shape a 2 1 1 0.02 1 1 1 0 name\np 0 0 0 1\nq 1 0.5 0.5 0.5 0.5 0\n" + bins ("t") + bins ("i") + bins ("s") + profiles +
           thickness_profile + contour_row + no_views,
       ":3: shape 'name': the contour has 1 histograms, not 0 or 64"},
      // Inner contexts: a count above kDistanceSources, a short line, none with parts, a histogram
      // that does not sum to 1, a thickness outside the range.
      {head + "shape a 3 1 1 0.02 1 1 0 65 name\np 0 0 0 1\n", ":3: expected 'shape"},
      {head + "shape a 3 1 1 0.02 1 1 0 1 name\np 0 0 0 1\nq 1 0.5 0.5 0.5 0.5 0\n" + description + "x -1 1 0\n",
       ":26: expected 'x' and 17 numbers"},
      {head + "shape a 3 1 1 0.02 1 1 0 0 name\np 0 0 0 1\nq 1 0.5 0.5 0.5 0.5 0\n" + description + no_views,
       ":3: shape 'name': the description has 0 inner contexts, not 1 to 64"},
      {head + "shape a 3 1 1 0.02 1 1 0 1 name\np 0 0 0 1\nq 1 0.5 0.5 0.5 0.5 0\n" + description + "x -1 0.5" + context_row.substr (6) + no_views,
       ":3: shape 'name': an inner-context histogram sums to 0.5"},
      {head + "shape a 3 1 1 0.02 1 1 0 1 name\np 0 0 0 1\nq 1 0.5 0.5 0.5 0.5 0\n" + description + "x 3" + context_row.substr (4) + no_views,
       ":3: shape 'name': an inner context's thickness is outside the thickness range"},
      // Views: the line, each view's two lines, and the values checked.
      {head + "shape a 3 1 1 0.02 1 0 0 0 name\np 0 0 0 1\n", ":5: expected 'views N SINGLE'"},
      {head + "shape a 3 1 1 0.02 1 0 0 0 name\np 0 0 0 1\nviews 1 2\n", ":5: expected 'views N SINGLE'"},
      {head + "shape a 3 1 1 0.02 1 0 0 0 name\np 0 0 0 1\nviews 1 0\nv 0 0 1 0 0 0 1 0.5\n", ":6: expected 'v DX DY DZ ROLL"},
      {head + "shape a 3 1 1 0.02 1 0 0 0 name\np 0 0 0 1\nviews 1 0\n" + view_line ("0 0 1", "1") + "u 999\n",
       ":7: expected 'u N' (N at most 128)"},
      {head + "shape a 3 1 1 0.02 1 0 0 0 name\np 0 0 0 1\nviews 1 0\n" + view_line ("0 0 1", "1") + "u 2 0 0 0 0 0 1 1\n",
       ":7: expected 'u N' and 2 points of 6 numbers"},
      {head + "shape a 3 1 1 0.02 1 0 0 0 name\np 0 0 0 1\nviews 1 0\n" + view_line ("0 0 2", "1") + two_points + "o 0\n",
       ":3: shape 'name': a view direction is not a unit vector"},
      {head + "shape a 3 1 1 0.02 1 0 0 0 name\np 0 0 0 1\nviews 1 0\n" + view_line ("0 0 1", "-1") + two_points + "o 0\n",
       ":3: shape 'name': a view's centre or roll is not finite or its scale not > 0"},
      {head + "shape a 3 1 1 0.02 1 0 0 0 name\np 0 0 0 1\nviews 2 1\n" + view_line ("0 0 1", "1") + two_points +
           view_line ("0 0 1", "1") + two_points + "o 0\n",
       ":3: shape 'name': a single-view set needs exactly one view, it has 2"},
      {head + "shape a 3 1 1 0.02 1 0 0 0 name\np 0 0 0 1\nviews 0 0\no 1 0 0 0 0 0 2\n", ":3: shape 'name': a normal is not a unit vector"},
      {"", "not a pcl_flowseg"},
  };
  for (std::size_t k = 0; k < cases.size (); ++k)
  {
    const std::string p = write ("bad" + std::to_string (k), cases[k].text);
    const Status s = db.load (p);
    EXPECT_FALSE (s.ok) << k;
    EXPECT_NE (s.message.find (cases[k].expected), std::string::npos) << k << ": " << s.message;
    EXPECT_EQ (db.size (), 0u);
    std::remove (p.c_str ());
  }
  EXPECT_FALSE (db.load ("/nonexistent/x.db").ok);
}

TEST (Retrieval, ScoresOfAKnownMatrix)
{
  // Four shapes, two classes; shape 0 ranks (1, 2, 3), shape 2 ranks (0, 3, 1).
  const std::vector<std::string> labels = {"a", "a", "b", "b"};
  const std::vector<std::vector<double>> m = {
      {1, 0.9, 0.5, 0.1}, {0.9, 1, 0.2, 0.1}, {0.8, 0.1, 1, 0.7}, {0.1, 0.2, 0.8, 1}};
  RetrievalScores s;
  ASSERT_TRUE (scoreRetrieval (m, labels, s));
  EXPECT_EQ (s.queries, 4u);
  EXPECT_DOUBLE_EQ (s.nearest_neighbour, 0.75); // shape 2's best match is shape 0
  EXPECT_DOUBLE_EQ (s.first_tier, 0.75);
  EXPECT_DOUBLE_EQ (s.second_tier, 1.0);
  // DCG (Princeton convention, rank 1 undiscounted, rank r >= 2 discounted by log2 r): shape 2's
  // single hit at rank 2 gains 1/log2 2 = 1, as much as the ideal hit at rank 1.
  EXPECT_DOUBLE_EQ (s.dcg, 1.0);
  // Bull's eye: top 2C = 4 including the query: all of each class.
  EXPECT_DOUBLE_EQ (s.bulls_eye, 1.0);
  // A matrix that does not fit the labels is refused, not read out of bounds.
  std::vector<std::vector<double>> short_row = m;
  short_row[2].pop_back ();
  EXPECT_FALSE (scoreRetrieval (short_row, labels, s));
  EXPECT_FALSE (scoreRetrieval ({m.begin (), m.begin () + 3}, labels, s));
  std::vector<std::vector<double>> with_nan = m;
  with_nan[1][3] = std::nan ("");
  const Status refused = scoreRetrieval (with_nan, labels, s);
  EXPECT_FALSE (refused);
  EXPECT_NE (refused.message.find ("NaN"), std::string::npos) << refused.message;
}

TEST (Retrieval, D2IsInvariantAndDiscriminates)
{
  const auto a = flowseg_test::shapeSample ("snowman3d", 3000, 1);
  std::vector<V> moved;
  for (const auto& p : a)
    moved.push_back (2.5 * (Eigen::AngleAxisd (0.5, V (0, 1, 1).normalized ()) * p) + V (1, 2, 3));
  const auto other = flowseg_test::shapeSample ("dumbbell3d", 3000, 1);
  const auto ha = d2Distribution (a), hm = d2Distribution (moved), ho = d2Distribution (other);
  EXPECT_GT (histogramSimilarity (ha, hm), 0.97);
  EXPECT_LT (histogramSimilarity (ha, ho), histogramSimilarity (ha, hm));
  std::vector<double> ea;
  ASSERT_TRUE (esfDescriptor (a, ea));
  EXPECT_EQ (ea.size (), 640u);
  double sum = 0.0;
  for (double v : ea)
    sum += v;
  EXPECT_NEAR (sum, 1.0, 1e-9);
}

TEST (Png, WellFormed)
{
  const std::string p = tempPath ("m.png");
  ASSERT_TRUE (writeSimilarityPng (p, {{1, 0.5}, {0.5, 1}}, 5, 3).ok);
  std::ifstream in (p, std::ios::binary);
  std::string bytes ((std::istreambuf_iterator<char> (in)), std::istreambuf_iterator<char> ());
  ASSERT_GT (bytes.size (), 50u);
  EXPECT_EQ (bytes.substr (1, 3), "PNG");
  EXPECT_NE (bytes.find ("IHDR"), std::string::npos);
  EXPECT_EQ (bytes.substr (bytes.size () - 8, 4), "IEND");
  EXPECT_FALSE (writePng (p, 2, 2, 1, std::vector<std::uint8_t> (3)).ok);
  std::remove (p.c_str ());
}

TEST (Database, CandidateIndexAlignsTheNearestSummariesFirst)
{
  // Many stored shapes: ones made of two equal points, of three, ... and one copy of the query
  // (turned by a quarter turn, which the summary and the matcher ignore).
  SignatureDatabase db;
  for (int n = 1; n <= 8; ++n)
    for (int copy = 0; copy < 10; ++copy)
    {
      std::vector<WeightedPoint> pts;
      for (int i = 0; i < n; ++i)
        pts.push_back (WeightedPoint{Eigen::Vector3d (std::cos (i + 0.1 * copy), std::sin (i + 0.1 * copy), 0.1 * copy), 1.0 / n});
      db.add (entry ("n" + std::to_string (n) + "_" + std::to_string (copy), "n" + std::to_string (n), pts));
    }
  const std::vector<WeightedPoint> query_points = {WeightedPoint{Eigen::Vector3d (2, 0, 0), 0.6}, WeightedPoint{Eigen::Vector3d (0, 1, 0), 0.3},
                                                   WeightedPoint{Eigen::Vector3d (0, 0, -1), 0.1}};
  std::vector<WeightedPoint> turned = query_points;
  for (auto& p : turned)
    p.position = Eigen::Vector3d (-p.position.y (), p.position.x (), p.position.z ());
  db.add (entry ("copy", "target", turned));
  Signature query;
  query.points = query_points;
  pcl::SignatureMatcher matcher;
  matcher.setMethod (MatchMethod::Paper);

  db.setCandidates (5);
  const auto hits = db.query (query, 0, matcher);
  ASSERT_EQ (hits.size (), db.size ());
  EXPECT_EQ (db.entries ()[hits[0].entry].name, "copy");
  EXPECT_NEAR (hits[0].similarity, 1.0, 1e-6);
  EXPECT_NEAR (hits[0].summary_distance, 0.0, 1e-5);
  for (std::size_t r = 0; r < hits.size (); ++r)
    EXPECT_EQ (hits[r].compared, r < 5) << r;
  for (std::size_t r = 6; r < hits.size (); ++r) // the unaligned follow by summary distance
    EXPECT_LE (hits[r - 1].summary_distance, hits[r].summary_distance);

  // Every shape aligned: the same best match, and every similarity set and ordered.
  db.setCandidates (0);
  const auto all = db.query (query, 0, matcher);
  ASSERT_EQ (all.size (), db.size ());
  EXPECT_EQ (db.entries ()[all[0].entry].name, "copy");
  for (std::size_t r = 1; r < all.size (); ++r)
  {
    EXPECT_TRUE (all[r].compared);
    EXPECT_GE (all[r - 1].similarity, all[r].similarity);
  }
  // The candidates are compared on several threads; one gives the same hits in the same order.
  db.setQueryThreads (1);
  const auto one = db.query (query, 0, matcher);
  ASSERT_EQ (one.size (), all.size ());
  for (std::size_t r = 0; r < all.size (); ++r)
  {
    EXPECT_EQ (one[r].entry, all[r].entry) << r;
    EXPECT_EQ (one[r].similarity, all[r].similarity) << r;
  }
  db.setQueryThreads (0);
  // Replacing a shape by name keeps the count and is seen by the next query (index rebuilt).
  EXPECT_FALSE (db.add (entry ("copy", "target", {WeightedPoint{Eigen::Vector3d (0, 0, 0), 1.0}})));
  EXPECT_EQ (db.size (), 81u);
  EXPECT_NE (db.entries ()[db.query (query, 1, matcher)[0].entry].name, "copy");
}

TEST (ParallelJobs, EveryJobOnceAndProgressCountsUp)
{
  for (unsigned threads : {1u, 2u, 0u})
  {
    std::vector<int> runs (57, 0);
    std::vector<std::size_t> dones;
    runParallelJobs (runs.size (), threads, [&] (std::size_t i) { ++runs[i]; },
                     [&] (std::size_t done, std::size_t index) {
                       dones.push_back (done);
                       EXPECT_EQ (runs[index], 1);
                     });
    EXPECT_EQ (std::count (runs.begin (), runs.end (), 1), 57) << threads;
    ASSERT_EQ (dones.size (), 57u);
    for (std::size_t k = 0; k < dones.size (); ++k)
      EXPECT_EQ (dones[k], k + 1);
  }
  EXPECT_GE (jobThreads (0), 1u);
  EXPECT_EQ (jobThreads (3), 3u);
  EXPECT_EQ (threadsPerJob (10, 1), 1u); // -j 1: sequential all the way down
  EXPECT_EQ (threadsPerJob (10, 2), 1u); // two jobs at a time share the cores
  EXPECT_EQ (threadsPerJob (1, 2), 2u);  // one job gets them all
  EXPECT_EQ (threadsPerJob (1, 0), 0u);
  EXPECT_EQ (threadsPerJob (10, 0), jobThreads (0) > 1 ? 1u : 0u);
  runParallelJobs (0, 2, [] (std::size_t) { ADD_FAILURE () << "no job to run"; });
}

TEST (Retrieval, SimilarityMatrixAndScoresFile)
{
  const std::vector<std::string> labels = {"a", "a", "b", "b"};
  auto sim = [&] (std::size_t i, std::size_t j) { return labels[i] == labels[j] ? 1.0 + 0.1 * i : 0.1 * static_cast<double> (j); };
  const auto m = similarityMatrix (labels.size (), sim, 2);
  ASSERT_EQ (m.size (), 4u);
  for (std::size_t i = 0; i < 4; ++i)
    for (std::size_t j = 0; j < 4; ++j)
      EXPECT_EQ (m[i][j], sim (i, j));
  // A symmetric similarity: each pair once, the same matrix.
  auto symmetric = [&] (std::size_t i, std::size_t j) { return 1.0 / (1.0 + static_cast<double> (i + j)) + (labels[i] == labels[j]); };
  std::atomic<int> calls{0};
  const auto half = symmetricSimilarityMatrix (labels.size (), [&] (std::size_t i, std::size_t j) {
    ++calls;
    return symmetric (i, j);
  }, 2);
  EXPECT_EQ (calls.load (), 10);
  for (std::size_t i = 0; i < 4; ++i)
    for (std::size_t j = 0; j < 4; ++j)
      EXPECT_EQ (half[i][j], symmetric (i, j)) << i << " " << j;
  MethodEvaluation e;
  e.name = "flow\"seg";
  ASSERT_TRUE (scoreRetrieval (m, labels, e.scores));
  EXPECT_EQ (e.scores.nearest_neighbour, 1.0);
  char dir[] = "/tmp/flowseg_scores_XXXXXX";
  ASSERT_NE (mkdtemp (dir), nullptr);
  const std::string path = std::string (dir) + "/scores.json";
  ASSERT_TRUE (writeRetrievalScoresJson (path, "root \"x\"", 4, true, {e}));
  std::ifstream in (path);
  const std::string json ((std::istreambuf_iterator<char> (in)), std::istreambuf_iterator<char> ());
  EXPECT_NE (json.find ("\"root\": \"root \\\"x\\\"\""), std::string::npos) << json;
  EXPECT_NE (json.find ("\"flow\\\"seg\": {\"nearest_neighbour\": 1.0000"), std::string::npos) << json;
  EXPECT_NE (json.find ("\"bulls_eye\": 1"), std::string::npos) << json;
  EXPECT_FALSE (writeRetrievalScoresJson (std::string (dir) + "/no/such/dir/scores.json", "r", 4, false, {e}));
  std::remove (path.c_str ());
  rmdir (dir);
}

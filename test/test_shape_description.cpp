/*
 * Shape descriptions (parts and interior distributions), the earth mover's distance between parts,
 * the description matching methods and their storage in the database.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include "test_support.h"

#include "signature/assignment_cost.h"
#include "signature/interior_graph.h"
#include "signature/transport_distance.h"

#include <pcl_flowseg/signature/describe_shape.h>
#include <pcl_flowseg/signature/signature_database.h>
#include <pcl_flowseg/signature/shape_signature.h>
#include <pcl_flowseg/signature/signature_matcher.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <numeric>
#include <random>
#include <unistd.h>

using namespace pcl_flowseg;
using V = Eigen::Vector3d;

namespace {

using flowseg_test::signatureOf;

/** A resampled copy of a sample shape, rotated, mirrored, scaled and moved. */
std::vector<V>
movedCopy (const std::string& name, std::size_t n)
{
  const bool planar = name.find ("2d") != std::string::npos;
  const Eigen::Matrix3d r = Eigen::AngleAxisd (1.1, planar ? V (0, 0, 1) : V (1, -2, 0.5).normalized ()).toRotationMatrix ();
  std::vector<V> out;
  for (V p : flowseg_test::shapeSample (name, n, 99))
  {
    p.y () = -p.y ();
    out.push_back (3.5 * (r * p) + V (4, -7, planar ? 0 : 2));
  }
  return out;
}

double
matchWith (MatchMethod method, const Signature& a, const Signature& b)
{
  pcl::SignatureMatcher matcher;
  matcher.setMethod (method);
  return matcher.match (a, b).similarity;
}

} // namespace

TEST (TransportDistance, EqualWeightsCostTheBestPermutation)
{
  std::mt19937 random (3);
  std::uniform_real_distribution<double> uniform (0.0, 1.0);
  for (int trial = 0; trial < 20; ++trial)
  {
    const int n = 5;
    Eigen::MatrixXd cost (n, n);
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j)
        cost (i, j) = uniform (random);
    std::vector<int> order (n);
    std::iota (order.begin (), order.end (), 0);
    double best = 1e300;
    do
    {
      double sum = 0.0;
      for (int i = 0; i < n; ++i)
        sum += cost (i, order[static_cast<std::size_t> (i)]) / n;
      best = std::min (best, sum);
    } while (std::next_permutation (order.begin (), order.end ()));
    const std::vector<double> w (n, 1.0 / n);
    EXPECT_NEAR (transportDistance (w, w, cost), best, 1e-12) << trial;
  }
}

TEST (AssignmentCost, TheBestOfAllAssignmentsSquareOrNot)
{
  std::mt19937 random (5);
  std::uniform_real_distribution<double> uniform (0.0, 1.0);
  for (std::size_t rows : {1u, 3u, 6u})
    for (int trial = 0; trial < 10; ++trial)
    {
      const std::size_t columns = 6;
      std::vector<double> cost (rows * columns);
      for (double& c : cost)
        c = uniform (random);
      // Every assignment of the rows: the first rows entries of every permutation of the columns.
      std::vector<std::size_t> order (columns);
      std::iota (order.begin (), order.end (), 0);
      double best = 1e300;
      do
      {
        double sum = 0.0;
        for (std::size_t i = 0; i < rows; ++i)
          sum += cost[i * columns + order[i]];
        best = std::min (best, sum);
      } while (std::next_permutation (order.begin (), order.end ()));
      EXPECT_NEAR (leastAssignmentCost (cost, rows, columns), best, 1e-12) << rows << " " << trial;
    }
  EXPECT_EQ (leastAssignmentCost ({}, 0, 4), 0.0);
  // The greedy first choice (row 0 -> column 0) is wrong.
  EXPECT_NEAR (leastAssignmentCost ({0.0, 1.0, 0.1, 10.0}, 2, 2), 1.1, 1e-12);
}

TEST (TransportDistance, SplitsAndUnequalTotals)
{
  Eigen::MatrixXd cost (1, 3);
  cost << 1.0, 2.0, 4.0;
  // One unit spread over three: every destination gets its share.
  EXPECT_NEAR (transportDistance ({1.0}, {0.5, 0.25, 0.25}, cost), 0.5 * 1 + 0.25 * 2 + 0.25 * 4, 1e-12);
  // The destination weights are scaled to the source total.
  EXPECT_NEAR (transportDistance ({2.0}, {1.0, 1.0, 2.0}, cost), 0.5 * 1 + 0.5 * 2 + 1.0 * 4, 1e-12);
  // A cheap route that must be undone: 2 x 2, the greedy first choice (0 -> 0) is wrong.
  Eigen::MatrixXd c2 (2, 2);
  c2 << 0.0, 1.0, 0.1, 10.0;
  EXPECT_NEAR (transportDistance ({0.5, 0.5}, {0.5, 0.5}, c2), 0.5 * 1.0 + 0.5 * 0.1, 1e-12);
  EXPECT_EQ (transportDistance ({}, {1.0}, Eigen::MatrixXd (0, 1)), 0.0);
}

TEST (ShapeDescription, PartsAndDistributionsOfTheAnimal)
{
  FlowResult r;
  ASSERT_TRUE (runFlowSegmentation (flowseg_test::shapeSample ("animal3d", 4000), FlowParameters (), r).ok);
  ShapeDescription d;
  ASSERT_TRUE (describeShape (r, d).ok);
  EXPECT_TRUE (checkShapeDescription (d).ok);
  ASSERT_GE (d.parts.size (), 6u); // body, head, four legs
  EXPECT_LE (d.parts.size (), kMaxParts);
  EXPECT_GT (d.parts[0].weight, 0.4); // the body
  // The body is thicker than the thinnest part (a leg or the tail) and is the least remote (nearest to everything by inner distance).
  const auto thinnest = std::min_element (d.parts.begin (), d.parts.end (),
                                          [] (const PartDescription& a, const PartDescription& b) { return a.thickness < b.thickness; });
  EXPECT_GT (d.parts[0].thickness, 1.5 * thinnest->thickness);
  for (std::size_t k = 1; k < d.parts.size (); ++k)
    EXPECT_LT (d.parts[0].remoteness, d.parts[k].remoteness) << k;
  // Seen from the centre out, the thick body comes first and the thin ends of the legs last.
  EXPECT_GT (d.thickness_profile.front (), d.thickness_profile.back () + 0.5);
  // The same result describes the same way: the sampling seed is fixed.
  ShapeDescription again;
  ASSERT_TRUE (describeShape (r, again).ok);
  EXPECT_EQ (again.thickness, d.thickness);
  EXPECT_EQ (again.inner_distance, d.inner_distance);
  ASSERT_EQ (again.parts.size (), d.parts.size ());
  EXPECT_EQ (again.parts.back ().extent, d.parts.back ().extent);
  // Nor do the worker threads of the inner-distance searches change it (default: all cores).
  for (unsigned threads : {1u, 2u, 3u})
  {
    r.parameters.execution.threads = threads;
    ShapeDescription with;
    ASSERT_TRUE (describeShape (r, with).ok);
    EXPECT_EQ (with.inner_distance, d.inner_distance) << threads;
    EXPECT_EQ (with.solid_distance, d.solid_distance) << threads;
    EXPECT_EQ (with.inner_profiles, d.inner_profiles) << threads;
    EXPECT_EQ (with.thickness_profile, d.thickness_profile) << threads;
  }
}

namespace {

/** Boundary samples of a 2D bar of \a length and width 0.6, bent along a circular arc through
  * \a bend radians (0: straight). */
std::vector<V>
barSample (double length, double bend)
{
  std::vector<V> pts;
  const double half_width = 0.1;
  const auto place = [&] (double s, double t) { // s along the bar, t across it
    if (bend == 0.0)
      return V (s, t, 0.0);
    const double radius = length / bend, angle = bend * s / length;
    return V ((radius + t) * std::cos (angle), (radius + t) * std::sin (angle), 0.0);
  };
  const int steps = static_cast<int> (100 * length);
  for (int k = 0; k <= steps; ++k)
    for (double t : {-half_width, half_width})
      pts.push_back (place (length * k / steps, t));
  for (int k = 1; k < 8; ++k)
  {
    const double t = -half_width + 2.0 * half_width * k / 8.0;
    pts.push_back (place (0.0, t));
    pts.push_back (place (length, t));
  }
  return pts;
}

} // namespace

TEST (InteriorEdges, EveryEdgeOfTheInteriorCellsOnceInOrderOnAnyThreads)
{
  for (const char* name : {"animal3d", "hand2d"})
    for (unsigned threads : {1u, 2u})
    {
      FlowParameters params;
      params.execution.threads = threads;
      FlowResult r;
      ASSERT_TRUE (runFlowSegmentation (flowseg_test::shapeSample (name, 3000), params, r).ok) << name;
      // The plain construction: all ordered corner pairs of the interior cells, sorted, unique.
      std::vector<std::pair<int, int>> pairs;
      for (const FlowCell& c : r.cells)
        for (int a = 0; c.inside == 1 && a <= r.dimension; ++a)
          for (int b = 0; b <= r.dimension; ++b)
            if (a != b)
              pairs.emplace_back (c.vertices[static_cast<std::size_t> (a)], c.vertices[static_cast<std::size_t> (b)]);
      std::sort (pairs.begin (), pairs.end ());
      pairs.erase (std::unique (pairs.begin (), pairs.end ()), pairs.end ());
      ASSERT_GT (pairs.size (), r.vertices.size ()) << name;
      const InteriorEdges edges (r);
      ASSERT_EQ (edges.first.size (), r.vertices.size () + 1) << name;
      ASSERT_EQ (edges.to.size (), pairs.size ()) << name;
      ASSERT_EQ (edges.length.size (), pairs.size ()) << name;
      for (std::size_t v = 0; v < r.vertices.size (); ++v)
        for (std::size_t e = edges.first[v]; e < edges.first[v + 1]; ++e)
        {
          ASSERT_EQ (pairs[e], std::make_pair (static_cast<int> (v), edges.to[e])) << name << " edge " << e;
          ASSERT_EQ (edges.length[e], (r.vertices[v] - r.vertices[static_cast<std::size_t> (edges.to[e])]).norm ());
        }
    }
}

TEST (InteriorEdges, ShortestPathsEqualRelaxingEveryEdgeUntilNothingChanges)
{
  // Random graphs with unreachable parts, several seeds with their own start distances: the
  // search's distances are exactly the fixed point of relaxing every edge (Bellman-Ford), which
  // takes the same sums whatever the order.
  std::mt19937 random (7);
  for (int round = 0; round < 20; ++round)
  {
    const int n = 40 + round * 10;
    std::uniform_int_distribution<int> vertex (0, n - 1);
    std::uniform_real_distribution<double> length (0.1, 2.0);
    std::vector<std::vector<std::pair<int, double>>> out (static_cast<std::size_t> (n));
    for (int k = 0; k < 3 * n; ++k)
    {
      const int a = vertex (random) % (n - 5), b = vertex (random) % (n - 5); // the last 5 stay unreached
      if (a != b)
        out[static_cast<std::size_t> (a)].emplace_back (b, length (random));
    }
    InteriorEdges edges = InteriorEdges (FlowResult ());
    edges.first.assign (1, 0);
    for (const auto& row : out)
    {
      for (const auto& [to, l] : row)
      {
        edges.to.push_back (to);
        edges.length.push_back (l);
      }
      edges.first.push_back (edges.to.size ());
    }
    const std::vector<std::pair<int, double>> seeds = {{0, 0.0}, {n / 3, 0.5}, {n / 2, 1.25}}; // distinct vertices
    std::vector<double> expected (static_cast<std::size_t> (n), std::numeric_limits<double>::infinity ());
    for (const auto& [v, d] : seeds)
      expected[static_cast<std::size_t> (v)] = std::min (expected[static_cast<std::size_t> (v)], d);
    for (bool changed = true; changed;)
    {
      changed = false;
      for (std::size_t v = 0; v < out.size (); ++v)
        for (const auto& [to, l] : out[v])
          if (expected[v] + l < expected[static_cast<std::size_t> (to)])
          {
            expected[static_cast<std::size_t> (to)] = expected[v] + l;
            changed = true;
          }
    }
    std::vector<double> distance (static_cast<std::size_t> (n), -1.0);
    shortestPaths (edges, seeds, distance);
    for (int v = 0; v < n; ++v)
      EXPECT_EQ (distance[static_cast<std::size_t> (v)], expected[static_cast<std::size_t> (v)]) << "round " << round << " vertex " << v;
    for (int v = n - 5; v < n; ++v)
      EXPECT_TRUE (std::isinf (distance[static_cast<std::size_t> (v)]));
  }
}

TEST (ShapeDescription, BendingABarKeepsItsInnerDistances)
{
  // Bending a bar into a half circle changes its straight distances much more than its inner ones.
  const ShapeDescription bar = signatureOf (barSample (10.0, 0.0)).description;
  const ShapeDescription bent = signatureOf (barSample (10.0, 3.14159265358979)).description;
  const auto l1 = [] (const Distribution& a, const Distribution& b) {
    double sum = 0.0;
    for (std::size_t k = 0; k < kDistributionBins; ++k)
      sum += std::abs (a[k] - b[k]);
    return sum;
  };
  const double inner = l1 (bar.inner_distance, bent.inner_distance), solid = l1 (bar.solid_distance, bent.solid_distance);
  EXPECT_LT (inner, 0.5 * solid) << "inner " << inner << ", solid " << solid;
  // Where its largest part lies, by inner distance, bending changes little too.
  ASSERT_FALSE (bar.parts.empty ());
  ASSERT_FALSE (bent.parts.empty ());
  EXPECT_NEAR (bent.parts[0].remoteness, bar.parts[0].remoteness, 0.1 * bar.parts[0].remoteness);
}

TEST (ShapeDescription, InnerProfilesRunFromTheCentreToTheEnds)
{
  const Signature bar = signatureOf (barSample (10.0, 0.0));
  const auto mean_bin = [] (const Distribution& row) {
    double mean = 0.0;
    for (std::size_t k = 0; k < kDistributionBins; ++k)
      mean += static_cast<double> (k) * row[k];
    return mean;
  };
  // Sources in the middle of a bar see at most half its length, sources at its ends all of it.
  const InnerProfiles& rows = bar.description.inner_profiles;
  EXPECT_LT (mean_bin (rows.front ()) + 2.0, mean_bin (rows.back ()));
  for (std::size_t r = 1; r < kProfileRows; ++r)
    EXPECT_LE (mean_bin (rows[r - 1]), mean_bin (rows[r]) + 0.5) << r;
  // Bending keeps the profiles; a bar half as long (its inner distances shorter over its unit) does not.
  const Signature bent = signatureOf (barSample (10.0, 3.14159265358979));
  const Signature shorter = signatureOf (barSample (5.0, 0.0));
  const double to_bent = matchWith (MatchMethod::InnerProfile, bar, bent);
  const double to_shorter = matchWith (MatchMethod::InnerProfile, bar, shorter);
  EXPECT_GT (to_bent, to_shorter) << "bent " << to_bent << ", shorter " << to_shorter;
  EXPECT_GT (to_bent, 0.9);
}

TEST (ShapeDescription, InnerContextsSeeTheShapeFromEachSource)
{
  // One context per source, each a histogram summing to 1 with a thickness in range.
  const Signature animal = signatureOf (flowseg_test::shapeSample ("animal3d", 4000));
  ASSERT_EQ (animal.description.inner_contexts.size (), kDistanceSources);
  for (const InnerContext& c : animal.description.inner_contexts)
  {
    EXPECT_NEAR (std::accumulate (c.distances.begin (), c.distances.end (), 0.0), 1.0, 1e-5);
    EXPECT_GE (c.thickness, kThicknessLogLow);
    EXPECT_LE (c.thickness, kThicknessLogHigh);
  }
  // Inner distances over their mean: bending a bar keeps its contexts, a bar of half the length
  // (thicker over its own mean distance) does not.
  const Signature bar = signatureOf (barSample (10.0, 0.0));
  const double to_bent = matchWith (MatchMethod::InnerContext, bar, signatureOf (barSample (10.0, 3.14159265358979)));
  const double to_shorter = matchWith (MatchMethod::InnerContext, bar, signatureOf (barSample (5.0, 0.0)));
  EXPECT_GT (to_bent, to_shorter) << "bent " << to_bent << ", shorter " << to_shorter;
  EXPECT_GT (to_bent, 0.9);
}

TEST (ShapeDescription, ContoursFollowTheOutlineOfTwoDimensionalShapes)
{
  // 64 histograms summing to 1 for a 2D shape, none for a 3D one.
  const Signature hand = signatureOf (flowseg_test::shapeSample ("hand2d", 1500, 1));
  ASSERT_EQ (hand.description.contour.size (), kContourPoints);
  for (const ContourHistogram& h : hand.description.contour)
    EXPECT_NEAR (std::accumulate (h.begin (), h.end (), 0.0), 1.0, 1e-5);
  EXPECT_TRUE (signatureOf (flowseg_test::shapeSample ("snowman3d", 1500, 1)).description.contour.empty ());
  // The mirror image, started elsewhere on its outline, is matched; another shape is not.
  std::vector<V> mirrored;
  for (const V& p : flowseg_test::shapeSample ("hand2d", 1500, 1))
    mirrored.emplace_back (-p.x (), p.y (), 0.0);
  const double to_mirror = matchWith (MatchMethod::Contour, hand, signatureOf (mirrored));
  const double to_star = matchWith (MatchMethod::Contour, hand, signatureOf (flowseg_test::shapeSample ("star2d", 1500, 1)));
  EXPECT_GT (to_mirror, 0.95);
  EXPECT_LT (to_star, to_mirror - 0.1) << "star " << to_star << ", mirror " << to_mirror;
}

class DescriptionInvariance : public ::testing::TestWithParam<const char*> {};

TEST_P (DescriptionInvariance, ATransformedResampledCopyIsTheMostSimilar)
{
  const std::string name = GetParam ();
  const std::size_t n = name.find ("2d") != std::string::npos ? 1500 : 4000;
  const Signature query = signatureOf (flowseg_test::shapeSample (name, n, 1));
  const Signature copy = signatureOf (movedCopy (name, n));
  for (MatchMethod method : kMatchMethods)
  {
    if (method == MatchMethod::Paper)
      continue;
    EXPECT_EQ (matchWith (method, query, copy), matchWith (method, copy, query)) << matchMethodName (method);
    EXPECT_NEAR (matchWith (method, query, query), 1.0, 1e-12) << matchMethodName (method);
  }
  const double self = matchWith (MatchMethod::Combined, query, copy);
  // Every component sees the copy as near (its distance, -log similarity, is small in its own
  // units); the combination ranks it above every other shape.
  for (MatchMethod method : kMatchMethods)
    if (method != MatchMethod::Paper && method != MatchMethod::Combined)
      EXPECT_LT (-std::log (matchWith (method, query, copy)), 0.2) << name << " " << matchMethodName (method);
  for (const auto& other : sampleShapes ())
  {
    if (other.name == name || (other.dimension == 2) != (name.find ("2d") != std::string::npos))
      continue;
    const Signature o = signatureOf (sampleBoundary (other, n, 5));
    EXPECT_LT (matchWith (MatchMethod::Combined, query, o), self) << name << " vs " << other.name;
  }
}

TEST_P (DescriptionInvariance, ARescaledCopyIsDescribedExactlyTheSame)
{
  // Scaling by a power of two changes no rounding: the triangulation, the segmentation and the
  // drawn cells (ordered by volume, not by place) are the same, so is the description.
  const std::string name = GetParam ();
  const std::vector<V> pts = flowseg_test::shapeSample (name, name.find ("2d") != std::string::npos ? 1500 : 4000, 1);
  std::vector<V> scaled;
  for (const V& p : pts)
    scaled.push_back (0.25 * p);
  const ShapeDescription a = signatureOf (pts).description, b = signatureOf (scaled).description;
  ASSERT_EQ (a.parts.size (), b.parts.size ());
  for (std::size_t k = 0; k < a.parts.size (); ++k)
  {
    EXPECT_NEAR (a.parts[k].weight, b.parts[k].weight, 1e-12);
    EXPECT_NEAR (a.parts[k].thickness, b.parts[k].thickness, 1e-12);
    EXPECT_NEAR (a.parts[k].remoteness, b.parts[k].remoteness, 1e-12);
  }
  EXPECT_EQ (a.thickness, b.thickness);
  EXPECT_EQ (a.inner_distance, b.inner_distance);
  EXPECT_EQ (a.solid_distance, b.solid_distance);
  EXPECT_EQ (a.inner_profiles, b.inner_profiles);
  EXPECT_EQ (a.contour, b.contour);
  ASSERT_EQ (a.inner_contexts.size (), b.inner_contexts.size ());
  for (std::size_t k = 0; k < a.inner_contexts.size (); ++k)
  {
    EXPECT_EQ (a.inner_contexts[k].distances, b.inner_contexts[k].distances) << k;
    EXPECT_NEAR (a.inner_contexts[k].thickness, b.inner_contexts[k].thickness, 1e-6) << k;
  }
  for (std::size_t r = 0; r < kProfileRows; ++r) // a log of a ratio: rounding may move it in the last bits
    EXPECT_NEAR (a.thickness_profile[r], b.thickness_profile[r], 1e-12) << r;
}

INSTANTIATE_TEST_SUITE_P (Shapes, DescriptionInvariance,
                          ::testing::Values ("star2d", "hand2d", "dumbbell3d", "snowman3d", "animal3d"));

TEST (DescriptionMatch, WeightsAreParametersOfTheCombinedMethod)
{
  const Signature a = signatureOf (flowseg_test::shapeSample ("animal3d", 2000, 1));
  const Signature b = signatureOf (flowseg_test::shapeSample ("snowman3d", 2000, 1));
  pcl::SignatureMatcher matcher;
  const auto by_default = matcher.match (a, b);
  ASSERT_TRUE (by_default.status);
  EXPECT_EQ (by_default.similarity, std::exp (-by_default.distance));
  EXPECT_TRUE (std::isnan (by_default.paper_score));
  // The combination with only the parts weighed 1 is the parts' method.
  MatchParameters parts_only;
  parts_only.weights_3d = DescriptionWeights ();
  parts_only.weights_3d.parts = 1.0;
  matcher.setParameters (parts_only);
  const auto combined = matcher.match (a, b);
  matcher.setMethod (MatchMethod::Parts);
  const auto parts = matcher.match (a, b);
  EXPECT_EQ (combined.distance, parts.distance);
  EXPECT_EQ (combined.similarity, parts.similarity);
  // Doubling every weight doubles the distance.
  MatchParameters doubled;
  for (double* w : {&doubled.weights_3d.parts, &doubled.weights_3d.thickness, &doubled.weights_3d.thickness_profile,
                    &doubled.weights_3d.inner_context})
    *w *= 2.0;
  EXPECT_EQ (doubled.weights_3d.inner_distance, 0.0);
  matcher.setParameters (doubled);
  EXPECT_NEAR (matcher.match (a, b).distance, 2.0 * by_default.distance, 1e-12 * by_default.distance);
  // Each method's weights: the paper's compares no description.
  MatchParameters p;
  EXPECT_EQ (descriptionWeights (p, 3).inner_context, defaultDescriptionWeights (3).inner_context);
  EXPECT_EQ (descriptionWeights (p, 2).contour, defaultDescriptionWeights (2).contour);
  p.method = MatchMethod::Paper;
  const DescriptionWeights none = descriptionWeights (p, 3);
  EXPECT_EQ (none.parts + none.thickness + none.inner_distance + none.solid_distance + none.inner_profile +
                 none.thickness_profile + none.contour + none.inner_context,
             0.0);
  matcher.setParameters (p);
  const auto paper = matcher.match (a, b);
  EXPECT_TRUE (std::isnan (paper.distance));
  EXPECT_EQ (paper.similarity, paper.paper_score / static_cast<double> (std::max (a.points.size (), b.points.size ())));
}

TEST (DescriptionMatch, BadWeightsAreRefused)
{
  for (double value : {-1.0, std::nan (""), std::numeric_limits<double>::infinity ()})
  {
    MatchParameters bad;
    bad.weights_2d.solid_distance = value;
    const Status s = checkMatchParameters (bad);
    EXPECT_FALSE (s);
    EXPECT_NE (s.message.find ("weights_2d.solid_distance"), std::string::npos) << s.message;
  }
  MatchParameters nothing;
  nothing.weights_3d = DescriptionWeights ();
  EXPECT_FALSE (checkMatchParameters (nothing));
  nothing.method = MatchMethod::Thickness; // uses no combined weights
  EXPECT_TRUE (checkMatchParameters (nothing));
  // The matcher and the database refuse them too.
  const Signature s = signatureOf (flowseg_test::shapeSample ("dumbbell3d", 1500));
  pcl::SignatureMatcher matcher;
  MatchParameters bad;
  bad.weights_3d.parts = -1.0;
  matcher.setParameters (bad);
  EXPECT_FALSE (matcher.match (s, s).status);
  SignatureDatabase db;
  db.add (ShapeEntry{"dumbbell", "dumbbell", s});
  EXPECT_TRUE (db.query (s, 1, matcher).empty ());
}

TEST (DescriptionMatch, TheCandidatesFollowTheWeights)
{
  SignatureDatabase db;
  std::uint32_t seed = 1;
  for (const char* name : {"animal3d", "snowman3d", "dumbbell3d"})
    for (int copy = 0; copy < 2; ++copy, ++seed)
      db.add (ShapeEntry{name + std::to_string (copy), name, signatureOf (flowseg_test::shapeSample (name, 1500, seed))});
  const Signature query = signatureOf (movedCopy ("snowman3d", 1500));
  pcl::SignatureMatcher parts;
  parts.setMethod (MatchMethod::Parts);
  MatchParameters parts_only;
  parts_only.weights_3d = DescriptionWeights ();
  parts_only.weights_3d.parts = 1.0;
  pcl::SignatureMatcher combined;
  combined.setParameters (parts_only);
  const auto by_default = db.query (query, 0, pcl::SignatureMatcher (), 2);
  // One candidate compared: which one follows the weights' summary, so the two agree throughout.
  for (std::size_t candidates : {1u, 2u, 0u})
  {
    const auto expected = db.query (query, 0, parts, candidates);
    const auto hits = db.query (query, 0, combined, candidates);
    ASSERT_EQ (hits.size (), expected.size ());
    for (std::size_t r = 0; r < hits.size (); ++r)
    {
      EXPECT_EQ (hits[r].entry, expected[r].entry) << candidates << " " << r;
      EXPECT_EQ (hits[r].compared, expected[r].compared) << candidates << " " << r;
      EXPECT_EQ (hits[r].summary_distance, expected[r].summary_distance) << candidates << " " << r;
      if (hits[r].compared)
        EXPECT_EQ (hits[r].similarity, expected[r].similarity) << candidates << " " << r;
    }
  }
  // The default's candidate index is not the parts' one.
  const auto again = db.query (query, 0, pcl::SignatureMatcher (), 2);
  ASSERT_EQ (again.size (), by_default.size ());
  for (std::size_t r = 0; r < again.size (); ++r)
  {
    EXPECT_EQ (again[r].entry, by_default[r].entry);
    EXPECT_EQ (again[r].summary_distance, by_default[r].summary_distance);
  }
}

TEST (DescriptionMatch, RefusesWhatItCannotCompare)
{
  const Signature planar = signatureOf (flowseg_test::shapeSample ("star2d", 800));
  const Signature solid = signatureOf (flowseg_test::shapeSample ("snowman3d", 1500));
  pcl::SignatureMatcher matcher;
  const auto mixed = matcher.match (planar, solid);
  EXPECT_FALSE (mixed.status);
  EXPECT_LT (mixed.similarity, -1e300);
  Signature bare = solid;
  bare.description = ShapeDescription ();
  const auto undescribed = matcher.match (solid, bare);
  EXPECT_FALSE (undescribed.status);
  EXPECT_NE (undescribed.status.message.find ("description"), std::string::npos) << undescribed.status.message;
  matcher.setMethod (MatchMethod::Paper); // the paper's method needs none
  EXPECT_TRUE (matcher.match (solid, bare).status);
  MatchMethod parsed = MatchMethod::Paper;
  EXPECT_TRUE (parseMatchMethod ("inner", parsed));
  EXPECT_EQ (parsed, MatchMethod::InnerDistance);
  EXPECT_FALSE (parseMatchMethod ("d2", parsed));
}

TEST (ShapeDescription, BrokenDescriptionsAreRefused)
{
  const Signature s = signatureOf (flowseg_test::shapeSample ("animal3d", 2000));
  ASSERT_TRUE (checkSignature (s).ok);
  auto refused = [&] (const std::function<void (ShapeDescription&)>& breakIt, const std::string& expected) {
    Signature broken = s;
    breakIt (broken.description);
    const Status st = checkSignature (broken);
    EXPECT_FALSE (st.ok) << expected;
    EXPECT_NE (st.message.find (expected), std::string::npos) << st.message;
  };
  refused ([] (ShapeDescription& d) { std::swap (d.parts[0], d.parts[1]); }, "decreasing weight");
  refused ([] (ShapeDescription& d) { d.parts[1].middle_ratio = 1.5; }, "axis ratio");
  refused ([] (ShapeDescription& d) { d.parts[0].thickness = std::nan (""); }, "thickness");
  refused ([] (ShapeDescription& d) { d.inner_distance[3] += 0.1; }, "inner-distance distribution sums");
  refused ([] (ShapeDescription& d) { d.contour.resize (3); }, "the contour has 3 histograms");
  refused ([] (ShapeDescription& d) {
    d.contour.assign (kContourPoints, ContourHistogram{});
    for (ContourHistogram& h : d.contour)
      h[7] = 0.5f;
  }, "a contour histogram sums to 0.5");
  refused ([] (ShapeDescription& d) { d.inner_contexts.clear (); }, "0 inner contexts");
  refused ([] (ShapeDescription& d) { d.inner_contexts[5].distances[2] += 0.5f; }, "an inner-context histogram sums to");
  refused ([] (ShapeDescription& d) { d.inner_contexts[0].thickness = std::nanf (""); }, "inner context's thickness");
  refused ([] (ShapeDescription& d) { d.parts.clear (); }, "without parts");
}

TEST (ShapeDescription, TheDatabaseKeepsDescriptionsExactlyAndRanksByThem)
{
  SignatureDatabase db;
  for (const char* name : {"animal3d", "snowman3d", "dumbbell3d", "hand2d"})
  {
    ShapeEntry e;
    e.name = name;
    e.label = name;
    e.signature = signatureOf (flowseg_test::shapeSample (name, 3000, 2));
    db.add (e);
  }
  const std::string path = "/tmp/flowseg_description_test_" + std::to_string (::getpid ()) + ".db";
  ASSERT_TRUE (db.save (path).ok);
  SignatureDatabase back;
  ASSERT_TRUE (back.load (path).ok);
  std::remove (path.c_str ());
  ASSERT_EQ (back.size (), 4u);
  EXPECT_EQ (back.entries ()[3].signature.description.contour, db.entries ()[3].signature.description.contour);
  EXPECT_EQ (back.entries ()[3].signature.description.contour.size (), kContourPoints);
  const ShapeDescription& before = db.entries ()[0].signature.description;
  const ShapeDescription& after = back.entries ()[0].signature.description;
  ASSERT_EQ (after.parts.size (), before.parts.size ());
  EXPECT_EQ (after.parts[1].remoteness, before.parts[1].remoteness);
  EXPECT_EQ (after.solid_distance, before.solid_distance);
  EXPECT_EQ (after.inner_profiles, before.inner_profiles);
  EXPECT_EQ (after.thickness_profile, before.thickness_profile);
  ASSERT_EQ (after.inner_contexts.size (), before.inner_contexts.size ());
  for (std::size_t k = 0; k < after.inner_contexts.size (); ++k)
  {
    EXPECT_EQ (after.inner_contexts[k].thickness, before.inner_contexts[k].thickness) << k;
    EXPECT_EQ (after.inner_contexts[k].distances, before.inner_contexts[k].distances) << k;
  }
  const Signature query = signatureOf (movedCopy ("animal3d", 3000));
  for (std::size_t candidates : {0u, 1u})
  {
    const auto hits = back.query (query, 3, pcl::SignatureMatcher (), candidates);
    ASSERT_EQ (hits.size (), 3u);
    EXPECT_EQ (back.entries ()[hits[0].entry].name, "animal3d") << candidates;
    EXPECT_TRUE (hits[0].compared);
    EXPECT_EQ (hits[0].similarity, matchWith (MatchMethod::Combined, query, back.entries ()[hits[0].entry].signature));
  }
}

TEST (DescriptionMatch, JitteredTwoDimensionalPointFilesAsHeldOutSetsArrive)
{
  // Held-out 2D sets arrive as `x y 0` text files of 1,000 boundary points jittered by a quarter
  // pixel. Each 2D sample shape written so (a pixel taken as 1/200 of the shape's extent) must find
  // its own re-sampled, moved copy before every other 2D shape.
  std::mt19937 random (9);
  const auto writeJittered = [&] (const std::string& name, std::uint32_t seed, double turn, const std::string& path) {
    std::vector<V> pts = flowseg_test::shapeSample (name, 1000, seed);
    Eigen::AlignedBox3d box;
    for (const V& p : pts)
      box.extend (p);
    std::uniform_real_distribution<double> jitter (-0.25, 0.25);
    const double pixel = box.sizes ().maxCoeff () / 200.0;
    const Eigen::Matrix3d r = Eigen::AngleAxisd (turn, V::UnitZ ()).toRotationMatrix ();
    std::ofstream out (path);
    for (const V& p : pts)
    {
      const V q = r * p + pixel * V (jitter (random), jitter (random), 0.0);
      out << q.x () << " " << q.y () << " 0\n";
    }
  };
  const std::string dir = "/tmp/flowseg_xyz_" + std::to_string (::getpid ()) + "_";
  std::vector<std::string> names;
  for (const auto& shape : sampleShapes ())
    if (shape.dimension == 2)
      names.push_back (shape.name);
  ASSERT_GE (names.size (), 3u);
  std::vector<Signature> stored, queries;
  for (const std::string& name : names)
  {
    Signature s, q;
    writeJittered (name, 1, 0.0, dir + name + ".xyz");
    writeJittered (name, 2, 0.9, dir + name + "_copy.xyz");
    ASSERT_TRUE (signatureOfShapeFile (dir + name + ".xyz", ShapeInputOptions (), FlowParameters (), kDefaultSignificance, s).ok);
    ASSERT_TRUE (signatureOfShapeFile (dir + name + "_copy.xyz", ShapeInputOptions (), FlowParameters (), kDefaultSignificance, q).ok);
    EXPECT_EQ (s.dimension, 2) << name;
    stored.push_back (s);
    queries.push_back (q);
    std::remove ((dir + name + ".xyz").c_str ());
    std::remove ((dir + name + "_copy.xyz").c_str ());
  }
  for (std::size_t i = 0; i < names.size (); ++i)
    for (std::size_t j = 0; j < names.size (); ++j)
      if (j != i)
        EXPECT_GT (matchWith (MatchMethod::Combined, queries[i], stored[i]), matchWith (MatchMethod::Combined, queries[i], stored[j]))
            << names[i] << " vs " << names[j];
}

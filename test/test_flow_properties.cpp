/*
 * Structural properties of the flow and its stable manifolds, checked against brute-force
 * references computed independently from the triangulation.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include "test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <deque>
#include <functional>
#include <limits>
#include <map>
#include <set>

using namespace pcl_flowseg;
using flowseg_test::segmentOrDie;
using flowseg_test::shapeSample;
using V = Eigen::Vector3d;

namespace {

/** Flow across facet i, recomputed in floating point from the coordinates: the apex lies strictly
  * inside the facet's diametral circle/sphere. 1 = flows, 0 = does not, -1 = too close to call. */
int
referenceFlows (const FlowResult& r, const FlowCell& c, int i)
{
  const int f = r.dimension + 1;
  using L = long double;
  auto P = [&] (int k) { return r.vertices[static_cast<std::size_t> (c.vertices[(i + k) % f])]; };
  const V p = P (0);
  if (r.dimension == 2)
  {
    const V a = P (1), b = P (2);
    const L dot = (L) (a - p).x () * (L) (b - p).x () + (L) (a - p).y () * (L) (b - p).y () + (L) (a - p).z () * (L) (b - p).z ();
    const L scale = (L) (a - p).squaredNorm () + (L) (b - p).squaredNorm ();
    return std::abs (dot) < 1e-12 * scale ? -1 : dot < 0;
  }
  V centre;
  // Centre and radius of the facet's smallest sphere, from its vertices.
  const V a = P (1), b = P (2), d = P (3);
  const V u = b - a, w = d - a, n = u.cross (w);
  centre = a + (u.squaredNorm () * w.cross (n) + w.squaredNorm () * n.cross (u)) / (2 * n.squaredNorm ());
  const double dp = (p - centre).squaredNorm (), r2 = (a - centre).squaredNorm ();
  return std::abs (dp - r2) < 1e-9 * r2 ? -1 : dp < r2;
}

std::vector<std::vector<int>>
predecessors (const FlowResult& r)
{
  std::vector<std::vector<int>> pred (r.cells.size ());
  const int f = r.dimension + 1;
  for (std::size_t c = 0; c < r.cells.size (); ++c)
    for (int i = 0; i < f; ++i)
      if (r.cells[c].flow_mask >> i & 1 && r.cells[c].neighbors[i] >= 0)
        pred[static_cast<std::size_t> (r.cells[c].neighbors[i])].push_back (static_cast<int> (c));
  return pred;
}

void
checkPartition (const FlowResult& r)
{
  std::size_t cells = 0;
  double volume = 0.0, cell_volume = 0.0;
  for (const auto& s : r.segments)
  {
    cells += s.cell_count;
    volume += s.volume;
  }
  for (const auto& c : r.cells)
  {
    ASSERT_GE (c.segment, 0);
    ASSERT_LT (static_cast<std::size_t> (c.segment), r.segments.size ());
    ASSERT_GE (c.manifold, 0);
    ASSERT_LT (static_cast<std::size_t> (c.manifold), r.manifolds.size ());
    cell_volume += c.volume;
  }
  EXPECT_EQ (cells, r.cells.size ());
  EXPECT_NEAR (volume, cell_volume, 1e-9 * cell_volume);
  std::size_t points = 0;
  for (const auto& s : r.segments)
    points += s.point_count;
  EXPECT_EQ (points, r.input_points - r.non_finite_points);
}

void
checkAcyclicAndUphill (const FlowResult& r)
{
  // Following the kept successor from any cell ends at a maximum or at the hull within n steps,
  // with circumradii that never decrease.
  for (std::size_t start = 0; start < r.cells.size (); ++start)
  {
    std::size_t c = start, steps = 0;
    while (r.cells[c].successor_facet >= 0)
    {
      const int next = r.cells[c].neighbors[static_cast<std::size_t> (r.cells[c].successor_facet)];
      if (next < 0)
        break;
      ASSERT_GE (r.cells[static_cast<std::size_t> (next)].squared_radius, r.cells[c].squared_radius * (1 - 1e-12));
      ASSERT_EQ (r.cells[static_cast<std::size_t> (next)].manifold, r.cells[c].manifold);
      c = static_cast<std::size_t> (next);
      ASSERT_LE (++steps, r.cells.size ()) << "cycle in the flow from cell " << start;
    }
  }
}

} // namespace

class FlowProperties2D : public ::testing::TestWithParam<std::string> {};

TEST_P (FlowProperties2D, MatchesBruteForceStableManifoldsAndGabrielBoundaries)
{
  const auto pts = GetParam () == "random" ? flowseg_test::randomPoints (800, 2, 3) : shapeSample (GetParam (), 800);
  const FlowResult r = segmentOrDie (pts);
  ASSERT_EQ (r.dimension, 2);
  EXPECT_EQ (r.cycle_breaks, 0u);
  checkPartition (r);
  checkAcyclicAndUphill (r);

  // The flow mask agrees with an independent computation of the relation.
  for (const auto& c : r.cells)
    for (int i = 0; i < 3; ++i)
    {
      const int ref = referenceFlows (r, c, i);
      if (ref >= 0)
        ASSERT_EQ (int (c.flow_mask >> i & 1), ref);
    }

  // Paper's STABLEMANIFOLD in 2D: explore from each maximum across edges into triangles that
  // flow into the current set. Every cell reached must carry that maximum's manifold.
  const auto pred = predecessors (r);
  std::vector<int> reference (r.cells.size (), -1);
  for (std::size_t m = 0; m < r.maxima.size (); ++m)
  {
    std::deque<int> queue{r.maxima[m].cell};
    while (!queue.empty ())
    {
      const int c = queue.front ();
      queue.pop_front ();
      ASSERT_EQ (reference[static_cast<std::size_t> (c)], -1) << "a triangle reached from two maxima";
      reference[static_cast<std::size_t> (c)] = static_cast<int> (m);
      for (int p : pred[static_cast<std::size_t> (c)])
        queue.push_back (p);
    }
  }
  const int infinity = static_cast<int> (r.maxima.size ());
  for (std::size_t c = 0; c < r.cells.size (); ++c)
    EXPECT_EQ (r.cells[c].manifold, reference[c] < 0 ? infinity : reference[c]) << "cell " << c;

  // Boundaries between stable manifolds are Gabriel edges: no vertex inside the diametral circle.
  std::size_t boundaries = 0;
  for (const auto& c : r.cells)
    for (int i = 0; i < 3; ++i)
    {
      const int nb = c.neighbors[i];
      if (nb < 0 || r.cells[static_cast<std::size_t> (nb)].manifold == c.manifold)
        continue;
      ++boundaries;
      const V a = r.vertices[static_cast<std::size_t> (c.vertices[(i + 1) % 3])];
      const V b = r.vertices[static_cast<std::size_t> (c.vertices[(i + 2) % 3])];
      const V mid = 0.5 * (a + b);
      const double r2 = 0.25 * (b - a).squaredNorm ();
      for (int k = 0; k < 3; ++k)
        EXPECT_GE ((r.vertices[static_cast<std::size_t> (c.vertices[k])] - mid).squaredNorm (), r2 * (1 - 1e-9));
    }
  EXPECT_GT (boundaries, 0u);
}

INSTANTIATE_TEST_SUITE_P (Shapes, FlowProperties2D, ::testing::Values ("random", "dumbbell2d", "star2d", "hand2d"));

class FlowProperties3D : public ::testing::TestWithParam<std::string> {};

TEST_P (FlowProperties3D, StrengthenedFlowKeepsTheStrongestSuccessor)
{
  const auto pts = GetParam () == "random" ? flowseg_test::randomPoints (600, 3, 5) : shapeSample (GetParam (), 1500);
  const FlowResult r = segmentOrDie (pts);
  ASSERT_EQ (r.dimension, 3);
  EXPECT_EQ (r.cycle_breaks, 0u);
  checkPartition (r);
  checkAcyclicAndUphill (r);

  std::size_t two_successors = 0;
  for (const auto& c : r.cells)
  {
    int count = 0;
    for (int i = 0; i < 4; ++i)
    {
      const bool flows = c.flow_mask >> i & 1;
      count += flows;
      const int ref = referenceFlows (r, c, i); // clear-cut cases only
      if (ref >= 0 && int (flows) != ref)
        ADD_FAILURE () << "flow relation differs from the reference";
    }
    EXPECT_LE (count, 2) << "Observation 5: at most two successors";
    two_successors += count == 2;
  }

  // Strength by brute force: the highest maximum reachable through the full relation <.
  const double inf = std::numeric_limits<double>::infinity ();
  std::vector<double> strength (r.cells.size (), -1.0);
  // Memoised depth-first search over all successors (the relation is acyclic).
  std::function<double (std::size_t)> strengthOf = [&] (std::size_t c) -> double {
    if (strength[c] >= 0.0)
      return strength[c];
    const FlowCell& cell = r.cells[c];
    double s = cell.flow_mask == 0 ? cell.squared_radius : -1.0;
    for (int i = 0; i < 4; ++i)
      if (cell.flow_mask >> i & 1)
        s = std::max (s, cell.neighbors[i] < 0 ? inf : strengthOf (static_cast<std::size_t> (cell.neighbors[i])));
    return strength[c] = s;
  };
  for (std::size_t c = 0; c < r.cells.size (); ++c)
    strengthOf (c);
  for (std::size_t c = 0; c < r.cells.size (); ++c)
  {
    const FlowSegment& m = r.manifolds[static_cast<std::size_t> (r.cells[c].manifold)];
    EXPECT_EQ (m.maximum.height, strength[c]) << "cell " << c << " is not in the manifold of its strongest maximum";
  }
  EXPECT_GT (two_successors, 0u) << "the 3D test should exercise cells with two successors";
}

INSTANTIATE_TEST_SUITE_P (Shapes, FlowProperties3D, ::testing::Values ("random", "dumbbell3d", "animal3d"));

TEST (Merging, LargerRhoNeverGivesMoreSegmentsAndBelowOneMergesNothing)
{
  for (const char* name : {"hand2d", "animal3d"})
  {
    FlowResult r = segmentOrDie (shapeSample (name, 1200), 0.5);
    EXPECT_EQ (r.segments.size (), r.manifolds.size ()) << name;
    ASSERT_TRUE (remergeFlowSegmentation (flowseg_test::mergeParameters (0.999), r).ok);
    EXPECT_EQ (r.segments.size (), r.manifolds.size ()) << name;
    // Monotone without the compact pass (documented: with it, groups grow with rho, so a
    // candidate may no longer join two compact groups).
    std::size_t previous = r.segments.size ();
    for (double rho : {1.0, 1.05, 1.1, 1.2, 1.4, 1.8, 2.5, 4.0, 10.0})
    {
      ASSERT_TRUE (remergeFlowSegmentation (
          flowseg_test::mergeParameters (rho, flowseg_test::kDefaultMerge.sampling_tolerance, flowseg_test::kDefaultMerge.stump_ratio, 0.0), r).ok);
      EXPECT_LE (r.segments.size (), previous) << name << " rho " << rho;
      previous = r.segments.size ();
      checkPartition (r);
    }
    EXPECT_LT (previous, r.manifolds.size ()) << name << ": large rho merges something";
    // Nor does a larger sampling tolerance, and below rho 1 no tolerance merges anything.
    previous = r.manifolds.size ();
    for (double tolerance : {0.0, 0.1, 0.25, 0.5, 1.0, 2.0, 5.0})
    {
      ASSERT_TRUE (remergeFlowSegmentation (flowseg_test::mergeParameters (1.05, tolerance, flowseg_test::kDefaultMerge.stump_ratio, 0.0), r).ok);
      EXPECT_LE (r.segments.size (), previous) << name << " tolerance " << tolerance;
      previous = r.segments.size ();
      checkPartition (r);
    }
    ASSERT_TRUE (remergeFlowSegmentation (flowseg_test::mergeParameters (0.999, 5.0), r).ok);
    EXPECT_EQ (r.segments.size (), r.manifolds.size ()) << name;
  }
}

TEST (Merging, RemergeWithTheNewParametersOffEqualsAFreshRunWithThePaperRule)
{
  const auto pts = shapeSample ("animal3d", 1500);
  FlowResult fresh = segmentOrDie (pts, 1.3, DimensionMode::Automatic, true, 0.0, 0.0, 0.0);
  FlowResult remerged = segmentOrDie (pts, flowseg_test::kDefaultMerge.rho, DimensionMode::Automatic, true);
  ASSERT_TRUE (remergeFlowSegmentation (flowseg_test::mergeParameters (1.3, 0.0, 0.0, 0.0), remerged).ok);
  ASSERT_EQ (remerged.segments.size (), fresh.segments.size ());
  for (std::size_t c = 0; c < fresh.cells.size (); ++c)
    ASSERT_EQ (remerged.cells[c].segment, fresh.cells[c].segment) << "cell " << c;
  EXPECT_EQ (remerged.point_labels, fresh.point_labels);
  EXPECT_EQ (remerged.features, fresh.features);
}

TEST (Merging, SegmentsFollowThePaperRule)
{
  // Independent check of each merge decision from the manifold adjacency: every pair of manifolds
  // that satisfies the rule ends up in one segment, and every segment is connected by such pairs.
  FlowResult r = segmentOrDie (shapeSample ("star2d", 1000), 1.4, DimensionMode::Automatic, false, 0.0, 0.0, 0.0);
  const double rho2 = 1.4 * 1.4;
  std::vector<int> segment_of_manifold (r.manifolds.size (), -1);
  for (const auto& c : r.cells)
    segment_of_manifold[static_cast<std::size_t> (c.manifold)] = c.segment;
  std::vector<int> parent (r.manifolds.size ());
  for (std::size_t k = 0; k < parent.size (); ++k)
    parent[k] = static_cast<int> (k);
  std::function<int (int)> find = [&] (int x) { return parent[x] == x ? x : parent[x] = find (parent[x]); };
  for (const auto& s : r.manifold_adjacency)
  {
    const auto& a = r.manifolds[static_cast<std::size_t> (s.segment_a)];
    const auto& b = r.manifolds[static_cast<std::size_t> (s.segment_b)];
    const bool rule = !a.flows_to_infinity && !b.flows_to_infinity && a.maximum.height < rho2 * s.squared_radius &&
                      b.maximum.height < rho2 * s.squared_radius;
    if (rule)
    {
      EXPECT_EQ (segment_of_manifold[static_cast<std::size_t> (s.segment_a)], segment_of_manifold[static_cast<std::size_t> (s.segment_b)]);
      parent[static_cast<std::size_t> (find (s.segment_a))] = find (s.segment_b);
    }
  }
  for (std::size_t a = 0; a < r.manifolds.size (); ++a)
    for (std::size_t b = a + 1; b < r.manifolds.size (); ++b)
      if (segment_of_manifold[a] == segment_of_manifold[b])
        EXPECT_EQ (find (static_cast<int> (a)), find (static_cast<int> (b)));
}

TEST (Merging, SegmentsFollowTheRuleWithSamplingTolerance)
{
  // The same independent check for R(max) < rho R(t) + tolerance s(t), s(t) = mean distance of the
  // saddle's vertices to their nearest other vertex, found here by brute force (not from the
  // triangulation); in 2D and 3D, on the raw segmentation and with interior/exterior sides.
  struct Case { const char* name; std::size_t points; bool sided; };
  for (const Case& test : {Case{"star2d", 1000, false}, Case{"animal3d", 1200, false}, Case{"animal3d", 1200, true}})
  {
    const double rho = 1.05, tolerance = 0.5;
    FlowResult r = segmentOrDie (shapeSample (test.name, test.points), rho, DimensionMode::Automatic, test.sided, tolerance, 0.0, 0.0);
    std::vector<double> nearest (r.vertices.size (), std::numeric_limits<double>::infinity ());
    for (std::size_t a = 0; a < r.vertices.size (); ++a)
      for (std::size_t b = 0; b < r.vertices.size (); ++b)
        if (a != b)
          nearest[a] = std::min (nearest[a], (r.vertices[a] - r.vertices[b]).norm ());
    std::vector<int> segment_of_manifold (r.manifolds.size (), -1);
    for (const auto& m : r.manifolds)
      if (!m.flows_to_infinity)
        segment_of_manifold[static_cast<std::size_t> (&m - r.manifolds.data ())] = r.cells[static_cast<std::size_t> (m.maximum.cell)].segment;
    std::vector<int> parent (r.manifolds.size ());
    for (std::size_t k = 0; k < parent.size (); ++k)
      parent[k] = static_cast<int> (k);
    std::function<int (int)> find = [&] (int x) { return parent[x] == x ? x : parent[x] = find (parent[x]); };
    std::size_t by_tolerance_only = 0;
    for (const auto& s : r.manifold_adjacency)
    {
      const auto& a = r.manifolds[static_cast<std::size_t> (s.segment_a)];
      const auto& b = r.manifolds[static_cast<std::size_t> (s.segment_b)];
      if (a.flows_to_infinity || b.flows_to_infinity)
        continue;
      if (test.sided && r.cells[static_cast<std::size_t> (a.maximum.cell)].inside != r.cells[static_cast<std::size_t> (b.maximum.cell)].inside)
        continue; // sides never merge
      double spacing = 0.0;
      for (int k = 0; k < r.dimension; ++k)
        spacing += nearest[static_cast<std::size_t> (s.vertices[static_cast<std::size_t> (k)])] / r.dimension;
      const double limit = rho * std::sqrt (s.squared_radius) + tolerance * spacing;
      const bool rule = std::sqrt (a.maximum.height) < limit && std::sqrt (b.maximum.height) < limit;
      const double rho2 = rho * rho;
      if (rule && !(a.maximum.height < rho2 * s.squared_radius && b.maximum.height < rho2 * s.squared_radius))
        ++by_tolerance_only;
      if (rule)
      {
        EXPECT_EQ (segment_of_manifold[static_cast<std::size_t> (s.segment_a)], segment_of_manifold[static_cast<std::size_t> (s.segment_b)])
            << test.name;
        parent[static_cast<std::size_t> (find (s.segment_a))] = find (s.segment_b);
      }
    }
    EXPECT_GT (by_tolerance_only, 0u) << test.name << ": the tolerance should decide some pairs";
    for (std::size_t a = 0; a < r.manifolds.size (); ++a)
      for (std::size_t b = a + 1; b < r.manifolds.size (); ++b)
        if (segment_of_manifold[a] >= 0 && segment_of_manifold[a] == segment_of_manifold[b])
          EXPECT_EQ (find (static_cast<int> (a)), find (static_cast<int> (b))) << test.name;
  }
}

TEST (Merging, StumpsMoveOnlyThinConnectedCellsFromMuchThickerSegments)
{
  // The same merging with and without stumps: the segments keep their maxima, and a cell changes
  // segment only from Y to X when Y's highest maximum is more than the ratio (2) times thicker
  // than X's, the cell is no larger than X's highest maximum nor smaller than half the saddle
  // between them (radii), and it hangs together with X.
  struct Case { const char* name; std::size_t points; bool sided; };
  for (const Case& test : {Case{"animal3d", 3000, true}, Case{"hand2d", 1500, true}, Case{"animal3d", 1500, false}})
  {
    const auto pts = shapeSample (test.name, test.points);
    const FlowResult plain = segmentOrDie (pts, flowseg_test::kDefaultMerge.rho, DimensionMode::Automatic, test.sided, flowseg_test::kDefaultMerge.sampling_tolerance, 0.0);
    const FlowResult stumps = segmentOrDie (pts, flowseg_test::kDefaultMerge.rho, DimensionMode::Automatic, test.sided, flowseg_test::kDefaultMerge.sampling_tolerance, 2.0);
    const FlowResult far = segmentOrDie (pts, flowseg_test::kDefaultMerge.rho, DimensionMode::Automatic, test.sided, flowseg_test::kDefaultMerge.sampling_tolerance, 1e6);
    ASSERT_EQ (stumps.segments.size (), plain.segments.size ()) << test.name;
    // A segment is known by its maximum cell (segments are ordered by volume, which stumps change).
    std::map<int, int> by_maximum; // maximum cell -> segment in `stumps`
    for (std::size_t k = 0; k < stumps.segments.size (); ++k)
      by_maximum[stumps.segments[k].maximum.cell] = static_cast<int> (k);
    std::vector<int> same (plain.segments.size (), -1); // segment of `plain` -> segment of `stumps`
    for (std::size_t k = 0; k < plain.segments.size (); ++k)
    {
      ASSERT_EQ (by_maximum.count (plain.segments[k].maximum.cell), 1u) << test.name;
      same[k] = by_maximum[plain.segments[k].maximum.cell];
      EXPECT_EQ (stumps.segments[static_cast<std::size_t> (same[k])].maxima, plain.segments[k].maxima) << test.name;
    }
    std::map<std::pair<int, int>, double> saddle; // segments of `plain` -> squared radius
    for (const auto& f : plain.segment_adjacency)
      saddle[{f.segment_a, f.segment_b}] = f.squared_radius;
    std::vector<int> back (stumps.segments.size (), -1); // segment of `stumps` -> segment of `plain`
    for (std::size_t k = 0; k < same.size (); ++k)
      back[static_cast<std::size_t> (same[k])] = static_cast<int> (k);
    std::size_t moved = 0;
    std::vector<char> reached (stumps.cells.size (), 0);
    std::deque<std::size_t> queue;
    for (std::size_t c = 0; c < plain.cells.size (); ++c)
    {
      const int before = same[static_cast<std::size_t> (plain.cells[c].segment)], after = stumps.cells[c].segment;
      if (before == after)
      {
        reached[c] = 1;
        queue.push_back (c);
        continue;
      }
      ++moved;
      const FlowSegment& x = stumps.segments[static_cast<std::size_t> (after)];
      const FlowSegment& y = stumps.segments[static_cast<std::size_t> (before)];
      ASSERT_FALSE (x.maxima.empty ()) << test.name << " cell " << c;
      EXPECT_LT (4.0 * x.maximum.height, y.maximum.height) << test.name << " cell " << c;
      EXPECT_LE (stumps.cells[c].squared_radius, x.maximum.height) << test.name << " cell " << c;
      const int px = back[static_cast<std::size_t> (after)], py = plain.cells[c].segment;
      const auto t = saddle.find ({std::min (px, py), std::max (px, py)});
      ASSERT_NE (t, saddle.end ()) << test.name << ": cell " << c << " moved between segments that do not touch";
      EXPECT_GE (stumps.cells[c].squared_radius, 0.25 * t->second) << test.name << " cell " << c;
      EXPECT_EQ (stumps.cells[c].inside, plain.cells[c].inside);
      for (const FlowMaximum& m : plain.maxima)
        EXPECT_NE (m.cell, static_cast<int> (c)) << test.name << ": a maximum moved";
    }
    // Every moved cell is connected to its new segment's unmoved cells through its moved cells.
    const int facets = stumps.dimension + 1;
    while (!queue.empty ())
    {
      const std::size_t c = queue.front ();
      queue.pop_front ();
      for (int i = 0; i < facets; ++i)
      {
        const int nb = stumps.cells[c].neighbors[static_cast<std::size_t> (i)];
        if (nb >= 0 && !reached[static_cast<std::size_t> (nb)] && stumps.cells[static_cast<std::size_t> (nb)].segment == stumps.cells[c].segment)
        {
          reached[static_cast<std::size_t> (nb)] = 1;
          queue.push_back (static_cast<std::size_t> (nb));
        }
      }
    }
    for (std::size_t c = 0; c < stumps.cells.size (); ++c)
      EXPECT_TRUE (reached[c]) << test.name << ": moved cell " << c << " is cut off from its new segment";
    if (std::string (test.name) == "animal3d")
      EXPECT_GT (moved, 0u) << test.name << ": the legs and neck of the animal have stumps";
    if (!test.sided) // with sides a sample may touch no interior cell (then it has no label)
      checkPartition (stumps);
    // A ratio no segment pair reaches changes nothing.
    ASSERT_EQ (far.segments.size (), plain.segments.size ());
    for (std::size_t c = 0; c < plain.cells.size (); ++c)
      ASSERT_EQ (far.cells[c].segment, plain.cells[c].segment) << test.name;
  }
}

TEST (Merging, AdjacencyHoldsTheHighestSharedFacet)
{
  const FlowResult r = segmentOrDie (shapeSample ("dumbbell3d", 1500));
  ASSERT_FALSE (r.segment_adjacency.empty ());
  std::set<std::pair<int, int>> pairs;
  for (const auto& s : r.segment_adjacency)
  {
    EXPECT_LT (s.segment_a, s.segment_b);
    EXPECT_TRUE (pairs.emplace (s.segment_a, s.segment_b).second);
    const FlowCell& c = r.cells[static_cast<std::size_t> (s.cell)];
    const int nb = c.neighbors[static_cast<std::size_t> (s.facet)];
    ASSERT_GE (nb, 0);
    std::set<int> sides{c.segment, r.cells[static_cast<std::size_t> (nb)].segment};
    EXPECT_EQ (sides, (std::set<int>{s.segment_a, s.segment_b}));
  }
  // No facet between two segments is higher than the pair's saddle.
  for (const auto& c : r.cells)
    for (int i = 0; i < 4; ++i)
    {
      const int nb = c.neighbors[i];
      if (nb < 0 || r.cells[static_cast<std::size_t> (nb)].segment == c.segment)
        continue;
      const int a = std::min (c.segment, r.cells[static_cast<std::size_t> (nb)].segment);
      const int b = std::max (c.segment, r.cells[static_cast<std::size_t> (nb)].segment);
      const auto it = std::find_if (r.segment_adjacency.begin (), r.segment_adjacency.end (),
                                    [&] (const SaddleFacet& s) { return s.segment_a == a && s.segment_b == b; });
      ASSERT_NE (it, r.segment_adjacency.end ());
      const V p = r.vertices[static_cast<std::size_t> (c.vertices[(i + 1) % 4])];
      const V q = r.vertices[static_cast<std::size_t> (c.vertices[(i + 2) % 4])];
      // Facet radius is at least half of any of its edges.
      EXPECT_LE (0.25 * (q - p).squaredNorm (), it->squared_radius * (1 + 1e-9));
    }
}

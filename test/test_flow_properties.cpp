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
    ASSERT_TRUE (remergeFlowSegmentation (0.999, r).ok);
    EXPECT_EQ (r.segments.size (), r.manifolds.size ()) << name;
    std::size_t previous = r.segments.size ();
    for (double rho : {1.0, 1.05, 1.1, 1.2, 1.4, 1.8, 2.5, 4.0, 10.0})
    {
      ASSERT_TRUE (remergeFlowSegmentation (rho, r).ok);
      EXPECT_LE (r.segments.size (), previous) << name << " rho " << rho;
      previous = r.segments.size ();
      checkPartition (r);
    }
    EXPECT_LT (previous, r.manifolds.size ()) << name << ": large rho merges something";
  }
}

TEST (Merging, SegmentsFollowThePaperRule)
{
  // Independent check of each merge decision from the manifold adjacency: every pair of manifolds
  // that satisfies the rule ends up in one segment, and every segment is connected by such pairs.
  FlowResult r = segmentOrDie (shapeSample ("star2d", 1000), 1.4);
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

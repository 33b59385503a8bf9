/*
 * Configurations whose flow, maxima and segments are known by construction.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include "test_support.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace pcl_flowseg;
using flowseg_test::segmentOrDie;
using V = Eigen::Vector3d;

TEST (HandChecked, AcuteTriangleHoldsItsMaximum)
{
  // Equilateral triangle of side 2: circumcentre at the centroid, circumradius 2/sqrt(3).
  const std::vector<V> pts = {V (-1, 0, 0), V (1, 0, 0), V (0, std::sqrt (3.0), 0)};
  const FlowResult r = segmentOrDie (pts);
  ASSERT_EQ (r.dimension, 2);
  ASSERT_EQ (r.cells.size (), 1u);
  EXPECT_EQ (r.cells[0].flow_mask, 0);
  ASSERT_EQ (r.maxima.size (), 1u);
  EXPECT_NEAR (r.maxima[0].height, 4.0 / 3.0, 1e-12);
  EXPECT_NEAR ((r.maxima[0].location - V (0, 1 / std::sqrt (3.0), 0)).norm (), 0.0, 1e-12);
  ASSERT_EQ (r.segments.size (), 1u);
  EXPECT_FALSE (r.segments[0].flows_to_infinity);
  EXPECT_NEAR (r.segments[0].volume, std::sqrt (3.0), 1e-12);
}

TEST (HandChecked, ObtuseTriangleFlowsToInfinity)
{
  // Obtuse at (0, 0.2): the circumcentre lies below the long hull edge, the flow leaves the hull.
  const std::vector<V> pts = {V (-1, 0, 0), V (1, 0, 0), V (0, 0.2, 0)};
  const FlowResult r = segmentOrDie (pts);
  ASSERT_EQ (r.cells.size (), 1u);
  EXPECT_EQ (r.maxima.size (), 0u);
  ASSERT_EQ (r.segments.size (), 1u);
  EXPECT_TRUE (r.segments[0].flows_to_infinity);
  EXPECT_EQ (r.segments[0].cell_count, 1u);
}

TEST (HandChecked, ObtuseTriangleFlowsIntoAcuteNeighbour)
{
  // ABC is acute (circumcentre (0, 0.75), radius 1.25); ABD is obtuse at D (0,-0.6) and D lies
  // outside the circle of ABC, so AB is a Delaunay edge and ABD flows across it into ABC.
  const std::vector<V> pts = {V (-1, 0, 0), V (1, 0, 0), V (0, 2, 0), V (0, -0.6, 0)};
  const FlowResult r = segmentOrDie (pts, 0.5);
  ASSERT_EQ (r.cells.size (), 2u);
  ASSERT_EQ (r.maxima.size (), 1u);
  EXPECT_NEAR (r.maxima[0].height, 1.5625, 1e-12);
  EXPECT_NEAR ((r.maxima[0].location - V (0, 0.75, 0)).norm (), 0.0, 1e-12);
  ASSERT_EQ (r.segments.size (), 1u);
  EXPECT_FALSE (r.segments[0].flows_to_infinity);
  EXPECT_EQ (r.segments[0].cell_count, 2u);
  const FlowCell& flat = r.cells[r.cells[0].flow_mask ? 0 : 1];
  ASSERT_GE (flat.successor_facet, 0);
  // The flat triangle's successor facet is the edge AB: opposite vertex D (index 3).
  EXPECT_EQ (flat.vertices[static_cast<std::size_t> (flat.successor_facet)], r.point_to_vertex[3]);
  for (std::uint32_t label : r.point_labels)
    EXPECT_EQ (label, 0u);
}

TEST (HandChecked, TwoAcuteTrianglesAreTwoMaximaMergedByRho)
{
  // A rhombus split along its short diagonal: two acute triangles, each holding a maximum,
  // separated by the Gabriel edge (0,-0.5)-(0,0.5) of circumradius 0.5.
  // The paper's rule: no sampling tolerance (see SamplingToleranceWidensTheRuleBySpacings).
  const std::vector<V> pts = {V (0, -0.5, 0), V (0, 0.5, 0), V (-0.8, 0, 0), V (0.8, 0, 0)};
  const auto paper = [&] (double rho) { return segmentOrDie (pts, rho, DimensionMode::Automatic, false, 0.0, 0.0, 0.0); };
  const FlowResult apart = paper (1.0);
  ASSERT_EQ (apart.maxima.size (), 2u);
  ASSERT_EQ (apart.segments.size (), 2u);
  ASSERT_EQ (apart.segment_adjacency.size (), 1u);
  EXPECT_NEAR (apart.segment_adjacency[0].squared_radius, 0.25, 1e-12);
  // Circumradius of each triangle: R = abc / (4 area); sides 1, sqrt(0.89), sqrt(0.89); area 0.4.
  const double R = 1.0 * 0.89 / (4 * 0.4);
  EXPECT_NEAR (apart.maxima[0].height, R * R, 1e-12);
  // Merged exactly when R < rho * 0.5.
  EXPECT_EQ (paper (0.999 * R / 0.5).segments.size (), 2u);
  EXPECT_EQ (paper (1.001 * R / 0.5).segments.size (), 1u);
}

TEST (HandChecked, SamplingToleranceWidensTheRuleBySpacings)
{
  // The rhombus above: maxima of circumradius R = 0.55625 either side of the saddle edge
  // (0,-0.5)-(0,0.5) of circumradius 0.5. Both saddle vertices have their nearest neighbour at
  // (+-0.8, 0), at distance sqrt(0.89) (the other saddle vertex lies at 1), so the spacing at the
  // saddle is s = sqrt(0.89), and the two merge exactly when R < rho 0.5 + tolerance s.
  const std::vector<V> pts = {V (0, -0.5, 0), V (0, 0.5, 0), V (-0.8, 0, 0), V (0.8, 0, 0)};
  const double R = 0.89 / 1.6, s = std::sqrt (0.89);
  const auto run = [&] (double rho, double tolerance) {
    return segmentOrDie (pts, rho, DimensionMode::Automatic, false, tolerance, flowseg_test::kDefaultMerge.stump_ratio, 0.0).segments.size ();
  };
  const double at_one = (R - 0.5) / s; // rho 1: the tolerance alone must cover R - 0.5
  EXPECT_EQ (run (1.0, 0.999 * at_one), 2u);
  EXPECT_EQ (run (1.0, 1.001 * at_one), 1u);
  const double at_105 = (R - 1.05 * 0.5) / s; // rho 1.05: the ratio covers part of it
  EXPECT_EQ (run (1.05, 0.999 * at_105), 2u);
  EXPECT_EQ (run (1.05, 1.001 * at_105), 1u);
  // The default tolerance merges them at rho 1 already; rho < 1 merges nothing whatever the tolerance.
  EXPECT_EQ (run (1.0, flowseg_test::kDefaultMerge.sampling_tolerance), 1u);
  EXPECT_EQ (run (0.999, 100.0), 2u);
  // Scaling the sample scales radii and spacings alike: the same decisions.
  std::vector<V> big;
  for (const V& p : pts)
    big.push_back (1000.0 * p);
  EXPECT_EQ (segmentOrDie (big, 1.0, DimensionMode::Automatic, false, 0.999 * at_one, flowseg_test::kDefaultMerge.stump_ratio, 0.0).segments.size (), 2u);
  EXPECT_EQ (segmentOrDie (big, 1.0, DimensionMode::Automatic, false, 1.001 * at_one, flowseg_test::kDefaultMerge.stump_ratio, 0.0).segments.size (), 1u);
}

TEST (HandChecked, CompactPassMergesSegmentsNoBiggerThanBallsOfTheirSaddle)
{
  // The rhombus above: two triangles of area 0.4 with maxima of circumradius R = 0.55625 either
  // side of the saddle edge of circumradius 0.5 (ratio 1.1125). With rho 1 and no tolerance the
  // ratio rule keeps them apart; the compact pass merges them exactly when the ratio is below
  // compact_rho and the smaller area (0.4) is at most compact_size discs of radius 0.5.
  const std::vector<V> pts = {V (0, -0.5, 0), V (0, 0.5, 0), V (-0.8, 0, 0), V (0.8, 0, 0)};
  const double R = 0.89 / 1.6, disc = 3.14159265358979323846 * 0.25, at_size = 0.4 / disc;
  const auto run = [&] (const std::vector<V>& sample, double compact_rho, double compact_size) {
    FlowParameters params;
    params.merge = MergeParameters::paperRule (1.0);
    params.interior.separate = false;
    params.merge.compact_rho = compact_rho;
    params.merge.compact_size = compact_size;
    FlowResult result;
    EXPECT_TRUE (runFlowSegmentation (sample, params, result).ok);
    return result.segments.size ();
  };
  EXPECT_EQ (run (pts, 1.001 * R / 0.5, 0.999 * at_size), 2u); // too big for a compact segment
  EXPECT_EQ (run (pts, 1.001 * R / 0.5, 1.001 * at_size), 1u);
  EXPECT_EQ (run (pts, 0.999 * R / 0.5, 1.001 * at_size), 2u); // too deep for compact_rho
  EXPECT_EQ (run (pts, 2.0, 0.0), 2u);                          // compact size 0: off
  // Scale invariant: areas and disc areas scale alike.
  std::vector<V> big;
  for (const V& p : pts)
    big.push_back (1000.0 * p);
  EXPECT_EQ (run (big, 1.001 * R / 0.5, 0.999 * at_size), 2u);
  EXPECT_EQ (run (big, 1.001 * R / 0.5, 1.001 * at_size), 1u);
  // rho < 1 merges nothing, whatever the compact pass.
  FlowParameters none;
  none.merge.rho = 0.999;
  none.interior.separate = false;
  none.merge.compact_rho = 10.0;
  none.merge.compact_size = 100.0;
  FlowResult result;
  ASSERT_TRUE (runFlowSegmentation (pts, none, result).ok);
  EXPECT_EQ (result.segments.size (), 2u);
}

TEST (HandChecked, TetrahedronFlowsIntoNeighbourHoldingTheMaximum)
{
  // ABCE contains its circumcentre (0,0,5/12); D = (0,0,-0.8) lies outside its sphere and
  // inside the diametral sphere of ABC (the unit sphere), so ABCD flows across ABC.
  const double s = std::sqrt (3.0) / 2;
  const std::vector<V> pts = {V (1, 0, 0), V (-0.5, s, 0), V (-0.5, -s, 0), V (0, 0, 1.5), V (0, 0, -0.8)};
  const FlowResult r = segmentOrDie (pts, 0.5);
  ASSERT_EQ (r.dimension, 3);
  ASSERT_EQ (r.cells.size (), 2u);
  ASSERT_EQ (r.maxima.size (), 1u);
  EXPECT_NEAR ((r.maxima[0].location - V (0, 0, 5.0 / 12)).norm (), 0.0, 1e-12);
  EXPECT_NEAR (r.maxima[0].height, 1 + 25.0 / 144, 1e-12);
  ASSERT_EQ (r.segments.size (), 1u);
  EXPECT_FALSE (r.segments[0].flows_to_infinity);
  EXPECT_EQ (r.segments[0].cell_count, 2u);
  const FlowCell& low = r.cells[r.cells[0].flow_mask ? 0 : 1];
  EXPECT_EQ (__builtin_popcount (low.flow_mask), 1);
  EXPECT_EQ (low.vertices[static_cast<std::size_t> (low.successor_facet)], r.point_to_vertex[4]); // across ABC, opposite D
}

TEST (HandChecked, RegularTetrahedronIsOneMaximum)
{
  const std::vector<V> pts = {V (1, 1, 1), V (1, -1, -1), V (-1, 1, -1), V (-1, -1, 1)};
  const FlowResult r = segmentOrDie (pts);
  ASSERT_EQ (r.cells.size (), 1u);
  ASSERT_EQ (r.maxima.size (), 1u);
  EXPECT_NEAR (r.maxima[0].height, 3.0, 1e-12);
  EXPECT_NEAR (r.maxima[0].location.norm (), 0.0, 1e-12);
  EXPECT_NEAR (r.segments[0].volume, 8.0 / 3.0, 1e-12);
}

/*
 * Degenerate input: a clear error or a correct result, never a crash or a hang.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include "test_support.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using namespace pcl_flowseg;
using flowseg_test::samePartition;
using flowseg_test::segmentOrDie;
using flowseg_test::shapeSample;
using V = Eigen::Vector3d;

namespace {
Status
run (const std::vector<V>& pts, DimensionMode mode = DimensionMode::Automatic, double rho = flowseg_test::kDefaultMerge.rho)
{
  FlowParameters params;
  params.preparation.dimension = mode;
  params.merge.rho = rho;
  FlowResult r;
  const Status full = runFlowSegmentation (pts, params, r);
  params.interior.separate = false;
  const Status raw = runFlowSegmentation (pts, params, r);
  EXPECT_EQ (raw.ok, full.ok);
  EXPECT_EQ (raw.message, full.message);
  return raw;
}

/** Every cell has a segment, every finite point a label, and the counts add up. */
void
expectConsistent (const FlowResult& r)
{
  if (r.interior.computed)
  {
    // Points inside the shape (grids, random clouds) touch no interior feature: unlabelled.
    for (const auto& c : r.cells)
      ASSERT_TRUE (c.segment >= 0 && static_cast<std::size_t> (c.segment) < r.segments.size ());
    return;
  }
  std::size_t cells = 0;
  for (const auto& s : r.segments)
    cells += s.cell_count;
  EXPECT_EQ (cells, r.cells.size ());
  for (std::size_t i = 0; i < r.point_labels.size (); ++i)
    if (r.point_to_vertex[i] >= 0)
      EXPECT_LT (r.point_labels[i], r.segments.size ());
}
} // namespace

TEST (Degenerate, EmptyAndTooFewPoints)
{
  EXPECT_NE (run ({}).message.find ("empty"), std::string::npos);
  const Status two = run ({V (0, 0, 0), V (1, 0, 0)});
  EXPECT_FALSE (two.ok);
  EXPECT_NE (two.message.find ("at least 3"), std::string::npos) << two.message;
  const Status three3d = run ({V (0, 0, 0), V (1, 0, 0), V (0, 1, 0)}, DimensionMode::Spatial);
  EXPECT_FALSE (three3d.ok);
  EXPECT_NE (three3d.message.find ("at least 4"), std::string::npos) << three3d.message;
}

TEST (Degenerate, CollinearAndCoplanar)
{
  std::vector<V> line;
  for (int i = 0; i < 50; ++i)
    line.push_back (V (i, 2 * i, 3 * i));
  const Status collinear = run (line);
  EXPECT_FALSE (collinear.ok);
  EXPECT_NE (collinear.message.find ("collinear"), std::string::npos) << collinear.message;

  const auto plane = flowseg_test::randomPoints (100, 2, 1);
  const Status coplanar = run (plane, DimensionMode::Spatial);
  EXPECT_FALSE (coplanar.ok);
  EXPECT_NE (coplanar.message.find ("coplanar"), std::string::npos) << coplanar.message;
  EXPECT_TRUE (run (plane, DimensionMode::Planar).ok);
  EXPECT_TRUE (run (plane).ok);
}

TEST (Degenerate, AllPointsEqual)
{
  const Status s = run (std::vector<V> (20, V (1, 2, 3)));
  EXPECT_FALSE (s.ok);
  EXPECT_FALSE (s.message.empty ());
}

TEST (Degenerate, DuplicatesAreReportedAndLabelledLikeTheirFirstCopy)
{
  auto pts = shapeSample ("hand2d", 500);
  const FlowResult clean = segmentOrDie (pts);
  const std::size_t n = pts.size ();
  for (std::size_t i = 0; i < n; i += 5)
    pts.push_back (pts[i]);
  const FlowResult r = segmentOrDie (pts);
  EXPECT_EQ (r.duplicate_points, (n + 4) / 5);
  EXPECT_FALSE (r.warnings.empty ());
  ASSERT_EQ (r.point_labels.size (), pts.size ());
  for (std::size_t i = 0; i < n; i += 5)
    EXPECT_EQ (r.point_labels[n + i / 5], r.point_labels[i]);
  const std::vector<std::uint32_t> first (r.point_labels.begin (), r.point_labels.begin () + static_cast<long> (n));
  EXPECT_TRUE (samePartition (first, clean.point_labels));
}

TEST (Degenerate, NonFinitePointsAreSkippedAndCounted)
{
  auto pts = shapeSample ("dumbbell3d", 800);
  pts.insert (pts.begin () + 10, V (std::nan (""), 0, 0));
  pts.push_back (V (0, std::numeric_limits<double>::infinity (), 0));
  const FlowResult r = segmentOrDie (pts);
  EXPECT_EQ (r.non_finite_points, 2u);
  EXPECT_EQ (r.point_labels[10], kNoSegment);
  EXPECT_EQ (r.point_labels.back (), kNoSegment);
  expectConsistent (r);
  const Status all_nan = run (std::vector<V> (5, V (std::nan (""), 1, 1)));
  EXPECT_FALSE (all_nan.ok);
  EXPECT_NE (all_nan.message.find ("no finite point"), std::string::npos);
}

TEST (Degenerate, RegularGridsAreCocircularEverywhere)
{
  std::vector<V> grid2, grid3;
  for (int i = 0; i < 20; ++i)
    for (int j = 0; j < 20; ++j)
    {
      grid2.push_back (V (i, j, 0));
      if (i < 9 && j < 9)
        for (int k = 0; k < 9; ++k)
          grid3.push_back (V (i, j, k));
    }
  const FlowResult r2 = segmentOrDie (grid2);
  EXPECT_EQ (r2.dimension, 2);
  expectConsistent (r2);
  const FlowResult r3 = segmentOrDie (grid3);
  EXPECT_EQ (r3.dimension, 3);
  expectConsistent (r3);
  // The whole pipeline (interior/exterior included) copes with the grids too.
  expectConsistent (segmentOrDie (grid2, flowseg_test::kDefaultMerge.rho, DimensionMode::Automatic, true));
  expectConsistent (segmentOrDie (grid3, flowseg_test::kDefaultMerge.rho, DimensionMode::Automatic, true));
  // Right triangles of a grid hold their circumcentre on an edge: no flow at all.
  for (const auto& c : r2.cells)
    EXPECT_EQ (c.flow_mask, 0);
}

TEST (Degenerate, CosphericalPoints)
{
  std::vector<V> sphere;
  // Vertices of a cube and an octahedron scaled onto one sphere, plus a fibonacci sphere.
  for (int i = 0; i < 8; ++i)
    sphere.push_back (V (i & 1 ? 1 : -1, i & 2 ? 1 : -1, i & 4 ? 1 : -1) / std::sqrt (3.0));
  for (int a = 0; a < 3; ++a)
    for (int s : {-1, 1})
    {
      V p = V::Zero ();
      p[a] = s;
      sphere.push_back (p);
    }
  const int n = 300;
  for (int i = 0; i < n; ++i)
  {
    const double z = 1 - 2 * (i + 0.5) / n, r = std::sqrt (1 - z * z), phi = i * M_PI * (3 - std::sqrt (5.0));
    sphere.push_back (V (r * std::cos (phi), r * std::sin (phi), z));
  }
  const FlowResult r = segmentOrDie (sphere);
  expectConsistent (r);
  const FlowResult full = segmentOrDie (sphere, flowseg_test::kDefaultMerge.rho, DimensionMode::Automatic, true);
  expectConsistent (full);
  EXPECT_GT (full.interior.inside_volume, 0.9 * 4.18879) << "the unit sphere encloses its volume";
  // A circle: every triangle is inscribed in the same circle.
  std::vector<V> circle;
  for (int i = 0; i < 64; ++i)
    circle.push_back (V (std::cos (i * M_PI / 32), std::sin (i * M_PI / 32), 0));
  const FlowResult c = segmentOrDie (circle);
  expectConsistent (c);
  EXPECT_EQ (c.cycle_breaks, 0u);
}

TEST (Degenerate, HugeAndTinyCoordinatesGiveTheSameSegmentation)
{
  const auto pts = shapeSample ("dumbbell3d", 800);
  const FlowResult unit = segmentOrDie (pts);
  // Powers of two (2^-40 ~ 9e-13, 2^40 ~ 1.1e12) scale exactly, so the exact predicates see
  // the same configuration and the partition must not change at all.
  for (double scale : {std::ldexp (1.0, -40), std::ldexp (1.0, 40)})
  {
    std::vector<V> scaled;
    for (const auto& p : pts)
      scaled.push_back (scale * p);
    const FlowResult r = segmentOrDie (scaled);
    EXPECT_EQ (r.segments.size (), unit.segments.size ()) << scale;
    EXPECT_TRUE (samePartition (r.point_labels, unit.point_labels)) << scale;
  }
  // Large offset: coordinates near 1e6 with unit-size features.
  std::vector<V> far;
  for (const auto& p : pts)
    far.push_back (p + V (1e6, -1e6, 1e6));
  const FlowResult r = segmentOrDie (far);
  expectConsistent (r);
}

/** Expects the default parameters changed by \a set to be refused with a message naming \a word. */
template <typename Set>
void
expectRefused (const std::vector<Eigen::Vector3d>& pts, Set set, const std::string& word)
{
  FlowParameters params;
  set (params);
  FlowResult bad;
  const Status s = runFlowSegmentation (pts, params, bad);
  EXPECT_FALSE (s.ok);
  EXPECT_NE (s.message.find (word), std::string::npos) << s.message;
}

TEST (Degenerate, AbsurdParametersAreRejected)
{
  const auto pts = shapeSample ("hand2d", 200);
  for (double rho : {0.0, -1.0, std::nan (""), std::numeric_limits<double>::infinity ()})
  {
    const Status s = run (pts, DimensionMode::Automatic, rho);
    EXPECT_FALSE (s.ok);
    EXPECT_NE (s.message.find ("rho"), std::string::npos);
  }
  for (double tolerance : {-0.1, std::nan (""), std::numeric_limits<double>::infinity ()})
    expectRefused (pts, [&] (FlowParameters& p) { p.merge.sampling_tolerance = tolerance; }, "tolerance");
  for (double ratio : {-1.0, 0.5, std::nan (""), std::numeric_limits<double>::infinity ()})
    expectRefused (pts, [&] (FlowParameters& p) { p.merge.stump_ratio = ratio; }, "stump");
  for (double value : {-1.0, std::nan (""), std::numeric_limits<double>::infinity ()})
  {
    expectRefused (pts, [&] (FlowParameters& p) { p.merge.compact_size = value; }, "compact size");
    expectRefused (pts, [&] (FlowParameters& p) { p.merge.compact_rho = value; }, "compact rho");
  }
  for (double value : {-0.1, 1.0, 5.0, std::nan (""), std::numeric_limits<double>::infinity ()})
  {
    expectRefused (pts, [&] (FlowParameters& p) { p.merge.min_part_share = value; }, "smallest part share");
    expectRefused (pts, [&] (FlowParameters& p) { p.merge.single_view_min_part_share = value; }, "part share of single views");
  }
  FlowResult r = segmentOrDie (pts);
  EXPECT_FALSE (remergeFlowSegmentation (flowseg_test::mergeParameters (-2.0), r).ok);
  EXPECT_FALSE (remergeFlowSegmentation (flowseg_test::mergeParameters (1.5, -1.0), r).ok);
  EXPECT_FALSE (remergeFlowSegmentation (flowseg_test::mergeParameters (1.5, std::nan ("")), r).ok);
  EXPECT_FALSE (remergeFlowSegmentation (flowseg_test::mergeParameters (1.5, 0.5, 0.9), r).ok);
  EXPECT_FALSE (remergeFlowSegmentation (flowseg_test::mergeParameters (1.5, 0.5, 2.0, -0.5), r).ok);
  FlowResult empty;
  EXPECT_FALSE (remergeFlowSegmentation (flowseg_test::mergeParameters (1.5), empty).ok);
}

TEST (Degenerate, NonPlanarPointsForcedTo2DAreProjectedWithAWarning)
{
  const auto pts = flowseg_test::randomPoints (200, 3, 9);
  FlowParameters params;
  params.preparation.dimension = DimensionMode::Planar;
  FlowResult r;
  ASSERT_TRUE (runFlowSegmentation (pts, params, r).ok);
  EXPECT_EQ (r.dimension, 2);
  EXPECT_FALSE (r.warnings.empty ());
  expectConsistent (r);
}

TEST (Degenerate, InputsThatWouldExceedMemoryAreRefusedUpFront)
{
  const auto pts = shapeSample ("snowman3d", 2000);
  FlowParameters params;
  params.execution.memory_limit = 1 << 20; // 1 MiB
  FlowResult r;
  const Status s = runFlowSegmentation (pts, params, r);
  EXPECT_FALSE (s.ok);
  EXPECT_NE (s.message.find ("refused before starting"), std::string::npos) << s.message;
  EXPECT_TRUE (r.cells.empty ());
  // 100M points would need about 300 GB: more than this machine (or CI) reports available.
  EXPECT_GT (estimateSegmentationMemory (100000000, 3), availableMemory ());
  params.execution.memory_limit = 0;
  EXPECT_TRUE (runFlowSegmentation (pts, params, r).ok);
}

TEST (Degenerate, OnePointFarAway)
{
  auto pts = shapeSample ("dumbbell3d", 1500);
  const FlowResult near = segmentOrDie (pts, flowseg_test::kDefaultMerge.rho, DimensionMode::Automatic, true);
  pts.push_back (V (1e6, 1e6, 1e6));
  const FlowResult far = segmentOrDie (pts, flowseg_test::kDefaultMerge.rho, DimensionMode::Automatic, true);
  expectConsistent (far);
  // The shape's interior is still found: the same inside volume within 1%.
  EXPECT_NEAR (far.interior.inside_volume, near.interior.inside_volume, 0.01 * near.interior.inside_volume);
}

/*
 * Segmentations of generated shapes with known parts.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include "test_support.h"

#include <pcl_flowseg/evaluation/segmentation_evaluation.h>

#include <gtest/gtest.h>

#include <Eigen/LU>

using namespace pcl_flowseg;
using flowseg_test::segmentOrDie;
using flowseg_test::shapeSample;
using V = Eigen::Vector3d;

namespace {

/** Barycentric containment test of \a p in a cell (brute force over all cells). */
int
cellContaining (const FlowResult& r, const V& p)
{
  const int d = r.dimension;
  for (std::size_t c = 0; c < r.cells.size (); ++c)
  {
    const auto& cell = r.cells[c];
    const V o = r.vertices[static_cast<std::size_t> (cell.vertices[0])];
    if (d == 2)
    {
      Eigen::Matrix2d m;
      for (int k = 1; k < 3; ++k)
        m.col (k - 1) = (r.vertices[static_cast<std::size_t> (cell.vertices[k])] - o).head<2> ();
      const Eigen::Vector2d b = m.partialPivLu ().solve ((p - o).head<2> ());
      if (b.minCoeff () >= 0 && b.sum () <= 1)
        return static_cast<int> (c);
    }
    else
    {
      Eigen::Matrix3d m;
      for (int k = 1; k < 4; ++k)
        m.col (k - 1) = r.vertices[static_cast<std::size_t> (cell.vertices[k])] - o;
      const V b = m.partialPivLu ().solve (p - o);
      if (b.minCoeff () >= 0 && b.sum () <= 1)
        return static_cast<int> (c);
    }
  }
  return -1;
}

/** Share of the volume of cells with centroids within \a radius of \a centre held by \a segment. */
double
shareOfBall (const FlowResult& r, const V& centre, double radius, int segment)
{
  double in = 0, total = 0;
  for (const auto& c : r.cells)
    if ((c.centroid - centre).norm () < radius)
    {
      total += c.volume;
      if (c.segment == segment)
        in += c.volume;
    }
  return total > 0 ? in / total : 0.0;
}

} // namespace

class Dumbbell : public ::testing::TestWithParam<const char*> {};

TEST_P (Dumbbell, DefaultRhoSeparatesTheTwoBulbs)
{
  const std::string name = GetParam ();
  // The whole pipeline: the bulbs must come out as separate interior features.
  const FlowResult r = segmentOrDie (shapeSample (name, name == "dumbbell2d" ? 1500 : 4000), flowseg_test::kDefaultMerge.rho,
                                     DimensionMode::Automatic, true);
  const V left (-2, 0, 0), right (2, 0, 0);
  const int cl = cellContaining (r, left), cr = cellContaining (r, right);
  ASSERT_GE (cl, 0);
  ASSERT_GE (cr, 0);
  const int sl = r.cells[static_cast<std::size_t> (cl)].segment, sr = r.cells[static_cast<std::size_t> (cr)].segment;
  EXPECT_NE (sl, sr) << "the two bulbs merged into one segment";
  EXPECT_EQ (r.segments[static_cast<std::size_t> (sl)].interior, 1);
  EXPECT_EQ (r.segments[static_cast<std::size_t> (sr)].interior, 1);
  // Each bulb's core belongs to its own segment.
  EXPECT_GT (shareOfBall (r, left, 0.8, sl), 0.95);
  EXPECT_GT (shareOfBall (r, right, 0.8, sr), 0.95);
  // The segment maxima sit near the bulb centres (the medial axis point of each ball).
  EXPECT_LT ((r.segments[static_cast<std::size_t> (sl)].maximum.location - left).norm (), 0.25);
  EXPECT_LT ((r.segments[static_cast<std::size_t> (sr)].maximum.location - right).norm (), 0.25);
}

INSTANTIATE_TEST_SUITE_P (Shapes, Dumbbell, ::testing::Values ("dumbbell2d", "dumbbell3d"));

TEST (Shapes, SnowmanBallsAreSeparateSegments)
{
  const BlobShape shape = sampleShape ("snowman3d");
  const FlowResult r = segmentOrDie (sampleBoundary (shape, 4000, 3), flowseg_test::kDefaultMerge.rho, DimensionMode::Automatic, true);
  std::vector<int> seg;
  for (const auto& part : shape.parts)
  {
    const int c = cellContaining (r, part.centre);
    ASSERT_GE (c, 0);
    seg.push_back (r.cells[static_cast<std::size_t> (c)].segment);
  }
  EXPECT_NE (seg[0], seg[1]);
  EXPECT_NE (seg[1], seg[2]);
  EXPECT_NE (seg[0], seg[2]);
}

TEST (Shapes, StumpsBringTheAnimalsPointLabelsCloserToItsParts)
{
  // The generated animal's legs, neck and tail are ellipsoids joined to the body: the flow leaves
  // the stretch of each between its narrowest place and the body with the body. Taking the stumps
  // back must bring the point labels closer to the known parts (Rand-index error, every point
  // weighing 1), and both the paper's merging and the new one must find the parts roughly.
  const BlobShape shape = sampleShape ("animal3d");
  const auto pts = sampleBoundary (shape, 4000, 1);
  std::vector<int> truth;
  for (const auto& p : pts)
    truth.push_back (shape.nearestPart (p));
  const std::vector<double> ones (pts.size (), 1.0);
  auto error = [&] (double stump_ratio) {
    const FlowResult r = segmentOrDie (pts, flowseg_test::kDefaultMerge.rho, DimensionMode::Automatic, true, flowseg_test::kDefaultMerge.sampling_tolerance, stump_ratio);
    std::vector<int> labels;
    for (std::uint32_t l : r.point_labels)
      labels.push_back (l == kNoSegment ? -1 : static_cast<int> (l));
    double e = -1.0;
    EXPECT_TRUE (randIndexError (ones, labels, truth, e));
    return e;
  };
  const double without = error (0.0), with = error (flowseg_test::kDefaultMerge.stump_ratio);
  EXPECT_LT (without, 0.05);
  EXPECT_LT (with, 0.6 * without) << "without stumps " << without << ", with " << with;
}

TEST (Shapes, GeneratorSamplesLieOnTheBoundary)
{
  for (const auto& shape : sampleShapes ())
  {
    const auto pts = sampleBoundary (shape, 500, 1);
    ASSERT_EQ (pts.size (), 500u) << shape.name;
    for (const auto& p : pts)
    {
      EXPECT_NEAR (shape.level (p), 1.0, 1e-9) << shape.name;
      if (shape.dimension == 2)
        EXPECT_EQ (p.z (), 0.0);
    }
    // Reproducible for a seed, different for another.
    EXPECT_EQ (sampleBoundary (shape, 50, 1), std::vector<V> (pts.begin (), pts.begin () + 50));
    EXPECT_NE (sampleBoundary (shape, 50, 2), std::vector<V> (pts.begin (), pts.begin () + 50));
  }
}

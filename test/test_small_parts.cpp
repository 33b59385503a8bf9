/*
 * The small-part pass: segments too small to be parts join the neighbour across their widest saddle.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include "test_support.h"

#include <pcl_flowseg/evaluation/shape_generator.h>

#include <gtest/gtest.h>

#include <map>
#include <set>

using namespace pcl_flowseg;
using flowseg_test::shapeSample;

namespace {

/** The default parameters with the interior separated and the given smallest part share. */
FlowParameters
withMinPartShare (double share)
{
  FlowParameters params;
  params.merge.min_part_share = share;
  return params;
}

FlowResult
segmentOrFail (const std::vector<Eigen::Vector3d>& pts, const FlowParameters& params)
{
  FlowResult r;
  const Status s = runFlowSegmentation (pts, params, r);
  EXPECT_TRUE (s.ok) << s.message;
  return r;
}

/** Volume of all segments on \a side (1 interior, 0 exterior). */
double
sideVolume (const FlowResult& r, int side)
{
  double total = 0.0;
  for (const FlowSegment& s : r.segments)
    total += s.interior == side ? s.volume : 0.0;
  return total;
}

/** The segment across \a segment's widest saddle on its own side, -1 if none. */
int
widestSameSideNeighbour (const FlowResult& r, int segment)
{
  int best = -1;
  double radius = -1.0;
  for (const SaddleFacet& s : r.segment_adjacency)
  {
    if (s.segment_a != segment && s.segment_b != segment)
      continue;
    const int other = s.segment_a == segment ? s.segment_b : s.segment_a;
    const auto& a = r.segments[static_cast<std::size_t> (segment)];
    const auto& b = r.segments[static_cast<std::size_t> (other)];
    if (a.interior == b.interior && s.squared_radius > radius)
      radius = s.squared_radius, best = other;
  }
  return best;
}

} // namespace

TEST (SmallParts, TheGeneratedAnimalReportsItsParts)
{
  // Eight ellipsoids (body, neck, head, tail, four legs); without the pass slivers of a few cells
  // along the surface come out as features of their own.
  const BlobShape shape = sampleShape ("animal3d");
  const auto pts = sampleBoundary (shape, 4000, 1);
  const FlowResult all = segmentOrFail (pts, withMinPartShare (0.0));
  const FlowResult parts = segmentOrFail (pts, FlowParameters ());
  EXPECT_GT (all.features.size (), shape.parts.size ());
  EXPECT_EQ (parts.features.size (), shape.parts.size ());
}

TEST (SmallParts, SmallSegmentsJoinTheirWidestNeighbourAndNothingIsLost)
{
  for (const char* name : {"animal3d", "hand2d"})
  {
    const auto pts = shapeSample (name, 3000);
    const double share = 0.01;
    const FlowResult before = segmentOrFail (pts, withMinPartShare (0.0));
    const FlowResult after = segmentOrFail (pts, withMinPartShare (share));
    ASSERT_EQ (before.cells.size (), after.cells.size ());
    // The groups of cells only join: every segment before lies in one segment after.
    std::map<int, std::set<int>> lands_in;
    for (std::size_t c = 0; c < before.cells.size (); ++c)
      lands_in[before.cells[c].segment].insert (after.cells[c].segment);
    for (const auto& [segment, targets] : lands_in)
      EXPECT_EQ (targets.size (), 1u) << name << ": segment " << segment << " was split";
    // A small segment whose widest neighbour is large ends in that neighbour's segment.
    int checked = 0;
    for (int s = 0; s < static_cast<int> (before.segments.size ()); ++s)
    {
      const FlowSegment& seg = before.segments[static_cast<std::size_t> (s)];
      const double total = sideVolume (before, seg.interior);
      const int n = widestSameSideNeighbour (before, s);
      if (seg.flows_to_infinity || n < 0 || seg.volume >= share * total ||
          before.segments[static_cast<std::size_t> (n)].volume < share * total)
        continue;
      EXPECT_EQ (*lands_in[s].begin (), *lands_in[n].begin ()) << name << ": segment " << s;
      ++checked;
    }
    EXPECT_GT (checked, 0) << name << ": the sample should have small segments";
    // After the pass no segment with a neighbour on its side is small.
    for (int s = 0; s < static_cast<int> (after.segments.size ()); ++s)
    {
      const FlowSegment& seg = after.segments[static_cast<std::size_t> (s)];
      if (!seg.flows_to_infinity && widestSameSideNeighbour (after, s) >= 0)
        EXPECT_GE (seg.volume, share * sideVolume (after, seg.interior)) << name << ": segment " << s;
    }
    EXPECT_EQ (after.point_labels.size (), before.point_labels.size ());
    std::size_t unlabelled_before = 0, unlabelled_after = 0;
    for (std::size_t i = 0; i < before.point_labels.size (); ++i)
    {
      unlabelled_before += before.point_labels[i] == kNoSegment;
      unlabelled_after += after.point_labels[i] == kNoSegment;
    }
    EXPECT_LE (unlabelled_after, unlabelled_before) << name;
  }
}

TEST (SmallParts, ThePaperRuleAndShareZeroKeepEverySegment)
{
  FlowParameters params;
  params.merge.usePaperRule ();
  EXPECT_EQ (params.merge.min_part_share, 0.0);
  EXPECT_EQ (params.merge.single_view_min_part_share, 0.0);
  const auto pts = shapeSample ("animal3d", 3000);
  const double share = FlowParameters ().merge.min_part_share;
  for (const FlowResult& r : {segmentOrFail (pts, params), segmentOrFail (pts, withMinPartShare (0.0))})
  {
    std::size_t small = 0;
    for (const FlowSegment& s : r.segments)
      small += s.interior == 1 && s.volume < share * sideVolume (r, 1);
    EXPECT_GT (small, 0u) << "slivers stay when the pass is off";
  }
}

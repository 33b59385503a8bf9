/*
 * pcl_flowseg - tests: the hidden side of a single-view scan, guessed by mirroring.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include "test_support.h"

#include "core/interior/interior_islands.h"
#include "core/preparation/hidden_side.h"

#include <pcl_flowseg/io/range_scan.h>
#include <pcl_flowseg/segmentation/flow_pipeline.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>

using namespace pcl_flowseg;
using flowseg_test::segmentWith;
using V = Eigen::Vector3d;

namespace {

using flowseg_test::addSphere;

std::vector<V>
scan (const TriangleMesh& mesh, const V& viewpoint, std::size_t points)
{
  RangeScanOptions o;
  o.viewpoint = viewpoint;
  o.points = points;
  std::vector<V> pts;
  EXPECT_TRUE (scanMesh (mesh, o, pts).ok);
  return pts;
}

/** The share of \a indices whose label is the most common among them, and that label. */
std::pair<double, std::uint32_t>
commonLabel (const FlowResult& r, const std::vector<std::size_t>& indices)
{
  std::map<std::uint32_t, std::size_t> count;
  for (std::size_t i : indices)
    ++count[r.point_labels[i]];
  const auto best = std::max_element (count.begin (), count.end (), [] (const auto& a, const auto& b) { return a.second < b.second; });
  return {static_cast<double> (best->second) / static_cast<double> (indices.size ()), best->first};
}

/** Two balls side by side (radii 1 and 0.6) scanned from the front, and which samples lie on which. */
struct TwoBallScan
{
  V sensor{0.5, 0, 12};
  std::vector<V> pts;
  std::vector<std::size_t> big, small;
};

TwoBallScan
scanTwoBalls ()
{
  TwoBallScan s;
  TriangleMesh mesh;
  addSphere (mesh, V::Zero (), 1.0);
  addSphere (mesh, V (1.5, 0, 0), 0.6);
  s.pts = scan (mesh, s.sensor, 6000);
  for (std::size_t i = 0; i < s.pts.size (); ++i)
    (std::abs ((s.pts[i] - V (1.5, 0, 0)).norm () - 0.6) < std::abs (s.pts[i].norm () - 1.0) ? s.small : s.big).push_back (i);
  return s;
}

} // namespace

TEST (HiddenSide, MirrorsTheSeenHalfOfABallOntoItsBack)
{
  TriangleMesh ball;
  addSphere (ball, V::Zero (), 1.0);
  const V sensor (0, 0, 10);
  const std::vector<V> pts = scan (ball, sensor, 4000);
  const std::vector<V> hidden = core::mirroredHiddenSide (pts, sensor);
  ASSERT_GT (hidden.size (), pts.size () / 2);
  std::vector<double> off_sphere;
  double mean_z = 0.0;
  for (const V& h : hidden)
  {
    EXPECT_LT (h.z (), 0.25); // behind the rim (which lies at z = 0.1 seen from z = 10)
    off_sphere.push_back (std::abs (h.norm () - 1.0));
    mean_z += h.z () / static_cast<double> (hidden.size ());
  }
  // A guess, not the truth: the rim samples lie a little before the limb, so the guessed back is
  // somewhat shallower than the ball's (mean z -0.57 on the true back).
  EXPECT_LT (mean_z, -0.3);
  std::nth_element (off_sphere.begin (), off_sphere.begin () + static_cast<long> (off_sphere.size () / 2), off_sphere.end ());
  EXPECT_LT (off_sphere[off_sphere.size () / 2], 0.25); // near the ball's true back
}

TEST (HiddenSide, NothingBehindTheInsideOfABowl)
{
  // The inside of a bowl seen from above: every sample lies deeper than the rim, nothing to mirror.
  TriangleMesh ball;
  addSphere (ball, V::Zero (), 1.0);
  std::vector<V> pts;
  for (const V& p : scan (ball, V (0, 0, -10), 4000)) // the lower half: seen from below, and ...
    if (p.z () < -0.2)
      pts.push_back (p);                             // ... from above, through the opening
  EXPECT_TRUE (core::mirroredHiddenSide (pts, V (0, 0, 10)).empty ());
}

TEST (HiddenSide, PartsOfAScanBecomeTheirOwnFeatures)
{
  // The big ball and the small one are two parts.
  const TwoBallScan s = scanTwoBalls ();
  ASSERT_GT (s.small.size (), 500u);

  const FlowResult r = segmentWith (s.pts, [&] (FlowParameters& p) { p.interior.viewpoint = s.sensor; });
  EXPECT_GT (r.hidden_side_vertices, s.pts.size () / 2);
  ASSERT_EQ (r.point_labels.size (), s.pts.size ()); // the added vertices label no point
  const auto [big_share, big_label] = commonLabel (r, s.big);
  const auto [small_share, small_label] = commonLabel (r, s.small);
  EXPECT_GT (big_share, 0.9);
  EXPECT_GT (small_share, 0.9);
  EXPECT_NE (big_label, small_label);

  const FlowResult off = segmentWith (s.pts, [&] (FlowParameters& p) {
    p.interior.viewpoint = s.sensor;
    p.interior.hidden_side = false;
  });
  EXPECT_EQ (off.hidden_side_vertices, 0u);
  EXPECT_EQ (off.vertices.size () + r.hidden_side_vertices, r.vertices.size ());
}

TEST (HiddenSide, ASingleViewTakesItsOwnSmallestPartShare)
{
  // The small ball holds about a sixth of the guessed volume: it stays a part of its own under a
  // whole sample's share of 0.3, and joins the big ball under a single view's share of 0.3.
  const TwoBallScan s = scanTwoBalls ();
  const auto labelsWith = [&] (double whole, double single_view) {
    const FlowResult r = segmentWith (s.pts, [&] (FlowParameters& p) {
      p.interior.viewpoint = s.sensor;
      p.merge.min_part_share = whole;
      p.merge.single_view_min_part_share = single_view;
    });
    return std::make_pair (commonLabel (r, s.big).second, commonLabel (r, s.small).second);
  };
  const auto whole = labelsWith (0.3, 0.0);
  EXPECT_NE (whole.first, whole.second);
  const auto single_view = labelsWith (0.0, 0.3);
  EXPECT_EQ (single_view.first, single_view.second);
}

TEST (HiddenSide, TinyPocketsOfInsideCellsAreDropped)
{
  TriangleMesh ball;
  addSphere (ball, V::Zero (), 1.0);
  FlowResult r = segmentWith (scan (ball, V (0, 0, 10), 3000), [] (FlowParameters& p) { p.interior.viewpoint = V (0, 0, 10); });
  // An outside cell among outside cells, labelled inside by hand: a pocket cut off from the rest.
  std::size_t pocket = r.cells.size (), inside = 0;
  for (std::size_t c = 0; c < r.cells.size (); ++c)
  {
    inside += r.cells[c].inside;
    bool lonely = !r.cells[c].inside;
    for (int i = 0; i < 4 && lonely; ++i)
      lonely = r.cells[c].neighbors[i] >= 0 && !r.cells[static_cast<std::size_t> (r.cells[c].neighbors[i])].inside;
    if (lonely && pocket == r.cells.size ())
      pocket = c;
  }
  ASSERT_LT (pocket, r.cells.size ());
  r.cells[pocket].inside = 1;
  EXPECT_EQ (core::dropInteriorIslands (r, core::kInteriorIslandShare), 1u);
  EXPECT_EQ (r.cells[pocket].inside, 0);
  std::size_t after = 0;
  for (const FlowCell& c : r.cells)
    after += c.inside;
  EXPECT_EQ (after, inside); // the ball's interior is one group and stays
  EXPECT_EQ (core::dropInteriorIslands (r, core::kInteriorIslandShare), 0u);
}

TEST (HiddenSide, NoGuessedVertexCopiesASampleOrAnother)
{
  const std::vector<V> samples{V (0, 0, 0), V (1, 0, 0)};
  const std::vector<V> mirrored{V (0, 0, 0), V (0, 0, -1), V (2, 0, 0), V (0, 0, -1), V (1, 0, 0), V (0, 0, -2)};
  const std::vector<V> kept = core::withoutCopies (samples, mirrored);
  ASSERT_EQ (kept.size (), 3u);
  EXPECT_EQ (kept[0], V (0, 0, -1));
  EXPECT_EQ (kept[1], V (2, 0, 0));
  EXPECT_EQ (kept[2], V (0, 0, -2));
}

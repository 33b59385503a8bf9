/*
 * Interior/exterior separation: labels of generated closed shapes against their ground truth.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include "core/interior/boundary_measure.h"
#include "core/interior/interior_labelling.h"
#include "core/interior/manifold_repair.h"
#include "test_support.h"

#include <pcl_flowseg/io/point_io.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <random>

using namespace pcl_flowseg;
using flowseg_test::shapeSample;
using V = Eigen::Vector3d;

namespace {

FlowResult
segmentWith (const std::vector<V>& pts, const std::function<void (FlowParameters&)>& tweak = {})
{
  FlowParameters params;
  if (tweak)
    tweak (params);
  FlowResult r;
  const Status s = runFlowSegmentation (pts, params, r);
  EXPECT_TRUE (s.ok) << s.message;
  return r;
}

/** Volume-weighted share of cells whose label agrees with \a inside (centroid test). */
double
agreement (const FlowResult& r, const std::function<bool (const V&)>& inside)
{
  double agree = 0, total = 0;
  for (const auto& c : r.cells)
  {
    total += c.volume;
    if ((c.inside == 1) == inside (c.centroid))
      agree += c.volume;
  }
  return agree / total;
}

std::vector<V>
circle (const V& centre, double radius, int n, double phase = 0.0)
{
  std::vector<V> pts;
  for (int i = 0; i < n; ++i)
  {
    const double a = phase + 2 * M_PI * i / n;
    pts.push_back (centre + radius * V (std::cos (a), std::sin (a), 0));
  }
  return pts;
}

std::vector<V>
sphere (const V& centre, double radius, int n, std::uint32_t seed)
{
  std::mt19937 rng (seed);
  std::normal_distribution<double> g (0, 1);
  std::vector<V> pts;
  for (int i = 0; i < n; ++i)
    pts.push_back (centre + radius * V (g (rng), g (rng), g (rng)).normalized ());
  return pts;
}

} // namespace

class GeneratedInterior : public ::testing::TestWithParam<std::string> {};

TEST_P (GeneratedInterior, LabelsMatchTheShapeAndTheBoundaryIsClosed)
{
  const BlobShape shape = sampleShape (GetParam ());
  const FlowResult r = segmentWith (sampleBoundary (shape, shape.dimension == 2 ? 1500 : 4000, 5));
  ASSERT_TRUE (r.interior.computed);
  EXPECT_TRUE (r.interior.closed);
  if (shape.dimension == 3)
    EXPECT_TRUE (r.interior.manifold) << r.interior.nonmanifold_edges << " edges, " << r.interior.nonmanifold_vertices << " vertices";
  EXPECT_EQ (r.interior.smoothing_passes, 0) << "a clean sample is not smoothed";
  EXPECT_LT (r.interior.vertices_off_boundary, r.vertices.size () / 100) << "samples lie on the surface";
  const double share = agreement (r, [&] (const V& p) { return shape.contains (p); });
  EXPECT_GT (share, shape.dimension == 2 ? 0.995 : 0.99) << GetParam ();
  // Every reported feature is interior and every interior cell is in one.
  ASSERT_FALSE (r.features.empty ());
  for (int k : r.features)
    EXPECT_EQ (r.segments[static_cast<std::size_t> (k)].interior, 1);
  for (const auto& c : r.cells)
    EXPECT_EQ (r.segments[static_cast<std::size_t> (c.segment)].interior, c.inside);
}

INSTANTIATE_TEST_SUITE_P (Shapes, GeneratedInterior,
                          ::testing::Values ("dumbbell2d", "star2d", "hand2d", "dumbbell3d", "snowman3d", "animal3d"));

namespace {

/** An outside cell of \a r and one of its vertices on the boundary such that no facet of the cell
  * holding that vertex is shared with an inside cell: labelling it inside pinches the boundary
  * there. False when there is none. */
bool
findPinch (const FlowResult& r, std::size_t& cell, int& vertex)
{
  std::vector<char> on_boundary (r.vertices.size (), 0);
  for (const FlowCell& c : r.cells)
    if (c.inside == 1)
      for (int v : c.vertices)
        on_boundary[static_cast<std::size_t> (v)] = 1;
  for (std::size_t k = 0; k < r.cells.size (); ++k)
  {
    const FlowCell& c = r.cells[k];
    if (c.inside != 0 || std::find (c.neighbors.begin (), c.neighbors.end (), kInfiniteCell) != c.neighbors.end ())
      continue;
    for (int i = 0; i < 4; ++i)
    {
      bool touches = false; // an inside cell across a facet holding vertices[i]
      for (int j = 0; j < 4; ++j)
        touches |= j != i && r.cells[static_cast<std::size_t> (c.neighbors[j])].inside == 1;
      if (!touches && on_boundary[static_cast<std::size_t> (c.vertices[i])])
      {
        cell = k;
        vertex = c.vertices[i];
        return true;
      }
    }
  }
  return false;
}

} // namespace

TEST (Interior, APinchedBoundaryIsMadeAManifoldAgain)
{
  FlowResult r = segmentWith (shapeSample ("snowman3d", 3000));
  ASSERT_TRUE (r.interior.manifold);
  ASSERT_TRUE (core::measureBoundary (r).empty ());
  std::size_t cell = 0;
  int vertex = -1;
  ASSERT_TRUE (findPinch (r, cell, vertex));
  r.cells[cell].inside = 1; // touches the inside only at the vertex
  const std::vector<int> bad = core::measureBoundary (r);
  EXPECT_NE (std::find (bad.begin (), bad.end (), vertex), bad.end ()) << "the pinch is seen";
  EXPECT_FALSE (r.interior.manifold);
  const std::size_t relabelled = core::repairManifold (r, bad);
  EXPECT_GE (relabelled, 1u);
  EXPECT_LE (relabelled, 20u) << "a local change";
  EXPECT_TRUE (r.interior.closed) << "the report is measured again";
  EXPECT_TRUE (r.interior.manifold);
  EXPECT_TRUE (core::measureBoundary (r).empty ());
}

TEST (Interior, ManifoldRepairCanBeSwitchedOff)
{
  pcl::PointCloud<pcl::PointXYZ> cloud; // the shipped sample: its labelling pinches the boundary once
  ASSERT_TRUE (loadPointCloud (std::string (PCL_FLOWSEG_SOURCE_DIR) + "/samples/animal3d.pcd", cloud).ok);
  std::vector<V> pts;
  for (const auto& p : cloud)
    pts.emplace_back (p.x, p.y, p.z);
  const FlowResult repaired = segmentWith (pts);
  const FlowResult raw = segmentWith (pts, [] (FlowParameters& p) { p.interior.manifold_repair = false; });
  EXPECT_TRUE (repaired.interior.manifold);
  EXPECT_GT (repaired.interior.repaired_cells, 0u);
  EXPECT_FALSE (raw.interior.manifold) << "this sample's labelling pinches its boundary";
  EXPECT_EQ (raw.interior.repaired_cells, 0u);
  EXPECT_LT (std::abs (repaired.interior.inside_volume - raw.interior.inside_volume), 1e-3 * raw.interior.inside_volume);
}

TEST (Interior, CurvesWithSeveralComponentsAndHoles)
{
  // An annulus (outer radius 2, hole of radius 1) and a separate disc: three closed curves.
  std::vector<V> pts = circle (V (0, 0, 0), 2.0, 240);
  for (const auto& p : circle (V (0, 0, 0), 1.0, 120, 0.01))
    pts.push_back (p);
  for (const auto& p : circle (V (5, 0.5, 0), 1.0, 120, 0.02))
    pts.push_back (p);
  const FlowResult r = segmentWith (pts);
  ASSERT_EQ (r.dimension, 2);
  EXPECT_TRUE (r.interior.manifold);
  const double share = agreement (r, [] (const V& p) {
    const double a = p.norm (), b = (p - V (5, 0.5, 0)).norm ();
    return (a < 2 && a > 1) || b < 1;
  });
  EXPECT_GT (share, 0.995);
  // The hole is outside: the cell holding the annulus centre is not inside.
  for (const auto& c : r.cells)
    if (c.centroid.norm () < 0.5)
      EXPECT_EQ (c.inside, 0);
}

TEST (Interior, HollowSphereIsAShell)
{
  std::vector<V> pts = sphere (V::Zero (), 2.0, 6000, 1);
  for (const auto& p : sphere (V::Zero (), 1.0, 1500, 2))
    pts.push_back (p);
  const FlowResult r = segmentWith (pts);
  const double share = agreement (r, [] (const V& p) { return p.norm () < 2 && p.norm () > 1; });
  EXPECT_GT (share, 0.98);
  EXPECT_TRUE (r.interior.closed);
}

TEST (Interior, NoisySampleIsSmoothedAndStillSeparated)
{
  const BlobShape shape = sampleShape ("snowman3d");
  auto pts = sampleBoundary (shape, 20000, 3);
  std::mt19937 rng (4);
  std::normal_distribution<double> g (0, 0.015); // 0.5% of the snowman's diagonal (about 3)
  for (auto& p : pts)
    p += V (g (rng), g (rng), g (rng));
  // The interior's own smoothing: with the sample's smoothing before the triangulation off.
  const FlowResult noisy = segmentWith (pts, [] (FlowParameters& p) { p.preparation.smoothing = Smoothing::Off; });
  EXPECT_GT (noisy.interior.surface_variation, 0.04);
  EXPECT_GE (noisy.interior.smoothing_passes, 1);
  EXPECT_GT (agreement (noisy, [&] (const V& p) { return shape.contains (p); }), 0.97);
  const FlowResult presmoothed = segmentWith (pts);
  EXPECT_GE (presmoothed.smoothing_passes, 1u);
  EXPECT_GT (agreement (presmoothed, [&] (const V& p) { return shape.contains (p); }), 0.97);
  const FlowResult raw = segmentWith (pts, [] (FlowParameters& p) {
    p.preparation.smoothing = Smoothing::Off;
    p.interior.denoising = Denoising::Off;
  });
  EXPECT_EQ (raw.interior.smoothing_passes, 0);
  EXPECT_GT (agreement (noisy, [&] (const V& p) { return shape.contains (p); }),
             agreement (raw, [&] (const V& p) { return shape.contains (p); }));
}

TEST (Interior, SmoothedSampleCanBeLabelledOnItsUnsmoothedVertices)
{
  // What the pipeline falls back to when smoothing before the triangulation collapsed thin parts
  // (more than kSmoothedOffBoundaryShare of the samples off the interior boundary).
  const BlobShape shape = sampleShape ("snowman3d");
  auto pts = sampleBoundary (shape, 8000, 3);
  std::mt19937 rng (4);
  std::normal_distribution<double> g (0, 0.015);
  for (auto& p : pts)
    p += V (g (rng), g (rng), g (rng));
  FlowResult r = segmentWith (pts, [] (FlowParameters& p) { p.preparation.smoothing = Smoothing::Always; });
  ASSERT_GE (r.smoothing_passes, 1u);
  const double presmoothed = agreement (r, [&] (const V& p) { return shape.contains (p); });
  std::vector<V> raw (r.vertices.size ());
  for (std::size_t i = 0; i < r.point_to_vertex.size (); ++i)
    raw[static_cast<std::size_t> (r.point_to_vertex[i])] = pts[i];
  ASSERT_TRUE (core::labelInteriorFromRawSample (r, InteriorParameters (), {}, raw).ok);
  EXPECT_TRUE (r.interior.computed);
  EXPECT_TRUE (r.interior.closed);
  const double carried = agreement (r, [&] (const V& p) { return shape.contains (p); });
  EXPECT_GT (carried, 0.97);
  EXPECT_GT (carried, presmoothed - 0.02);
}

TEST (Interior, OpenScanGivesAWarningNotACrash)
{
  // A hemisphere: the sample does not enclose a volume.
  std::vector<V> pts;
  for (const auto& p : sphere (V::Zero (), 1.0, 3000, 7))
    if (p.z () > 0.05)
      pts.push_back (p);
  const FlowResult r = segmentWith (pts);
  EXPECT_TRUE (r.interior.computed);
  bool warned = false;
  for (const auto& w : r.warnings)
    warned |= w.find ("boundary") != std::string::npos || w.find ("enclose") != std::string::npos;
  // Either the reconstruction closes the cap (then nothing to warn about) or it says so.
  EXPECT_TRUE (warned || r.interior.manifold);
}

TEST (Interior, ViewpointMarksTheSpaceInFrontOfAScanOutside)
{
  // A single-view scan of the dumbbell from a sensor on the +y axis: only the points the sensor
  // sees (nothing of the shape between them and the sensor).
  const BlobShape shape = sampleShape ("dumbbell3d");
  const V sensor (0, 8, 0);
  std::vector<V> pts;
  for (const auto& p : sampleBoundary (shape, 12000, 6))
  {
    bool visible = true;
    for (int k = 1; k <= 40 && visible; ++k)
      visible = !shape.contains (p + (sensor - p) * (k / 40.0) * 0.999 + (sensor - p).normalized () * 1e-3);
    if (visible)
      pts.push_back (p);
  }
  ASSERT_GT (pts.size (), 3000u);
  auto frontOutside = [&] (const FlowResult& r) {
    // Free space in front of the scan: outside the shape, on the sensor's side.
    double front = 0, out = 0;
    for (const auto& c : r.cells)
      if (!shape.contains (c.centroid) && c.centroid.y () > 0.05)
      {
        front += c.volume;
        out += c.inside == 0 ? c.volume : 0;
      }
    EXPECT_GT (front, 0);
    return out / front;
  };
  const FlowResult with = segmentWith (pts, [&] (FlowParameters& p) {
    p.interior.viewpoint = sensor;
  });
  EXPECT_GT (with.interior.ray_cells, 0u);
  EXPECT_GT (frontOutside (with), 0.99);
}

TEST (Interior, ViewpointOpensABowl)
{
  // The inside of a bowl (lower cap of the unit sphere) scanned from above: without the sensor (and
  // without the open exterior's evidence) the cap looks like a solid half-ball; the rays show that
  // the space above it is free.
  std::vector<V> pts;
  for (const auto& p : sphere (V::Zero (), 1.0, 8000, 12))
    if (p.z () < -0.1)
      pts.push_back (p);
  auto bowlOutside = [] (const FlowResult& r) {
    double volume = 0, out = 0;
    for (const auto& c : r.cells)
    {
      volume += c.volume;
      out += c.inside == 0 ? c.volume : 0;
    }
    return out / volume;
  };
  const FlowResult with = segmentWith (pts, [] (FlowParameters& p) {
    p.interior.viewpoint = V (0, 0, 1.5);
  });
  EXPECT_GT (bowlOutside (with), 0.99);
  // Without the sensor, only the open exterior's evidence (exterior_opening) opens it.
  const FlowResult without = segmentWith (pts, [] (FlowParameters& p) { p.interior.exterior_opening = 0.0; });
  EXPECT_GT (bowlOutside (with), bowlOutside (without));
  EXPECT_GT (bowlOutside (segmentWith (pts)), 0.99);
}

TEST (Interior, OrientedNormalsAreUsed)
{
  const BlobShape shape = sampleShape ("dumbbell3d");
  const auto pts = sampleBoundary (shape, 3000, 2);
  FlowParameters params;
  std::vector<V> normals;
  // Outward normals of the union of ellipsoids: the gradient of the nearest part's level set.
  for (const auto& p : pts)
  {
    const auto& part = shape.parts[static_cast<std::size_t> (shape.nearestPart (p))];
    const V local = part.rotation.transpose () * (p - part.centre);
    V g (local.x () / (part.radii.x () * part.radii.x ()), local.y () / (part.radii.y () * part.radii.y ()),
         local.z () / (part.radii.z () * part.radii.z ()));
    normals.push_back ((part.rotation * g).normalized ());
  }
  FlowResult r;
  ASSERT_TRUE (runFlowSegmentation (pts, normals, params, r).ok);
  EXPECT_GT (agreement (r, [&] (const V& p) { return shape.contains (p); }), 0.99);
  normals.pop_back ();
  EXPECT_FALSE (runFlowSegmentation (pts, normals, params, r).ok) << "normals must match the points";
}

TEST (Interior, SwitchedOffGivesTheRawSegmentation)
{
  const auto pts = shapeSample ("hand2d", 800);
  const FlowResult r = segmentWith (pts, [] (FlowParameters& p) { p.interior.separate = false; });
  EXPECT_FALSE (r.interior.computed);
  EXPECT_EQ (r.features.size (), r.segments.size ());
  for (const auto& c : r.cells)
    EXPECT_EQ (c.inside, -1);
}

TEST (Interior, ExteriorAndBothSides)
{
  const auto pts = shapeSample ("star2d", 1000);
  const FlowResult in = segmentWith (pts);
  const FlowResult out = segmentWith (pts, [] (FlowParameters& p) { p.features = FeatureSide::Exterior; });
  const FlowResult both = segmentWith (pts, [] (FlowParameters& p) { p.features = FeatureSide::Both; });
  EXPECT_EQ (in.features.size () + out.features.size (), both.features.size ());
  for (int k : out.features)
    EXPECT_EQ (out.segments[static_cast<std::size_t> (k)].interior, 0);
  // The star's five arms and its centre are interior features of significant size.
  std::size_t significant = 0;
  double total = 0;
  for (int k : in.features)
    total += in.segments[static_cast<std::size_t> (k)].volume;
  for (int k : in.features)
    significant += in.segments[static_cast<std::size_t> (k)].volume > 0.05 * total;
  EXPECT_EQ (significant, 6u);
}

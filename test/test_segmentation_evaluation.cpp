/*
 * Segmentation evaluation: Rand-index error, PSB .seg files, point-to-face label transfer.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include <pcl_flowseg/evaluation/segmentation_evaluation.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <random>
#include <unistd.h>

using namespace pcl_flowseg;

namespace {

/** The Rand-index error of a call that must succeed. */
double
errorOf (const std::vector<double>& w, const std::vector<int>& a, const std::vector<int>& b)
{
  double e = -1.0;
  EXPECT_TRUE (randIndexError (w, a, b, e));
  return e;
}

/** The face labels of a transfer that must succeed. */
std::vector<int>
facesOf (const TriangleMesh& mesh, const std::vector<Eigen::Vector3d>& points, const std::vector<std::uint32_t>& labels,
         const std::vector<std::uint32_t>& unlabelled = {})
{
  std::vector<int> faces;
  EXPECT_TRUE (transferPointLabelsToFaces (mesh, points, labels, faces, unlabelled));
  return faces;
}

/** Error by counting every pair i < j: the definition, for checking the contingency table. */
double
randIndexErrorOverAllPairs (const std::vector<double>& w, const std::vector<int>& a, const std::vector<int>& b)
{
  double disagree = 0.0, all = 0.0;
  for (std::size_t i = 0; i < w.size (); ++i)
    for (std::size_t j = i + 1; j < w.size (); ++j)
    {
      all += w[i] * w[j];
      if ((a[i] == a[j]) != (b[i] == b[j]))
        disagree += w[i] * w[j];
    }
  return disagree / all;
}

std::vector<int>
randomLabels (std::size_t n, int segments, std::mt19937& rng)
{
  std::uniform_int_distribution<int> pick (0, segments - 1);
  std::vector<int> labels (n);
  for (auto& l : labels)
    l = pick (rng);
  return labels;
}

/** Axis-aligned cube [x0, x0 + 1] x [0, 1] x [0, 1] as 12 triangles appended to \a mesh. */
void
addCube (TriangleMesh& mesh, double x0)
{
  const int base = static_cast<int> (mesh.vertices.size ());
  for (int k = 0; k < 8; ++k)
    mesh.vertices.emplace_back (x0 + (k & 1), (k >> 1) & 1, (k >> 2) & 1);
  const int quads[6][4] = {{0, 1, 3, 2}, {4, 6, 7, 5}, {0, 4, 5, 1}, {2, 3, 7, 6}, {0, 2, 6, 4}, {1, 5, 7, 3}};
  for (const auto& q : quads)
  {
    mesh.faces.push_back ({{base + q[0], base + q[1], base + q[2]}});
    mesh.faces.push_back ({{base + q[0], base + q[2], base + q[3]}});
  }
}

class SegFile
{
public:
  explicit SegFile (const std::string& text)
    : path_ ("/tmp/flowseg_seg_test_" + std::to_string (::getpid ()) + "_" + std::to_string (counter_++) + ".seg")
  {
    std::ofstream (path_, std::ios::binary) << text;
  }
  ~SegFile () { std::remove (path_.c_str ()); }
  const std::string& path () const { return path_; }

private:
  static int counter_;
  std::string path_;
};
int SegFile::counter_ = 0;

} // namespace

TEST (SegmentationEvaluation, IdenticalLabellingsHaveNoError)
{
  std::mt19937 rng (3);
  const auto labels = randomLabels (500, 7, rng);
  std::vector<double> weights (labels.size ());
  std::uniform_real_distribution<double> area (0.1, 2.0);
  for (auto& w : weights)
    w = area (rng);
  EXPECT_EQ (errorOf (weights, labels, labels), 0.0);
}

TEST (SegmentationEvaluation, RenamedSegmentIdsHaveNoError)
{
  std::mt19937 rng (4);
  const auto a = randomLabels (400, 5, rng);
  const int renamed[5] = {42, -3, 7, 1000, 0};
  std::vector<int> b;
  for (int l : a)
    b.push_back (renamed[l]);
  EXPECT_NEAR (errorOf (std::vector<double> (a.size (), 1.0), a, b), 0.0, 1e-12);
}

TEST (SegmentationEvaluation, FourFacesWithUnequalWeightsByHand)
{
  // Faces 0..3 of areas 1, 2, 3, 4. a = {0, 0, 1, 1}, b = {0, 1, 1, 1}. Pair weights (products):
  // {0,1} 2 together in a, apart in b: disagree    {0,2} 3 apart in both     {0,3} 4 apart in both
  // {1,2} 6 apart in a, together in b: disagree    {1,3} 8 disagree          {2,3} 12 together in both
  // disagreeing weight 2 + 6 + 8 = 16 of 2 + 3 + 4 + 6 + 8 + 12 = 35.
  const std::vector<double> w = {1, 2, 3, 4};
  const std::vector<int> a = {0, 0, 1, 1}, b = {0, 1, 1, 1};
  EXPECT_NEAR (errorOf (w, a, b), 16.0 / 35.0, 1e-12);
  EXPECT_NEAR (errorOf (w, b, a), 16.0 / 35.0, 1e-12);
  // Unit weights: pairs {0,1}, {1,2}, {1,3} of 6 disagree.
  EXPECT_NEAR (errorOf (std::vector<double> (4, 1.0), a, b), 3.0 / 6.0, 1e-12);
}

TEST (SegmentationEvaluation, ContingencyTableAgreesWithCountingPairs)
{
  std::mt19937 rng (5);
  std::uniform_real_distribution<double> area (0.01, 3.0);
  for (int trial = 0; trial < 5; ++trial)
  {
    const std::size_t n = 50 + 40 * static_cast<std::size_t> (trial);
    const auto a = randomLabels (n, 2 + trial, rng), b = randomLabels (n, 6 - trial, rng);
    std::vector<double> w (n);
    for (auto& x : w)
      x = area (rng);
    EXPECT_NEAR (errorOf (w, a, b), randIndexErrorOverAllPairs (w, a, b), 1e-12) << "trial " << trial;
    const std::vector<double> ones (n, 1.0);
    EXPECT_NEAR (errorOf (ones, a, b), randIndexErrorOverAllPairs (ones, a, b), 1e-12) << "trial " << trial;
  }
}

TEST (SegmentationEvaluation, ExtremeAndInvalidInputs)
{
  // One segment against every face on its own: every pair disagrees.
  EXPECT_NEAR (errorOf ({1, 2, 3}, {5, 5, 5}, {0, 1, 2}), 1.0, 1e-12);
  EXPECT_EQ (errorOf ({2.0}, {0}, {1}), 0.0);
  EXPECT_EQ (errorOf ({}, {}, {}), 0.0);
  double e = 0.5;
  const Status mismatch = randIndexError ({1, 1}, {0, 1}, {0}, e);
  EXPECT_FALSE (mismatch);
  EXPECT_NE (mismatch.message.find ("2 weights"), std::string::npos) << mismatch.message;
}

TEST (SegmentationEvaluation, ReadsSegFiles)
{
  std::vector<int> labels;
  const SegFile good ("3\n3\n-1\r\n12\n\n");
  const Status ok = readFaceSegmentation (good.path (), 4, labels);
  ASSERT_TRUE (ok.ok) << ok.message;
  EXPECT_EQ (labels, (std::vector<int>{3, 3, -1, 12}));

  const Status missing = readFaceSegmentation ("/nonexistent/dir/x.seg", 4, labels);
  EXPECT_FALSE (missing.ok);
  EXPECT_NE (missing.message.find ("cannot open"), std::string::npos) << missing.message;
  EXPECT_TRUE (labels.empty ());

  const SegFile word ("1\n2\nthree\n4\n");
  const Status not_integer = readFaceSegmentation (word.path (), 4, labels);
  EXPECT_FALSE (not_integer.ok);
  EXPECT_NE (not_integer.message.find (":3:"), std::string::npos) << not_integer.message;

  const SegFile fraction ("1\n2.5\n");
  EXPECT_FALSE (readFaceSegmentation (fraction.path (), 2, labels).ok);

  const SegFile two_per_line ("1 2\n3\n");
  EXPECT_FALSE (readFaceSegmentation (two_per_line.path (), 2, labels).ok);

  const Status wrong_count = readFaceSegmentation (good.path (), 5, labels);
  EXPECT_FALSE (wrong_count.ok);
  EXPECT_NE (wrong_count.message.find ("4 segment ids for a mesh of 5 faces"), std::string::npos) << wrong_count.message;
}

TEST (SegmentationEvaluation, FaceAreas)
{
  TriangleMesh mesh;
  addCube (mesh, 0.0);
  const auto areas = faceAreas (mesh);
  ASSERT_EQ (areas.size (), 12u);
  for (double a : areas)
    EXPECT_NEAR (a, 0.5, 1e-12);
}

TEST (SegmentationEvaluation, TransfersLabelsOnTwoPartMesh)
{
  TriangleMesh mesh;
  addCube (mesh, 0.0); // faces 0..11: part 0
  addCube (mesh, 1.5); // faces 12..23: part 1
  auto points = sampleMeshSurface (mesh, 600, 0.0, 11);
  std::vector<std::uint32_t> labels;
  for (const auto& p : points)
    labels.push_back (p.x () < 1.25 ? 0u : 1u);
  // Decoys that must not vote: three copies of every sample, labelled kNoSegment on part 1 and with
  // a label the caller declares unlabelled (9) on part 0. They outnumber the samples 3 to 1.
  const std::size_t samples = points.size ();
  for (std::size_t i = 0; i < samples; ++i)
  {
    const Eigen::Vector3d p = points[i];
    const std::uint32_t decoy = labels[i] == 0 ? 9u : kNoSegment;
    for (int copy = 0; copy < 3; ++copy)
    {
      points.push_back (p);
      labels.push_back (decoy);
    }
  }
  const auto faces = facesOf (mesh, points, labels, {9u});
  ASSERT_EQ (faces.size (), mesh.faces.size ());
  for (std::size_t f = 0; f < faces.size (); ++f)
    EXPECT_EQ (faces[f], f < 12 ? 0 : 1) << "face " << f;
  // Without declaring 9 unlabelled, those decoys outvote the samples on part 0.
  const auto with_nine = facesOf (mesh, points, labels);
  for (std::size_t f = 0; f < 12; ++f)
    EXPECT_EQ (with_nine[f], 9) << "face " << f;
  // The transferred labelling scores perfectly against the parts.
  std::vector<int> truth;
  for (std::size_t f = 0; f < faces.size (); ++f)
    truth.push_back (f < 12 ? 4 : 8);
  EXPECT_EQ (errorOf (faceAreas (mesh), faces, truth), 0.0);
}

TEST (SegmentationEvaluation, NoLabelledPointMeansNoFaceLabel)
{
  TriangleMesh mesh;
  addCube (mesh, 0.0);
  const auto points = sampleMeshSurface (mesh, 50, 0.0, 2);
  const std::vector<std::uint32_t> labels (points.size (), kNoSegment);
  const auto faces = facesOf (mesh, points, labels);
  ASSERT_EQ (faces.size (), mesh.faces.size ());
  for (int label : faces)
    EXPECT_EQ (label, -1);
  std::vector<int> unused;
  EXPECT_FALSE (transferPointLabelsToFaces (mesh, points, std::vector<std::uint32_t> (3, 0u), unused)) << "sizes differ";
}

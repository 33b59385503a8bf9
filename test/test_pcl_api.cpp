/*
 * pcl::FlowSegmentation as a PCL user sees it: clouds, indices, labels, errors.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include "test_support.h"

#include <pcl_flowseg/segmentation/flow_segmentation.h>

#include <gtest/gtest.h>

#include <limits>
#include <random>

using flowseg_test::shapeSample;

namespace {
template <typename PointT>
typename pcl::PointCloud<PointT>::Ptr
makeCloud (const std::vector<Eigen::Vector3d>& pts)
{
  typename pcl::PointCloud<PointT>::Ptr cloud (new pcl::PointCloud<PointT>);
  for (const auto& p : pts)
  {
    PointT q;
    q.x = static_cast<float> (p.x ());
    q.y = static_cast<float> (p.y ());
    q.z = static_cast<float> (p.z ());
    cloud->push_back (q);
  }
  return cloud;
}
} // namespace

template <typename PointT>
class FlowSegmentationTyped : public ::testing::Test {};
using PointTypes = ::testing::Types<pcl::PointXYZ, pcl::PointXYZRGB, pcl::PointNormal>;
TYPED_TEST_SUITE (FlowSegmentationTyped, PointTypes);

TYPED_TEST (FlowSegmentationTyped, SegmentsCoverEveryPointOnce)
{
  auto cloud = makeCloud<TypeParam> (shapeSample ("dumbbell3d", 2000));
  typename pcl::FlowSegmentation<TypeParam>::Ptr seg (new pcl::FlowSegmentation<TypeParam>);
  seg->setInputCloud (cloud);
  EXPECT_EQ (seg->getRho (), pcl_flowseg::MergeParameters ().rho);
  EXPECT_EQ (seg->getParameters ().merge.sampling_tolerance, pcl_flowseg::MergeParameters ().sampling_tolerance);
  EXPECT_EQ (seg->getParameters ().merge.stump_ratio, pcl_flowseg::MergeParameters ().stump_ratio);
  pcl_flowseg::FlowParameters raw = seg->getParameters ();
  EXPECT_TRUE (raw.interior.separate);
  raw.interior.separate = false; // the raw segmentation covers every point
  seg->setParameters (raw);
  std::vector<pcl::PointIndices> segments;
  ASSERT_TRUE (seg->segment (segments)) << seg->getLastError ();
  EXPECT_TRUE (seg->getLastError ().empty ());
  ASSERT_EQ (segments.size (), seg->getResult ().segments.size ());
  std::vector<int> seen (cloud->size (), 0);
  for (std::size_t k = 0; k < segments.size (); ++k)
  {
    EXPECT_EQ (segments[k].indices.size (), seg->getResult ().segments[k].point_count);
    for (const auto i : segments[k].indices)
      ++seen[static_cast<std::size_t> (i)];
  }
  for (int s : seen)
    EXPECT_EQ (s, 1);
  pcl::PointCloud<pcl::PointXYZL> labels;
  seg->getLabelCloud (labels);
  ASSERT_EQ (labels.size (), cloud->size ());
  for (std::size_t k = 0; k < segments.size (); ++k)
    for (const auto i : segments[k].indices)
    {
      EXPECT_EQ (labels[static_cast<std::size_t> (i)].label, k);
      EXPECT_EQ (labels[static_cast<std::size_t> (i)].x, (*cloud)[static_cast<std::size_t> (i)].x);
    }
  const auto& t = seg->getTimings ();
  EXPECT_GT (t.delaunay_ms, 0.0);
  EXPECT_GE (t.total_ms, t.delaunay_ms + t.flow_ms + t.merge_ms);
}

TEST (FlowSegmentation, InteriorFeaturesByDefault)
{
  auto cloud = makeCloud<pcl::PointXYZ> (shapeSample ("dumbbell3d", 3000));
  pcl::FlowSegmentation<pcl::PointXYZ> seg;
  seg.setInputCloud (cloud);
  std::vector<pcl::PointIndices> features;
  ASSERT_TRUE (seg.segment (features)) << seg.getLastError ();
  const auto& r = seg.getResult ();
  ASSERT_TRUE (r.interior.computed);
  ASSERT_EQ (features.size (), r.features.size ());
  for (int k : r.features)
    EXPECT_EQ (r.segments[static_cast<std::size_t> (k)].interior, 1);
  // Every sample of a closed surface touches the interior: all points are labelled.
  std::size_t labelled = 0;
  for (const auto& f : features)
    labelled += f.indices.size ();
  EXPECT_EQ (labelled, cloud->size ());
  EXPECT_GT (r.timings.interior_ms, 0.0);

  seg.setFeatureSide (pcl_flowseg::FeatureSide::Exterior);
  std::vector<pcl::PointIndices> pockets;
  ASSERT_TRUE (seg.segment (pockets));
  for (int k : seg.getResult ().features)
    EXPECT_EQ (seg.getResult ().segments[static_cast<std::size_t> (k)].interior, 0);
}

TEST (FlowSegmentation, NormalsAndSensorOriginAreUsedOnRequest)
{
  // Outward normals of the unit sphere are the positions themselves.
  pcl::PointCloud<pcl::PointNormal>::Ptr cloud (new pcl::PointCloud<pcl::PointNormal>);
  std::mt19937 rng (3);
  std::normal_distribution<float> g (0, 1);
  for (int i = 0; i < 2000; ++i)
  {
    Eigen::Vector3f p (g (rng), g (rng), g (rng));
    p.normalize ();
    pcl::PointNormal q;
    q.x = p.x (); q.y = p.y (); q.z = p.z ();
    q.normal_x = p.x (); q.normal_y = p.y (); q.normal_z = p.z ();
    cloud->push_back (q);
  }
  pcl::FlowSegmentation<pcl::PointNormal> seg;
  seg.setInputCloud (cloud);
  seg.setUseNormals (true);
  std::vector<pcl::PointIndices> features;
  ASSERT_TRUE (seg.segment (features)) << seg.getLastError ();
  EXPECT_NEAR (seg.getResult ().interior.inside_volume, 4.18879, 0.1);
  // Normals pointing inwards turn the sphere inside out: then the labelling changes.
  for (auto& q : *cloud)
  {
    q.normal_x = -q.normal_x; q.normal_y = -q.normal_y; q.normal_z = -q.normal_z;
  }
  ASSERT_TRUE (seg.segment (features));
  EXPECT_LT (seg.getResult ().interior.inside_volume, 4.0);
  seg.setUseNormals (false);
  cloud->sensor_origin_ = Eigen::Vector4f (0, 0, 5, 0);
  seg.setUseSensorOrigin (true);
  ASSERT_TRUE (seg.segment (features));
  EXPECT_GT (seg.getResult ().interior.ray_cells, 0u);
}

TEST (FlowSegmentation, IndicesRestrictTheInput)
{
  auto cloud = makeCloud<pcl::PointXYZ> (shapeSample ("dumbbell3d", 2000));
  pcl::IndicesPtr indices (new pcl::Indices);
  for (std::size_t i = 0; i < cloud->size (); ++i)
    if ((*cloud)[i].x < 0.5f)
      indices->push_back (static_cast<pcl::index_t> (i));
  pcl::FlowSegmentation<pcl::PointXYZ> seg;
  seg.setInputCloud (cloud);
  seg.setIndices (indices);
  pcl_flowseg::FlowParameters raw;
  raw.interior.separate = false;
  seg.setParameters (raw);
  std::vector<pcl::PointIndices> segments;
  ASSERT_TRUE (seg.segment (segments)) << seg.getLastError ();
  EXPECT_EQ (seg.getResult ().input_points, indices->size ());
  std::size_t total = 0;
  for (const auto& s : segments)
    for (const auto i : s.indices)
    {
      EXPECT_LT ((*cloud)[static_cast<std::size_t> (i)].x, 0.5f);
      ++total;
    }
  EXPECT_EQ (total, indices->size ());
  pcl::PointCloud<pcl::PointXYZL> labels;
  seg.getLabelCloud (labels);
  for (std::size_t i = 0; i < cloud->size (); ++i)
    EXPECT_EQ (labels[i].label == pcl_flowseg::kNoSegment, (*cloud)[i].x >= 0.5f);
}

TEST (FlowSegmentation, ErrorsAreReportedNotThrown)
{
  pcl::FlowSegmentation<pcl::PointXYZ> seg;
  std::vector<pcl::PointIndices> segments (3);
  EXPECT_FALSE (seg.segment (segments));
  EXPECT_TRUE (segments.empty ());
  EXPECT_FALSE (seg.getLastError ().empty ());

  auto tiny = makeCloud<pcl::PointXYZ> ({Eigen::Vector3d (0, 0, 0), Eigen::Vector3d (1, 0, 0)});
  seg.setInputCloud (tiny);
  EXPECT_FALSE (seg.segment (segments));
  EXPECT_NE (seg.getLastError ().find ("at least"), std::string::npos) << seg.getLastError ();

  seg.setInputCloud (makeCloud<pcl::PointXYZ> (shapeSample ("hand2d", 300)));
  seg.setRho (-1.0);
  EXPECT_FALSE (seg.segment (segments));
  EXPECT_NE (seg.getLastError ().find ("rho"), std::string::npos);
  seg.setRho (1.5);
  pcl_flowseg::FlowParameters bad = seg.getParameters ();
  bad.merge.sampling_tolerance = -0.5;
  seg.setParameters (bad);
  EXPECT_FALSE (seg.segment (segments));
  EXPECT_NE (seg.getLastError ().find ("tolerance"), std::string::npos) << seg.getLastError ();
  bad.merge.sampling_tolerance = 0.5;
  seg.setParameters (bad);
  seg.setDimension (7);
  EXPECT_FALSE (seg.segment (segments));
  EXPECT_NE (seg.getLastError ().find ("dimension"), std::string::npos);
  seg.setDimension (0);
  EXPECT_TRUE (seg.segment (segments));
  EXPECT_EQ (seg.getResult ().dimension, 2);
}

TEST (FlowSegmentation, RemergeEqualsAFreshRun)
{
  auto cloud = makeCloud<pcl::PointXYZ> (shapeSample ("animal3d", 2500));
  pcl::FlowSegmentation<pcl::PointXYZ> a, b;
  a.setInputCloud (cloud);
  b.setInputCloud (cloud);
  b.setRho (2.0);
  std::vector<pcl::PointIndices> sa, sb;
  ASSERT_TRUE (a.segment (sa));
  ASSERT_TRUE (b.segment (sb));
  ASSERT_TRUE (a.remerge (2.0, sa));
  EXPECT_EQ (a.getRho (), 2.0);
  ASSERT_EQ (sa.size (), sb.size ());
  for (std::size_t k = 0; k < sa.size (); ++k)
    EXPECT_EQ (sa[k].indices, sb[k].indices);
  // remerge keeps the sampling tolerance and stump ratio that were set (here 0: the paper's rule).
  for (pcl::FlowSegmentation<pcl::PointXYZ>* s : {&a, &b})
  {
    pcl_flowseg::FlowParameters p = s->getParameters ();
    p.merge.sampling_tolerance = p.merge.stump_ratio = 0.0;
    s->setParameters (p);
  }
  b.setRho (1.3);
  ASSERT_TRUE (b.segment (sb));
  ASSERT_TRUE (a.remerge (1.3, sa));
  ASSERT_EQ (sa.size (), sb.size ());
  for (std::size_t k = 0; k < sa.size (); ++k)
    EXPECT_EQ (sa[k].indices, sb[k].indices);
}

namespace {
void
expectSameMerge (const pcl_flowseg::MergeParameters& a, const pcl_flowseg::MergeParameters& b)
{
  EXPECT_EQ (a.rho, b.rho);
  EXPECT_EQ (a.sampling_tolerance, b.sampling_tolerance);
  EXPECT_EQ (a.stump_ratio, b.stump_ratio);
  EXPECT_EQ (a.compact_rho, b.compact_rho);
  EXPECT_EQ (a.compact_size, b.compact_size);
  EXPECT_EQ (a.min_part_share, b.min_part_share);
  EXPECT_EQ (a.single_view_min_part_share, b.single_view_min_part_share);
}
} // namespace

TEST (FlowSegmentation, ParametersRoundTripAndTheResultRecordsThem)
{
  pcl::FlowSegmentation<pcl::PointXYZ> seg;
  pcl_flowseg::FlowParameters given;
  given.merge.sampling_tolerance = 0.25;
  given.merge.stump_ratio = 3.0;
  given.merge.compact_rho = 1.4;
  given.merge.compact_size = 1.5;
  given.merge.min_part_share = 0.01;
  given.merge.single_view_min_part_share = 0.02;
  given.preparation.planar_tolerance = 1e-6;
  given.preparation.outliers = pcl_flowseg::OutlierRemoval::Always;
  given.preparation.smoothing = pcl_flowseg::Smoothing::Always;
  given.preparation.smoothing_passes = 1;
  given.interior.manifold_repair = false;
  given.interior.denoising = pcl_flowseg::Denoising::Off;
  given.execution.memory_limit = std::size_t (1) << 33;
  seg.setParameters (given);
  // The setters a PCL user reaches for change their field and keep the others.
  seg.setRho (1.3);
  seg.setDimension (2);
  seg.setFeatureSide (pcl_flowseg::FeatureSide::Both);
  seg.setNumberOfThreads (1);
  const pcl_flowseg::FlowParameters p = seg.getParameters ();
  EXPECT_EQ (p.merge.rho, 1.3);
  EXPECT_EQ (p.merge.sampling_tolerance, 0.25);
  EXPECT_EQ (p.merge.stump_ratio, 3.0);
  EXPECT_EQ (p.merge.compact_rho, 1.4);
  EXPECT_EQ (p.merge.compact_size, 1.5);
  EXPECT_EQ (p.merge.min_part_share, 0.01);
  EXPECT_EQ (p.merge.single_view_min_part_share, 0.02);
  EXPECT_EQ (p.preparation.dimension, pcl_flowseg::DimensionMode::Planar);
  EXPECT_EQ (p.preparation.planar_tolerance, 1e-6);
  EXPECT_EQ (p.preparation.outliers, pcl_flowseg::OutlierRemoval::Always);
  EXPECT_EQ (p.preparation.smoothing, pcl_flowseg::Smoothing::Always);
  EXPECT_EQ (p.preparation.smoothing_passes, 1u);
  EXPECT_EQ (p.interior.denoising, pcl_flowseg::Denoising::Off);
  EXPECT_FALSE (p.interior.manifold_repair);
  EXPECT_EQ (p.features, pcl_flowseg::FeatureSide::Both);
  EXPECT_EQ (p.execution.threads, 1u);
  EXPECT_EQ (p.execution.memory_limit, std::size_t (1) << 33);

  pcl::FlowSegmentation<pcl::PointXYZ> other;
  other.setParameters (p);
  EXPECT_EQ (other.getRho (), 1.3);
  EXPECT_EQ (other.getDimension (), 2);
  EXPECT_EQ (other.getParameters ().preparation.outliers, pcl_flowseg::OutlierRemoval::Always);
  EXPECT_EQ (other.getParameters ().preparation.smoothing_passes, 1u);
  EXPECT_EQ (other.getFeatureSide (), pcl_flowseg::FeatureSide::Both);
  EXPECT_EQ (other.getParameters ().execution.memory_limit, std::size_t (1) << 33);

  auto cloud = makeCloud<pcl::PointXYZ> (shapeSample ("hand2d", 600));
  cloud->sensor_origin_ = Eigen::Vector4f (0.5f, 9.0f, 0.0f, 0.0f);
  other.setInputCloud (cloud);
  other.setUseSensorOrigin (true);
  std::vector<pcl::PointIndices> segments;
  ASSERT_TRUE (other.segment (segments)) << other.getLastError ();
  const pcl_flowseg::FlowParameters& used = other.getResult ().parameters;
  expectSameMerge (used.merge, p.merge);
  EXPECT_EQ (used.preparation.dimension, p.preparation.dimension);
  EXPECT_EQ (used.preparation.outliers, p.preparation.outliers);
  EXPECT_EQ (used.features, p.features);
  ASSERT_TRUE (used.interior.viewpoint.has_value ());
  EXPECT_EQ (*used.interior.viewpoint, Eigen::Vector3d (0.5, 9.0, 0.0));

  // remerge takes the whole merge group, and the result records it.
  const pcl_flowseg::MergeParameters paper = pcl_flowseg::MergeParameters::paperRule (1.8);
  ASSERT_TRUE (other.remerge (paper, segments));
  expectSameMerge (other.getResult ().parameters.merge, paper);
  expectSameMerge (other.getParameters ().merge, paper);
}

TEST (FlowSegmentation, ProgressIsReportedInOrder)
{
  pcl::FlowSegmentation<pcl::PointXYZ> seg;
  seg.setInputCloud (makeCloud<pcl::PointXYZ> (shapeSample ("star2d", 300)));
  std::vector<double> fractions;
  seg.setProgressCallback ([&] (const std::string&, double f) { fractions.push_back (f); });
  std::vector<pcl::PointIndices> segments;
  ASSERT_TRUE (seg.segment (segments));
  ASSERT_GE (fractions.size (), 3u);
  EXPECT_EQ (fractions.front (), 0.0);
  EXPECT_EQ (fractions.back (), 1.0);
  EXPECT_TRUE (std::is_sorted (fractions.begin (), fractions.end ()));
}

/*
 * pcl_flowseg tests - shared helpers.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include <pcl_flowseg/segmentation/flow_pipeline.h>
#include <pcl_flowseg/evaluation/shape_generator.h>
#include <pcl_flowseg/io/mesh_io.h>
#include <pcl_flowseg/signature/signature.h>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <map>
#include <random>
#include <string>
#include <vector>

namespace flowseg_test {

/** The library's default merge group, for tests that vary one of its values. */
constexpr pcl_flowseg::MergeParameters kDefaultMerge{};

/** The signature (points and description) of a sample, with the default parameters. */
inline pcl_flowseg::Signature
signatureOf (const std::vector<Eigen::Vector3d>& pts)
{
  pcl_flowseg::FlowResult r;
  EXPECT_TRUE (pcl_flowseg::runFlowSegmentation (pts, pcl_flowseg::FlowParameters (), r).ok);
  pcl_flowseg::Signature s;
  EXPECT_TRUE (pcl_flowseg::signatureFromSegmentation (r, pcl_flowseg::kDefaultSignificance, s).ok);
  return s;
}

/** Boundary sample of one of the shipped procedural shapes. */
inline std::vector<Eigen::Vector3d>
shapeSample (const std::string& name, std::size_t count, std::uint32_t seed = 7)
{
  return pcl_flowseg::sampleBoundary (pcl_flowseg::sampleShape (name), count, seed);
}

/** Uniform random points in the unit square (z = 0) or cube. */
inline std::vector<Eigen::Vector3d>
randomPoints (std::size_t count, int dimension, std::uint32_t seed)
{
  std::mt19937 rng (seed);
  std::uniform_real_distribution<double> u (-1.0, 1.0);
  std::vector<Eigen::Vector3d> pts;
  for (std::size_t i = 0; i < count; ++i)
    pts.emplace_back (u (rng), u (rng), dimension == 3 ? u (rng) : 0.0);
  return pts;
}

/** A merge group: \a rho and the given values, the library's defaults for the others except the
  * smallest part share, 0 unless given: the tests of the rule and its passes see every segment
  * they make (test_small_parts.cpp tests the small-part pass). */
inline pcl_flowseg::MergeParameters
mergeParameters (double rho, double sampling_tolerance = kDefaultMerge.sampling_tolerance,
                 double stump_ratio = kDefaultMerge.stump_ratio,
                 double compact_size = kDefaultMerge.compact_size, double min_part_share = 0.0)
{
  pcl_flowseg::MergeParameters params;
  params.rho = rho;
  params.sampling_tolerance = sampling_tolerance;
  params.stump_ratio = stump_ratio;
  params.compact_size = compact_size;
  params.min_part_share = min_part_share;
  return params;
}

/** Runs the core and fails the calling test when it does not succeed. By default the paper's raw
  * segmentation of the whole convex hull (no interior/exterior separation): the structural
  * tests check the flow itself. The merging has the default sampling tolerance, stump ratio and
  * compact size unless given (all 0: the paper's segments exactly), and no small-part pass. */
inline pcl_flowseg::FlowResult
segmentOrDie (const std::vector<Eigen::Vector3d>& pts, double rho = kDefaultMerge.rho,
              pcl_flowseg::DimensionMode mode = pcl_flowseg::DimensionMode::Automatic, bool separate_interior = false,
              double sampling_tolerance = kDefaultMerge.sampling_tolerance,
              double stump_ratio = kDefaultMerge.stump_ratio,
              double compact_size = kDefaultMerge.compact_size)
{
  pcl_flowseg::FlowParameters params;
  params.merge = mergeParameters (rho, sampling_tolerance, stump_ratio, compact_size);
  params.preparation.dimension = mode;
  params.interior.separate = separate_interior;
  pcl_flowseg::FlowResult result;
  const auto status = pcl_flowseg::runFlowSegmentation (pts, params, result);
  if (!status.ok)
  {
    ADD_FAILURE () << "segmentation failed: " << status.message;
  }
  return result;
}

/** Runs the pipeline with \a params and fails the calling test when it does not succeed. */
inline pcl_flowseg::FlowResult
segmentWithParameters (const std::vector<Eigen::Vector3d>& pts, const pcl_flowseg::FlowParameters& params)
{
  pcl_flowseg::FlowResult result;
  const auto status = pcl_flowseg::runFlowSegmentation (pts, params, result);
  if (!status.ok)
  {
    ADD_FAILURE () << "segmentation failed: " << status.message;
  }
  return result;
}

/** Runs the pipeline with the default parameters changed by \a set (a callable on FlowParameters&)
  * and fails the calling test when it does not succeed. */
template <typename Set>
pcl_flowseg::FlowResult
segmentWith (const std::vector<Eigen::Vector3d>& pts, Set set)
{
  pcl_flowseg::FlowParameters params;
  set (params);
  return segmentWithParameters (pts, params);
}

/** True when the two label vectors describe the same partition (labels may be renamed). */
inline bool
samePartition (const std::vector<std::uint32_t>& a, const std::vector<std::uint32_t>& b, std::string* why = nullptr)
{
  if (a.size () != b.size ())
  {
    if (why) *why = "sizes differ";
    return false;
  }
  std::map<std::uint32_t, std::uint32_t> ab, ba;
  for (std::size_t i = 0; i < a.size (); ++i)
  {
    auto x = ab.emplace (a[i], b[i]);
    auto y = ba.emplace (b[i], a[i]);
    if (x.first->second != b[i] || y.first->second != a[i])
    {
      if (why) *why = "point " + std::to_string (i) + " breaks the label correspondence";
      return false;
    }
  }
  return true;
}

/** Path of a file of ../shared/data, or "" when the shared folder is not beside the project. */
inline std::string
sharedDataPath (const std::string& relative)
{
  const char* env = std::getenv ("PCL_FLOWSEG_SHARED_DATA");
  const std::string base = env ? env : std::string (PCL_FLOWSEG_SOURCE_DIR) + "/../shared/data";
  const std::string path = base + "/" + relative;
  FILE* f = std::fopen (path.c_str (), "rb");
  if (!f)
    return "";
  std::fclose (f);
  return path;
}

/** \brief Appends a UV sphere of \a radius around \a centre (\a around x \a down quads, two
  * triangles each) to \a mesh. */
inline void
addSphere (pcl_flowseg::TriangleMesh& mesh, const Eigen::Vector3d& centre, double radius, int around = 64, int down = 32)
{
  const int base = static_cast<int> (mesh.vertices.size ());
  for (int i = 0; i <= down; ++i)
    for (int j = 0; j < around; ++j)
    {
      const double theta = M_PI * i / down, phi = 2.0 * M_PI * j / around;
      mesh.vertices.push_back (centre + radius * Eigen::Vector3d (std::sin (theta) * std::cos (phi),
                                                                  std::sin (theta) * std::sin (phi), std::cos (theta)));
    }
  const auto at = [&] (int i, int j) { return base + i * around + (j % around); };
  for (int i = 0; i < down; ++i)
    for (int j = 0; j < around; ++j)
    {
      mesh.faces.push_back ({at (i, j), at (i + 1, j), at (i + 1, j + 1)});
      mesh.faces.push_back ({at (i, j), at (i + 1, j + 1), at (i, j + 1)});
    }
}

} // namespace flowseg_test

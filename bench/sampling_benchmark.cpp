/*
 * flowseg_bench_sampling: are the features the same when a shape is sampled sparsely and densely?
 * (the paper's Figure 8: HAND at 25,626 and 2,301 points).
 *
 * For each shape: segment a sparse and a dense sample with the default parameters, keep the
 * significant interior features (volume above --significance of the interior volume), match each
 * sparse feature to the nearest dense one, and report counts, volume shares and centroid distances
 * relative to the bounding-box diagonal.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include <pcl_flowseg/common/feature_significance.h>
#include <pcl_flowseg/segmentation/flow_pipeline.h>
#include <pcl_flowseg/io/mesh_io.h>
#include <pcl_flowseg/evaluation/shape_generator.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace {
struct Feature
{
  double share;
  Eigen::Vector3d centroid;
};

std::vector<Feature>
significantFeatures (const std::vector<Eigen::Vector3d>& pts, double significance, double& ms)
{
  pcl_flowseg::FlowParameters params;
  pcl_flowseg::FlowResult r;
  std::vector<Feature> out;
  if (!pcl_flowseg::runFlowSegmentation (pts, params, r))
    return out;
  ms = r.timings.total_ms;
  double total = 0;
  for (int k : r.features)
    total += r.segments[static_cast<std::size_t> (k)].volume;
  for (int k : pcl_flowseg::significantSegments (r, r.features, significance))
  {
    const auto& s = r.segments[static_cast<std::size_t> (k)];
    out.push_back (Feature{s.volume / total, s.centroid});
  }
  return out;
}

double
diagonalOf (const std::vector<Eigen::Vector3d>& pts)
{
  Eigen::Vector3d lo = pts.front (), hi = pts.front ();
  for (const auto& p : pts)
  {
    lo = lo.cwiseMin (p);
    hi = hi.cwiseMax (p);
  }
  return (hi - lo).norm ();
}

void
compare (const std::string& name, const std::vector<Eigen::Vector3d>& sparse, const std::vector<Eigen::Vector3d>& dense,
         double significance)
{
  double ms_sparse = 0, ms_dense = 0;
  const auto a = significantFeatures (sparse, significance, ms_sparse);
  const auto b = significantFeatures (dense, significance, ms_dense);
  const double diag = diagonalOf (dense);
  std::printf ("\n### %s: %zu points -> %zu significant features (%.0f ms); %zu points -> %zu (%.0f ms)\n\n", name.c_str (),
               sparse.size (), a.size (), ms_sparse, dense.size (), b.size (), ms_dense);
  std::printf ("| sparse feature | volume share | nearest dense feature | volume share | centroid distance / diagonal |\n|---|---|---|---|---|\n");
  double worst = 0;
  for (std::size_t i = 0; i < a.size (); ++i)
  {
    std::size_t best = 0;
    double best_d = 1e300;
    for (std::size_t j = 0; j < b.size (); ++j)
    {
      const double d = (a[i].centroid - b[j].centroid).norm ();
      if (d < best_d)
      {
        best_d = d;
        best = j;
      }
    }
    if (b.empty ())
      break;
    worst = std::max (worst, best_d / diag);
    std::printf ("| %zu | %.3f | %zu | %.3f | %.4f |\n", i, a[i].share, best, b[best].share, best_d / diag);
  }
  std::printf ("\nlargest centroid distance: %.4f of the diagonal\n", worst);
}
} // namespace

int
main (int argc, char** argv)
{
  std::string meshes = "../shared/data/meshes";
  double significance = 0.01;
  std::size_t sparse = 2000, dense = 25000;
  for (int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    if (a == "--meshes" && i + 1 < argc) meshes = argv[++i];
    else if (a == "--significance" && i + 1 < argc) significance = std::atof (argv[++i]);
    else
    {
      std::fprintf (stderr, "usage: flowseg_bench_sampling [--meshes DIR] [--significance 0.01]\n");
      return 2;
    }
  }
  std::printf ("Significant: volume above %.1f%% of the interior volume.\n", 100 * significance);
  pcl_flowseg::TriangleMesh hand;
  const auto st = pcl_flowseg::loadTriangleMesh (meshes + "/hand.off", hand);
  if (st)
    compare ("hand.off", pcl_flowseg::sampleMeshSurface (hand, sparse, 0, 1), pcl_flowseg::sampleMeshSurface (hand, dense, 0, 2),
             significance);
  else
    std::fprintf (stderr, "skipping hand.off: %s\n", st.message.c_str ());
  for (const char* name : {"animal3d", "snowman3d", "hand2d"})
  {
    const auto shape = pcl_flowseg::sampleShape (name);
    const std::size_t s = shape.dimension == 2 ? 300 : sparse, d = shape.dimension == 2 ? 3000 : dense;
    compare (name, pcl_flowseg::sampleBoundary (shape, s, 1), pcl_flowseg::sampleBoundary (shape, d, 2), significance);
  }
  return 0;
}

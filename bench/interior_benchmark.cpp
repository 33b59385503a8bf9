/*
 * flowseg_bench_interior: how well the interior/exterior separation matches the ground truth on
 * points sampled from closed meshes, at several densities and noise levels.
 *
 * For every mesh: sample N points area-uniformly, add Gaussian noise of sigma = fraction of the
 * bounding-box diagonal, segment, and compare every Delaunay cell's label with whether its centroid
 * lies inside the mesh. Prints a Markdown table (one row per run) and a summary.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include <pcl_flowseg/segmentation/flow_pipeline.h>
#include <pcl_flowseg/evaluation/mesh_inside_test.h>
#include "mls_prepass.h"


#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <dirent.h>
#include <string>
#include <vector>

namespace {
std::vector<std::string>
meshesIn (const std::string& dir)
{
  std::vector<std::string> out;
  if (DIR* d = opendir (dir.c_str ()))
  {
    while (dirent* e = readdir (d))
    {
      const std::string name = e->d_name;
      if (name.size () > 4 && (name.substr (name.size () - 4) == ".off" || name.substr (name.size () - 4) == ".obj"))
        out.push_back (dir + "/" + name);
    }
    closedir (d);
  }
  std::sort (out.begin (), out.end ());
  return out;
}

std::vector<double>
parseList (const char* text)
{
  std::vector<double> v;
  for (const char* s = text; *s;)
  {
    char* end = nullptr;
    v.push_back (std::strtod (s, &end));
    s = *end ? end + 1 : end;
  }
  return v;
}

/** A whole finite number >= 0 (an MLS radius in sample spacings); false for anything else. */
bool
parseRadius (const char* text, double& radius)
{
  char* end = nullptr;
  const double value = std::strtod (text, &end);
  if (end == text || *end || !std::isfinite (value) || value < 0.0)
    return false;
  radius = value;
  return true;
}

struct Options
{
  std::string dir = "../shared/data/meshes";
  std::vector<double> counts = {5000, 50000}, noises = {0.0, 0.0025, 0.005};
  std::string only;
  bool verbose = false;
  pcl_flowseg::Denoising denoising = pcl_flowseg::Denoising::Automatic;
  pcl_flowseg::PreparationParameters preparation; // its smoothing and smoothing_passes
  double mls_radius = 0.0; // > 0: PCL's MovingLeastSquares before the segmentation, radius in sample spacings
};

bool
parseOptions (int argc, char** argv, Options& o)
{
  for (int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    if (a == "--meshes" && i + 1 < argc) o.dir = argv[++i];
    else if (a == "--points" && i + 1 < argc) o.counts = parseList (argv[++i]);
    else if (a == "--noise" && i + 1 < argc) o.noises = parseList (argv[++i]);
    else if (a == "--only" && i + 1 < argc) o.only = argv[++i];
    else if (a == "--verbose") o.verbose = true;
    else if (a == "--denoise" && i + 1 < argc)
    {
      const std::string m = argv[++i];
      o.denoising = m == "off" ? pcl_flowseg::Denoising::Off : m == "on" ? pcl_flowseg::Denoising::Always : pcl_flowseg::Denoising::Automatic;
    }
    else if (a == "--smooth" && i + 1 < argc)
    {
      const std::string m = argv[++i];
      o.preparation.smoothing = m == "off" ? pcl_flowseg::Smoothing::Off : m == "on" ? pcl_flowseg::Smoothing::Always : pcl_flowseg::Smoothing::Automatic;
    }
    else if (a == "--smooth-passes" && i + 1 < argc) o.preparation.smoothing_passes = static_cast<unsigned> (std::atoi (argv[++i]));
    else if (a == "--mls" && i + 1 < argc && parseRadius (argv[i + 1], o.mls_radius)) ++i;
    else
    {
      std::fprintf (stderr, "usage: flowseg_bench_interior [--meshes DIR] [--points 5000,50000] [--noise 0,0.0025,0.005] [--only NAME]\n"
                            "                              [--denoise auto|off|on] [--smooth auto|off|on] [--smooth-passes N] [--mls R] [--verbose]\n"
                            "  --smooth, --smooth-passes: smoothing before the triangulation (PreparationParameters::smoothing, ::smoothing_passes)\n"
                            "  --mls R: PCL's MovingLeastSquares (quadratic) first, radius R sample spacings (0: none)\n"
                            "  noise: standard deviation as a fraction of the bounding-box diagonal\n");
      return false;
    }
  }
  return true;
}

struct Summary { double worst = 1.0, sum = 0.0, iou_worst = 1.0, iou_sum = 0.0; int runs = 0, closed = 0, manifold = 0; };
struct PivotRow { std::string mesh; std::vector<std::string> cells; };

/** One run: \a count points with noise \a noise (share of the diagonal) on \a mesh, its row printed,
  * its agreement added to \a pivot and \a summary. */
void
evaluateRun (const std::string& name, const pcl_flowseg::TriangleMesh& mesh, const pcl_flowseg::MeshInsideTest& truth,
             double count, double noise, bool first_noise, const Options& o, PivotRow& pivot, Summary& summary)
{
  auto pts = pcl_flowseg::sampleMeshSurface (mesh, static_cast<std::size_t> (count), noise * mesh.diagonal (), 1);
  if (o.mls_radius > 0.0)
    pts = flowseg_bench::movingLeastSquares (pts, o.mls_radius);
  pcl_flowseg::FlowParameters params;
  params.preparation.dimension = pcl_flowseg::DimensionMode::Spatial;
  params.interior.denoising = o.denoising;
  params.preparation.smoothing = o.preparation.smoothing;
  params.preparation.smoothing_passes = o.preparation.smoothing_passes;
  pcl_flowseg::FlowResult r;
  const auto status = pcl_flowseg::runFlowSegmentation (pts, params, r);
  if (!status)
  {
    std::printf ("| %s | %.0f | %.2f%% | failed: %s | | | | | | |\n", name.c_str (), count, 100 * noise, status.message.c_str ());
    return;
  }
  double agree = 0.0, total = 0.0, labelled_in = 0.0, truly_in = 0.0, both_in = 0.0;
  for (const auto& c : r.cells)
  {
    total += c.volume;
    const bool t = truth.inside (c.centroid);
    if ((c.inside == 1) == t)
      agree += c.volume;
    both_in += c.inside == 1 && t ? c.volume : 0.0;
    labelled_in += c.inside == 1 ? c.volume : 0.0;
    truly_in += t ? c.volume : 0.0;
  }
  if (o.verbose)
    std::fprintf (stderr, "%s: labelled inside %.4f of the hull volume, truly inside %.4f\n", name.c_str (), labelled_in / total,
                  truly_in / total);
  const double share = total > 0 ? agree / total : 0.0;
  const double united = labelled_in + truly_in - both_in, iou = united > 0 ? both_in / united : 0.0;
  const auto& in = r.interior;
  std::printf ("| %s | %.0f | %.2f%% | %.4f%% | %.4f | %s | %s | %zu / %zu | %.1f | %.1f |\n", name.c_str (), count, 100 * noise,
               100 * share, iou, in.closed ? "yes" : "no", in.manifold ? "yes" : "no", in.nonmanifold_edges, in.nonmanifold_vertices,
               r.timings.interior_ms, r.timings.total_ms);
  std::fflush (stdout);
  char cell[64];
  std::snprintf (cell, sizeof (cell), "%.2f%s", 100 * share, first_noise ? (in.manifold ? "" : (in.closed ? " c" : " open")) : "");
  pivot.cells.push_back (cell);
  summary.worst = std::min (summary.worst, share);
  summary.sum += share;
  summary.iou_worst = std::min (summary.iou_worst, iou);
  summary.iou_sum += iou;
  ++summary.runs;
  summary.closed += in.closed;
  summary.manifold += in.manifold;
}

void
printPivot (const std::vector<PivotRow>& pivot, const Options& o)
{
  std::printf ("\nAgreement in %% by points and noise (clean runs: \"c\" = boundary closed but not manifold):\n\n| mesh |");
  for (double count : o.counts)
    for (double noise : o.noises)
      std::printf (" %.0fk, %.2f%% |", count / 1000, 100 * noise);
  std::printf ("\n|---|");
  for (std::size_t k = 0; k < o.counts.size () * o.noises.size (); ++k)
    std::printf ("---|");
  std::printf ("\n");
  for (const auto& row : pivot)
  {
    std::printf ("| %s |", row.mesh.c_str ());
    for (const auto& c : row.cells)
      std::printf (" %s |", c.c_str ());
    std::printf ("\n");
  }
}

void
printSummary (const std::vector<Summary>& by_run, const Options& o)
{
  std::printf ("\n| points | noise | runs | mean agreement | worst agreement | mean volume IoU | worst volume IoU | closed | manifold |\n"
               "|---|---|---|---|---|---|---|---|---|\n");
  for (std::size_t ci = 0; ci < o.counts.size (); ++ci)
    for (std::size_t k = 0; k < o.noises.size (); ++k)
    {
      const Summary& s = by_run[ci * o.noises.size () + k];
      if (s.runs)
        std::printf ("| %.0f | %.2f%% | %d | %.3f%% | %.3f%% | %.4f | %.4f | %d | %d |\n", o.counts[ci], 100 * o.noises[k], s.runs,
                     100 * s.sum / s.runs, 100 * s.worst, s.iou_sum / s.runs, s.iou_worst, s.closed, s.manifold);
    }
}
} // namespace

int
main (int argc, char** argv)
{
  Options o;
  if (!parseOptions (argc, argv, o))
    return 2;
  const auto meshes = meshesIn (o.dir);
  if (meshes.empty ())
  {
    std::fprintf (stderr, "flowseg_bench_interior: no .off/.obj meshes in %s\n", o.dir.c_str ());
    return 1;
  }
  std::printf ("| mesh | points | noise | agreement | volume IoU | closed | manifold | non-manifold edges / vertices | interior ms | total ms |\n");
  std::printf ("|---|---|---|---|---|---|---|---|---|---|\n");
  std::vector<PivotRow> pivot;
  std::vector<Summary> by_run (o.counts.size () * o.noises.size ());
  for (const auto& path : meshes)
  {
    const std::string name = path.substr (path.find_last_of ('/') + 1);
    if (!o.only.empty () && name.find (o.only) == std::string::npos)
      continue;
    pcl_flowseg::TriangleMesh mesh;
    if (const auto st = pcl_flowseg::loadTriangleMesh (path, mesh); !st)
    {
      std::fprintf (stderr, "skip %s: %s\n", name.c_str (), st.message.c_str ());
      continue;
    }
    pcl_flowseg::MeshInsideTest truth (mesh);
    if (!truth.valid ())
    {
      std::fprintf (stderr, "skip %s: not a closed manifold mesh\n", name.c_str ());
      continue;
    }
    pivot.push_back (PivotRow{name, {}});
    for (std::size_t ci = 0; ci < o.counts.size (); ++ci)
      for (std::size_t k = 0; k < o.noises.size (); ++k)
        evaluateRun (name, mesh, truth, o.counts[ci], o.noises[k], k == 0, o, pivot.back (), by_run[ci * o.noises.size () + k]);
  }
  printPivot (pivot, o);
  printSummary (by_run, o);
  return 0;
}

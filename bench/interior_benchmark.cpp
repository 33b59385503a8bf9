/*
 * flowseg_bench_interior: how well the interior/exterior separation matches the ground truth on
 * points sampled from closed meshes, at several densities and noise levels, with Poisson surface
 * reconstruction beside it (--peer poisson).
 *
 * For every mesh: sample N points area-uniformly, add Gaussian noise of sigma = fraction of the
 * bounding-box diagonal, segment, and compare every Delaunay cell's label with whether its centroid
 * lies inside the mesh. The peer's label of a cell is whether its solid holds the cell's centroid,
 * so both are scored on the same cells. Meshes in subfolders are grouped by folder (a class, as in
 * ../shared/data/shrec07_dev). Prints a Markdown table (one row per run), a pivot, a summary and,
 * for classes, the mean IoU per class.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include <pcl_flowseg/segmentation/flow_pipeline.h>
#include <pcl_flowseg/evaluation/mesh_inside_test.h>
#include "mls_prepass.h"
#include "poisson_peer.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <dirent.h>
#include <map>
#include <string>
#include <vector>

namespace {
struct MeshFile { std::string path, name, group; };

bool
isMeshName (const std::string& name)
{
  const auto ends = [&] (const char* ext) { return name.size () > 4 && name.compare (name.size () - 4, 4, ext) == 0; };
  return ends (".off") || ends (".obj");
}

/** The meshes in \a dir and, one level down, in its subfolders (their group is the folder's name);
  * at most \a per_group of each group (0: all), in name order. */
std::vector<MeshFile>
meshesIn (const std::string& dir, std::size_t per_group)
{
  std::vector<MeshFile> out;
  std::vector<std::string> folders;
  if (DIR* d = opendir (dir.c_str ()))
  {
    while (dirent* e = readdir (d))
    {
      const std::string name = e->d_name;
      if (isMeshName (name))
        out.push_back ({dir + "/" + name, name, ""});
      else if (name[0] != '.')
        folders.push_back (name);
    }
    closedir (d);
  }
  const auto by_name = [] (const MeshFile& a, const MeshFile& b) { return a.name < b.name; };
  std::sort (out.begin (), out.end (), by_name);
  std::sort (folders.begin (), folders.end ());
  for (const auto& folder : folders)
  {
    std::vector<MeshFile> in_folder;
    if (DIR* d = opendir ((dir + "/" + folder).c_str ()))
    {
      while (dirent* e = readdir (d))
        if (isMeshName (e->d_name))
          in_folder.push_back ({dir + "/" + folder + "/" + e->d_name, folder + "/" + e->d_name, folder});
      closedir (d);
    }
    std::sort (in_folder.begin (), in_folder.end (), by_name);
    if (per_group && in_folder.size () > per_group)
      in_folder.resize (per_group);
    out.insert (out.end (), in_folder.begin (), in_folder.end ());
  }
  return out; // loose meshes by name, then each folder's by name
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

/** A finite number >= 0 (a radius or an opening in sample spacings); false for anything else. */
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
  std::size_t per_group = 0; // --per-class N: the first N meshes of each subfolder (0: all)
  bool verbose = false, poisson = false;
  pcl_flowseg::Denoising denoising = pcl_flowseg::Denoising::Automatic;
  pcl_flowseg::PreparationParameters preparation; // its smoothing and smoothing_passes
  double mls_radius = 0.0; // > 0: PCL's MovingLeastSquares before the segmentation, radius in sample spacings
  double exterior_opening = pcl_flowseg::InteriorParameters ().exterior_opening;
};

void
printUsage ()
{
  std::fprintf (stderr, "usage: flowseg_bench_interior [--meshes DIR] [--per-class N] [--points 5000,50000] [--noise 0,0.0025,0.005]\n"
                        "                              [--only NAME] [--peer poisson] [--denoise auto|off|on] [--smooth auto|off|on]\n"
                        "                              [--smooth-passes N] [--mls R] [--exterior-opening S] [--verbose]\n"
                        "  --meshes DIR: .off/.obj meshes in DIR and its subfolders (a subfolder is a class)\n"
                        "  --per-class N: the first N meshes of each subfolder, by name (default: all)\n"
                        "  --peer poisson: CGAL's Poisson reconstruction on jet normals oriented by a spanning tree, scored on the same cells\n"
                        "  --smooth, --smooth-passes: smoothing before the triangulation (PreparationParameters::smoothing, ::smoothing_passes)\n"
                        "  --exterior-opening S: InteriorParameters::exterior_opening, sample spacings (0: off; default 4)\n"
                        "  --mls R: PCL's MovingLeastSquares (quadratic) first, radius R sample spacings (0: none)\n"
                        "  noise: standard deviation as a fraction of the bounding-box diagonal\n");
}

pcl_flowseg::Denoising
denoisingMode (const std::string& m)
{
  return m == "off" ? pcl_flowseg::Denoising::Off : m == "on" ? pcl_flowseg::Denoising::Always : pcl_flowseg::Denoising::Automatic;
}

pcl_flowseg::Smoothing
smoothingMode (const std::string& m)
{
  return m == "off" ? pcl_flowseg::Smoothing::Off : m == "on" ? pcl_flowseg::Smoothing::Always : pcl_flowseg::Smoothing::Automatic;
}

bool
parseOptions (int argc, char** argv, Options& o)
{
  for (int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    const bool has_value = i + 1 < argc;
    if (a == "--meshes" && has_value) o.dir = argv[++i];
    else if (a == "--per-class" && has_value) o.per_group = static_cast<std::size_t> (std::atoi (argv[++i]));
    else if (a == "--points" && has_value) o.counts = parseList (argv[++i]);
    else if (a == "--noise" && has_value) o.noises = parseList (argv[++i]);
    else if (a == "--only" && has_value) o.only = argv[++i];
    else if (a == "--peer" && has_value && std::string (argv[i + 1]) == "poisson") o.poisson = (++i, true);
    else if (a == "--verbose") o.verbose = true;
    else if (a == "--denoise" && has_value) o.denoising = denoisingMode (argv[++i]);
    else if (a == "--smooth" && has_value) o.preparation.smoothing = smoothingMode (argv[++i]);
    else if (a == "--smooth-passes" && has_value) o.preparation.smoothing_passes = static_cast<unsigned> (std::atoi (argv[++i]));
    else if (a == "--mls" && has_value && parseRadius (argv[i + 1], o.mls_radius)) ++i;
    else if (a == "--exterior-opening" && has_value && parseRadius (argv[i + 1], o.exterior_opening)) ++i;
    else
    {
      printUsage ();
      return false;
    }
  }
  return true;
}

/** Volumes of the cells labelled inside, truly inside, both, and agreeing. */
struct Overlap
{
  double agree = 0.0, total = 0.0, both = 0.0, labelled = 0.0, truly = 0.0;
  void add (double volume, bool labelled_in, bool truly_in)
  {
    total += volume;
    agree += labelled_in == truly_in ? volume : 0.0;
    both += labelled_in && truly_in ? volume : 0.0;
    labelled += labelled_in ? volume : 0.0;
    truly += truly_in ? volume : 0.0;
  }
  double share () const { return total > 0 ? agree / total : 0.0; }
  double iou () const { return labelled + truly - both > 0 ? both / (labelled + truly - both) : 0.0; }
};

/** Sums over the runs of one point count and noise level (of all meshes, or of one class). */
struct Summary
{
  double worst = 1.0, sum = 0.0, iou_worst = 1.0, iou_sum = 0.0, peer_iou_sum = 0.0, peer_iou_worst = 1.0;
  int runs = 0, closed = 0, manifold = 0, peer_runs = 0;
};
struct PivotRow { std::string mesh; std::vector<std::string> cells; };
/** One run's place: its mesh's pivot row, the summary of its count and noise, and its class's. */
struct RunSinks { PivotRow& pivot; Summary& overall; Summary* group; };

void
addPeer (double iou, Summary& s)
{
  s.peer_iou_sum += iou;
  s.peer_iou_worst = std::min (s.peer_iou_worst, iou);
  ++s.peer_runs;
}

/** The Poisson peer's IoU on \a r's cells, or -1 (reason on stderr) when it fails. */
double
poissonIou (const std::string& name, const std::vector<Eigen::Vector3d>& pts, const pcl_flowseg::FlowResult& r,
            const std::vector<char>& truly_inside, double& seconds)
{
  flowseg_bench::PoissonSolid solid;
  if (const auto st = solid.reconstruct (pts, 18, &seconds); !st)
  {
    std::fprintf (stderr, "%s: %s\n", name.c_str (), st.message.c_str ());
    return -1.0;
  }
  Overlap overlap;
  for (std::size_t i = 0; i < r.cells.size (); ++i)
    overlap.add (r.cells[i].volume, solid.inside (r.cells[i].centroid), truly_inside[i]);
  return overlap.iou ();
}

/** One run: \a count points with noise \a noise (share of the diagonal) on \a mesh, its row printed,
  * its agreement added to the pivot and summaries of \a sinks. */
void
evaluateRun (const std::string& name, const pcl_flowseg::TriangleMesh& mesh, const pcl_flowseg::MeshInsideTest& truth,
             double count, double noise, bool first_noise, const Options& o, RunSinks sinks)
{
  auto pts = pcl_flowseg::sampleMeshSurface (mesh, static_cast<std::size_t> (count), noise * mesh.diagonal (), 1);
  if (o.mls_radius > 0.0)
    pts = flowseg_bench::movingLeastSquares (pts, o.mls_radius);
  pcl_flowseg::FlowParameters params;
  params.preparation.dimension = pcl_flowseg::DimensionMode::Spatial;
  params.interior.denoising = o.denoising;
  params.interior.exterior_opening = o.exterior_opening;
  params.preparation.smoothing = o.preparation.smoothing;
  params.preparation.smoothing_passes = o.preparation.smoothing_passes;
  pcl_flowseg::FlowResult r;
  const auto status = pcl_flowseg::runFlowSegmentation (pts, params, r);
  if (!status)
  {
    std::printf ("| %s | %.0f | %.2f%% | failed: %s | | | | | | | | |\n", name.c_str (), count, 100 * noise, status.message.c_str ());
    return;
  }
  std::vector<char> truly_inside (r.cells.size ());
  Overlap overlap;
  for (std::size_t i = 0; i < r.cells.size (); ++i)
  {
    truly_inside[i] = truth.inside (r.cells[i].centroid);
    overlap.add (r.cells[i].volume, r.cells[i].inside == 1, truly_inside[i]);
  }
  if (o.verbose)
    std::fprintf (stderr, "%s: labelled inside %.4f of the hull volume, truly inside %.4f\n", name.c_str (),
                  overlap.labelled / overlap.total, overlap.truly / overlap.total);
  double peer_seconds = 0.0;
  const double peer_iou = o.poisson ? poissonIou (name, pts, r, truly_inside, peer_seconds) : -1.0;
  const double share = overlap.share (), iou = overlap.iou ();
  const auto& in = r.interior;
  std::printf ("| %s | %.0f | %.2f%% | %.4f%% | %.4f | %s | %s | %zu / %zu | %.1f | %.1f |", name.c_str (), count, 100 * noise,
               100 * share, iou, in.closed ? "yes" : "no", in.manifold ? "yes" : "no", in.nonmanifold_edges, in.nonmanifold_vertices,
               r.timings.interior_ms, r.timings.total_ms);
  if (peer_iou >= 0.0)
    std::printf (" %.4f | %.0f |\n", peer_iou, 1000 * peer_seconds);
  else
    std::printf (o.poisson ? " failed | |\n" : " | |\n");
  std::fflush (stdout);
  char cell[64];
  std::snprintf (cell, sizeof (cell), "%.2f%s", 100 * share, first_noise ? (in.manifold ? "" : (in.closed ? " c" : " open")) : "");
  sinks.pivot.cells.push_back (cell);
  for (Summary* s : {&sinks.overall, sinks.group})
  {
    if (!s)
      continue;
    s->worst = std::min (s->worst, share);
    s->sum += share;
    s->iou_worst = std::min (s->iou_worst, iou);
    s->iou_sum += iou;
    ++s->runs;
    s->closed += in.closed;
    s->manifold += in.manifold;
    if (peer_iou >= 0.0)
      addPeer (peer_iou, *s);
  }
}

/** The header of a table with \a leading columns (e.g. "| mesh |") and one column per point count
  * and noise level, with its separator row. */
void
printRunColumns (const char* leading, std::size_t leading_count, const Options& o)
{
  std::printf ("%s", leading);
  for (double count : o.counts)
    for (double noise : o.noises)
      std::printf (" %.0fk, %.2f%% |", count / 1000, 100 * noise);
  std::printf ("\n|");
  for (std::size_t k = 0; k < leading_count + o.counts.size () * o.noises.size (); ++k)
    std::printf ("---|");
  std::printf ("\n");
}

void
printPivot (const std::vector<PivotRow>& pivot, const Options& o)
{
  std::printf ("\nAgreement in %% by points and noise (clean runs: \"c\" = boundary closed but not manifold):\n\n");
  printRunColumns ("| mesh |", 1, o);
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
  std::printf ("\n| points | noise | runs | mean agreement | worst agreement | mean volume IoU | worst volume IoU | closed | manifold |"
               " Poisson mean IoU | Poisson worst IoU | Poisson runs |\n|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  for (std::size_t ci = 0; ci < o.counts.size (); ++ci)
    for (std::size_t k = 0; k < o.noises.size (); ++k)
    {
      const Summary& s = by_run[ci * o.noises.size () + k];
      if (!s.runs)
        continue;
      std::printf ("| %.0f | %.2f%% | %d | %.3f%% | %.3f%% | %.4f | %.4f | %d | %d |", o.counts[ci], 100 * o.noises[k], s.runs,
                   100 * s.sum / s.runs, 100 * s.worst, s.iou_sum / s.runs, s.iou_worst, s.closed, s.manifold);
      if (s.peer_runs)
        std::printf (" %.4f | %.4f | %d |\n", s.peer_iou_sum / s.peer_runs, s.peer_iou_worst, s.peer_runs);
      else
        std::printf (" | | |\n");
    }
}

/** Mean volume IoU per class (subfolder) and run, the peer's after a slash. */
void
printClasses (const std::map<std::string, std::vector<Summary>>& by_group, const Options& o)
{
  if (by_group.empty ())
    return;
  std::printf ("\nMean volume IoU per class%s:\n\n", o.poisson ? " (module / Poisson)" : "");
  printRunColumns ("| class | models |", 2, o);
  for (const auto& [group, runs] : by_group)
  {
    std::printf ("| %s | %d |", group.c_str (), runs.front ().runs);
    for (const Summary& s : runs)
    {
      if (s.peer_runs)
        std::printf (" %.3f / %.3f |", s.runs ? s.iou_sum / s.runs : 0.0, s.peer_iou_sum / s.peer_runs);
      else
        std::printf (" %.3f |", s.runs ? s.iou_sum / s.runs : 0.0);
    }
    std::printf ("\n");
  }
}
} // namespace

int
main (int argc, char** argv)
{
  Options o;
  if (!parseOptions (argc, argv, o))
    return 2;
  const auto meshes = meshesIn (o.dir, o.per_group);
  if (meshes.empty ())
  {
    std::fprintf (stderr, "flowseg_bench_interior: no .off/.obj meshes in %s or its subfolders\n", o.dir.c_str ());
    return 1;
  }
  std::printf ("| mesh | points | noise | agreement | volume IoU | closed | manifold | non-manifold edges / vertices | interior ms | total ms |"
               " Poisson IoU | Poisson ms |\n|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  const std::size_t run_kinds = o.counts.size () * o.noises.size ();
  std::vector<PivotRow> pivot;
  std::vector<Summary> by_run (run_kinds);
  std::map<std::string, std::vector<Summary>> by_group;
  for (const auto& file : meshes)
  {
    if (!o.only.empty () && file.name.find (o.only) == std::string::npos)
      continue;
    pcl_flowseg::TriangleMesh mesh;
    if (const auto st = pcl_flowseg::loadTriangleMesh (file.path, mesh); !st)
    {
      std::fprintf (stderr, "skip %s: %s\n", file.name.c_str (), st.message.c_str ());
      continue;
    }
    pcl_flowseg::MeshInsideTest truth (mesh);
    if (!truth.valid ())
    {
      std::fprintf (stderr, "skip %s: not a closed manifold mesh\n", file.name.c_str ());
      continue;
    }
    pivot.push_back (PivotRow{file.name, {}});
    std::vector<Summary>* group = file.group.empty () ? nullptr : &by_group.try_emplace (file.group, run_kinds).first->second;
    for (std::size_t ci = 0; ci < o.counts.size (); ++ci)
      for (std::size_t k = 0; k < o.noises.size (); ++k)
      {
        const std::size_t run = ci * o.noises.size () + k;
        evaluateRun (file.name, mesh, truth, o.counts[ci], o.noises[k], k == 0, o,
                     RunSinks{pivot.back (), by_run[run], group ? &(*group)[run] : nullptr});
      }
  }
  printPivot (pivot, o);
  printSummary (by_run, o);
  printClasses (by_group, o);
  return 0;
}

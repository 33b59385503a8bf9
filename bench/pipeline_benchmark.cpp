/*
 * flowseg_bench_pipeline: where the time and memory of a segmentation go, against the floor of a
 * bare CGAL Delaunay triangulation of the same points.
 *
 * For each input (the paper's HORSE: the vertices of horse.off; procedural shapes of growing size),
 * in a child process of its own so that its peak memory is its own:
 *   - bare CGAL Delaunay_triangulation_3 of the points, sequential and parallel (TBB): the floor;
 *   - runFlowSegmentation with default parameters, per stage (best of --repeat runs by total);
 *   - the signature of the result;
 *   - the whole flowseg_segment process (built beside this benchmark) on the points written as a
 *     binary PCD: read, pipeline and its default outputs; its time and its peak resident memory
 *     (the memory a user sees; the in-process figure would include what the bare triangulations
 *     left in the heap).
 * Prints one Markdown table, the ratio of the whole pipeline to the sequential floor and the
 * speed-up over the paper's Figure 9 (2.8 GHz Pentium IV) where a size matches its models.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include <pcl_flowseg/segmentation/flow_pipeline.h>
#include <pcl_flowseg/io/mesh_io.h>
#include <pcl_flowseg/io/point_cloud_writer.h>
#include <pcl_flowseg/evaluation/shape_generator.h>
#include <pcl_flowseg/signature/signature.h>

#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <tbb/global_control.h>

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

namespace {

using Clock = std::chrono::steady_clock;
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;

double
msSince (Clock::time_point t)
{
  return std::chrono::duration<double, std::milli> (Clock::now () - t).count ();
}

/** Peak resident set of this process in bytes since the last resetPeakMemory (Linux VmHWM). */
std::size_t
peakMemory ()
{
  std::ifstream status ("/proc/self/status");
  std::string key;
  while (status >> key)
  {
    if (key == "VmHWM:")
    {
      std::size_t kb = 0;
      status >> kb;
      return kb * 1024;
    }
    status.ignore (1 << 12, '\n');
  }
  return 0;
}

void
resetPeakMemory ()
{
  std::ofstream ("/proc/self/clear_refs") << "5"; // resets VmHWM to the current RSS
}

/** Best-of-repeat wall time of a bare CGAL triangulation (no information attached to anything). */
template <class Concurrency>
double
bareDelaunay (const std::vector<Kernel::Point_3>& points, int repeat, std::size_t& cells)
{
  using Tds = CGAL::Triangulation_data_structure_3<CGAL::Triangulation_vertex_base_3<Kernel>,
                                                   CGAL::Delaunay_triangulation_cell_base_3<Kernel>, Concurrency>;
  using Delaunay = CGAL::Delaunay_triangulation_3<Kernel, Tds>;
  double best = 1e300;
  for (int r = 0; r < repeat; ++r)
  {
    const auto start = Clock::now ();
    if constexpr (std::is_same<Concurrency, CGAL::Parallel_tag>::value)
    {
      CGAL::Bbox_3 box;
      for (const auto& p : points)
        box += p.bbox ();
      typename Delaunay::Lock_data_structure locks (box, 50);
      Delaunay dt (points.begin (), points.end (), &locks);
      cells = dt.number_of_finite_cells ();
      best = std::min (best, msSince (start)); // destruction not counted
    }
    else
    {
      Delaunay dt (points.begin (), points.end ());
      cells = dt.number_of_finite_cells ();
      best = std::min (best, msSince (start));
    }
  }
  return best;
}

/** What one child process measures. Plain data: it crosses a pipe. */
struct Measurement
{
  int ok = 0;
  std::size_t points = 0, cells = 0, features = 0, significant = 0;
  double bare_sequential_ms = 0, bare_parallel_ms = 0, signature_ms = 0;
  double process_ms = 0; ///< the whole flowseg_segment process (read, pipeline, default outputs); 0 = not run
  pcl_flowseg::StageTimings stages;
  std::size_t process_peak_bytes = 0, bare_peak_bytes = 0;
  char error[200] = {0};
};

struct Input
{
  std::string name;
  std::size_t count = 0;      // 0: the mesh's vertices
  double paper_seconds = 0.0; // Figure 9, Delaunay + segmentation + in/out, 0 when none matches
};

std::vector<Eigen::Vector3d>
makePoints (const Input& in, const std::string& mesh_path, std::string& error)
{
  if (in.count == 0)
  {
    pcl_flowseg::TriangleMesh mesh;
    const auto st = pcl_flowseg::loadTriangleMesh (mesh_path, mesh);
    if (!st)
      error = st.message;
    return mesh.vertices;
  }
  return pcl_flowseg::sampleBoundary (pcl_flowseg::sampleShape ("animal3d"), in.count, 1);
}

/** The flowseg_segment app built beside this benchmark, or "" when it is not there. */
std::string
segmentApp ()
{
  char exe[4096] = {0};
  const ssize_t n = readlink ("/proc/self/exe", exe, sizeof (exe) - 1);
  std::string path = n > 0 ? std::string (exe, static_cast<std::size_t> (n)) : "";
  path = path.substr (0, path.find_last_of ('/'));             // .../build/bench
  path = path.substr (0, path.find_last_of ('/')) + "/apps/flowseg_segment";
  return access (path.c_str (), X_OK) == 0 ? path : "";
}

/** Best wall time of the whole flowseg_segment process on \a points (written as a binary PCD
  * first), with its default outputs; 0 when the app is missing or fails. */
double
wholeProcessMs (const std::vector<Eigen::Vector3d>& points, unsigned threads, int repeat, std::size_t& peak_bytes)
{
  const std::string app = segmentApp ();
  if (app.empty ())
    return 0.0;
  const std::string base = "/tmp/flowseg_bench_pipeline_" + std::to_string (getpid ());
  pcl::PointCloud<pcl::PointXYZ> cloud;
  for (const auto& p : points)
    cloud.push_back (pcl::PointXYZ (static_cast<float> (p.x ()), static_cast<float> (p.y ()), static_cast<float> (p.z ())));
  if (!pcl_flowseg::writePointCloud (base + ".pcd", cloud, true))
    return 0.0;
  const std::string command = app + " " + base + ".pcd -o " + base + " -q -j " + std::to_string (threads) + " 2>/dev/null";
  double best = 0.0;
  for (int r = 0; r < repeat; ++r)
  {
    const auto start = Clock::now ();
    if (std::system (command.c_str ()) != 0)
      return 0.0;
    const double ms = msSince (start);
    best = r == 0 ? ms : std::min (best, ms);
  }
  for (const char* suffix : {".pcd", ".labels.pcd", ".json", ".ply", ".surface.ply", ".svg"})
    std::remove ((base + suffix).c_str ());
  rusage children;
  if (getrusage (RUSAGE_CHILDREN, &children) == 0) // the largest of the children: the app, not its shell
    peak_bytes = static_cast<std::size_t> (children.ru_maxrss) * 1024;
  return best;
}

Measurement
measure (const Input& in, const std::string& mesh_path, int repeat, unsigned threads)
{
  Measurement m;
  std::string error;
  const auto points = makePoints (in, mesh_path, error);
  if (!error.empty () || points.empty ())
  {
    std::snprintf (m.error, sizeof (m.error), "%s", error.empty () ? "no points" : error.c_str ());
    return m;
  }
  m.points = points.size ();
  // The whole process first, while this process is small: a child forked later would start with
  // (and so report as its peak) everything this process then holds resident.
  m.process_ms = wholeProcessMs (points, threads, repeat, m.process_peak_bytes);
  {
    std::vector<Kernel::Point_3> cgal_points;
    cgal_points.reserve (points.size ());
    for (const auto& p : points)
      cgal_points.emplace_back (p.x (), p.y (), p.z ());
    resetPeakMemory ();
    m.bare_sequential_ms = bareDelaunay<CGAL::Sequential_tag> (cgal_points, repeat, m.cells);
    m.bare_peak_bytes = peakMemory ();
    tbb::global_control limit (tbb::global_control::max_allowed_parallelism, threads ? threads : std::thread::hardware_concurrency ());
    m.bare_parallel_ms = bareDelaunay<CGAL::Parallel_tag> (cgal_points, repeat, m.cells);
  }
  pcl_flowseg::FlowParameters params;
  params.execution.threads = threads;
  double best = 1e300;
  for (int r = 0; r < repeat; ++r)
  {
    pcl_flowseg::FlowResult result;
    const auto st = pcl_flowseg::runFlowSegmentation (points, params, result);
    if (!st)
    {
      std::snprintf (m.error, sizeof (m.error), "%s", st.message.c_str ());
      return m;
    }
    if (result.timings.total_ms < best)
    {
      best = result.timings.total_ms;
      m.stages = result.timings;
      m.features = result.features.size ();
      const auto start = Clock::now ();
      pcl_flowseg::Signature signature;
      if (pcl_flowseg::signatureFromSegmentation (result, pcl_flowseg::kDefaultSignificance, signature))
        m.significant = signature.points.size ();
      m.signature_ms = msSince (start);
    }
  }
  m.ok = 1;
  return m;
}

/** Runs measure() in a child process (fresh heap, its own peak memory, TBB started there). */
Measurement
measureInChild (const Input& in, const std::string& mesh_path, int repeat, unsigned threads)
{
  int fds[2];
  Measurement m;
  if (pipe (fds) != 0)
    return m;
  const pid_t pid = fork ();
  if (pid == 0)
  {
    close (fds[0]);
    const Measurement r = measure (in, mesh_path, repeat, threads);
    const ssize_t written = write (fds[1], &r, sizeof (r));
    _exit (written == static_cast<ssize_t> (sizeof (r)) ? 0 : 1);
  }
  close (fds[1]);
  std::size_t got = 0;
  while (got < sizeof (m))
  {
    const ssize_t n = read (fds[0], reinterpret_cast<char*> (&m) + got, sizeof (m) - got);
    if (n <= 0)
      break;
    got += static_cast<std::size_t> (n);
  }
  close (fds[0]);
  int status = 0;
  waitpid (pid, &status, 0);
  if (got != sizeof (m))
  {
    m = Measurement ();
    std::snprintf (m.error, sizeof (m.error), "the measuring process died (status %d): out of memory?", status);
  }
  return m;
}

std::vector<std::size_t>
parseSizes (const std::string& text)
{
  std::vector<std::size_t> v;
  std::size_t start = 0;
  while (start < text.size ())
  {
    const std::size_t comma = text.find (',', start);
    v.push_back (static_cast<std::size_t> (std::atof (text.substr (start, comma - start).c_str ())));
    if (comma == std::string::npos)
      break;
    start = comma + 1;
  }
  return v;
}

/** Figure 9 of the paper: seconds for Delaunay + segmentation + in/out, by model size. */
double
paperSeconds (std::size_t points)
{
  struct Row { std::size_t points; double seconds; };
  const Row rows[] = {{37000, 15.7 + 19.1 + 14.8}, {48485, 17.9 + 26.8 + 25.1}, {95000, 52.7 + 46.3 + 46.0}, {120000, 70.5 + 56.1 + 54.2}};
  for (const Row& r : rows)
    if (points >= r.points * 98 / 100 && points <= r.points * 102 / 100)
      return r.seconds;
  return 0.0;
}

} // namespace

int
main (int argc, char** argv)
{
  std::string mesh = "../shared/data/meshes/horse.off";
  std::vector<std::size_t> sizes = {37000, 95000, 120000, 500000, 1000000};
  std::vector<unsigned> threads = {1, 0};
  int repeat = 3;
  for (int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    if (a == "--mesh" && i + 1 < argc) mesh = argv[++i];
    else if (a == "--sizes" && i + 1 < argc) sizes = parseSizes (argv[++i]);
    else if (a == "--repeat" && i + 1 < argc) repeat = std::max (1, std::atoi (argv[++i]));
    else if (a == "--threads" && i + 1 < argc)
    {
      threads.clear ();
      for (std::size_t t : parseSizes (argv[++i]))
        threads.push_back (static_cast<unsigned> (t));
    }
    else
    {
      std::fprintf (stderr,
                    "usage: flowseg_bench_pipeline [--mesh OFF] [--sizes 37000,95000,120000,500000,1000000]\n"
                    "                              [--repeat 3] [--threads 1,0]\n"
                    "  mesh: its vertices are the first input ('' to skip); sizes: procedural animal3d samples;\n"
                    "  threads: each value is one row per input (0 = all hardware threads)\n");
      return 2;
    }
  }
  std::vector<Input> inputs;
  if (!mesh.empty ())
  {
    if (!std::ifstream (mesh))
      std::fprintf (stderr, "flowseg_bench_pipeline: %s not found, skipping the mesh input\n", mesh.c_str ());
    else
      inputs.push_back (Input{mesh.substr (mesh.find_last_of ('/') + 1), 0, 0.0});
  }
  for (std::size_t n : sizes)
    inputs.push_back (Input{"animal3d", n, 0.0});

  std::printf ("hardware threads: %u; times in ms, best of %d; bare = CGAL Delaunay_triangulation_3 alone\n\n",
               std::thread::hardware_concurrency (), repeat);
  std::printf ("| input | points | cells | threads | bare seq | bare par | prep | delaunay | flow | manifolds | interior | merge | labels | pipeline | signature | whole process | pipeline / bare seq | after delaunay / bare seq | process / bare seq | process peak MiB (bare seq) | paper s | speed-up |\n");
  std::printf ("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  for (const Input& in : inputs)
    for (unsigned t : threads)
    {
      std::fprintf (stderr, "measuring %s %zu with %u thread(s)...\n", in.name.c_str (), in.count, t);
      const Measurement m = measureInChild (in, mesh, repeat, t);
      if (!m.ok)
      {
        std::printf ("| %s | %zu | | %u | failed: %s |\n", in.name.c_str (), in.count, t, m.error);
        continue;
      }
      const auto& s = m.stages;
      const double paper = paperSeconds (m.points);
      char speedup[32] = "";
      char paper_text[32] = "";
      if (paper > 0)
      {
        std::snprintf (paper_text, sizeof (paper_text), "%.1f", paper);
        std::snprintf (speedup, sizeof (speedup), "%.0fx", paper * 1000.0 / s.total_ms);
      }
      char process[32] = "-", process_ratio[32] = "-";
      if (m.process_ms > 0)
      {
        std::snprintf (process, sizeof (process), "%.0f", m.process_ms);
        std::snprintf (process_ratio, sizeof (process_ratio), "%.2f", m.process_ms / m.bare_sequential_ms);
      }
      std::printf ("| %s | %zu | %zu | %u | %.0f | %.0f | %.0f | %.0f | %.0f | %.0f | %.0f | %.0f | %.0f | %.0f | %.1f | %s | %.2f | %.2f | %s | %.0f (%.0f) | %s | %s |\n",
                   in.name.c_str (), m.points, m.cells, t ? t : std::thread::hardware_concurrency (), m.bare_sequential_ms,
                   m.bare_parallel_ms, s.preparation_ms, s.delaunay_ms, s.flow_ms, s.manifolds_ms, s.interior_ms, s.merge_ms,
                   s.labels_ms, s.total_ms, m.signature_ms, process, s.total_ms / m.bare_sequential_ms,
                   (s.total_ms - s.delaunay_ms) / m.bare_sequential_ms, process_ratio, m.process_peak_bytes / 1048576.0,
                   m.bare_peak_bytes / 1048576.0, paper_text, speedup);
      std::fflush (stdout);
    }
  return 0;
}

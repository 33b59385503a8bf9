/*
 * flowseg_bench_pipeline: where the time and memory of a segmentation go, against the floor of a
 * bare CGAL Delaunay triangulation of the same points.
 *
 * For each input (the paper's HORSE: the vertices of horse.off; procedural shapes of growing size),
 * in --repeat rounds of fresh processes run one after the other, in alternating order:
 *   - the bare floor: a plain CGAL Delaunay_triangulation_3 of the points, sequential, in a process
 *     of its own (this benchmark, run with --bare-child), on the default malloc;
 *   - the whole flowseg_segment process (built beside this benchmark) on the points written as a
 *     binary PCD: read, pipeline and its default outputs. Its JSON gives the pipeline's stages.
 * A third process per round triangulates again on glibc's huge-page malloc, the setting the app
 * relaunches itself with (docs/apps.md): the floor on equal terms.
 * The ratios to the floor are medians over the rounds of each round's own ratio: on a shared
 * virtual machine the speed drifts by 10-30% within a minute, and a ratio of runs made next to
 * each other cancels most of that drift, where one of best-of-N figures made apart does not.
 * Stage times and the pipeline are those of the round whose pipeline was fastest. Also measured:
 * the parallel bare triangulation (best of the rounds) and the signature of one in-process run.
 * Prints one Markdown table, and the speed-up over the paper's Figure 9 (2.8 GHz Pentium IV) where
 * a size matches its models.
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

/** Peak resident set of this process in bytes (Linux VmHWM). */
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

/** Wall time of one bare CGAL triangulation of \a points (no information attached to anything;
  * its destruction not counted); \a cells receives its number of finite cells. */
template <class Concurrency>
double
bareDelaunay (const std::vector<Kernel::Point_3>& points, std::size_t& cells)
{
  using Tds = CGAL::Triangulation_data_structure_3<CGAL::Triangulation_vertex_base_3<Kernel>,
                                                   CGAL::Delaunay_triangulation_cell_base_3<Kernel>, Concurrency>;
  using Delaunay = CGAL::Delaunay_triangulation_3<Kernel, Tds>;
  const auto start = Clock::now ();
  double ms = 0.0;
  if constexpr (std::is_same<Concurrency, CGAL::Parallel_tag>::value)
  {
    CGAL::Bbox_3 box;
    for (const auto& p : points)
      box += p.bbox ();
    typename Delaunay::Lock_data_structure locks (box, 50);
    Delaunay dt (points.begin (), points.end (), &locks);
    cells = dt.number_of_finite_cells ();
    ms = msSince (start);
  }
  else
  {
    Delaunay dt (points.begin (), points.end ());
    cells = dt.number_of_finite_cells ();
    ms = msSince (start);
  }
  return ms;
}

/** The median of \a values (the mean of the middle two for an even count); 0 when empty. */
double
median (std::vector<double> values)
{
  if (values.empty ())
    return 0.0;
  std::sort (values.begin (), values.end ());
  const std::size_t n = values.size ();
  return n % 2 == 1 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

/** What one child process measures. Plain data: it crosses a pipe. */
struct Measurement
{
  int ok = 0;
  std::size_t points = 0, cells = 0, features = 0, significant = 0;
  double bare_sequential_ms = 0, bare_parallel_ms = 0, signature_ms = 0;
  double bare_huge_ms = 0; ///< the bare sequential floor on glibc's huge-page malloc
  double process_ms = 0;   ///< the whole flowseg_segment process (read, pipeline, default outputs)
  /// Medians over the rounds of each round's pipeline, stages after the triangulation and whole
  /// process, each divided by its bare floor (default malloc); and the last two by the huge-page floor.
  double pipeline_ratio = 0, after_triangulation_ratio = 0, process_ratio = 0, pipeline_huge_ratio = 0, process_huge_ratio = 0;
  pcl_flowseg::StageTimings stages; ///< of the round whose pipeline was fastest
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

/** The path of this benchmark's executable, or "" when it cannot be read. */
std::string
selfPath ()
{
  char exe[4096] = {0};
  const ssize_t n = readlink ("/proc/self/exe", exe, sizeof (exe) - 1);
  return n > 0 ? std::string (exe, static_cast<std::size_t> (n)) : "";
}

/** The flowseg_segment app built beside this benchmark, or "" when it is not there. */
std::string
segmentApp ()
{
  std::string path = selfPath ();
  path = path.substr (0, path.find_last_of ('/'));             // .../build/bench
  path = path.substr (0, path.find_last_of ('/')) + "/apps/flowseg_segment";
  return access (path.c_str (), X_OK) == 0 ? path : "";
}

/** The number after "\"key\": " in the "timings_ms" object of \a json (flowseg_segment's), or 0. */
double
timingOf (const std::string& json, const std::string& key)
{
  const std::size_t timings = json.find ("\"timings_ms\": {");
  const std::size_t at = timings == std::string::npos ? timings : json.find ("\"" + key + "\": ", timings);
  return at == std::string::npos ? 0.0 : std::atof (json.c_str () + at + key.size () + 4);
}

/** The processes of one input: the bare floor (this benchmark in --bare-child mode, on a binary
  * file of the points) and flowseg_segment (on a binary PCD); their files go with it. */
class Processes
{
public:
  Processes (const std::vector<Eigen::Vector3d>& points, unsigned threads)
    : base_ ("/tmp/flowseg_bench_pipeline_" + std::to_string (getpid ()))
  {
    const std::string app = segmentApp ();
    // Both read the same coordinates: the PCD's floats.
    pcl::PointCloud<pcl::PointXYZ> cloud;
    std::vector<Eigen::Vector3d> rounded;
    for (const auto& p : points)
    {
      cloud.push_back (pcl::PointXYZ (static_cast<float> (p.x ()), static_cast<float> (p.y ()), static_cast<float> (p.z ())));
      rounded.push_back (cloud.back ().getVector3fMap ().cast<double> ());
    }
    if (!app.empty () && pcl_flowseg::writePointCloud (base_ + ".pcd", cloud, true))
      app_command_ = app + " " + base_ + ".pcd -o " + base_ + " -q -j " + std::to_string (threads) + " 2>/dev/null";
    std::ofstream out (base_ + ".xyz", std::ios::binary);
    out.write (reinterpret_cast<const char*> (rounded.data ()), static_cast<std::streamsize> (rounded.size () * sizeof (Eigen::Vector3d)));
    if (out)
      bare_command_ = selfPath () + " --bare-child " + base_ + ".xyz";
  }

  ~Processes ()
  {
    for (const char* suffix : {".pcd", ".xyz", ".labels.pcd", ".json", ".ply", ".surface.ply", ".svg"})
      std::remove ((base_ + suffix).c_str ());
  }

  /** One bare sequential triangulation in a fresh process: its ms, cells and peak bytes; false
    * when it failed. \a huge_pages: on glibc's huge-page malloc. */
  bool
  bare (bool huge_pages, double& ms, std::size_t& cells, std::size_t& peak) const
  {
    const std::string command = (huge_pages ? "GLIBC_TUNABLES=glibc.malloc.hugetlb=1 " : "GLIBC_TUNABLES= ") + bare_command_;
    FILE* child = popen (command.c_str (), "r");
    if (!child)
      return false;
    const int got = std::fscanf (child, "%lf %zu %zu", &ms, &cells, &peak);
    return pclose (child) == 0 && got == 3;
  }

  /** Whether flowseg_segment was found beside this benchmark and both input files written. */
  bool ready () const { return !app_command_.empty () && !bare_command_.empty (); }

  /** One whole flowseg_segment process: its wall ms and the timings of its JSON; false when it failed. */
  bool
  segment (double& ms, pcl_flowseg::StageTimings& stages) const
  {
    if (app_command_.empty ())
      return false;
    const auto start = Clock::now ();
    if (std::system (app_command_.c_str ()) != 0)
      return false;
    ms = msSince (start);
    std::ifstream in (base_ + ".json");
    const std::string json ((std::istreambuf_iterator<char> (in)), std::istreambuf_iterator<char> ());
    stages.preparation_ms = timingOf (json, "preparation");
    stages.noise_ms = timingOf (json, "noise");
    stages.delaunay_ms = timingOf (json, "delaunay");
    stages.flow_ms = timingOf (json, "flow");
    stages.manifolds_ms = timingOf (json, "manifolds");
    stages.interior_ms = timingOf (json, "interior");
    stages.merge_ms = timingOf (json, "merge");
    stages.labels_ms = timingOf (json, "labels");
    stages.total_ms = timingOf (json, "total");
    return stages.total_ms > 0.0;
  }

  /** The largest resident set of the children so far: the app's (the bare floor's is smaller). */
  static std::size_t
  largestChildPeak ()
  {
    rusage children;
    return getrusage (RUSAGE_CHILDREN, &children) == 0 ? static_cast<std::size_t> (children.ru_maxrss) * 1024 : 0;
  }

private:
  std::string base_, app_command_, bare_command_;
};

/** The ratios of the rounds, and their medians into \a m. */
struct RoundRatios
{
  std::vector<double> pipeline, after_triangulation, process, pipeline_huge, process_huge;

  void
  add (const pcl_flowseg::StageTimings& t, double process_ms, double bare_ms, double huge_ms)
  {
    pipeline.push_back (t.total_ms / bare_ms);
    // The "stages after the triangulation": preparation and noise come before it.
    after_triangulation.push_back ((t.total_ms - t.preparation_ms - t.noise_ms - t.delaunay_ms) / bare_ms);
    process.push_back (process_ms / bare_ms);
    pipeline_huge.push_back (t.total_ms / huge_ms);
    process_huge.push_back (process_ms / huge_ms);
  }

  void
  store (Measurement& m) const
  {
    m.pipeline_ratio = median (pipeline);
    m.after_triangulation_ratio = median (after_triangulation);
    m.process_ratio = median (process);
    m.pipeline_huge_ratio = median (pipeline_huge);
    m.process_huge_ratio = median (process_huge);
  }
};

/** The rounds: the bare floor, flowseg_segment and the floor on huge pages, in that order in even
  * rounds and the reverse in odd ones; the fastest of each kept in \a m. */
bool
measureRounds (const Processes& processes, int repeat, Measurement& m)
{
  if (!processes.ready ())
  {
    std::snprintf (m.error, sizeof (m.error), "flowseg_segment not found beside this benchmark (build the apps), or /tmp not writable");
    return false;
  }
  RoundRatios ratios;
  for (int r = 0; r < repeat; ++r)
  {
    double bare_ms = 0, huge_ms = 0, process_ms = 0;
    std::size_t bare_peak = 0, huge_peak = 0;
    pcl_flowseg::StageTimings stages;
    const bool forward = r % 2 == 0;
    bool ok = processes.bare (!forward, forward ? bare_ms : huge_ms, m.cells, forward ? bare_peak : huge_peak);
    ok = ok && processes.segment (process_ms, stages);
    ok = ok && processes.bare (forward, forward ? huge_ms : bare_ms, m.cells, forward ? huge_peak : bare_peak);
    if (!ok)
    {
      std::snprintf (m.error, sizeof (m.error), "round %d: a bare triangulation or flowseg_segment failed", r);
      return false;
    }
    ratios.add (stages, process_ms, bare_ms, huge_ms);
    std::fprintf (stderr, "  round %d/%d: bare %.0f ms, flowseg_segment %.0f ms (pipeline %.0f), bare on huge pages %.0f ms\n",
                  r + 1, repeat, bare_ms, process_ms, stages.total_ms, huge_ms);
    const bool first = r == 0;
    m.bare_sequential_ms = first ? bare_ms : std::min (m.bare_sequential_ms, bare_ms);
    m.bare_huge_ms = first ? huge_ms : std::min (m.bare_huge_ms, huge_ms);
    m.process_ms = first ? process_ms : std::min (m.process_ms, process_ms);
    m.bare_peak_bytes = std::max (m.bare_peak_bytes, bare_peak);
    if (first || stages.total_ms < m.stages.total_ms)
      m.stages = stages;
  }
  ratios.store (m);
  m.process_peak_bytes = Processes::largestChildPeak ();
  return true;
}

/** The signature of one in-process run, timed. */
bool
measureSignature (const std::vector<Eigen::Vector3d>& points, unsigned threads, Measurement& m)
{
  pcl_flowseg::FlowParameters params;
  params.execution.threads = threads;
  pcl_flowseg::FlowResult result;
  if (const auto st = pcl_flowseg::runFlowSegmentation (points, params, result); !st)
  {
    std::snprintf (m.error, sizeof (m.error), "%s", st.message.c_str ());
    return false;
  }
  m.features = result.features.size ();
  const auto start = Clock::now ();
  pcl_flowseg::Signature signature;
  if (pcl_flowseg::signatureFromSegmentation (result, pcl_flowseg::kDefaultSignificance, signature))
    m.significant = signature.points.size ();
  m.signature_ms = msSince (start);
  return true;
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
  {
    const Processes processes (points, threads);
    if (!measureRounds (processes, repeat, m))
      return m;
  }
  std::vector<Kernel::Point_3> cgal_points;
  cgal_points.reserve (points.size ());
  for (const auto& p : points)
    cgal_points.emplace_back (p.x (), p.y (), p.z ());
  {
    tbb::global_control limit (tbb::global_control::max_allowed_parallelism, threads ? threads : std::thread::hardware_concurrency ());
    for (int r = 0; r < repeat; ++r)
    {
      const double ms = bareDelaunay<CGAL::Parallel_tag> (cgal_points, m.cells);
      m.bare_parallel_ms = r == 0 ? ms : std::min (m.bare_parallel_ms, ms);
    }
  }
  if (measureSignature (points, threads, m))
    m.ok = 1;
  return m;
}

/** --bare-child FILE: one sequential triangulation of the points in FILE (raw x y z doubles);
  * prints its ms, finite cells and this process's peak resident bytes. */
int
bareChild (const std::string& file)
{
  std::ifstream in (file, std::ios::binary);
  std::vector<Kernel::Point_3> points;
  double xyz[3];
  while (in.read (reinterpret_cast<char*> (xyz), sizeof (xyz)))
    points.emplace_back (xyz[0], xyz[1], xyz[2]);
  if (points.size () < 4)
    return 1;
  std::size_t cells = 0;
  const double ms = bareDelaunay<CGAL::Sequential_tag> (points, cells);
  std::printf ("%.3f %zu %zu\n", ms, cells, peakMemory ());
  return 0;
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

/** One row of the table. */
void
printRow (const Input& in, const Measurement& m, unsigned threads)
{
  const auto& s = m.stages;
  const double paper = paperSeconds (m.points);
  char speedup[32] = "", paper_text[32] = "";
  if (paper > 0)
  {
    std::snprintf (paper_text, sizeof (paper_text), "%.1f", paper);
    std::snprintf (speedup, sizeof (speedup), "%.0fx", paper * 1000.0 / s.total_ms);
  }
  std::printf ("| %s | %zu | %zu | %u | %.0f | %.0f | %.0f | %.0f | %.0f | %.0f | %.0f | %.0f | %.0f | %.0f | %.0f | %.0f "
               "| %.2f | %.2f | %.2f | %.2f | %.2f | %.0f (%.0f) | %.1f | %s | %s |\n",
               in.name.c_str (), m.points, m.cells, threads ? threads : std::thread::hardware_concurrency (),
               m.bare_sequential_ms, m.bare_huge_ms, m.bare_parallel_ms, s.preparation_ms + s.noise_ms, s.delaunay_ms,
               s.flow_ms, s.manifolds_ms, s.interior_ms, s.merge_ms, s.labels_ms, s.total_ms, m.process_ms,
               m.pipeline_ratio, m.after_triangulation_ratio, m.process_ratio, m.pipeline_huge_ratio, m.process_huge_ratio,
               m.process_peak_bytes / 1048576.0, m.bare_peak_bytes / 1048576.0, m.signature_ms, paper_text, speedup);
  std::fflush (stdout);
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
    if (a == "--bare-child" && i + 1 < argc) return bareChild (argv[i + 1]);
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
                    "  repeat: rounds per input (each: bare floor, flowseg_segment, bare floor on huge pages);\n"
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

  std::printf ("hardware threads: %u; times in ms; %d rounds, each a bare sequential CGAL Delaunay_triangulation_3 "
               "and a whole flowseg_segment run, fresh processes side by side in time;\n"
               "times: the fastest round; ratios: the median of the rounds' own ratios; "
               "'huge': the bare floor on glibc's huge-page malloc, as the app runs\n\n",
               std::thread::hardware_concurrency (), repeat);
  std::printf ("| input | points | cells | threads | bare seq | bare seq huge | bare par | prep + noise | delaunay | flow | manifolds "
               "| interior | merge | labels | pipeline | whole process | pipeline / bare seq | after triangulation / bare seq "
               "| process / bare seq | pipeline / bare huge | process / bare huge | process peak MiB (bare seq) | signature "
               "| paper s | speed-up |\n");
  std::printf ("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
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
      printRow (in, m, t);
    }
  return 0;
}

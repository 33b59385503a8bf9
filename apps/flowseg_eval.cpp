/*
 * flowseg_eval: retrieval over a labelled folder tree with this module's signatures, Osada's D2
 * shape distribution and PCL's ESF descriptor, side by side.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include "common/flow_options.h"
#include "common/huge_page_malloc.h"
#include "common/options.h"
#include "common/progress.h"

#include <pcl_flowseg/common/parallel_jobs.h>
#include <pcl_flowseg/evaluation/recognition_report.h>
#include <pcl_flowseg/evaluation/single_view_figure.h>
#include <pcl_flowseg/evaluation/retrieval_report.h>
#include <pcl_flowseg/evaluation/retrieval_scores.h>
#include <pcl_flowseg/evaluation/shape_distributions.h>
#include <pcl_flowseg/signature/view_sphere.h>
#include <pcl_flowseg/io/shape_input.h>
#include <pcl_flowseg/segmentation/flow_pipeline.h>
#include <pcl_flowseg/signature/signature.h>
#include <pcl_flowseg/signature/signature_matcher.h>

#include <pcl/console/print.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <sys/stat.h>
#include <tuple>
#include <vector>

namespace {

using flowseg_app::OptionParser;
using Clock = std::chrono::steady_clock;

double
msSince (Clock::time_point t)
{
  return std::chrono::duration<double, std::milli> (Clock::now () - t).count ();
}

constexpr const char* kRetrievalMethods =
    "flowseg,paper,parts,thickness,inner,solid,inner-profile,thickness-profile,contour,inner-context,d2,esf";
constexpr const char* kRecognitionMethods = "flowseg,esf,esf-views";
constexpr std::size_t kRecognitionMeshPoints = 10000; // the single-view protocol's database samples

struct Options
{
  std::string output;
  std::string methods = kRetrievalMethods;
  std::string queries;    ///< single-view recognition: the folder of scans
  std::size_t views = 42; ///< single-view recognition: views rendered per model (esf-views)
  pcl_flowseg::FlowParameters params;
  flowseg_app::SignatureOptions signature;
  pcl_flowseg::MatchParameters match;
  unsigned threads = 0;
  bool quiet = false;
  std::vector<pcl_flowseg::MatchMethod> signature_methods; ///< from methods, in their order
  bool flowseg = false, d2 = false, esf = false;           ///< signatures, d2, esf needed
};

OptionParser
makeParser (Options& o)
{
  OptionParser p ("flowseg_eval", "flowseg_eval ROOT -o OUTDIR [options]\n       flowseg_eval ROOT --queries SCANS -o OUTDIR [options]",
                  "Every shape file below ROOT is a query against all others (class = name of the folder holding\n"
                  "the file). For each method: OUTDIR/similarity_METHOD.csv (higher = more similar; header row and\n"
                  "first column name the shapes in one order), OUTDIR/similarity_METHOD.png (row i: the 5 best\n"
                  "matches of shape i, black = best), OUTDIR/top5_METHOD.png (the first shape of up to eight\n"
                  "classes and its five best matches; green frame: same class, red: another), and\n"
                  "OUTDIR/scores.json (nearest neighbour, first and second tier, DCG, bull's eye for 2D sets, time).\n\n"
                  "Methods: flowseg (this module's default: its components combined), paper (the paper's\n"
                  "weighted points and alignment), the components parts, thickness, inner, solid, inner-profile,\n"
                  "thickness-profile, contour (2D only), inner-context (as flowseg_match compares them), d2 (Osada's\n"
                  "D2 shape distribution on the same points), esf (PCL's Ensemble of Shape Functions).");
  p.text ("-o, --output", "DIR", "output folder (created), required", o.output);
  p.text ("--methods", "LIST", "comma-separated, any of the methods above (single-view recognition: below)", o.methods);
  p.text ("--queries", "DIR", "single-view recognition: the scans below DIR are the queries, the shapes below ROOT the database (below)", o.queries);
  p.count ("--views", "N", "esf-views: views rendered per model, 12 (icosahedron) or 42 (subdivided once), 162, ...", o.views, 12, 100000,
           [] (long long n) {
             std::vector<Eigen::Vector3d> directions;
             return pcl_flowseg::viewSphereDirections (static_cast<std::size_t> (n), directions);
           });
  flowseg_app::addSegmentationOptions (p, o.params);
  flowseg_app::addViewpointOptions (p, o.params.interior.viewpoint, o.signature.input.use_sensor_origin);
  flowseg_app::addSignatureOptions (p, o.signature);
  flowseg_app::addMatchOptions (p, o.match);
  flowseg_app::addThreadsOption (p, o.threads);
  p.flag ("-q, --quiet", "no progress on stderr", o.quiet);
  p.epilogue ("The segmentation options apply to every shape; with --use-sensor-origin each file has its own\n"
              "VIEWPOINT (a collection of single-view scans).\n\n"
              "Single-view recognition (--queries SCANS): each file below SCANS is a view of the model below ROOT\n"
              "at the same relative path without extension (chair/3.pcd shows chair/3.off); meshes below ROOT are\n"
              "sampled with 10000 points unless --mesh-points says otherwise. The models are segmented without a\n"
              "viewpoint; --use-sensor-origin gives each scan its own. Category (the query's own model left out of\n"
              "its ranking): NN, the best match has the query's class; FT, the share of the class's other models in\n"
              "the first |class|-1. Instance (own model kept): the best match is the own model.\n"
              "Methods (default " + std::string (kRecognitionMethods) + "): any signature method (the scan's\n"
              "signature against the models'), esf (the scan's ESF against the ESF of each model's sample),\n"
              "esf-views (against the ESF of views of each mesh rendered by the single-view protocol's camera from\n"
              "--views directions; the nearest view counts; skipped when a model is a point sample). With\n"
              "--use-sensor-origin the module's methods query a signature database as flowseg_db query does: the\n"
              "scan is aligned with the models' rendered views.\n"
              "ms/query: CPU time of describing a query and comparing it with every model (each query on one\n"
              "thread); ms/model: of describing a model. Writes OUTDIR/single_view.tsv (per method and class, and\n"
              "class all), OUTDIR/top5_single_view_METHOD.png (the first scan of up to eight classes, coloured by\n"
              "its features, and its five best models by the first module method) and prints the table.\n\n"
              "Exit status: 0 success, 1 unreadable input or output, 2 bad options.");
  return p;
}

/** Splits --methods into signature methods, d2 and esf; refuses unknown, repeated or no names. */
pcl_flowseg::Status
parseMethods (Options& o)
{
  std::vector<std::string> seen;
  std::size_t start = 0;
  while (start <= o.methods.size ())
  {
    const std::size_t end = std::min (o.methods.find (',', start), o.methods.size ());
    const std::string name = o.methods.substr (start, end - start);
    start = end + 1;
    if (std::find (seen.begin (), seen.end (), name) != seen.end ())
      return pcl_flowseg::Status::error ("--methods names " + name + " twice");
    seen.push_back (name);
    pcl_flowseg::MatchMethod method;
    if (name == "d2" || name == "esf")
      (name == "d2" ? o.d2 : o.esf) = true;
    else if (pcl_flowseg::parseMatchMethod (name, method))
      o.signature_methods.push_back (method);
    else
    {
      std::string names;
      for (pcl_flowseg::MatchMethod m : pcl_flowseg::kMatchMethods)
        names += std::string (pcl_flowseg::matchMethodName (m)) + ", ";
      return pcl_flowseg::Status::error ("--methods: '" + name + "' is none of " + names + "d2, esf");
    }
  }
  o.flowseg = !o.signature_methods.empty ();
  return pcl_flowseg::Status::success ();
}

/** What each method knows of each shape. */
struct Collection
{
  std::vector<std::string> files, labels, errors;
  std::vector<pcl_flowseg::Signature> signatures;
  std::vector<std::vector<double>> d2, esf;
  std::vector<std::vector<Eigen::Vector3d>> drawings; ///< a few thousand points per shape, for pictures
  std::vector<int> dimensions;
  std::array<double, 3> describe_ms{{0.0, 0.0, 0.0}}; ///< flowseg, d2, esf, summed over shapes
};

/** Reads shape \a i and computes what the chosen methods need. */
void
describeShape (const std::string& root, const Options& o, std::size_t i, Collection& c, std::mutex& timing)
{
  c.labels[i] = pcl_flowseg::shapeLabel (c.files[i]);
  std::vector<Eigen::Vector3d> pts;
  std::optional<Eigen::Vector3d> origin;
  pcl_flowseg::Status s = pcl_flowseg::loadShapeSample (root + "/" + c.files[i], o.signature.input, pts, &origin);
  for (std::size_t k = 0; k < pts.size (); k += std::max<std::size_t> (1, pts.size () / 3000))
    c.drawings[i].push_back (pts[k]);
  std::array<double, 3> ms{{0.0, 0.0, 0.0}};
  if (s && o.flowseg)
  {
    const auto t0 = Clock::now ();
    pcl_flowseg::FlowResult r;
    pcl_flowseg::FlowParameters params = o.params;
    if (o.signature.input.use_sensor_origin)
      params.interior.viewpoint = origin; // this file's own
    s = pcl_flowseg::runFlowSegmentation (pts, params, r);
    if (s)
      s = pcl_flowseg::signatureFromSegmentation (r, o.signature.significance, c.signatures[i]);
    c.dimensions[i] = r.dimension;
    ms[0] = msSince (t0);
  }
  if (s && o.d2)
  {
    const auto t0 = Clock::now ();
    c.d2[i] = pcl_flowseg::d2Distribution (pts);
    ms[1] = msSince (t0);
  }
  if (s && o.esf)
  {
    const auto t0 = Clock::now ();
    s = pcl_flowseg::esfDescriptor (pts, c.esf[i]);
    ms[2] = msSince (t0);
  }
  if (!s)
    c.errors[i] = s.message;
  std::lock_guard<std::mutex> lock (timing);
  for (int k = 0; k < 3; ++k)
    c.describe_ms[static_cast<std::size_t> (k)] += ms[static_cast<std::size_t> (k)];
}

void
describeShapes (const std::string& root, const Options& o, Collection& c)
{
  const std::size_t n = c.files.size ();
  c.labels.assign (n, std::string ());
  c.errors.assign (n, std::string ());
  c.signatures.assign (n, pcl_flowseg::Signature ());
  c.d2.assign (n, {});
  c.esf.assign (n, {});
  c.drawings.assign (n, {});
  c.dimensions.assign (n, 0);
  std::mutex timing;
  Options per_job = o;
  per_job.params.execution.threads = pcl_flowseg::threadsPerJob (n, o.threads);
  flowseg_app::ProgressLine progress ("describing shapes", n, o.quiet);
  pcl_flowseg::runParallelJobs (
      n, o.threads, [&] (std::size_t i) { describeShape (root, per_job, i, c, timing); },
      [&] (std::size_t done, std::size_t) { progress.update (done); });
}

/** Compares every pair by \a similarity, scores the ranking and writes the method's figures. Every
  * method compares a to b exactly as b to a (the paper's aligns both ways and keeps the better;
  * the others are tested to), so each unordered pair is compared once. */
pcl_flowseg::Status
evaluateMethod (const std::string& name, double describe_ms, const std::function<double (std::size_t, std::size_t)>& similarity,
                const Options& o, const Collection& c, pcl_flowseg::MethodEvaluation& e)
{
  const std::size_t n = c.files.size ();
  const auto t0 = Clock::now ();
  std::vector<std::vector<double>> m;
  {
    flowseg_app::ProgressLine progress ("comparing (" + name + ")", n, o.quiet);
    m = pcl_flowseg::symmetricSimilarityMatrix (n, similarity, o.threads, [&] (std::size_t done) { progress.update (done); });
  }
  e.name = name;
  const double comparisons = 0.5 * static_cast<double> (n * (n + 1));
  e.compare_ms_per_pair = msSince (t0) * pcl_flowseg::jobThreads (o.threads) / comparisons; // CPU time
  e.describe_ms_per_shape = describe_ms / static_cast<double> (n);
  if (const pcl_flowseg::Status s = pcl_flowseg::scoreRetrieval (m, c.labels, e.scores); !s)
    return s;
  return pcl_flowseg::writeRetrievalFigures (o.output, name, c.files, c.labels, m, c.drawings);
}

void
printScores (const pcl_flowseg::MethodEvaluation& e, bool planar)
{
  const auto& s = e.scores;
  std::printf ("%-8s NN %.3f  FT %.3f  ST %.3f  DCG %.3f%s  (%zu queries, %.3f ms per comparison)\n", e.name.c_str (),
               s.nearest_neighbour, s.first_tier, s.second_tier, s.dcg,
               planar ? ("  bull's eye " + std::to_string (s.bulls_eye)).c_str () : "", s.queries, e.compare_ms_per_pair);
}

/** Evaluates every chosen method and writes scores.json. */
int
evaluate (const OptionParser& p, const std::string& root, const Options& o, const Collection& c)
{
  const bool planar = o.flowseg && std::all_of (c.dimensions.begin (), c.dimensions.end (), [] (int d) { return d == 2; });
  std::vector<pcl::SignatureMatcher> matchers (o.signature_methods.size ());
  std::vector<std::tuple<std::string, std::size_t, std::function<double (std::size_t, std::size_t)>>> methods;
  const bool any_planar = std::find (c.dimensions.begin (), c.dimensions.end (), 2) != c.dimensions.end ();
  for (std::size_t m = 0; m < o.signature_methods.size (); ++m)
  {
    if (o.signature_methods[m] == pcl_flowseg::MatchMethod::Contour && !any_planar)
    {
      std::printf ("contour  skipped: it compares the outlines of 2D shapes, and this collection has none\n");
      continue;
    }
    matchers[m].setParameters (o.match);
    matchers[m].setMethod (o.signature_methods[m]);
    methods.emplace_back (pcl_flowseg::matchMethodName (o.signature_methods[m]), 0, [&, m] (std::size_t i, std::size_t j) {
      return matchers[m].match (c.signatures[i], c.signatures[j]).similarity;
    });
  }
  if (o.d2)
    methods.emplace_back ("d2", 1, [&] (std::size_t i, std::size_t j) { return pcl_flowseg::histogramSimilarity (c.d2[i], c.d2[j]); });
  if (o.esf)
    methods.emplace_back ("esf", 2, [&] (std::size_t i, std::size_t j) { return pcl_flowseg::histogramSimilarity (c.esf[i], c.esf[j]); });
  std::vector<pcl_flowseg::MethodEvaluation> results;
  for (const auto& [name, described_by, similarity] : methods)
  {
    pcl_flowseg::MethodEvaluation e;
    if (const pcl_flowseg::Status s = evaluateMethod (name, c.describe_ms[described_by], similarity, o, c, e); !s)
      return p.failure (s.message);
    printScores (e, planar);
    results.push_back (e);
  }
  if (const pcl_flowseg::Status s = pcl_flowseg::writeRetrievalScoresJson (o.output + "/scores.json", root, c.files.size (), planar, results); !s)
    return p.failure (s.message);
  return flowseg_app::kExitSuccess;
}

/** Creates the folder \a dir (its parent must exist); false when it is not a folder then. */
bool
makeFolder (const std::string& dir)
{
  mkdir (dir.c_str (), 0755);
  struct stat dir_stat;
  return stat (dir.c_str (), &dir_stat) == 0 && S_ISDIR (dir_stat.st_mode);
}

/** Whether \a name (--option) is among the arguments, alone or with =VALUE. */
bool
given (int argc, char** argv, const char* name)
{
  const std::size_t n = std::strlen (name);
  for (int i = 1; i < argc; ++i)
    if (std::strncmp (argv[i], name, n) == 0 && (argv[i][n] == '\0' || argv[i][n] == '='))
      return true;
  return false;
}

/** Single-view recognition: the scans below --queries against the shapes below \a root. */
int
recogniseSingleViews (const OptionParser& p, const std::string& root, Options o, bool mesh_points_given, bool methods_given)
{
  std::vector<pcl_flowseg::RecognitionMethod> methods;
  if (const pcl_flowseg::Status s = pcl_flowseg::parseRecognitionMethods (methods_given ? o.methods : kRecognitionMethods, methods); !s)
    return p.usageError ("--methods: " + s.message);
  pcl_flowseg::SingleViewRecognitionParameters params;
  params.flow = o.params;
  params.signature = o.signature;
  if (!mesh_points_given)
    params.signature.input.mesh_points = kRecognitionMeshPoints;
  params.match = o.match;
  params.views = o.views;
  params.threads = o.threads;
  pcl_flowseg::ShapeCollection models{root, {}}, queries{o.queries, {}};
  for (auto* c : {&models, &queries})
    if (const pcl_flowseg::Status s = pcl_flowseg::listShapeFiles (c->root, c->files); !s || c->files.empty ())
      return p.failure (s ? "no shape files below " + c->root : s.message);
  if (!makeFolder (o.output))
    return p.failure ("cannot create the folder " + o.output);
  std::unique_ptr<flowseg_app::ProgressLine> line;
  std::string stage;
  std::vector<pcl_flowseg::MethodRecognition> results;
  const pcl_flowseg::Status s = pcl_flowseg::evaluateSingleViewRecognition (
      models, queries, methods, params, results, [&] (const std::string& now, std::size_t done, std::size_t total) {
        if (now != stage)
        {
          line.reset (); // ends the previous stage's line first
          line = std::make_unique<flowseg_app::ProgressLine> (now, total, o.quiet);
          stage = now;
        }
        line->update (done);
      });
  line.reset ();
  if (!s)
    return p.failure (s.message);
  if (const pcl_flowseg::Status w = pcl_flowseg::writeRecognitionTsv (o.output + "/single_view.tsv", results); !w)
    return p.failure (w.message);
  for (std::size_t m = 0; m < methods.size (); ++m)
    if (methods[m].kind == pcl_flowseg::RecognitionMethodKind::kSignature && results[m].skipped.empty ())
    {
      const std::string figure = o.output + "/top5_single_view_" + results[m].name + ".png";
      if (const pcl_flowseg::Status w = pcl_flowseg::writeSingleViewFigure (figure, models, queries, params, results[m]); !w)
        return p.failure (w.message);
      break; // the first of the module's methods
    }
  std::printf ("single-view recognition: %zu queries below %s against %zu models below %s (meshes sampled with %zu points)\n%s",
               queries.files.size (), o.queries.c_str (), models.files.size (), root.c_str (), params.signature.input.mesh_points,
               pcl_flowseg::recognitionTable (results).c_str ());
  return flowseg_app::kExitSuccess;
}

} // namespace

int
main (int argc, char** argv)
{
  flowseg_app::relaunchWithHugePageMalloc (argv);
  Options o;
  const OptionParser parser = makeParser (o);
  std::vector<std::string> roots;
  if (const int status = parser.parse (argc, argv, roots); status != flowseg_app::kContinue)
    return status;
  if (roots.size () != 1 || o.output.empty ())
    return parser.usageError (roots.size () > 1 ? "more than one ROOT" : "need ROOT and --output DIR");
  if (o.queries.empty () && given (argc, argv, "--views"))
    return parser.usageError ("--views is for single-view recognition (--queries)");
  if (const pcl_flowseg::Status s = o.queries.empty () ? parseMethods (o) : pcl_flowseg::Status::success (); !s)
    return parser.usageError (s.message);
  if (const int status = flowseg_app::checkViewpointOptions (parser, o.params, o.signature.input.use_sensor_origin);
      status != flowseg_app::kContinue)
    return status;
  pcl::console::setVerbosityLevel (pcl::console::L_ERROR);
  if (!o.queries.empty ())
    return recogniseSingleViews (parser, roots[0], o, given (argc, argv, "--mesh-points"), given (argc, argv, "--methods"));

  Collection c;
  if (const pcl_flowseg::Status s = pcl_flowseg::listShapeFiles (roots[0], c.files); !s || c.files.empty ())
    return parser.failure (s ? "no shape files below " + roots[0] : s.message);
  if (!makeFolder (o.output))
    return parser.failure ("cannot create the folder " + o.output);
  describeShapes (roots[0], o, c);
  for (std::size_t i = 0; i < c.files.size (); ++i)
    if (!c.errors[i].empty ())
      return parser.failure (c.files[i] + ": " + c.errors[i]);
  return evaluate (parser, roots[0], o, c);
}

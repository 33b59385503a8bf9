/*
 * flowseg_eval: retrieval over a labelled folder tree with this module's signatures, Osada's D2
 * shape distribution and PCL's ESF descriptor, side by side.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include "app_common.h"

#include <pcl_flowseg/segmentation/flow_pipeline.h>
#include <pcl_flowseg/evaluation/retrieval.h>
#include <pcl_flowseg/io/shape_input.h>
#include <pcl_flowseg/signature/signature.h>
#include <pcl_flowseg/signature/signature_matcher.h>

#include <pcl/console/print.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <iostream>
#include <mutex>
#include <string>
#include <sys/stat.h>
#include <unistd.h>
#include <thread>
#include <vector>

namespace {

void
printHelp ()
{
  std::cout << R"(Usage: flowseg_eval ROOT -o OUTDIR [options]

Every shape file below ROOT is a query against all others (class = name of the folder holding
the file). For each method: OUTDIR/similarity_METHOD.csv (higher = more similar; header row and
first column name the shapes in one order), OUTDIR/similarity_METHOD.png (row i: the 5 best
matches of shape i, black = best) and OUTDIR/scores.json (nearest neighbour, first and second tier,
DCG, bull's eye for 2D sets, time), and OUTDIR/top5_METHOD.png: the first shape of up to eight
classes and its five best matches (green frame: same class, red: another).

Methods: flowseg (this module's signatures and matcher), d2 (Osada's D2 shape distribution on the
same points), esf (PCL's Ensemble of Shape Functions).

Options:
  -o, --output DIR     output folder (created), required
      --methods LIST   comma-separated, default flowseg,d2,esf
      --rho R          merge threshold (default )" << pcl_flowseg::MergeParameters ().rho << R"()
      --significance F feature significance (default )" << pcl_flowseg::kDefaultSignificance << R"()
      --threshold T    matcher threshold (default 0.4)
      --alignment-points N  heaviest points generating alignments (default 4)
      --mesh-points N  points sampled on meshes (default 5000)
  -j, --jobs N         threads (default: all cores)
  -q, --quiet          no progress
  -h, --help           this help
)";
}

int
usageError (const std::string& message)
{
  return flowseg_app::usageError ("flowseg_eval", message);
}

/** Runs job (i) for i in [0, n) on \a jobs threads, with a progress line. */
void
parallelFor (std::size_t n, unsigned jobs, bool quiet, const char* what, const std::function<void (std::size_t)>& job)
{
  std::atomic<std::size_t> next (0), done (0);
  std::mutex print;
  auto worker = [&] () {
    for (std::size_t i; (i = next++) < n;)
    {
      job (i);
      const std::size_t d = ++done;
      if (!quiet && (d % 10 == 0 || d == n) && isatty (2))
      {
        std::lock_guard<std::mutex> lock (print);
        std::fprintf (stderr, "\r%s %zu/%zu", what, d, n);
        std::fflush (stderr);
      }
    }
  };
  std::vector<std::thread> threads;
  for (unsigned t = 0; t < std::max (1u, jobs); ++t)
    threads.emplace_back (worker);
  for (auto& t : threads)
    t.join ();
  if (!quiet)
    std::fprintf (stderr, "\n");
}

} // namespace

int
main (int argc, char** argv)
{
  std::string root, out;
  std::string methods = "flowseg,d2,esf";
  double rho = pcl_flowseg::MergeParameters ().rho, significance = pcl_flowseg::kDefaultSignificance, threshold = pcl::SignatureMatcher ().getThreshold ();
  pcl_flowseg::ShapeInputOptions input;
  unsigned jobs = std::max (1u, std::thread::hardware_concurrency ());
  bool quiet = false;
  int alignment_points = pcl::SignatureMatcher ().getAlignmentPoints ();
  for (int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    const bool more = i + 1 < argc;
    double v;
    if (a == "-h" || a == "--help")
    {
      printHelp ();
      return 0;
    }
    else if ((a == "-o" || a == "--output") && more)
      out = argv[++i];
    else if (a == "--methods" && more)
      methods = argv[++i];
    else if (a == "--rho" && more && flowseg_app::parseNumber (argv[i + 1], v) && v > 0)
      rho = v, ++i;
    else if (a == "--significance" && more && flowseg_app::parseNumber (argv[i + 1], v) && v >= 0 && v < 1)
      significance = v, ++i;
    else if (a == "--threshold" && more && flowseg_app::parseNumber (argv[i + 1], v) && v > 0)
      threshold = v, ++i;
    else if (a == "--alignment-points" && more && flowseg_app::parseNumber (argv[i + 1], v) && v >= 1 && v <= 100 && v == std::floor (v))
      alignment_points = static_cast<int> (v), ++i;
    else if (a == "--mesh-points" && more && flowseg_app::parseNumber (argv[i + 1], v) && v >= 4 && v <= 1e8 && v == std::floor (v))
      input.mesh_points = static_cast<std::size_t> (v), ++i;
    else if ((a == "-j" || a == "--jobs") && more && flowseg_app::parseNumber (argv[i + 1], v) && v >= 1 && v <= 256 && v == std::floor (v))
      jobs = static_cast<unsigned> (v), ++i;
    else if (a == "-q" || a == "--quiet")
      quiet = true;
    else if (!a.empty () && a[0] == '-')
      return usageError ("bad, incomplete or unknown option '" + a + "'");
    else if (root.empty ())
      root = a;
    else
      return usageError ("more than one ROOT");
  }
  if (root.empty () || out.empty ())
    return usageError ("need ROOT and --output DIR");
  const bool use_flowseg = methods.find ("flowseg") != std::string::npos;
  const bool use_d2 = methods.find ("d2") != std::string::npos;
  const bool use_esf = methods.find ("esf") != std::string::npos;
  if (!use_flowseg && !use_d2 && !use_esf)
    return usageError ("--methods names none of flowseg, d2, esf");
  pcl::console::setVerbosityLevel (pcl::console::L_ERROR);

  std::vector<std::string> files;
  auto st = pcl_flowseg::listShapeFiles (root, files);
  if (!st || files.empty ())
  {
    std::cerr << "flowseg_eval: " << (st ? "no shape files below " + root : st.message) << "\n";
    return 1;
  }
  mkdir (out.c_str (), 0755);
  struct stat dir_stat;
  if (stat (out.c_str (), &dir_stat) != 0 || !S_ISDIR (dir_stat.st_mode))
  {
    std::cerr << "flowseg_eval: cannot create the folder " << out << "\n";
    return 1;
  }

  const std::size_t n = files.size ();
  std::vector<std::string> labels (n);
  std::vector<pcl_flowseg::Signature> sigs (n);
  std::vector<std::vector<double>> d2 (n), esf (n);
  std::vector<std::vector<Eigen::Vector3d>> drawings (n); // a few thousand points per shape for pictures
  std::vector<std::string> errors (n);
  std::vector<int> dims (n, 0);
  double extract_ms[3] = {0, 0, 0};
  std::mutex timing;
  auto clock = [] { return std::chrono::steady_clock::now (); };
  auto ms = [] (std::chrono::steady_clock::time_point t) {
    return std::chrono::duration<double, std::milli> (std::chrono::steady_clock::now () - t).count ();
  };
  parallelFor (n, jobs, quiet, "describing shapes", [&] (std::size_t i) {
    labels[i] = pcl_flowseg::shapeLabel (files[i]);
    std::vector<Eigen::Vector3d> pts;
    auto s = pcl_flowseg::loadShapeSample (root + "/" + files[i], input, pts);
    for (std::size_t k = 0; k < pts.size (); k += std::max<std::size_t> (1, pts.size () / 3000))
      drawings[i].push_back (pts[k]);
    double t[3] = {0, 0, 0};
    if (s.ok && use_flowseg)
    {
      const auto t0 = clock ();
      pcl_flowseg::FlowParameters params;
      params.merge.rho = rho;
      pcl_flowseg::FlowResult r;
      s = pcl_flowseg::runFlowSegmentation (pts, params, r);
      if (s.ok)
        s = pcl_flowseg::signatureFromSegmentation (r, significance, sigs[i]);
      dims[i] = r.dimension;
      t[0] = ms (t0);
    }
    if (s.ok && use_d2)
    {
      const auto t0 = clock ();
      d2[i] = pcl_flowseg::d2Distribution (pts);
      t[1] = ms (t0);
    }
    if (s.ok && use_esf)
    {
      const auto t0 = clock ();
      esf[i] = pcl_flowseg::esfDescriptor (pts);
      t[2] = ms (t0);
    }
    if (!s.ok)
      errors[i] = s.message;
    std::lock_guard<std::mutex> lock (timing);
    for (int k = 0; k < 3; ++k)
      extract_ms[k] += t[k];
  });
  for (std::size_t i = 0; i < n; ++i)
    if (!errors[i].empty ())
    {
      std::cerr << "flowseg_eval: " << files[i] << ": " << errors[i] << "\n";
      return 1;
    }
  const bool planar = use_flowseg && std::all_of (dims.begin (), dims.end (), [] (int d) { return d == 2; });

  std::string json = "{\n  \"root\": \"" + root + "\",\n  \"shapes\": " + std::to_string (n) + ",\n  \"methods\": {";
  bool first_method = true;
  auto run = [&] (const std::string& name, double describe_ms, const std::function<double (std::size_t, std::size_t)>& sim) {
    std::vector<std::vector<double>> m (n, std::vector<double> (n, 0.0));
    const auto t0 = clock ();
    parallelFor (n, jobs, quiet, ("comparing (" + name + ")").c_str (), [&] (std::size_t i) {
      for (std::size_t j = 0; j < n; ++j)
        m[i][j] = sim (i, j);
    });
    const double compare_ms = ms (t0) * std::max (1u, jobs); // CPU time, summed over threads
    const auto scores = pcl_flowseg::scoreRetrieval (m, labels);
    auto s1 = pcl_flowseg::writeSimilarityCsv (out + "/similarity_" + name + ".csv", files, m);
    auto s2 = pcl_flowseg::writeSimilarityPng (out + "/similarity_" + name + ".png", m);
    // Figure 10: the first shape of up to eight classes and its five best matches.
    std::vector<std::size_t> queries;
    for (std::size_t i = 0; i < n && queries.size () < 8; ++i)
      if (i == 0 || labels[i] != labels[i - 1])
        queries.push_back (i);
    auto s3 = pcl_flowseg::writeTopMatchesPng (out + "/top5_" + name + ".png", drawings, labels, m, queries);
    for (const auto* st : {&s1, &s2, &s3})
      if (!*st)
      {
        std::cerr << "flowseg_eval: " << st->message << "\n";
        std::exit (1);
      }
    char buf[640];
    std::snprintf (buf, sizeof (buf),
                   "%s\n    \"%s\": {\"nearest_neighbour\": %.4f, \"first_tier\": %.4f, \"second_tier\": %.4f, \"dcg\": %.4f%s, "
                   "\"queries\": %zu, \"describe_ms_per_shape\": %.3f, \"compare_ms_per_pair\": %.4f}",
                   first_method ? "" : ",", name.c_str (), scores.nearest_neighbour, scores.first_tier, scores.second_tier, scores.dcg,
                   planar ? (", \"bulls_eye\": " + std::to_string (scores.bulls_eye)).c_str () : "", scores.queries,
                   describe_ms / static_cast<double> (n), compare_ms / static_cast<double> (n * n));
    json += buf;
    first_method = false;
    std::printf ("%-8s NN %.3f  FT %.3f  ST %.3f  DCG %.3f%s  (%zu queries, %.3f ms per comparison)\n", name.c_str (),
                 scores.nearest_neighbour, scores.first_tier, scores.second_tier, scores.dcg,
                 planar ? ("  bull's eye " + std::to_string (scores.bulls_eye)).c_str () : "", scores.queries,
                 compare_ms / static_cast<double> (n * n));
  };
  if (use_flowseg)
  {
    pcl::SignatureMatcher matcher;
    matcher.setThreshold (threshold);
    matcher.setAlignmentPoints (alignment_points);
    run ("flowseg", extract_ms[0], [&] (std::size_t i, std::size_t j) { return matcher.match (sigs[i], sigs[j]).similarity; });
  }
  if (use_d2)
    run ("d2", extract_ms[1], [&] (std::size_t i, std::size_t j) { return pcl_flowseg::histogramSimilarity (d2[i], d2[j]); });
  if (use_esf)
    run ("esf", extract_ms[2], [&] (std::size_t i, std::size_t j) { return pcl_flowseg::histogramSimilarity (esf[i], esf[j]); });
  json += "\n  }\n}\n";
  std::ofstream (out + "/scores.json.tmp") << json;
  if (std::rename ((out + "/scores.json.tmp").c_str (), (out + "/scores.json").c_str ()) != 0)
  {
    std::cerr << "flowseg_eval: cannot write " << out << "/scores.json\n";
    return 1;
  }
  return 0;
}

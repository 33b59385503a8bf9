/*
 * flowseg_db: build, extend and query a database of shape signatures.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include "app_common.h"

#include <pcl_flowseg/segmentation/flow_pipeline.h>
#include <pcl_flowseg/io/shape_input.h>
#include <pcl_flowseg/signature/shape_signature.h>
#include <pcl_flowseg/signature/signature_database.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

namespace {

void
printHelp ()
{
  std::cout << R"(Usage:
  flowseg_db build DB ROOT [options]    signatures of every shape file below ROOT (class = folder)
  flowseg_db add DB FILE... [options]   add or replace shapes (the others are kept as they are)
  flowseg_db query DB FILE [options]    the most similar stored shapes
  flowseg_db list DB                    the stored shapes

Shape files: .pcd .ply .xyz .txt .csv (points) and .off .obj .ply meshes (sampled on their faces).

Options:
  -k N                 query: how many results (default 10; 0 = all)
      --candidates N   query: align the N stored shapes whose signature summaries are nearest
                       (default )" << pcl_flowseg::kDefaultCandidates << R"(; 0 = align every stored shape); the rest are
                       listed after them by summary distance, similarity "-"
      --label L        add: class of the added shapes (default: their folder name)
      --rho R          merge threshold (default )" << pcl_flowseg::MergeParameters ().rho << R"()
      --significance F features above this share of the interior volume (default )" << pcl_flowseg::kDefaultSignificance << R"()
      --threshold T    matcher distance threshold, normalised units (default 0.4)
      --mesh-points N  points sampled on a mesh (default 5000)
  -j, --jobs N         parallel signature extraction (default: all cores)
  -q, --quiet          no progress
  -h, --help           this help
Exit status: 0 success, 1 unreadable input or database, 2 bad options.
)";
}

int
usageError (const std::string& message)
{
  return flowseg_app::usageError ("flowseg_db", message);
}

struct Options
{
  std::size_t k = 10;
  std::size_t candidates = pcl_flowseg::kDefaultCandidates;
  std::string label;
  bool has_label = false;
  double rho = pcl_flowseg::MergeParameters ().rho;
  double significance = pcl_flowseg::kDefaultSignificance;
  double threshold = pcl::SignatureMatcher ().getThreshold ();
  pcl_flowseg::ShapeInputOptions input;
  unsigned jobs = std::max (1u, std::thread::hardware_concurrency ());
  bool quiet = false;
};

/** Signature of one file; false with a message on failure. */
bool
signatureOfFile (const std::string& path, const Options& o, pcl_flowseg::Signature& s, std::string& error)
{
  pcl_flowseg::FlowParameters params;
  params.merge.rho = o.rho;
  const auto st = pcl_flowseg::signatureOfShapeFile (path, o.input, params, o.significance, s);
  error = st.message;
  return st.ok;
}

/** Computes the signatures of \a files (root + "/" + file) on o.jobs threads. */
bool
extract (const std::string& root, const std::vector<std::string>& files, const Options& o, pcl_flowseg::SignatureDatabase& db,
         const std::string& forced_label)
{
  std::vector<pcl_flowseg::ShapeEntry> entries (files.size ());
  std::vector<std::string> errors (files.size ());
  std::atomic<std::size_t> next (0), done (0);
  std::mutex print;
  auto worker = [&] () {
    for (std::size_t i; (i = next++) < files.size ();)
    {
      const std::string path = root.empty () ? files[i] : root + "/" + files[i];
      entries[i].name = files[i];
      entries[i].label = forced_label.empty () ? pcl_flowseg::shapeLabel (files[i]) : forced_label;
      if (entries[i].label.empty ())
        entries[i].label = "-";
      signatureOfFile (path, o, entries[i].signature, errors[i]);
      const std::size_t d = ++done;
      if (!o.quiet)
      {
        std::lock_guard<std::mutex> lock (print);
        std::fprintf (stderr, "\r[%zu/%zu] %s%s", d, files.size (), files[i].c_str (), errors[i].empty () ? "" : " (failed)");
        std::fflush (stderr);
      }
    }
  };
  std::vector<std::thread> threads;
  for (unsigned t = 0; t < std::max (1u, o.jobs); ++t)
    threads.emplace_back (worker);
  for (auto& t : threads)
    t.join ();
  if (!o.quiet)
    std::fprintf (stderr, "\n");
  std::size_t failed = 0;
  for (std::size_t i = 0; i < files.size (); ++i)
  {
    if (!errors[i].empty ())
    {
      std::cerr << "flowseg_db: skipped " << errors[i] << "\n";
      ++failed;
      continue;
    }
    db.add (entries[i]);
  }
  if (!o.quiet)
    std::fprintf (stderr, "%zu signatures computed, %zu files skipped\n", files.size () - failed, failed);
  return failed < files.size () || files.empty ();
}

} // namespace

int
main (int argc, char** argv)
{
  std::vector<std::string> args;
  Options o;
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
    else if (a == "-k" && more && flowseg_app::parseNumber (argv[i + 1], v) && v >= 0 && v == std::floor (v))
      o.k = static_cast<std::size_t> (v), ++i;
    else if (a == "--candidates" && more && flowseg_app::parseNumber (argv[i + 1], v) && v >= 0 && v == std::floor (v))
      o.candidates = static_cast<std::size_t> (v), ++i;
    else if (a == "--label" && more)
      o.label = argv[++i], o.has_label = true;
    else if (a == "--rho" && more && flowseg_app::parseNumber (argv[i + 1], v) && v > 0)
      o.rho = v, ++i;
    else if (a == "--significance" && more && flowseg_app::parseNumber (argv[i + 1], v) && v >= 0 && v < 1)
      o.significance = v, ++i;
    else if (a == "--threshold" && more && flowseg_app::parseNumber (argv[i + 1], v) && v > 0)
      o.threshold = v, ++i;
    else if (a == "--mesh-points" && more && flowseg_app::parseNumber (argv[i + 1], v) && v >= 4 && v <= 1e8 && v == std::floor (v))
      o.input.mesh_points = static_cast<std::size_t> (v), ++i;
    else if ((a == "-j" || a == "--jobs") && more && flowseg_app::parseNumber (argv[i + 1], v) && v >= 1 && v <= 256 && v == std::floor (v))
      o.jobs = static_cast<unsigned> (v), ++i;
    else if (a == "-q" || a == "--quiet")
      o.quiet = true;
    else if (!a.empty () && a[0] == '-')
      return usageError ("bad, incomplete or unknown option '" + a + "'");
    else
      args.push_back (a);
  }
  if (args.size () < 2)
    return usageError ("need a command and a database");
  const std::string command = args[0], db_path = args[1];
  if (o.has_label && (o.label.empty () || o.label.find_first_of (" \t\n") != std::string::npos))
    return usageError ("--label needs a class name without white space");

  pcl_flowseg::SignatureDatabase db;
  if (command == "build")
  {
    if (args.size () != 3)
      return usageError ("build needs DB and ROOT");
    std::vector<std::string> files;
    const auto st = pcl_flowseg::listShapeFiles (args[2], files);
    if (!st)
    {
      std::cerr << "flowseg_db: " << st.message << "\n";
      return 1;
    }
    if (files.empty ())
    {
      std::cerr << "flowseg_db: no shape files below " << args[2] << "\n";
      return 1;
    }
    if (!extract (args[2], files, o, db, ""))
      return 1;
  }
  else if (command == "add")
  {
    if (args.size () < 3)
      return usageError ("add needs DB and at least one FILE");
    if (std::ifstream (db_path).good ())
    {
      const auto st = db.load (db_path);
      if (!st)
      {
        std::cerr << "flowseg_db: " << st.message << "\n";
        return 1;
      }
    }
    std::vector<std::string> files (args.begin () + 2, args.end ());
    if (!extract ("", files, o, db, o.label))
      return 1;
  }
  else if (command == "query" || command == "list")
  {
    const auto st = db.load (db_path);
    if (!st)
    {
      std::cerr << "flowseg_db: " << st.message << "\n";
      return 1;
    }
    if (command == "list")
    {
      for (const auto& e : db.entries ())
        std::printf ("%s\t%s\t%zu features\n", e.label.c_str (), e.name.c_str (), e.signature.points.size ());
      return 0;
    }
    if (args.size () != 3)
      return usageError ("query needs DB and FILE");
    pcl_flowseg::Signature s;
    std::string error;
    if (!signatureOfFile (args[2], o, s, error))
    {
      std::cerr << "flowseg_db: " << error << "\n";
      return 1;
    }
    pcl::SignatureMatcher matcher;
    matcher.setThreshold (o.threshold);
    db.setCandidates (o.candidates);
    const auto t0 = std::chrono::steady_clock::now ();
    const auto hits = db.query (s, o.k, matcher);
    const double ms = std::chrono::duration<double, std::milli> (std::chrono::steady_clock::now () - t0).count ();
    std::printf ("rank\tsimilarity\tscore\tclass\tshape\n");
    for (std::size_t r = 0; r < hits.size (); ++r)
    {
      const auto& e = db.entries ()[hits[r].entry];
      if (hits[r].aligned)
        std::printf ("%zu\t%.4f\t%.4f\t%s\t%s\n", r + 1, hits[r].similarity, hits[r].score, e.label.c_str (), e.name.c_str ());
      else
        std::printf ("%zu\t-\t-\t%s\t%s\n", r + 1, e.label.c_str (), e.name.c_str ());
    }
    if (!o.quiet)
      std::fprintf (stderr, "query against %zu stored signatures (%s aligned): %.2f ms\n", db.size (),
                    o.candidates ? std::to_string (std::min (o.candidates, db.size ())).c_str () : "all", ms);
    return 0;
  }
  else
    return usageError ("unknown command '" + command + "' (build, add, query, list)");

  const auto saved = db.save (db_path);
  if (!saved)
  {
    std::cerr << "flowseg_db: " << saved.message << "\n";
    return 1;
  }
  if (!o.quiet)
    std::fprintf (stderr, "%s: %zu shapes\n", db_path.c_str (), db.size ());
  return 0;
}

/*
 * flowseg_db: build, extend and query a database of shape signatures.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include "common/flow_options.h"
#include "common/huge_page_malloc.h"
#include "common/options.h"
#include "common/progress.h"

#include <pcl_flowseg/io/shape_input.h>
#include <pcl_flowseg/signature/shape_signature.h>
#include <pcl_flowseg/signature/signature_database.h>

#include <chrono>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

namespace {

using flowseg_app::OptionParser;

struct Options
{
  std::size_t k = pcl_flowseg::kDefaultQueryResults;
  std::size_t candidates = pcl_flowseg::kDefaultCandidates;
  std::size_t view_candidates = pcl_flowseg::kDefaultViewCandidates;
  std::string label;
  bool no_views = false;
  pcl_flowseg::FlowParameters params;
  flowseg_app::SignatureOptions signature;
  pcl_flowseg::MatchParameters match;
  unsigned threads = 0;
  bool quiet = false;
};

OptionParser
makeParser (Options& o)
{
  OptionParser p ("flowseg_db",
                  "flowseg_db build DB ROOT [options]    signatures of every shape file below ROOT (class = folder)\n"
                  "       flowseg_db add DB FILE... [options]   add or replace shapes (the others are kept as they are)\n"
                  "       flowseg_db merge DB SHARD...          add every shape of other databases, in order\n"
                  "       flowseg_db query DB FILE [options]    the most similar stored shapes\n"
                  "       flowseg_db list DB                    the stored shapes",
                  "Shape files: .pcd .ply .xyz .txt .csv (points), .off .obj .ply meshes (sampled on their faces)\n"
                  "and .png .bmp .pgm silhouettes (their boundary, 2D).");
  p.count ("-k", "N", "query: how many results; 0 = all", o.k, 0, 1000000000);
  p.count ("--candidates", "N", "query: compare in full the N stored shapes whose summaries are\nnearest; 0 = every stored shape; the rest are listed after them\nby summary distance, similarity \"-\"",
           o.candidates, 0, 1000000000);
  p.count ("--view-candidates", "N", "query of a single-view scan (--use-sensor-origin, --viewpoint):\nalign the scan with the N stored shapes whose views' histograms\nare nearest (at most --candidates)",
           o.view_candidates, 1, 1000000000);
  p.text ("--label", "L", "add: class of the added shapes (default: their folder name)", o.label);
  p.flag ("--no-views", "build, add: store the shapes without their views (about 20 KB per 3D\nshape in place of 270 KB); single-view scans then find none of them", o.no_views);
  flowseg_app::addSegmentationOptions (p, o.params);
  flowseg_app::addViewpointOptions (p, o.params.interior.viewpoint, o.signature.input.use_sensor_origin);
  flowseg_app::addSignatureOptions (p, o.signature);
  flowseg_app::addMatchMethodOption (p, o.match);
  flowseg_app::addMatchOptions (p, o.match);
  flowseg_app::addThreadsOption (p, o.threads);
  p.flag ("-q, --quiet", "no progress or summary on stderr", o.quiet);
  p.epilogue ("build, add and query segment every shape with the segmentation options; with\n"
              "--use-sensor-origin each file has its own VIEWPOINT (a collection of single-view scans).\n\n"
              "Exit status: 0 success, 1 unreadable input or database, 2 bad options.");
  return p;
}

/** The entries of \a files (read at root + "/" + file, or as given when root is empty), labelled
  * \a label or by their folder; false when every file failed. Computed before the database is
  * locked, so that other writers wait only for the write itself. */
bool
computeEntries (const std::string& root, const std::vector<std::string>& files, const Options& o, const std::string& label,
                std::vector<pcl_flowseg::ShapeEntry>& entries)
{
  std::vector<std::string> paths;
  for (const auto& f : files)
    paths.push_back (root.empty () ? f : root + "/" + f);
  std::vector<pcl_flowseg::Signature> signatures;
  std::vector<pcl_flowseg::Status> statuses;
  {
    flowseg_app::ProgressLine progress ("signatures", files.size (), o.quiet);
    pcl_flowseg::signaturesOfShapeFiles (paths, o.signature.input, o.params, o.signature.significance, o.threads, signatures,
                                         statuses, [&] (std::size_t done, const std::string& path, const pcl_flowseg::Status& s) {
                                           progress.update (done, path + (s ? "" : " (failed)"));
                                         });
  }
  std::size_t failed = 0;
  for (std::size_t i = 0; i < files.size (); ++i)
  {
    if (!statuses[i])
    {
      std::cerr << "flowseg_db: skipped " << statuses[i].message << "\n";
      ++failed;
      continue;
    }
    pcl_flowseg::ShapeEntry entry;
    entry.name = files[i];
    entry.label = label.empty () ? pcl_flowseg::shapeLabel (files[i]) : label;
    if (entry.label.empty ())
      entry.label = "-";
    entry.signature = signatures[i];
    if (o.no_views)
      entry.signature.views = pcl_flowseg::ViewSet ();
    entries.push_back (std::move (entry));
  }
  if (!o.quiet)
    std::fprintf (stderr, "%zu signatures computed, %zu files skipped\n", files.size () - failed, failed);
  return failed < files.size () || files.empty ();
}

/** Replaces the database at args[1] with the signatures of every shape file below args[2]. */
int
build (const OptionParser& p, const std::vector<std::string>& args, const Options& o, std::size_t& stored)
{
  if (args.size () != 3)
    return p.usageError ("build needs DB and ROOT");
  std::vector<std::string> files;
  if (const pcl_flowseg::Status s = pcl_flowseg::listShapeFiles (args[2], files); !s)
    return p.failure (s.message);
  if (files.empty ())
    return p.failure ("no shape files below " + args[2]);
  std::vector<pcl_flowseg::ShapeEntry> entries;
  if (!computeEntries (args[2], files, o, "", entries))
    return flowseg_app::kExitFailure;
  pcl_flowseg::SignatureDatabase db;
  for (const auto& e : entries)
    db.add (e);
  if (const pcl_flowseg::Status saved = db.save (args[1]); !saved)
    return p.failure (saved.message);
  stored = db.size ();
  return flowseg_app::kExitSuccess;
}

/** Adds every shape of \a shards to the database at \a path in one locked transaction, so that
  * concurrent writers lose nothing. A damaged database is refused before anything changes. */
int
mergeUnderLock (const OptionParser& p, const std::string& path, const std::vector<pcl_flowseg::SignatureDatabase>& shards,
                std::size_t& stored)
{
  const pcl_flowseg::Status s = pcl_flowseg::SignatureDatabase::update (path, [&] (pcl_flowseg::SignatureDatabase& db) {
    for (const auto& shard : shards)
      db.merge (shard);
    stored = db.size ();
    return pcl_flowseg::Status::success ();
  });
  return s ? flowseg_app::kExitSuccess : p.failure (s.message);
}

/** The database at \a path, if there is one, is readable (checked before long work). */
pcl_flowseg::Status
existingDatabaseReads (const std::string& path)
{
  if (!std::ifstream (path).good ())
    return pcl_flowseg::Status::success ();
  return pcl_flowseg::SignatureDatabase ().load (path);
}

/** Adds the signatures of args[2...] to the database at args[1]; a damaged database fails before
  * the signatures are computed. */
int
add (const OptionParser& p, const std::vector<std::string>& args, const Options& o, std::size_t& stored)
{
  if (args.size () < 3)
    return p.usageError ("add needs DB and at least one FILE");
  if (const pcl_flowseg::Status s = existingDatabaseReads (args[1]); !s)
    return p.failure (s.message);
  const std::vector<std::string> files (args.begin () + 2, args.end ());
  std::vector<pcl_flowseg::ShapeEntry> entries;
  if (!computeEntries ("", files, o, o.label, entries))
    return flowseg_app::kExitFailure;
  std::vector<pcl_flowseg::SignatureDatabase> added (1);
  for (const auto& e : entries)
    added[0].add (e);
  return mergeUnderLock (p, args[1], added, stored);
}

/** Adds every shape of the databases args[2...] to the database at args[1]. The shards are read
  * and checked first: a damaged one changes nothing. */
int
merge (const OptionParser& p, const std::vector<std::string>& args, std::size_t& stored)
{
  if (args.size () < 3)
    return p.usageError ("merge needs DB and at least one SHARD");
  std::vector<pcl_flowseg::SignatureDatabase> shards (args.size () - 2);
  for (std::size_t i = 0; i < shards.size (); ++i)
    if (const pcl_flowseg::Status s = shards[i].load (args[i + 2]); !s)
      return p.failure (s.message);
  if (const pcl_flowseg::Status s = existingDatabaseReads (args[1]); !s)
    return p.failure (s.message);
  return mergeUnderLock (p, args[1], shards, stored);
}

int
query (const OptionParser& p, const std::vector<std::string>& args, const Options& o, pcl_flowseg::SignatureDatabase& db)
{
  if (args.size () != 3)
    return p.usageError ("query needs DB and FILE");
  pcl_flowseg::Signature s;
  if (const pcl_flowseg::Status st = pcl_flowseg::signatureOfShapeFile (args[2], o.signature.input, o.params,
                                                                         o.signature.significance, s);
      !st)
    return p.failure (st.message);
  pcl::SignatureMatcher matcher;
  matcher.setParameters (o.match);
  db.setCandidates (o.candidates);
  db.setViewCandidates (o.view_candidates);
  db.setQueryThreads (o.threads);
  const auto t0 = std::chrono::steady_clock::now ();
  const auto hits = db.query (s, o.k, matcher);
  const double ms = std::chrono::duration<double, std::milli> (std::chrono::steady_clock::now () - t0).count ();
  const bool paper = o.match.method == pcl_flowseg::MatchMethod::Paper;
  const bool single_view = s.views.single_view && !paper;
  std::printf ("rank\tsimilarity\t%s\tclass\tshape\n", paper ? "score" : "distance");
  for (std::size_t r = 0; r < hits.size (); ++r)
  {
    const pcl_flowseg::QueryHit& h = hits[r];
    if (h.compared)
      std::printf ("%zu\t%.4f\t%.4f\t%s\t%s\n", r + 1, h.similarity, paper ? h.paper_score : h.distance, h.label.c_str (),
                   h.name.c_str ());
    else
      std::printf ("%zu\t-\t-\t%s\t%s\n", r + 1, h.label.c_str (), h.name.c_str ());
  }
  if (single_view && hits.empty () && db.size () > 0)
    std::fprintf (stderr, "flowseg_db: warning: none of the %zu stored shapes has views (a database built with --no-views, "
                          "or 2D shapes): a single-view scan finds none of them\n", db.size ());
  std::size_t compared = o.candidates == 0 ? db.size () : std::min (o.candidates, db.size ());
  if (single_view && o.candidates != 0)
    compared = std::min (compared, o.view_candidates);
  if (!o.quiet)
    std::fprintf (stderr, "query (method %s%s) against %zu stored signatures (at most %zu compared in full): %.2f ms\n",
                  pcl_flowseg::matchMethodName (o.match.method), single_view ? ", a single view aligned with their views" : "",
                  db.size (), compared, ms);
  return flowseg_app::kExitSuccess;
}

int
list (const OptionParser& p, const std::vector<std::string>& args, pcl_flowseg::SignatureDatabase& db)
{
  if (args.size () != 2)
    return p.usageError ("list needs DB only");
  for (const auto& e : db.entries ())
    std::printf ("%s\t%s\t%zu features\t%zu parts\n", e.label.c_str (), e.name.c_str (), e.signature.points.size (),
                 e.signature.description.parts.size ());
  return flowseg_app::kExitSuccess;
}

} // namespace

int
main (int argc, char** argv)
{
  flowseg_app::relaunchWithHugePageMalloc (argv);
  Options o;
  const OptionParser parser = makeParser (o);
  std::vector<std::string> args;
  if (const int status = parser.parse (argc, argv, args); status != flowseg_app::kContinue)
    return status;
  if (args.size () < 2)
    return parser.usageError ("need a command and a database");
  if (!o.label.empty () && o.label.find_first_of (" \t\n") != std::string::npos)
    return parser.usageError ("--label needs a class name without white space");
  if (const int status = flowseg_app::checkViewpointOptions (parser, o.params, o.signature.input.use_sensor_origin);
      status != flowseg_app::kContinue)
    return status;
  const std::string& command = args[0];
  if (command == "query" || command == "list")
  {
    pcl_flowseg::SignatureDatabase db;
    if (const pcl_flowseg::Status s = db.load (args[1]); !s)
      return parser.failure (s.message);
    return command == "list" ? list (parser, args, db) : query (parser, args, o, db);
  }
  if (command != "build" && command != "add" && command != "merge")
    return parser.usageError ("unknown command '" + command + "' (build, add, merge, query, list)");
  std::size_t stored = 0;
  const int status = command == "build"   ? build (parser, args, o, stored)
                     : command == "merge" ? merge (parser, args, stored)
                                          : add (parser, args, o, stored);
  if (status == flowseg_app::kExitSuccess && !o.quiet)
    std::fprintf (stderr, "%s: %zu shapes\n", args[1].c_str (), stored);
  return status;
}

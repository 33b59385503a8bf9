/*
 * pcl_flowseg Python bindings - the signature database: open, add, merge, save, query.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include "bindings.h"
#include "python_values.h"

#include <pcl_flowseg/signature/signature_database.h>

#include <pybind11/stl.h>

#include <cmath>

namespace pcl_flowseg_python {
namespace {

using pcl_flowseg::SignatureDatabase;

/** A query hit with the stored shape's name and class. */
struct Hit
{
  std::size_t index = 0;
  std::string name, label;
  double similarity = 0.0, distance = 0.0, paper_score = 0.0, summary_distance = 0.0;
  bool compared = true;
};

pcl_flowseg::ShapeEntry
makeEntry (const std::string& name, const std::string& label, const pcl_flowseg::Signature& signature)
{
  if (name.empty () || name.find ('\n') != std::string::npos)
    throw py::value_error ("name: needs one non-empty line, got '" + name + "'");
  if (label.find_first_of (" \t\n") != std::string::npos)
    throw py::value_error ("label: needs one word without white space, got '" + label + "'");
  raiseIfFailed (pcl_flowseg::checkSignature (signature));
  return pcl_flowseg::ShapeEntry{name, label, signature};
}

SignatureDatabase
open (const std::string& path)
{
  SignatureDatabase db;
  pcl_flowseg::Status s;
  {
    py::gil_scoped_release release;
    s = db.load (path);
  }
  raiseOsErrorIfFailed (s);
  return db;
}

std::vector<Hit>
query (const SignatureDatabase& db, const pcl_flowseg::Signature& signature, std::size_t k, std::size_t candidates,
       const py::kwargs& kwargs)
{
  CallParameters unused;
  pcl_flowseg::MatchParameters params;
  applyKwargs (kwargs, kMatchArguments, unused, params);
  raiseIfFailed (pcl_flowseg::checkSignature (signature));
  pcl::SignatureMatcher matcher;
  matcher.setParameters (params);
  std::vector<pcl_flowseg::QueryHit> hits;
  {
    py::gil_scoped_release release;
    hits = db.query (signature, k, matcher, candidates);
  }
  std::vector<Hit> out;
  for (const auto& h : hits)
    out.push_back ({h.entry, h.name, h.label, h.similarity, h.distance, h.paper_score, h.summary_distance, h.compared});
  return out;
}

/** Adds \a shards to the database file \a path in one locked transaction, without the GIL;
  * \return the number of stored shapes. */
std::size_t
mergeIntoFile (const std::string& path, const std::vector<SignatureDatabase>& shards, double lock_wait)
{
  std::size_t stored = 0;
  pcl_flowseg::Status s;
  {
    py::gil_scoped_release release;
    s = SignatureDatabase::update (path, [&] (SignatureDatabase& db) {
      for (const auto& shard : shards)
        db.merge (shard);
      stored = db.size ();
      return pcl_flowseg::Status::success ();
    }, lock_wait);
  }
  raiseOsErrorIfFailed (s);
  return stored;
}

/** Adds \a shapes (name, label, signature) to the database file \a path in one locked transaction. */
std::size_t
addToFile (const std::string& path, const std::vector<std::tuple<std::string, std::string, pcl_flowseg::Signature>>& shapes,
           double lock_wait)
{
  std::vector<SignatureDatabase> added (1);
  for (const auto& [name, label, signature] : shapes)
    added[0].add (makeEntry (name, label, signature));
  return mergeIntoFile (path, added, lock_wait);
}

/** Merges the database files \a shards, in order, into the file \a path in one locked transaction. */
std::size_t
mergeFiles (const std::string& path, const std::vector<std::string>& shards, double lock_wait)
{
  std::vector<SignatureDatabase> loaded;
  for (const auto& shard : shards)
    loaded.push_back (open (shard));
  return mergeIntoFile (path, loaded, lock_wait);
}

void
bindHit (py::module_& m)
{
  py::class_<Hit> (m, "QueryHit", "One result of Database.query().")
      .def_readonly ("index", &Hit::index, "Position of the shape in Database.entries().")
      .def_readonly ("name", &Hit::name)
      .def_readonly ("label", &Hit::label)
      .def_readonly ("similarity", &Hit::similarity, "MatchResult.similarity, the ranking key (NaN when not compared).")
      .def_readonly ("distance", &Hit::distance, "MatchResult.distance (NaN for 'paper' and when not compared).")
      .def_readonly ("paper_score", &Hit::paper_score, "MatchResult.paper_score (NaN for the other methods and when not compared).")
      .def_readonly ("compared", &Hit::compared,
                     "True when compared in full; false for shapes outside the candidates, ranked by summary distance only.")
      .def_readonly ("summary_distance", &Hit::summary_distance, "Distance between the two shapes' candidate summaries.")
      .def_property_readonly ("aligned", [] (const Hit& h) {
            warnDeprecated ("QueryHit.aligned is deprecated: use compared");
            return h.compared;
          }, "Deprecated: compared.")
      .def_property_readonly ("score", [] (const Hit& h) {
            warnDeprecated ("QueryHit.score is deprecated: use distance (description methods) or paper_score ('paper')");
            return std::isnan (h.paper_score) ? h.distance : h.paper_score;
          }, "Deprecated: paper_score for 'paper', distance for the other methods.")
      .def ("__repr__", [] (const Hit& h) { return "<QueryHit " + h.label + " " + h.name + " similarity=" + std::to_string (h.similarity) + ">"; });
}

} // namespace

void
bindDatabase (py::module_& m)
{
  bindHit (m);
  py::class_<SignatureDatabase> (m, "Database",
                                 "Signatures of many shapes, kept in one text file (the format of flowseg_db). Any number of "
                                 "threads may query a Database while others add to it, merge into it or save it.")
      .def (py::init<> (), "An empty database.")
      .def_static ("open", &open, py::arg ("path"), "Reads a database file; OSError when it is missing or damaged.")
      .def ("add", [] (SignatureDatabase& db, const std::string& name, const std::string& label, const pcl_flowseg::Signature& s) {
            const pcl_flowseg::ShapeEntry entry = makeEntry (name, label, s);
            py::gil_scoped_release release; // waits for the queries running on other threads
            return db.add (entry);
          }, py::arg ("name"), py::arg ("label"), py::arg ("signature"),
          "Adds a shape (replacing one of the same name); True when it was new.")
      .def ("merge", &SignatureDatabase::merge, py::arg ("shard"), py::call_guard<py::gil_scoped_release> (),
            "Adds every shape of another database, in its order; returns how many were new.")
      .def ("save", [] (const SignatureDatabase& db, const std::string& path, double lock_wait) {
            pcl_flowseg::Status s;
            {
              py::gil_scoped_release release;
              s = db.save (path, lock_wait);
            }
            raiseOsErrorIfFailed (s);
          }, py::arg ("path"), py::arg ("lock_wait") = pcl_flowseg::kDefaultLockWait,
          "Writes the whole database (replacing the file) under its lock, atomically: readers see the old or the new file.")
      .def ("query", &query, py::arg ("signature"), py::arg ("k") = pcl_flowseg::kDefaultQueryResults, py::arg ("candidates") = pcl_flowseg::kDefaultCandidates,
            "The k most similar stored shapes (all when k = 0), comparing in full the `candidates` nearest by summary (0 = all); "
            "a single-view scan's signature (single_view) is aligned with the min(candidates, view_candidates) shapes whose "
            "views' histograms are nearest; keywords as match().")
      .def_property (
          "view_candidates", [] (const SignatureDatabase& db) { return db.getViewCandidates (); },
          [] (SignatureDatabase& db, std::size_t count) {
            if (count == 0)
              throw py::value_error ("view_candidates must be at least 1");
            db.setViewCandidates (count);
          },
          "How many stored shapes a single-view query aligns with the scan (default 40).")
      .def ("entries", [] (const SignatureDatabase& db) {
            std::vector<pcl_flowseg::ShapeEntry> entries;
            {
              py::gil_scoped_release release;
              entries = db.copyEntries ();
            }
            std::vector<std::tuple<std::string, std::string, pcl_flowseg::Signature>> out;
            for (auto& e : entries)
              out.emplace_back (std::move (e.name), std::move (e.label), std::move (e.signature));
            return out;
          }, "Every stored shape as (name, label, signature), in file order.")
      .def ("__len__", &SignatureDatabase::size, py::call_guard<py::gil_scoped_release> ())
      .def ("__contains__", &SignatureDatabase::contains, py::call_guard<py::gil_scoped_release> ())
      .def_static ("add_to_file", &addToFile, py::arg ("path"), py::arg ("shapes"), py::arg ("lock_wait") = pcl_flowseg::kDefaultLockWait,
                   "Adds (name, label, signature) tuples to a database file in one locked read-modify-write: concurrent "
                   "writers (processes or threads) lose nothing. Returns the number of stored shapes.")
      .def_static ("merge_files", &mergeFiles, py::arg ("path"), py::arg ("shards"), py::arg ("lock_wait") = pcl_flowseg::kDefaultLockWait,
                   "Merges database files into the file at path (created when missing), in order, in one locked "
                   "transaction, as `flowseg_db merge`. Returns the number of stored shapes.");
}

} // namespace pcl_flowseg_python

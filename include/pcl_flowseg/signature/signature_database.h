/*
 * pcl_flowseg - a database of shape signatures: a versioned file, incremental additions, queries.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include <pcl_flowseg/signature/shape_entry.h>
#include <pcl_flowseg/signature/signature.h>
#include <pcl_flowseg/signature/signature_matcher.h>
#include <pcl_flowseg/common/status.h>
#include <pcl_flowseg/io/file_lock.h>

#include <atomic>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <shared_mutex>
#include <string>
#include <unordered_map>
#include <vector>

namespace pcl_flowseg {


/** \brief A query result. */
struct QueryHit
{
  std::size_t entry = 0; ///< index into SignatureDatabase::entries() when the query ran
  std::string name;      ///< the shape's ShapeEntry::name
  std::string label;     ///< the shape's ShapeEntry::label
  /** SignatureMatcher::Result::similarity (the ranking key, higher = more similar); NaN when not
    * compared. */
  double similarity = 0.0;
  /** SignatureMatcher::Result::distance (description methods); NaN for MatchMethod::Paper and when
    * not compared. */
  double distance = 0.0;
  /** SignatureMatcher::Result::paper_score (MatchMethod::Paper); NaN for the other methods and
    * when not compared. */
  double paper_score = 0.0;
  /** True when the query was compared with this shape in full (SignatureMatcher::match); false for
    * shapes outside the candidates, ranked by summary distance only. */
  bool compared = true;
  double summary_distance = 0.0; ///< distance between the two signatures' candidate summaries
};

/** \brief Default number of results of a query (the k of SignatureDatabase::query in the apps and
  * the Python module). */
constexpr std::size_t kDefaultQueryResults = 10;

/** \brief Default number of stored shapes compared in full per query (SignatureDatabase::setCandidates);
  * how well the candidate index finds the exact top results with it is measured in
  * docs/measurements.md ("Speed and memory"). */
constexpr std::size_t kDefaultCandidates = 1000;

/** \brief Default number of stored shapes a single-view query aligns with the scan
  * (SignatureDatabase::setViewCandidates). */
constexpr std::size_t kDefaultViewCandidates = 40;

/** \brief Signatures of many shapes, kept in one text file (version kDatabaseVersion):
  *
  *     pcl_flowseg signature database 7
  *     shapes N
  *     shape LABEL DIMENSION UNIT VOLUME SIGNIFICANCE POINTS PARTS CONTOUR CONTEXTS NAME...
  *     p X Y Z WEIGHT                                        POINTS lines: Signature::points
  *     q WEIGHT THICKNESS EXTENT MIDDLE SMALLEST REMOTENESS  PARTS lines: ShapeDescription::parts
  *     t B1 ... B32                                          the distributions (kDistributionBins
  *     i B1 ... B32                                          each): thickness, inner distance,
  *     s B1 ... B32                                          solid distance
  *     r B1 ... B32                                          kProfileRows lines: inner_profiles
  *     h V1 ... V16                                          thickness_profile (kProfileRows)
  *     c B1 ... B60                                          CONTOUR lines (0 or kContourPoints):
  *                                                           contour (kContourBins each)
  *     x THICKNESS B1 ... B16                                CONTEXTS lines: inner_contexts
  *                                                           (kContextBins each)
  *     views N SINGLE                                        Signature::views (SINGLE 1: a scan's)
  *     v DX DY DZ ROLL CX CY CZ SCALE B1 ... B80             N pairs of lines: a view's direction,
  *     u M X1 Y1 Z1 NX1 NY1 NZ1 ... NZM                      frame and histogram, its M points and
  *                                                           their normals
  *     o M X1 Y1 Z1 NX1 NY1 NZ1 ... NZM                      ViewSet::shape_points, shape_normals
  *
  * A shape without a description (PARTS = CONTOUR = CONTEXTS = 0) has only its shape, p and views
  * lines; a 2D shape has no views (N = 0).
  * Labels contain no white space ("-" for none); names may. Numbers are written with 17 significant
  * digits, the c and x lines' (floats) with 9, so that every value reads back exactly; the views' with 4 (the o line's points with 7), their normals with 2. Loading
  * checks the header, the version, every count and number, and reports the line of the first
  * problem. Files of versions 1 to 6 (written by older builds, without parts of today's
  * descriptions) are refused with a message that says to rebuild them.
  *
  * Threads: any number may query a database (and call the other const members) while others add,
  * merge, load or assign: readers share a lock that changes hold alone (a waiting change goes
  * before queries that come after it). Only the reference entries() returns is not guarded. */
class SignatureDatabase
{
public:
  static constexpr int kVersion = kDatabaseVersion;

  SignatureDatabase () = default;
  /** Copies and moves take the other database's lock: safe while other threads query it. */
  SignatureDatabase (const SignatureDatabase& other);
  SignatureDatabase (SignatureDatabase&& other) noexcept;
  SignatureDatabase& operator= (const SignatureDatabase& other);
  SignatureDatabase& operator= (SignatureDatabase&& other) noexcept;
  ~SignatureDatabase () = default;

  /** Reads a database file in place of the stored shapes (none when it fails). It needs no file
    * lock: writers replace the file in one rename, so a reader sees one complete version. Every
    * value is checked (checkSignature); the first problem is reported with its line. */
  Status load (const std::string& path);
  /** Writes the whole database, under the file's lock (FileLock, waiting at most \a lock_wait
    * seconds), to a temporary file flushed to the disk and renamed when complete: a writer that
    * dies leaves the previous complete file. Refuses entries that checkSignature refuses. To change
    * a database other processes may change too, use update(), not load() + save(). */
  Status save (const std::string& path, double lock_wait = kDefaultLockWait) const;

  /** \brief Read-modify-write of the database file \a path as one transaction: under the file's
    * lock, loads it (empty when it does not exist), calls \a change, and saves the result as
    * save() does. Concurrent updates from any number of processes and threads serialise, so none
    * is lost. Keep \a change short (compute signatures before): other writers wait for it.
    * \return the first failure: the lock not had within \a lock_wait seconds, the file not
    *         readable, \a change's own Status, or the write; the file is then unchanged. */
  static Status update (const std::string& path, const std::function<Status (SignatureDatabase&)>& change,
                        double lock_wait = kDefaultLockWait);

  /** Adds a shape, replacing a stored one of the same name. \return true when it was new. */
  bool add (const ShapeEntry& entry);
  /** \brief Adds every shape of \a shard, in its order, as add() does (a shape of the same name is
    * replaced). Merging the shards of a collection split in file order, in that order, gives the
    * database built from the whole collection at once. \return how many shapes were new. */
  std::size_t merge (const SignatureDatabase& shard);
  bool contains (const std::string& name) const;
  std::size_t size () const;
  /** \brief The stored shapes, in the order they were added (QueryHit::entry indexes them). The
    * reference is not guarded: use it only while no other thread changes the database (add, merge,
    * load, assignment); otherwise use copyEntries(). */
  const std::vector<ShapeEntry>& entries () const { return entries_; }
  /** \brief A copy of the stored shapes, taken under the lock: safe while other threads change
    * the database. */
  std::vector<ShapeEntry> copyEntries () const;

  /** \brief How many stored shapes a query compares in full: the \a count whose summaries lie
    * nearest to the query's (a FLANN k-d tree over signatureSummary for MatchMethod::Paper,
    * descriptionSummary with the method's descriptionWeights for the other methods, picks them);
    * 0 = every stored shape (exact ranking; the cost grows with the database). Default
    * kDefaultCandidates. */
  void setCandidates (std::size_t count) { candidates_ = count; }
  std::size_t getCandidates () const { return candidates_; }

  /** \brief How many stored shapes a single-view query (a scan's signature, ViewSet::single_view)
    * aligns with the scan: the \a count whose nearest view's histogram lies nearest the scan's; the
    * smaller of this and the candidates of the query is used (candidates 0: every stored shape).
    * Default kDefaultViewCandidates. */
  void setViewCandidates (std::size_t count) { view_candidates_ = count; }
  std::size_t getViewCandidates () const { return view_candidates_; }

  /** \brief Threads one query compares its candidates on: 0 (default) = every core, 1 = the
    * calling thread only (for callers that run many queries side by side). The results are the
    * same for every count. */
  void setQueryThreads (unsigned threads) { query_threads_ = threads; }
  unsigned getQueryThreads () const { return query_threads_; }

  /** \brief The \a k most similar stored shapes (all when k = 0) under \a matcher's method. The
    * compared candidates come first, by decreasing similarity; the other shapes follow by
    * increasing summary distance (compared = false). Shapes of another dimension are skipped.
    * A single-view scan's signature (ViewSet::single_view) is, under every method but the paper's,
    * aligned with the stored shapes' views (SignatureMatcher): its candidates are picked by the
    * views' histograms (setViewCandidates), and shapes without views are skipped. Parameters that
    * checkMatchParameters refuses find nothing. */
  std::vector<QueryHit> query (const Signature& signature, std::size_t k, const pcl::SignatureMatcher& matcher) const;
  /** \brief As above with \a candidates in place of getCandidates(): for callers that share one
    * database between threads asking with different candidate counts. */
  std::vector<QueryHit> query (const Signature& signature, std::size_t k, const pcl::SignatureMatcher& matcher,
                               std::size_t candidates) const;

private:
  /** Writes the file, the file's lock held. */
  Status saveLocked (const std::string& path) const;
  /** add() with the write lock held. */
  bool addLocked (const ShapeEntry& entry);
  /** query() with the read lock held. */
  std::vector<QueryHit> queryLocked (const Signature& signature, std::size_t k, const pcl::SignatureMatcher& matcher,
                                     std::size_t candidates) const;

  /** queryLocked for a single-view scan: candidates by view histograms, compared by alignment. */
  std::vector<QueryHit> querySingleViewLocked (const Signature& signature, std::size_t k,
                                               const pcl::SignatureMatcher& matcher, std::size_t candidates) const;
  /** Matches the first \a compared hits in full (side by side) and sorts them by similarity. */
  void compareCandidates (const Signature& signature, const pcl::SignatureMatcher& matcher, std::size_t compared,
                          std::vector<QueryHit>& hits) const;

  struct CandidateIndex;
  /** The candidate index for \a params (the summaries depend on the method and, for the
    * description methods, on their weights), built on its first query after a change. */
  std::shared_ptr<const CandidateIndex> candidateIndex (const MatchParameters& params) const;
  /** Drops the candidate indexes (the entries changed; the write lock held). */
  void forgetIndexes ();

  std::vector<ShapeEntry> entries_;
  std::unordered_map<std::string, std::size_t> by_name_;
  std::atomic<std::size_t> candidates_{kDefaultCandidates};
  std::atomic<std::size_t> view_candidates_{kDefaultViewCandidates};
  std::atomic<unsigned> query_threads_{0};
  /** The candidate indexes built, by what their summaries depend on (summaryKey). */
  mutable std::map<std::vector<double>, std::shared_ptr<const CandidateIndex>> indexes_;

  /** Guards entries_ and by_name_: queries, copies and the other readers share it, add, merge,
    * load and assignment hold it alone. */
  mutable std::shared_mutex entries_mutex_;
  /** Taken by writers while they wait for entries_mutex_ and hold it, and briefly by readers
    * before they share it: a waiting writer is not starved by a stream of queries. */
  mutable std::mutex writer_gate_;
  /** Guards indexes_, which queries build under the shared lock. */
  mutable std::mutex index_mutex_;
};

} // namespace pcl_flowseg

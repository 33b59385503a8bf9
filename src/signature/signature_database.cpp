/*
 * pcl_flowseg - a database of shape signatures: a versioned file, incremental additions, queries.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include <pcl_flowseg/signature/signature_database.h>

#include <pcl_flowseg/common/parallel_jobs.h>
#include <pcl_flowseg/io/atomic_file.h>
#include <pcl_flowseg/io/file_lock.h>

#include <pcl_flowseg/signature/signature_summary.h>

#include "database_format.h"

#include <flann/flann.hpp>
#include <pcl/console/print.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iomanip>
#include <limits>
#include <mutex>
#include <shared_mutex>
#include <sstream>
#include <unistd.h>

namespace pcl_flowseg {

namespace {

/** A reader's share of a database's lock: it waits at the writers' gate first, so that a writer
  * waiting for the lock is served before readers that come after it. */
class ReadLock
{
public:
  ReadLock (std::mutex& gate, std::shared_mutex& mutex) : mutex_ (mutex)
  {
    std::lock_guard<std::mutex> passing (gate);
    mutex_.lock_shared ();
  }
  ~ReadLock () { mutex_.unlock_shared (); }
  ReadLock (const ReadLock&) = delete;
  ReadLock& operator= (const ReadLock&) = delete;

private:
  std::shared_mutex& mutex_;
};

/** A writer's lock of a database: the gate (new readers wait), then the lock alone. */
class WriteLock
{
public:
  WriteLock (std::mutex& gate, std::shared_mutex& mutex) : gate_ (gate), mutex_ (mutex) {}

private:
  std::lock_guard<std::mutex> gate_;
  std::lock_guard<std::shared_mutex> mutex_;
};

/** The index of each name in \a entries (the last of equal names). */
std::unordered_map<std::string, std::size_t>
indexByName (const std::vector<ShapeEntry>& entries)
{
  std::unordered_map<std::string, std::size_t> by_name;
  for (std::size_t i = 0; i < entries.size (); ++i)
    by_name[entries[i].name] = i;
  return by_name;
}

/** The shapes of the database file \a path (read and checked), or the first problem. */
Status
readDatabaseFile (const std::string& path, std::vector<ShapeEntry>& loaded)
{
  std::ifstream in (path, std::ios::binary);
  if (!in)
    return Status::error (path + ": cannot open (" + std::strerror (errno) + ")");
  std::size_t count = 0;
  if (const Status header = readDatabaseHeader (in, path, count); !header)
    return header;
  LineReader reader{in, path, 2};
  loaded.reserve (count);
  for (std::size_t s = 0; s < count; ++s)
  {
    ShapeEntry e;
    if (const Status read = readShape (reader, s, count, e); !read)
      return read;
    loaded.push_back (std::move (e));
  }
  return Status::success ();
}

} // namespace

SignatureDatabase::SignatureDatabase (const SignatureDatabase& other)
{
  ReadLock lock (other.writer_gate_, other.entries_mutex_);
  entries_ = other.entries_;
  by_name_ = other.by_name_;
  candidates_ = other.candidates_.load ();
  view_candidates_ = other.view_candidates_.load ();
  query_threads_ = other.query_threads_.load ();
}

SignatureDatabase::SignatureDatabase (SignatureDatabase&& other) noexcept
{
  *this = std::move (other); // this one is new: nobody else can hold its locks
}

SignatureDatabase&
SignatureDatabase::operator= (const SignatureDatabase& other)
{
  if (this != &other)
    *this = SignatureDatabase (other);
  return *this;
}

SignatureDatabase&
SignatureDatabase::operator= (SignatureDatabase&& other) noexcept
{
  if (this == &other)
    return *this;
  // Both databases alone; std::scoped_lock takes the four without deadlock whatever the order.
  std::scoped_lock both (writer_gate_, entries_mutex_, other.writer_gate_, other.entries_mutex_);
  entries_ = std::move (other.entries_);
  by_name_ = std::move (other.by_name_);
  candidates_ = other.candidates_.load ();
  view_candidates_ = other.view_candidates_.load ();
  query_threads_ = other.query_threads_.load ();
  other.entries_.clear ();
  other.by_name_.clear ();
  std::scoped_lock indexes (index_mutex_, other.index_mutex_);
  indexes_ = std::move (other.indexes_);
  other.indexes_.clear ();
  return *this;
}

Status
SignatureDatabase::load (const std::string& path)
{
  std::vector<ShapeEntry> loaded;
  const Status read = readDatabaseFile (path, loaded);
  if (!read)
    loaded.clear ();
  std::unordered_map<std::string, std::size_t> by_name = indexByName (loaded);
  WriteLock lock (writer_gate_, entries_mutex_);
  entries_ = std::move (loaded);
  by_name_ = std::move (by_name);
  forgetIndexes ();
  return read;
}

Status
SignatureDatabase::save (const std::string& path, double lock_wait) const
{
  FileLock lock;
  if (const Status s = lock.acquire (path, lock_wait); !s)
    return s;
  return saveLocked (path);
}

Status
SignatureDatabase::update (const std::string& path, const std::function<Status (SignatureDatabase&)>& change,
                           double lock_wait)
{
  FileLock lock;
  if (const Status s = lock.acquire (path, lock_wait); !s)
    return s;
  SignatureDatabase db;
  if (::access (path.c_str (), F_OK) == 0)
    if (const Status s = db.load (path); !s)
      return s;
  if (const Status s = change (db); !s)
    return s;
  return db.saveLocked (path);
}

Status
SignatureDatabase::saveLocked (const std::string& path) const
{
  ReadLock lock (writer_gate_, entries_mutex_);
  for (const ShapeEntry& e : entries_)
  {
    if (const Status s = checkSignature (e.signature); !s)
      return Status::error ("cannot write " + path + ": shape '" + e.name + "': " + s.message);
    if (e.name.empty () || e.name.find ('\n') != std::string::npos || e.label.find_first_of (" \t\n") != std::string::npos)
      return Status::error ("cannot write " + path + ": shape '" + e.name + "': names must be one line, labels one word");
  }
  return writeFileAtomically (path, [&] (const std::string& tmp) {
    std::ofstream out (tmp, std::ios::binary);
    if (!out)
      return Status::error ("cannot create file");
    writeDatabaseHeader (out, entries_.size ());
    for (const ShapeEntry& e : entries_)
      writeShape (out, e);
    out.flush ();
    return out.good () ? Status::success () : Status::error ("write failed");
  }, true);
}

void
SignatureDatabase::forgetIndexes ()
{
  std::lock_guard<std::mutex> lock (index_mutex_);
  indexes_.clear ();
}

bool
SignatureDatabase::add (const ShapeEntry& entry)
{
  WriteLock lock (writer_gate_, entries_mutex_);
  return addLocked (entry);
}

bool
SignatureDatabase::addLocked (const ShapeEntry& entry)
{
  forgetIndexes ();
  const auto found = by_name_.find (entry.name);
  if (found != by_name_.end ())
  {
    entries_[found->second] = entry;
    return false;
  }
  by_name_.emplace (entry.name, entries_.size ());
  entries_.push_back (entry);
  return true;
}

std::size_t
SignatureDatabase::merge (const SignatureDatabase& shard)
{
  // A copy first: the two locks are never held together (no deadlock when two databases merge
  // each other, and a database may merge itself).
  const std::vector<ShapeEntry> added_entries = shard.copyEntries ();
  WriteLock lock (writer_gate_, entries_mutex_);
  std::size_t added = 0;
  for (const ShapeEntry& entry : added_entries)
    added += addLocked (entry) ? 1 : 0;
  return added;
}

bool
SignatureDatabase::contains (const std::string& name) const
{
  ReadLock lock (writer_gate_, entries_mutex_);
  return by_name_.count (name) > 0;
}

std::size_t
SignatureDatabase::size () const
{
  ReadLock lock (writer_gate_, entries_mutex_);
  return entries_.size ();
}

std::vector<ShapeEntry>
SignatureDatabase::copyEntries () const
{
  ReadLock lock (writer_gate_, entries_mutex_);
  return entries_;
}

namespace {

/** The vector candidates for \a params are picked by: signatureSummary for the paper's method,
  * which compares no descriptions; for the description methods descriptionSummary, each block
  * weighted as the method weighs its distance. */
std::vector<float>
candidateSummary (const Signature& signature, const MatchParameters& params)
{
  if (params.method == MatchMethod::Paper)
  {
    const auto summary = signatureSummary (signature);
    return std::vector<float> (summary.begin (), summary.end ());
  }
  const auto summary = descriptionSummary (signature, descriptionWeights (params, signature.dimension));
  return std::vector<float> (summary.begin (), summary.end ());
}

/** What candidateSummary depends on besides the signature: the paper's method, or the weights of
  * the description distances for 2D and for 3D shapes. Equal keys, equal summaries. */
std::vector<double>
summaryKey (const MatchParameters& params)
{
  if (params.method == MatchMethod::Paper)
    return {1.0};
  std::vector<double> key{0.0};
  for (int dimension : {2, 3})
  {
    const DescriptionWeights w = descriptionWeights (params, dimension);
    key.insert (key.end (), {w.parts, w.thickness, w.inner_distance, w.solid_distance, w.inner_profile,
                             w.thickness_profile, w.contour, w.inner_context});
  }
  return key;
}

/** Most candidate indexes kept: a caller trying many weights does not pile up indexes. */
constexpr std::size_t kKeptIndexes = 16;

} // namespace

/** The summaries of the stored signatures for one summaryKey in a FLANN k-d tree, one tree per dimension. */
struct SignatureDatabase::CandidateIndex
{
  struct Tree
  {
    std::vector<std::size_t> entry;  // row -> entry index
    std::vector<float> rows;         // width floats per row
    std::unique_ptr<flann::Index<flann::L2<float>>> index;
  };
  Tree trees[2]; // [0]: 2D, [1]: 3D
  std::size_t width = 0;
};

std::shared_ptr<const SignatureDatabase::CandidateIndex>
SignatureDatabase::candidateIndex (const MatchParameters& params) const
{
  std::vector<double> key = summaryKey (params);
  std::lock_guard<std::mutex> lock (index_mutex_);
  if (const auto found = indexes_.find (key); found != indexes_.end ())
    return found->second;
  auto built = std::make_shared<CandidateIndex> ();
  for (std::size_t i = 0; i < entries_.size (); ++i)
  {
    auto& tree = built->trees[entries_[i].signature.dimension == 2 ? 0 : 1];
    const std::vector<float> summary = candidateSummary (entries_[i].signature, params);
    built->width = summary.size ();
    tree.entry.push_back (i);
    tree.rows.insert (tree.rows.end (), summary.begin (), summary.end ());
  }
  for (auto& tree : built->trees)
    if (!tree.entry.empty ())
    {
      tree.index.reset (new flann::Index<flann::L2<float>> (flann::Matrix<float> (tree.rows.data (), tree.entry.size (), built->width),
                                                            flann::KDTreeSingleIndexParams (10)));
      tree.index->buildIndex ();
    }
  if (indexes_.size () >= kKeptIndexes)
    indexes_.clear (); // queries still using one keep it alive
  indexes_[std::move (key)] = built;
  return built;
}

std::vector<QueryHit>
SignatureDatabase::query (const Signature& signature, std::size_t k, const pcl::SignatureMatcher& matcher) const
{
  return query (signature, k, matcher, candidates_);
}

std::vector<QueryHit>
SignatureDatabase::query (const Signature& signature, std::size_t k, const pcl::SignatureMatcher& matcher,
                          std::size_t candidates) const
{
  ReadLock lock (writer_gate_, entries_mutex_);
  std::vector<QueryHit> hits = queryLocked (signature, k, matcher, candidates);
  for (QueryHit& hit : hits)
  {
    hit.name = entries_[hit.entry].name;
    hit.label = entries_[hit.entry].label;
  }
  return hits;
}

std::vector<QueryHit>
SignatureDatabase::queryLocked (const Signature& signature, std::size_t k, const pcl::SignatureMatcher& matcher,
                                std::size_t candidates) const
{
  const MatchParameters& params = matcher.getParameters ();
  if (const Status s = checkMatchParameters (params); !s)
  {
    PCL_ERROR ("[pcl_flowseg::SignatureDatabase::query] %s\n", s.message.c_str ());
    return {}; // summaries with such weights would order nothing
  }
  if (signature.views.single_view && params.method != MatchMethod::Paper)
    return querySingleViewLocked (signature, k, matcher, candidates == 0 ? 0 : std::min (candidates, view_candidates_.load ()));
  const auto index = candidateIndex (params);
  const auto& tree = index->trees[signature.dimension == 2 ? 0 : 1];
  const std::size_t stored = tree.entry.size ();
  if (stored == 0)
    return {};
  // Every stored shape of this dimension by summary distance: the nearest are the candidates. The
  // k-d tree answers exactly; only as many rows as are needed are asked for.
  const std::size_t compared = candidates == 0 ? stored : std::min (candidates, stored);
  const std::size_t wanted = k == 0 ? stored : std::min (stored, std::max (k, compared));
  std::vector<float> summary = candidateSummary (signature, params);
  std::vector<int> rows (wanted);
  std::vector<float> distances (wanted);
  flann::Matrix<int> row_matrix (rows.data (), 1, wanted);
  flann::Matrix<float> distance_matrix (distances.data (), 1, wanted);
  tree.index->knnSearch (flann::Matrix<float> (summary.data (), 1, summary.size ()), row_matrix, distance_matrix, wanted,
                         flann::SearchParams (flann::FLANN_CHECKS_UNLIMITED));
  std::vector<QueryHit> hits;
  hits.reserve (wanted);
  for (std::size_t r = 0; r < wanted; ++r)
  {
    if (rows[r] < 0 || static_cast<std::size_t> (rows[r]) >= stored)
      break; // FLANN leaves rows unset when distances are not numbers; stored summaries never are
    QueryHit hit;
    hit.entry = tree.entry[static_cast<std::size_t> (rows[r])];
    hit.summary_distance = std::sqrt (static_cast<double> (distances[r]));
    hit.compared = r < compared;
    hit.similarity = hit.distance = hit.paper_score = std::numeric_limits<double>::quiet_NaN ();
    hits.push_back (hit);
  }
  compareCandidates (signature, matcher, compared, hits);
  if (k > 0 && hits.size () > k)
    hits.resize (k);
  return hits;
}

void
SignatureDatabase::compareCandidates (const Signature& signature, const pcl::SignatureMatcher& matcher, std::size_t compared,
                                      std::vector<QueryHit>& hits) const
{
  compared = std::min (compared, hits.size ());
  // The candidates compared in full, side by side: each writes only its own hit.
  runParallelJobs (compared, query_threads_, [&] (std::size_t r) {
    const auto m = matcher.match (signature, entries_[hits[r].entry].signature);
    hits[r].similarity = m.similarity;
    hits[r].distance = m.distance;
    hits[r].paper_score = m.paper_score;
  });
  std::stable_sort (hits.begin (), hits.begin () + static_cast<std::ptrdiff_t> (compared),
                    [] (const QueryHit& a, const QueryHit& b) { return a.similarity > b.similarity; });
}

} // namespace pcl_flowseg

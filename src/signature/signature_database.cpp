/*
 * pcl_flowseg - a database of shape signatures: a versioned file, incremental additions, queries.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include <pcl_flowseg/signature/signature_database.h>

#include <pcl_flowseg/io/atomic_file.h>
#include <pcl_flowseg/io/file_lock.h>

#include <pcl_flowseg/signature/signature_summary.h>

#include <flann/flann.hpp>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iomanip>
#include <limits>
#include <sstream>
#include <unistd.h>

namespace pcl_flowseg {

namespace {
const char* const kMagic = "pcl_flowseg signature database";

Status
lineError (const std::string& path, std::size_t line, const std::string& what)
{
  return Status::error (path + ":" + std::to_string (line) + ": " + what);
}

/** Reads the first two lines (magic and version, "shapes N") into \a count. Every shape takes a
  * line of at least 20 bytes ("shape L 3 1 1 0 0 N\n"), so a count the rest of the file cannot
  * hold is refused before anything is allocated for it. */
Status
readHeader (std::istream& in, const std::string& path, std::size_t& count)
{
  std::string line, word;
  if (!std::getline (in, line) || line.compare (0, std::strlen (kMagic), kMagic) != 0)
    return Status::error (path + ": not a pcl_flowseg signature database");
  int version = 0;
  if (!(std::istringstream (line.substr (std::strlen (kMagic))) >> version) || version != SignatureDatabase::kVersion)
    return lineError (path, 1, "unsupported database version (this build reads version " +
                                   std::to_string (SignatureDatabase::kVersion) + ")");
  if (!std::getline (in, line) || !(std::istringstream (line) >> word >> count) || word != "shapes")
    return lineError (path, 2, "expected 'shapes N'");
  in.clear (); // a file that ends right after this line has set eof
  const std::streampos here = in.tellg ();
  in.seekg (0, std::ios::end);
  const auto rest = static_cast<unsigned long long> (in.tellg () - here);
  in.seekg (here);
  if (count > rest / 20)
    return lineError (path, 2, std::to_string (count) + " shapes cannot fit in the " + std::to_string (rest) +
                                   " bytes that follow");
  return Status::success ();
}
} // namespace

Status
SignatureDatabase::load (const std::string& path)
{
  entries_.clear ();
  by_name_.clear ();
  index_.reset ();
  std::ifstream in (path, std::ios::binary);
  if (!in)
    return Status::error (path + ": cannot open (" + std::strerror (errno) + ")");
  std::size_t count = 0;
  if (const Status header = readHeader (in, path, count); !header)
    return header;
  std::string line;
  std::size_t number = 2;
  std::vector<ShapeEntry> loaded;
  loaded.reserve (count);
  for (std::size_t s = 0; s < count; ++s)
  {
    ++number;
    if (!std::getline (in, line))
      return Status::error (path + ": ends after " + std::to_string (s) + " of " + std::to_string (count) + " shapes");
    std::istringstream head (line);
    std::string word;
    ShapeEntry e;
    std::size_t points = 0;
    if (!(head >> word >> e.label >> e.signature.dimension >> e.signature.unit >> e.signature.interior_volume >>
          e.signature.significance >> points) ||
        word != "shape" || (e.signature.dimension != 2 && e.signature.dimension != 3) || points > 100000 ||
        !std::isfinite (e.signature.unit) || !std::isfinite (e.signature.interior_volume))
      return lineError (path, number, "expected 'shape LABEL DIMENSION UNIT VOLUME SIGNIFICANCE POINTS NAME'");
    std::getline (head >> std::ws, e.name);
    if (e.name.empty ())
      return lineError (path, number, "shape without a name");
    const std::size_t shape_line = number;
    for (std::size_t k = 0; k < points; ++k)
    {
      ++number;
      WeightedPoint p;
      if (!std::getline (in, line) || !(std::istringstream (line) >> word >> p.position.x () >> p.position.y () >> p.position.z () >> p.weight) ||
          word != "p")
        return lineError (path, number, "expected 'p X Y Z WEIGHT'");
      if (!p.position.allFinite () || p.position.cwiseAbs ().maxCoeff () > kLargestSignatureCoordinate)
        return lineError (path, number, "coordinates must be finite numbers of at most 1e9 in size");
      if (!(p.weight >= 0.0 && p.weight <= 1.0))
        return lineError (path, number, "the weight must be a number in [0, 1]");
      e.signature.points.push_back (p);
    }
    if (const Status checked = checkSignature (e.signature); !checked)
      return lineError (path, shape_line, "shape '" + e.name + "': " + checked.message);
    loaded.push_back (std::move (e));
  }
  entries_ = std::move (loaded);
  index_.reset ();
  by_name_.clear ();
  for (std::size_t i = 0; i < entries_.size (); ++i)
    by_name_[entries_[i].name] = i;
  return Status::success ();
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
    out << kMagic << " " << kVersion << "\nshapes " << entries_.size () << "\n" << std::setprecision (17);
    for (const ShapeEntry& e : entries_)
    {
      const Signature& s = e.signature;
      out << "shape " << (e.label.empty () ? "-" : e.label) << " " << s.dimension << " " << s.unit << " " << s.interior_volume << " "
          << s.significance << " " << s.points.size () << " " << e.name << "\n";
      for (const auto& p : s.points)
        out << "p " << p.position.x () << " " << p.position.y () << " " << p.position.z () << " " << p.weight << "\n";
    }
    out.flush ();
    return out.good () ? Status::success () : Status::error ("write failed");
  }, true);
}

bool
SignatureDatabase::add (const ShapeEntry& entry)
{
  index_.reset ();
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
  std::size_t added = 0;
  for (const ShapeEntry& entry : shard.entries_)
    added += add (entry) ? 1 : 0;
  return added;
}

bool
SignatureDatabase::contains (const std::string& name) const
{
  return by_name_.count (name) > 0;
}

/** Summaries of the stored signatures in a FLANN k-d tree, one tree per dimension (2D, 3D). */
struct SignatureDatabase::CandidateIndex
{
  struct Tree
  {
    std::vector<std::size_t> entry;  // row -> entry index
    std::vector<float> rows;         // kSummarySize floats per row
    std::unique_ptr<flann::Index<flann::L2<float>>> index;
  };
  Tree trees[2]; // [0]: 2D, [1]: 3D
};

std::shared_ptr<const SignatureDatabase::CandidateIndex>
SignatureDatabase::candidateIndex () const
{
  std::lock_guard<std::mutex> lock (*index_mutex_);
  if (index_)
    return index_;
  auto built = std::make_shared<CandidateIndex> ();
  for (std::size_t i = 0; i < entries_.size (); ++i)
  {
    auto& tree = built->trees[entries_[i].signature.dimension == 2 ? 0 : 1];
    const auto summary = signatureSummary (entries_[i].signature);
    tree.entry.push_back (i);
    tree.rows.insert (tree.rows.end (), summary.begin (), summary.end ());
  }
  for (auto& tree : built->trees)
    if (!tree.entry.empty ())
    {
      tree.index.reset (new flann::Index<flann::L2<float>> (flann::Matrix<float> (tree.rows.data (), tree.entry.size (), kSummarySize),
                                                            flann::KDTreeSingleIndexParams (10)));
      tree.index->buildIndex ();
    }
  index_ = built;
  return index_;
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
  const auto index = candidateIndex ();
  const auto& tree = index->trees[signature.dimension == 2 ? 0 : 1];
  const std::size_t stored = tree.entry.size ();
  if (stored == 0)
    return {};
  // Every stored shape of this dimension by summary distance: the nearest are the candidates. The
  // k-d tree answers exactly; only as many rows as are needed are asked for.
  const std::size_t aligned = candidates == 0 ? stored : std::min (candidates, stored);
  const std::size_t wanted = k == 0 ? stored : std::min (stored, std::max (k, aligned));
  auto summary = signatureSummary (signature);
  std::vector<int> rows (wanted);
  std::vector<float> distances (wanted);
  flann::Matrix<int> row_matrix (rows.data (), 1, wanted);
  flann::Matrix<float> distance_matrix (distances.data (), 1, wanted);
  tree.index->knnSearch (flann::Matrix<float> (summary.data (), 1, kSummarySize), row_matrix, distance_matrix, wanted,
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
    if (r < aligned)
    {
      const auto m = matcher.match (signature, entries_[hit.entry].signature);
      hit.similarity = m.similarity;
      hit.score = m.score;
    }
    else
    {
      hit.aligned = false;
      hit.similarity = hit.score = std::numeric_limits<double>::quiet_NaN ();
    }
    hits.push_back (hit);
  }
  std::stable_sort (hits.begin (), hits.begin () + static_cast<std::ptrdiff_t> (aligned),
                    [] (const QueryHit& a, const QueryHit& b) { return a.similarity > b.similarity; });
  if (k > 0 && hits.size () > k)
    hits.resize (k);
  return hits;
}

} // namespace pcl_flowseg

/*
 * pcl_flowseg - a database of shape signatures: a versioned file, incremental additions, queries.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include <pcl_flowseg/signature_database.h>

#include "atomic_file.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iomanip>
#include <sstream>

namespace pcl_flowseg {

namespace {
const char* const kMagic = "pcl_flowseg signature database";

Status
lineError (const std::string& path, std::size_t line, const std::string& what)
{
  return Status::error (path + ":" + std::to_string (line) + ": " + what);
}
} // namespace

Status
SignatureDatabase::load (const std::string& path)
{
  entries_.clear ();
  std::ifstream in (path, std::ios::binary);
  if (!in)
    return Status::error (path + ": cannot open (" + std::strerror (errno) + ")");
  std::string line;
  std::size_t number = 1;
  if (!std::getline (in, line) || line.compare (0, std::strlen (kMagic), kMagic) != 0)
    return Status::error (path + ": not a pcl_flowseg signature database");
  int version = 0;
  if (!(std::istringstream (line.substr (std::strlen (kMagic))) >> version) || version != kVersion)
    return lineError (path, number, "unsupported database version (this build reads version " + std::to_string (kVersion) + ")");
  std::size_t count = 0;
  ++number;
  {
    std::string word;
    if (!std::getline (in, line) || !(std::istringstream (line) >> word >> count) || word != "shapes" || count > 100000000)
      return lineError (path, number, "expected 'shapes N'");
  }
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
    for (std::size_t k = 0; k < points; ++k)
    {
      ++number;
      WeightedPoint p;
      if (!std::getline (in, line) || !(std::istringstream (line) >> word >> p.position.x () >> p.position.y () >> p.position.z () >> p.weight) ||
          word != "p" || !p.position.allFinite () || !std::isfinite (p.weight) || p.weight < 0)
        return lineError (path, number, "expected 'p X Y Z WEIGHT'");
      e.signature.points.push_back (p);
    }
    loaded.push_back (std::move (e));
  }
  entries_ = std::move (loaded);
  return Status::success ();
}

Status
SignatureDatabase::save (const std::string& path) const
{
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
  });
}

bool
SignatureDatabase::add (const ShapeEntry& entry)
{
  for (auto& e : entries_)
    if (e.name == entry.name)
    {
      e = entry;
      return false;
    }
  entries_.push_back (entry);
  return true;
}

bool
SignatureDatabase::contains (const std::string& name) const
{
  return std::any_of (entries_.begin (), entries_.end (), [&] (const ShapeEntry& e) { return e.name == name; });
}

std::vector<QueryHit>
SignatureDatabase::query (const Signature& signature, std::size_t k, const pcl::SignatureMatcher& matcher) const
{
  std::vector<QueryHit> hits;
  hits.reserve (entries_.size ());
  for (std::size_t i = 0; i < entries_.size (); ++i)
    if (entries_[i].signature.dimension == signature.dimension)
    {
      const auto m = matcher.match (signature, entries_[i].signature);
      hits.push_back (QueryHit{i, m.similarity, m.score});
    }
  std::stable_sort (hits.begin (), hits.end (), [] (const QueryHit& a, const QueryHit& b) { return a.similarity > b.similarity; });
  if (k > 0 && hits.size () > k)
    hits.resize (k);
  return hits;
}

} // namespace pcl_flowseg

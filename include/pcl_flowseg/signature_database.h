/*
 * pcl_flowseg - a database of shape signatures: a versioned file, incremental additions, queries.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include <pcl_flowseg/signature.h>
#include <pcl_flowseg/signature_matcher.h>
#include <pcl_flowseg/status.h>

#include <string>
#include <vector>

namespace pcl_flowseg {

/** \brief One stored shape. */
struct ShapeEntry
{
  std::string name;  ///< identifies the shape (the file path relative to the database's root)
  std::string label; ///< its class (the name of the folder holding the file)
  Signature signature;
};

/** \brief A query result. */
struct QueryHit
{
  std::size_t entry = 0; ///< index into SignatureDatabase::entries()
  double similarity = 0.0; ///< SignatureMatcher::Result::similarity (the ranking key)
  double score = 0.0;      ///< the paper's raw score
};

/** \brief Signatures of many shapes, kept in one text file:
  *
  *     pcl_flowseg signature database 1
  *     shapes N
  *     shape LABEL DIMENSION UNIT VOLUME SIGNIFICANCE POINTS NAME...
  *     p X Y Z WEIGHT          (POINTS lines)
  *
  * Labels contain no white space; names may. Loading checks the header, the version, every count
  * and number, and reports the line of the first problem. */
class SignatureDatabase
{
public:
  static constexpr int kVersion = 1;

  Status load (const std::string& path);
  /** Writes the whole database (to a temporary file, renamed when complete). */
  Status save (const std::string& path) const;

  /** Adds a shape, replacing a stored one of the same name. \return true when it was new. */
  bool add (const ShapeEntry& entry);
  bool contains (const std::string& name) const;
  const std::vector<ShapeEntry>& entries () const { return entries_; }
  std::size_t size () const { return entries_.size (); }

  /** The \a k most similar stored shapes (all when k = 0), by decreasing similarity; shapes of
    * another dimension are skipped. */
  std::vector<QueryHit> query (const Signature& signature, std::size_t k, const pcl::SignatureMatcher& matcher) const;

private:
  std::vector<ShapeEntry> entries_;
};

} // namespace pcl_flowseg

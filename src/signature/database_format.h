/*
 * pcl_flowseg - the signature database's text format (internal header; the format is documented
 * at SignatureDatabase).
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include <pcl_flowseg/common/status.h>
#include <pcl_flowseg/signature/shape_entry.h>

#include <istream>
#include <ostream>
#include <string>

namespace pcl_flowseg {

/** \brief Lines of a database file, counted for messages. */
struct LineReader
{
  std::istream& in;
  const std::string& path;
  std::size_t number = 0;

  bool next (std::string& line)
  {
    ++number;
    return static_cast<bool> (std::getline (in, line));
  }
  Status error (const std::string& what) const;
};

/** \brief Reads the first two lines (magic and version, "shapes N") into \a count; refuses other
  * versions (the older ones, 1 to kDatabaseVersion - 1, with what they lack and what to do) and
  * counts the rest of the file cannot hold. */
Status
readDatabaseHeader (std::istream& in, const std::string& path, std::size_t& count);

/** \brief Reads shape \a s of \a count: its shape line, p lines (points), q lines (parts with
  * their remoteness), the t, i, s, r and h lines of a described shape (distributions, profiles),
  * c lines (contour) and x lines (inner contexts), then checks it (checkSignature). Messages name
  * the line. */
Status
readShape (LineReader& reader, std::size_t s, std::size_t count, ShapeEntry& e);

/** \brief The header for \a count shapes; sets the precision numbers are written with. */
void
writeDatabaseHeader (std::ostream& out, std::size_t count);

/** \brief One shape in the file's format: doubles with the header's precision, the contour's and
  * the inner contexts' floats with 9 digits; a shape without parts has no description lines. */
void
writeShape (std::ostream& out, const ShapeEntry& e);

} // namespace pcl_flowseg

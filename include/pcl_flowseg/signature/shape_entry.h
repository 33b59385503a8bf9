/*
 * pcl_flowseg - one shape stored in a signature database, and the database file's version.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include <pcl_flowseg/signature/signature.h>

#include <string>

namespace pcl_flowseg {

/** \brief Version of the signature database file this build reads and writes (2: signatures with
  * shape descriptions; 3: the descriptions with inner-distance and thickness profiles; 4: and with
  * the 2D contour; 5: and with the inner-distance contexts; 6: parts placed by their remoteness
  * (inner distance) instead of their straight distance from the centre); 7: and the views for
  * single-view scans). */
constexpr int kDatabaseVersion = 7;

/** \brief One stored shape. */
struct ShapeEntry
{
  std::string name;  ///< identifies the shape (the file path relative to the database's root)
  std::string label; ///< its class (the name of the folder holding the file)
  Signature signature;
};

} // namespace pcl_flowseg

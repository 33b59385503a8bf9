/*
 * pcl_flowseg - the reference of every parameter, as docs/parameters.md shows it: the tables of
 * the segmentation, the signatures and the matching, made from the parameter tables themselves.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include <string>

namespace pcl_flowseg {

/** \brief Markdown: a section per parameter table (flowParameterTable, signatureParameterTable,
  * matchParameterTable), each a table of every parameter with its keyword, option, value type,
  * unit, range, default and description, then its deprecated spellings. */
std::string
parameterReferenceMarkdown ();

/** \brief The lines of docs/parameters.md that enclose parameterReferenceMarkdown(). */
constexpr const char* kParameterReferenceBegin = "<!-- parameter tables: made by parameterReferenceMarkdown (), do not edit -->";
constexpr const char* kParameterReferenceEnd = "<!-- end of the parameter tables -->";

} // namespace pcl_flowseg

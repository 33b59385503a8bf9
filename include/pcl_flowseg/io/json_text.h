/*
 * pcl_flowseg - JSON text of numbers and strings, for the files the module and its apps write.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include <string>

namespace pcl_flowseg {

/** \brief \a value as a JSON number with up to \a precision significant digits; NaN and infinities
  * (which JSON cannot hold) become null. */
std::string
jsonNumber (double value, int precision = 10);

/** \brief \a text as a JSON string literal: quotes, backslashes and control characters escaped. */
std::string
jsonString (const std::string& text);

/** \brief "true" or "false". */
inline const char*
jsonBool (bool value)
{
  return value ? "true" : "false";
}

} // namespace pcl_flowseg

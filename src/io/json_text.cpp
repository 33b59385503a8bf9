/*
 * pcl_flowseg - JSON text of numbers and strings, for the files the module and its apps write.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include <pcl_flowseg/io/json_text.h>

#include <cmath>
#include <cstdio>
#include <iomanip>
#include <sstream>

namespace pcl_flowseg {

std::string
jsonNumber (double value, int precision)
{
  if (!std::isfinite (value))
    return "null";
  std::ostringstream s;
  s << std::setprecision (precision) << value;
  return s.str ();
}

std::string
jsonString (const std::string& text)
{
  std::string s = "\"";
  for (const char c : text)
  {
    switch (c)
    {
      case '"': s += "\\\""; break;
      case '\\': s += "\\\\"; break;
      case '\n': s += "\\n"; break;
      case '\t': s += "\\t"; break;
      default:
        if (static_cast<unsigned char> (c) < 0x20)
        {
          char buf[8];
          std::snprintf (buf, sizeof (buf), "\\u%04x", c);
          s += buf;
        }
        else
          s += c;
    }
  }
  return s + "\"";
}

} // namespace pcl_flowseg

/*
 * pcl_flowseg - parameter values as text, and the parameter tables as Markdown.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include <pcl_flowseg/common/parameter_table.h>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>

namespace pcl_flowseg {

std::string
optionName (const std::string& name)
{
  std::string option = "--" + name;
  for (char& c : option)
    if (c == '_')
      c = '-';
  return option;
}

std::string
numberText (double value)
{
  char text[64];
  for (int digits = 6; digits <= 17; ++digits)
  {
    std::snprintf (text, sizeof text, "%.*g", digits, value);
    if (std::strtod (text, nullptr) == value)
      break;
  }
  return text;
}

Status
parseNumber (const std::string& text, double& value)
{
  char* end = nullptr;
  errno = 0;
  const double v = std::strtod (text.c_str (), &end);
  if (text.empty () || *end != '\0' || !std::isfinite (v))
    return Status::error ("needs a finite number, got '" + text + "'");
  value = v;
  return Status::success ();
}

Status
parseCount (const std::string& text, unsigned long long max, unsigned long long& value)
{
  char* end = nullptr;
  errno = 0;
  const unsigned long long v = std::strtoull (text.c_str (), &end, 10);
  if (text.empty () || text[0] == '-' || text[0] == '+' || *end != '\0' || errno != 0 || v > max)
    return Status::error ("needs a whole number from 0 to " + std::to_string (max) + ", got '" + text + "'");
  value = v;
  return Status::success ();
}

Status
parseSwitch (const std::string& text, bool& value)
{
  if (text != "true" && text != "false")
    return Status::error ("needs true or false, got '" + text + "'");
  value = text == "true";
  return Status::success ();
}

Status
parsePoint (const std::string& text, std::optional<Eigen::Vector3d>& value)
{
  if (text.empty ())
  {
    value.reset ();
    return Status::success ();
  }
  double x = 0, y = 0, z = 0;
  char c1 = 0, c2 = 0, extra = 0;
  if (std::sscanf (text.c_str (), "%lf%c%lf%c%lf%c", &x, &c1, &y, &c2, &z, &extra) != 5 || c1 != ',' || c2 != ',' ||
      !std::isfinite (x) || !std::isfinite (y) || !std::isfinite (z))
    return Status::error ("needs X,Y,Z (three finite numbers), got '" + text + "'");
  value = Eigen::Vector3d (x, y, z);
  return Status::success ();
}

std::string
pointText (const std::optional<Eigen::Vector3d>& value)
{
  if (!value)
    return std::string ();
  return numberText (value->x ()) + "," + numberText (value->y ()) + "," + numberText (value->z ());
}

Status
parseWeights (const std::string& text, const std::vector<std::string>& names, std::vector<double>& values)
{
  std::vector<double> parsed = values;
  std::stringstream in (text);
  for (std::string item; std::getline (in, item, ',');)
  {
    const std::size_t equals = item.find ('=');
    std::size_t k = 0;
    while (equals != std::string::npos && k < names.size () && names[k] != item.substr (0, equals))
      ++k;
    double v = 0.0;
    if (equals == std::string::npos || k == names.size () || !parseNumber (item.substr (equals + 1), v) || v < 0.0)
    {
      std::string all;
      for (const auto& n : names)
        all += (all.empty () ? "" : ", ") + n;
      return Status::error ("needs NAME=WEIGHT,... with weights >= 0 and names from " + all + ", got '" + item + "'");
    }
    parsed[k] = v;
  }
  values = parsed;
  return Status::success ();
}

std::string
weightsText (const std::vector<std::string>& names, const std::vector<double>& values)
{
  std::string text;
  for (std::size_t k = 0; k < names.size () && k < values.size (); ++k)
    text += (text.empty () ? "" : ",") + names[k] + "=" + numberText (values[k]);
  return text;
}

std::string
currentValueSpelling (const ParameterInfo& info, const std::string& text, std::string* warning)
{
  for (const auto& [old, current] : info.old_values)
    if (text == old)
    {
      if (warning)
        *warning = info.name + " = '" + old + "' is deprecated: write '" + current + "'";
      return current;
    }
  return text;
}

} // namespace pcl_flowseg

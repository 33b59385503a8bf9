/*
 * pcl_flowseg - the parameter tables as Markdown (docs/parameters.md is made from them).
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include <pcl_flowseg/common/parameter_table.h>

namespace pcl_flowseg {

namespace {

std::string
joined (const std::vector<std::string>& items, const std::string& separator)
{
  std::string out;
  for (const auto& item : items)
    out += (out.empty () ? "" : separator) + item;
  return out;
}

/** The option column: the short option, the long one, and for a switch its negation. */
std::string
optionCell (const ParameterInfo& info)
{
  std::string cell = info.short_option.empty () ? "" : "`" + info.short_option + "`, ";
  cell += "`" + optionName (info.name) + "`";
  if (info.type == ParameterType::Switch)
    cell += ", `--no-" + optionName (info.name).substr (2) + "`";
  return cell;
}

std::string
typeCell (const ParameterInfo& info)
{
  switch (info.type)
  {
  case ParameterType::Number:
    return "number";
  case ParameterType::Count:
    return "whole number";
  case ParameterType::Switch:
    return "switch";
  case ParameterType::Choice:
    return joined (info.choices, " \\| ");
  case ParameterType::Point:
    return "X,Y,Z";
  case ParameterType::Weights:
    return "NAME=WEIGHT,... (" + joined (info.choices, ", ") + ")";
  }
  return "";
}

} // namespace

std::string
parameterMarkdownHeader ()
{
  return "| keyword | option | value | unit | range | default | description |\n"
         "|---|---|---|---|---|---|---|\n";
}

std::string
parameterMarkdownRow (const ParameterInfo& info, const std::string& default_text)
{
  const std::string shown = default_text.empty () ? "none" : "`" + default_text + "`";
  return "| `" + info.name + "` | " + optionCell (info) + " | " + typeCell (info) + " | " + info.unit + " | " +
         info.range + " | " + shown + " | " + info.description + " |\n";
}

std::string
oldSpellingsMarkdown (const std::vector<const ParameterInfo*>& infos)
{
  std::string out;
  for (const ParameterInfo* info : infos)
  {
    std::vector<std::string> old;
    for (const auto& name : info->old_names)
      old.push_back ("`" + name + "` / `" + optionName (name) + "`");
    for (const auto& [was, is] : info->old_values)
      old.push_back ("value `" + was + "` (now `" + is + "`)");
    if (!old.empty ())
      out += "- `" + info->name + "`: " + joined (old, ", ") + "\n";
  }
  return out.empty () ? out : "\nDeprecated spellings, still accepted with a warning:\n\n" + out;
}

} // namespace pcl_flowseg

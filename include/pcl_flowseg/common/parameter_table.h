/*
 * pcl_flowseg - a table that describes every parameter of a parameter type once: its name (the
 * apps' option and Python's keyword), type, unit, range and description, and reads and writes its
 * value as text. The apps' options, the Python keywords and docs/parameters.md are made from it.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include <pcl_flowseg/common/status.h>

#include <Eigen/Core>

#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace pcl_flowseg {

/** \brief How a parameter's value is spelled. */
enum class ParameterType
{
  Number, ///< a finite real number ("0.5")
  Count,  ///< a whole number >= 0 ("6")
  Switch, ///< on or off: "true" / "false"; the apps' --NAME / --no-NAME, Python's True / False
  Choice, ///< one of ParameterInfo::choices
  Point,  ///< three finite numbers "X,Y,Z", or "" for none
  Weights ///< named non-negative numbers "name=value,name=value,..." (names in ParameterInfo::choices)
};

/** \brief What is said about a parameter, everywhere the same. */
struct ParameterInfo
{
  /** Python's keyword; the apps' long option is "--" and this with '_' as '-'. */
  std::string name;
  std::string short_option; ///< "-r", or "" for none
  std::string group;        ///< the heading it is listed under ("merge", "preparation", ...)
  ParameterType type = ParameterType::Number;
  std::string unit;         ///< "" when dimensionless
  std::string range;        ///< the values it takes, for a person ("finite, > 0")
  std::string description;  ///< one line: what it does
  std::vector<std::string> choices = {}; ///< Choice: the value names; Weights: the weight names
  /** Earlier names of the parameter, still accepted with a deprecation warning. */
  std::vector<std::string> old_names = {};
  /** Earlier spellings of values (old, current), still accepted with a deprecation warning. */
  std::vector<std::pair<std::string, std::string>> old_values = {};
};

/** \brief One parameter of the parameter type \a Params: its description and its value as text. */
template <class Params>
struct ParameterSpec
{
  ParameterInfo info;
  /** The value in \a params as text (ParameterType says how it is spelled). */
  std::function<std::string (const Params&)> get;
  /** Parses \a text into \a params; an error says why the text is no value of this type. Ranges are
    * checked by the table's check, not here. */
  std::function<Status (Params&, const std::string&)> set;
};

/** \brief Every parameter of \a Params and the library's check of a whole \a Params. */
template <class Params>
struct ParameterTable
{
  std::string title; ///< what the type is ("segmentation", "matching", ...)
  std::vector<ParameterSpec<Params>> specs;
  std::function<Status (const Params&)> check;
};

/** \brief The long option of a parameter name: "--" + name with '_' as '-'. */
std::string
optionName (const std::string& name);

/** \brief \a value as the shortest text that reads back as the same double. */
std::string
numberText (double value);

/** \brief Parsers of the value types; each reports what it wanted in its message. */
Status
parseNumber (const std::string& text, double& value);
Status
parseCount (const std::string& text, unsigned long long max, unsigned long long& value);
Status
parseSwitch (const std::string& text, bool& value);
Status
parsePoint (const std::string& text, std::optional<Eigen::Vector3d>& value);
/** \brief "name=value,..." with names from \a names; names not given keep their value in \a values. */
Status
parseWeights (const std::string& text, const std::vector<std::string>& names, std::vector<double>& values);
std::string
pointText (const std::optional<Eigen::Vector3d>& value);
std::string
weightsText (const std::vector<std::string>& names, const std::vector<double>& values);

/** \brief The parameter called \a name, or one of its old names (then \a old_name is set); nullptr
  * when the table has none of that name. */
template <class Params>
const ParameterSpec<Params>*
findParameter (const ParameterTable<Params>& table, const std::string& name, bool* old_name = nullptr)
{
  for (const auto& spec : table.specs)
  {
    if (spec.info.name == name)
      return &spec;
    for (const auto& old : spec.info.old_names)
      if (old == name)
      {
        if (old_name)
          *old_name = true;
        return &spec;
      }
  }
  return nullptr;
}

/** \brief The current spelling of \a text for \a info (an old value spelling is translated and
  * noted in \a warning). */
std::string
currentValueSpelling (const ParameterInfo& info, const std::string& text, std::string* warning);

/** \brief Sets the parameter \a spec of \a params from \a text, checked by the table's check: on
  * any error \a params is unchanged and the message names the parameter (the table's check
  * names it in its own words). An old value spelling
  * is accepted and noted in \a warning (when given). */
template <class Params>
Status
setParameter (const ParameterTable<Params>& table, const ParameterSpec<Params>& spec, Params& params,
              const std::string& text, std::string* warning = nullptr)
{
  Params changed = params;
  if (const Status parsed = spec.set (changed, currentValueSpelling (spec.info, text, warning)); !parsed)
    return Status::error (spec.info.name + " " + parsed.message);
  if (table.check)
    if (const Status checked = table.check (changed); !checked)
      return checked;
  params = changed;
  return Status::success ();
}

/** \brief The table in Markdown: one row per parameter (name, option, type, unit, range, default
  * taken from \a defaults, description), the old spellings after it. */
template <class Params>
std::string
parameterTableMarkdown (const ParameterTable<Params>& table, const Params& defaults = Params ());

/** \brief One Markdown row of \a info with the default \a default_text (for parameterTableMarkdown). */
std::string
parameterMarkdownRow (const ParameterInfo& info, const std::string& default_text);
/** \brief The Markdown table's header. */
std::string
parameterMarkdownHeader ();
/** \brief The old spellings of the parameters of \a infos, as a Markdown list ("" when none). */
std::string
oldSpellingsMarkdown (const std::vector<const ParameterInfo*>& infos);

template <class Params>
std::string
parameterTableMarkdown (const ParameterTable<Params>& table, const Params& defaults)
{
  std::string out = parameterMarkdownHeader ();
  std::vector<const ParameterInfo*> infos;
  for (const auto& spec : table.specs)
  {
    out += parameterMarkdownRow (spec.info, spec.get (defaults));
    infos.push_back (&spec.info);
  }
  return out + oldSpellingsMarkdown (infos);
}

} // namespace pcl_flowseg

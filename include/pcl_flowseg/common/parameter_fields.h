/*
 * pcl_flowseg - building a parameter table's rows from the fields of a parameter type: each
 * builder binds a ParameterInfo to a field and reads and writes it as text of its type.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include <pcl_flowseg/common/parameter_table.h>

#include <string>
#include <utility>
#include <vector>

namespace pcl_flowseg {

/** \brief The field of a parameter type a table row reads and writes. */
template <class Params, class T>
using ParameterField = T& (*) (Params&);

/** \brief A row of a finite real number. */
template <class Params>
ParameterSpec<Params>
numberField (ParameterInfo info, ParameterField<Params, double> field)
{
  info.type = ParameterType::Number;
  return {std::move (info), [field] (const Params& p) { Params c = p; return numberText (field (c)); },
          [field] (Params& p, const std::string& text) {
            double v = 0.0;
            const Status s = parseNumber (text, v);
            if (s)
              field (p) = v;
            return s;
          }};
}

/** \brief A row of a whole number from 0 to \a max. */
template <class Params, class T>
ParameterSpec<Params>
countField (ParameterInfo info, ParameterField<Params, T> field, unsigned long long max)
{
  info.type = ParameterType::Count;
  return {std::move (info), [field] (const Params& p) { Params c = p; return std::to_string (field (c)); },
          [field, max] (Params& p, const std::string& text) {
            unsigned long long v = 0;
            const Status s = parseCount (text, max, v);
            if (s)
              field (p) = static_cast<T> (v);
            return s;
          }};
}

/** \brief A row of a switch (true / false). */
template <class Params>
ParameterSpec<Params>
switchField (ParameterInfo info, ParameterField<Params, bool> field)
{
  info.type = ParameterType::Switch;
  return {std::move (info), [field] (const Params& p) { Params c = p; return std::string (field (c) ? "true" : "false"); },
          [field] (Params& p, const std::string& text) {
            bool v = false;
            const Status s = parseSwitch (text, v);
            if (s)
              field (p) = v;
            return s;
          }};
}

/** \brief A row of an optional point (X,Y,Z, or none). */
template <class Params>
ParameterSpec<Params>
pointField (ParameterInfo info, ParameterField<Params, std::optional<Eigen::Vector3d>> field)
{
  info.type = ParameterType::Point;
  return {std::move (info), [field] (const Params& p) { Params c = p; return pointText (field (c)); },
          [field] (Params& p, const std::string& text) { return parsePoint (text, field (p)); }};
}

/** \brief A row of an enumeration, each value under the name \a choices gives it. */
template <class Params, class Enum>
ParameterSpec<Params>
choiceField (ParameterInfo info, ParameterField<Params, Enum> field, std::vector<std::pair<std::string, Enum>> choices)
{
  info.type = ParameterType::Choice;
  info.choices.clear ();
  for (const auto& c : choices)
    info.choices.push_back (c.first);
  return {std::move (info),
          [field, choices] (const Params& p) {
            Params c = p;
            for (const auto& choice : choices)
              if (choice.second == field (c))
                return choice.first;
            return std::string ("unknown");
          },
          [field, choices] (Params& p, const std::string& text) {
            std::string names;
            for (const auto& choice : choices)
            {
              if (choice.first == text)
              {
                field (p) = choice.second;
                return Status::success ();
              }
              names += (names.empty () ? "" : ", ") + choice.first;
            }
            return Status::error ("needs one of " + names + ", got '" + text + "'");
          }};
}

} // namespace pcl_flowseg

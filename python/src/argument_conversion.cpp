/*
 * pcl_flowseg Python bindings - keyword values to parameters, strided arrays to points.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include "argument_conversion.h"

#include <pcl_flowseg/common/flow_parameter_table.h>
#include <pcl_flowseg/signature/match_parameter_table.h>
#include <pcl_flowseg/signature/signature.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <optional>
#include <set>

namespace pcl_flowseg_python {
namespace {

Conversion
badValue (const std::string& message)
{
  return Conversion{ArgumentError::BadValue, message};
}

const char*
typeName (const ArgumentValue& value)
{
  static const char* const names[] = {"None", "bool", "int", "float", "str", "sequence"};
  return names[value.index ()];
}

/** A real number: float, or int (bool is not a number here, as a flag given for a number is a slip). */
Conversion
toNumber (const std::string& name, const ArgumentValue& value, double& out)
{
  if (const auto* d = std::get_if<double> (&value))
    out = *d;
  else if (const auto* i = std::get_if<std::int64_t> (&value))
    out = static_cast<double> (*i);
  else
    return badValue (name + ": needs a number, got " + typeName (value));
  if (!std::isfinite (out))
    return badValue (name + ": needs a finite number");
  return {};
}

/** A whole number in [low, high]. */
Conversion
toCount (const std::string& name, const ArgumentValue& value, std::int64_t low, std::int64_t high, std::int64_t& out)
{
  const auto* i = std::get_if<std::int64_t> (&value);
  if (!i)
    return badValue (name + ": needs a whole number, got " + typeName (value));
  if (*i < low || *i > high)
    return badValue (name + ": needs a whole number from " + std::to_string (low) + " to " + std::to_string (high) +
                     ", got " + std::to_string (*i));
  out = *i;
  return {};
}

Conversion
toFlag (const std::string& name, const ArgumentValue& value, bool& out)
{
  const auto* b = std::get_if<bool> (&value);
  if (!b)
    return badValue (name + ": needs True or False, got " + typeName (value));
  out = *b;
  return {};
}

Conversion
toViewpoint (const std::string& name, const ArgumentValue& value, std::optional<Eigen::Vector3d>& out)
{
  if (std::holds_alternative<std::monostate> (value))
  {
    out.reset ();
    return {};
  }
  const auto* v = std::get_if<std::vector<double>> (&value);
  if (!v || v->size () != 3)
    return badValue (name + ": needs None or three numbers (x, y, z)");
  for (double c : *v)
    if (!std::isfinite (c))
      return badValue (name + ": needs finite coordinates");
  out = Eigen::Vector3d ((*v)[0], (*v)[1], (*v)[2]);
  return {};
}

/** \a value as the text the parameter table reads for a row of \a info's type, or why it cannot be one. */
Conversion
toText (const pcl_flowseg::ParameterInfo& info, const ArgumentValue& value, std::string& text)
{
  using pcl_flowseg::ParameterType;
  const std::string& name = info.name;
  switch (info.type)
  {
  case ParameterType::Number:
  {
    double v = 0.0;
    const Conversion r = toNumber (name, value, v);
    text = pcl_flowseg::numberText (v);
    return r;
  }
  case ParameterType::Count:
  {
    std::int64_t v = 0;
    const Conversion r = toCount (name, value, 0, std::numeric_limits<std::int64_t>::max (), v);
    text = std::to_string (v);
    return r;
  }
  case ParameterType::Switch:
  {
    bool v = false;
    const Conversion r = toFlag (name, value, v);
    text = v ? "true" : "false";
    return r;
  }
  case ParameterType::Point:
  {
    std::optional<Eigen::Vector3d> v;
    const Conversion r = toViewpoint (name, value, v);
    text = pcl_flowseg::pointText (v);
    return r;
  }
  case ParameterType::Choice:
  case ParameterType::Weights:
    if (const auto* s = std::get_if<std::string> (&value))
    {
      text = *s;
      return {};
    }
    return badValue (name + ": needs a str, got " + typeName (value));
  }
  return badValue (name + ": unknown parameter type");
}

/** The table row's text \a text as Python's value for a row of \a info's type. */
ArgumentValue
fromText (const pcl_flowseg::ParameterInfo& info, const std::string& text)
{
  using pcl_flowseg::ParameterType;
  switch (info.type)
  {
  case ParameterType::Number:
    return std::strtod (text.c_str (), nullptr);
  case ParameterType::Count:
    return static_cast<std::int64_t> (std::strtoll (text.c_str (), nullptr, 10));
  case ParameterType::Switch:
    return text == "true";
  case ParameterType::Point:
  {
    std::optional<Eigen::Vector3d> v;
    pcl_flowseg::parsePoint (text, v);
    if (!v)
      return std::monostate ();
    return std::vector<double>{v->x (), v->y (), v->z ()};
  }
  case ParameterType::Choice:
  case ParameterType::Weights:
    break;
  }
  return text;
}

/** Sets the row \a spec of \a table in \a params from Python's \a value; an old spelling of the
  * name (\a old_name) or of the value adds a deprecation warning to \a warnings. */
template <class Params>
Conversion
setFromValue (const pcl_flowseg::ParameterTable<Params>& table, const pcl_flowseg::ParameterSpec<Params>& spec,
              const std::string& given_name, const ArgumentValue& value, Params& params, std::vector<std::string>& warnings)
{
  std::string text, warning;
  if (const Conversion r = toText (spec.info, value, text); !r)
    return r;
  if (given_name != spec.info.name)
    warnings.push_back ("keyword '" + given_name + "' is deprecated: use '" + spec.info.name + "'");
  const pcl_flowseg::Status s = pcl_flowseg::setParameter (table, spec, params, text, &warning);
  if (!warning.empty ())
    warnings.push_back (warning);
  return s ? Conversion{} : badValue (s.message);
}

/** The keyword form of every row of \a table in \a params. */
template <class Params>
void
appendArguments (const pcl_flowseg::ParameterTable<Params>& table, const Params& params, Arguments& arguments)
{
  for (const auto& spec : table.specs)
    arguments.emplace_back (spec.info.name, fromText (spec.info, spec.get (params)));
}

/** The group a row of the signature table belongs to. */
ArgumentGroups
signatureGroup (const pcl_flowseg::ParameterInfo& info)
{
  return info.group == "input" ? kShapeInputArguments : kSignificanceArgument;
}

/** The library's own checks of what the keywords produced, for the groups in use. */
Conversion
checkGroups (unsigned groups, const CallParameters& call, const pcl_flowseg::MatchParameters& match)
{
  pcl_flowseg::Status s;
  if ((groups & kFlowArguments) && !(s = pcl_flowseg::checkParameters (call.flow)))
    return badValue (s.message);
  if ((groups & (kSignificanceArgument | kShapeInputArguments)) && !(s = pcl_flowseg::checkSignatureParameters (call)))
    return badValue (s.message);
  if ((groups & kMatchArguments) && !(s = pcl_flowseg::checkMatchParameters (match)))
    return badValue (s.message);
  if (call.input.use_sensor_origin && call.flow.interior.viewpoint)
    return badValue ("viewpoint and use_sensor_origin exclude each other: give one");
  return {};
}

} // namespace

namespace {

/** Applies the keyword \a name of the flow, signature or match table, when \a groups take it: true when
  * one of the tables has it (\a result then says how it went, \a canonical names the row). */
bool
applyTableKeyword (const std::string& name, const ArgumentValue& value, unsigned groups, CallParameters& call,
                   pcl_flowseg::MatchParameters& match, Conversion& result, std::string& canonical)
{
  std::vector<std::string> warnings;
  if (const auto* spec = pcl_flowseg::findParameter (pcl_flowseg::flowParameterTable (), name))
  {
    canonical = spec->info.name;
    result = (groups & kFlowArguments)
                 ? setFromValue (pcl_flowseg::flowParameterTable (), *spec, name, value, call.flow, warnings)
                 : Conversion{ArgumentError::UnknownName, "unexpected keyword argument '" + name + "'"};
  }
  else if (const auto* spec = pcl_flowseg::findParameter (pcl_flowseg::signatureParameterTable (), name))
  {
    canonical = spec->info.name;
    pcl_flowseg::SignatureParameters& signature = call;
    result = (groups & signatureGroup (spec->info))
                 ? setFromValue (pcl_flowseg::signatureParameterTable (), *spec, name, value, signature, warnings)
                 : Conversion{ArgumentError::UnknownName, "unexpected keyword argument '" + name + "'"};
  }
  else if (const auto* spec = pcl_flowseg::findParameter (pcl_flowseg::matchParameterTable (), name))
  {
    canonical = spec->info.name;
    result = (groups & kMatchArguments)
                 ? setFromValue (pcl_flowseg::matchParameterTable (), *spec, name, value, match, warnings)
                 : Conversion{ArgumentError::UnknownName, "unexpected keyword argument '" + name + "'"};
  }
  else
    return false;
  result.warnings = warnings;
  return true;
}

} // namespace

Conversion
applyArguments (const Arguments& arguments, unsigned groups, CallParameters& call, pcl_flowseg::MatchParameters& match)
{
  std::set<std::string> seen;
  std::vector<std::string> warnings;
  for (const auto& [name, value] : arguments)
  {
    Conversion r;
    std::string canonical = name;
    if (!applyTableKeyword (name, value, groups, call, match, r, canonical))
      return Conversion{ArgumentError::UnknownName, "unexpected keyword argument '" + name + "'"};
    if (!seen.insert (canonical).second)
      return Conversion{ArgumentError::UnknownName, "keyword argument '" + canonical + "' given twice"};
    if (!r)
      return r;
    warnings.insert (warnings.end (), r.warnings.begin (), r.warnings.end ());
  }
  Conversion checked = checkGroups (groups, call, match);
  checked.warnings = warnings;
  return checked;
}

Arguments
flowArguments (const pcl_flowseg::FlowParameters& p)
{
  Arguments a;
  appendArguments (pcl_flowseg::flowParameterTable (), p, a);
  return a;
}

Arguments
signatureArguments (const pcl_flowseg::SignatureParameters& p)
{
  Arguments a;
  appendArguments (pcl_flowseg::signatureParameterTable (), p, a);
  return a;
}

Arguments
matchArguments (const pcl_flowseg::MatchParameters& m)
{
  Arguments a;
  appendArguments (pcl_flowseg::matchParameterTable (), m, a);
  return a;
}

namespace {

/** The lowest and one past the highest byte an array's elements occupy, relative to its data. */
bool
byteExtent (const ArrayView& a, std::int64_t& low, std::int64_t& high)
{
  low = 0;
  high = static_cast<std::int64_t> (a.item_size);
  for (std::size_t axis = 0; axis < a.shape.size (); ++axis)
  {
    if (a.shape[axis] == 0)
      return true;
    const long double reach = static_cast<long double> (a.shape[axis] - 1) * a.strides[axis];
    if (std::fabs (reach) > 1e18L)
      return false;
    (reach < 0 ? low : high) += static_cast<std::int64_t> (reach);
  }
  return true;
}

template <typename Real>
void
copyPoints (const ArrayView& a, std::vector<Eigen::Vector3d>& points)
{
  const auto* base = static_cast<const unsigned char*> (a.data);
  const std::int64_t n = a.shape[0], columns = a.shape[1];
  points.assign (static_cast<std::size_t> (n), Eigen::Vector3d::Zero ());
  for (std::int64_t i = 0; i < n; ++i)
    for (std::int64_t c = 0; c < columns; ++c)
    {
      Real value;
      std::memcpy (&value, base + i * a.strides[0] + c * a.strides[1], sizeof (Real));
      points[static_cast<std::size_t> (i)][c] = static_cast<double> (value);
    }
}

} // namespace

Conversion
pointsFromArray (const ArrayView& a, const std::string& what, bool require_finite, std::size_t buffer_bytes,
                 std::vector<Eigen::Vector3d>& points)
{
  points.clear ();
  if (a.shape.size () != 2 || a.strides.size () != 2 || a.shape[0] < 0 || (a.shape[1] != 2 && a.shape[1] != 3))
  {
    std::string shape;
    for (std::size_t i = 0; i < a.shape.size (); ++i)
      shape += (i ? ", " : "") + std::to_string (a.shape[i]);
    return badValue (what + ": needs an array of shape (n, 2) or (n, 3), got shape (" + shape + ")");
  }
  if (a.kind != 'f' || (a.item_size != 4 && a.item_size != 8))
    return badValue (what + ": needs float32 or float64 values (numpy dtype kind 'f'), got kind '" + std::string (1, a.kind) +
                     "' of " + std::to_string (a.item_size) + " bytes");
  std::int64_t low = 0, high = 0;
  if (a.shape[0] > 0 && (!a.data || !byteExtent (a, low, high) ||
                         (buffer_bytes && (low < 0 || high > static_cast<std::int64_t> (buffer_bytes)))))
    return badValue (what + ": the array's strides leave its buffer");
  if (a.item_size == 4)
    copyPoints<float> (a, points);
  else
    copyPoints<double> (a, points);
  if (require_finite)
    for (std::size_t i = 0; i < points.size (); ++i)
      if (!points[i].allFinite ())
      {
        points.clear ();
        return badValue (what + ": row " + std::to_string (i) + " is not finite");
      }
  return {};
}

} // namespace pcl_flowseg_python

/*
 * pcl_flowseg Python bindings - keyword values to parameters, strided arrays to points.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include "argument_conversion.h"

#include <pcl_flowseg/signature/signature.h>

#include <cmath>
#include <cstring>
#include <functional>
#include <limits>
#include <map>
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

/** One of \a choices by name; the enumeration's value is the index. */
Conversion
toChoice (const std::string& name, const ArgumentValue& value, const std::vector<std::string>& choices, std::size_t& out)
{
  const auto* s = std::get_if<std::string> (&value);
  std::string all;
  for (const auto& c : choices)
    all += (all.empty () ? "'" : ", '") + c + "'";
  if (s)
    for (std::size_t i = 0; i < choices.size (); ++i)
      if (*s == choices[i])
      {
        out = i;
        return {};
      }
  return badValue (name + ": needs one of " + all);
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

using Setter = std::function<Conversion (const std::string&, const ArgumentValue&, CallParameters&, pcl_flowseg::MatchParameters&)>;

struct Keyword
{
  ArgumentGroups group;
  Setter set;
};

Setter
numberSetter (double CallParameters::*group_field)
{
  return [group_field] (const std::string& n, const ArgumentValue& v, CallParameters& c, pcl_flowseg::MatchParameters&) {
    return toNumber (n, v, c.*group_field);
  };
}

template <typename Group>
Setter
flowNumber (Group pcl_flowseg::FlowParameters::*group, double Group::*field)
{
  return [group, field] (const std::string& n, const ArgumentValue& v, CallParameters& c, pcl_flowseg::MatchParameters&) {
    return toNumber (n, v, (c.flow.*group).*field);
  };
}

const std::vector<std::string> kDimensionNames = {"automatic", "", "planar", "spatial"};
/** The names of the Automatic / Off / Always modes (Denoising, OutlierRemoval, Smoothing), in enum order. */
const std::vector<std::string> kModeNames = {"automatic", "off", "always"};
const std::vector<std::string> kFeatureNames = {"interior", "exterior", "both"};

/** A keyword naming one of \a names, stored in \a field of \a group as the enum of that index. */
template <typename Group, typename Enum>
Setter
flowChoice (Group pcl_flowseg::FlowParameters::*group, Enum Group::*field, const std::vector<std::string>& names)
{
  return [group, field, &names] (const std::string& n, const ArgumentValue& v, CallParameters& c, pcl_flowseg::MatchParameters&) {
    std::size_t i = 0;
    const Conversion r = toChoice (n, v, names, i);
    (c.flow.*group).*field = static_cast<Enum> (i);
    return r;
  };
}

/** The flow keywords: every FlowParameters field under its own name. */
void
addFlowKeywords (std::map<std::string, Keyword>& k)
{
  using FP = pcl_flowseg::FlowParameters;
  using MP = pcl_flowseg::MatchParameters;
  k["dimension"] = {kFlowArguments, [] (const std::string& n, const ArgumentValue& v, CallParameters& c, MP&) {
                      std::size_t i = 0;
                      const Conversion r = toChoice (n, v, {"automatic", "planar", "spatial"}, i);
                      if (r)
                        c.flow.preparation.dimension = i == 0 ? pcl_flowseg::DimensionMode::Automatic
                                                       : i == 1 ? pcl_flowseg::DimensionMode::Planar
                                                                : pcl_flowseg::DimensionMode::Spatial;
                      return r;
                    }};
  k["planar_tolerance"] = {kFlowArguments, flowNumber (&FP::preparation, &pcl_flowseg::PreparationParameters::planar_tolerance)};
  k["outliers"] = {kFlowArguments, flowChoice (&FP::preparation, &pcl_flowseg::PreparationParameters::outliers, kModeNames)};
  k["smoothing"] = {kFlowArguments, flowChoice (&FP::preparation, &pcl_flowseg::PreparationParameters::smoothing, kModeNames)};
  k["smoothing_passes"] = {kFlowArguments, [] (const std::string& n, const ArgumentValue& v, CallParameters& c, MP&) {
                             std::int64_t passes = 0;
                             const Conversion r = toCount (n, v, 1, pcl_flowseg::kMaxSmoothingPasses, passes);
                             c.flow.preparation.smoothing_passes = static_cast<unsigned> (passes);
                             return r;
                           }};
  k["rho"] = {kFlowArguments, flowNumber (&FP::merge, &pcl_flowseg::MergeParameters::rho)};
  k["sampling_tolerance"] = {kFlowArguments, flowNumber (&FP::merge, &pcl_flowseg::MergeParameters::sampling_tolerance)};
  k["stump_ratio"] = {kFlowArguments, flowNumber (&FP::merge, &pcl_flowseg::MergeParameters::stump_ratio)};
  k["compact_rho"] = {kFlowArguments, flowNumber (&FP::merge, &pcl_flowseg::MergeParameters::compact_rho)};
  k["compact_size"] = {kFlowArguments, flowNumber (&FP::merge, &pcl_flowseg::MergeParameters::compact_size)};
  k["min_part_share"] = {kFlowArguments, flowNumber (&FP::merge, &pcl_flowseg::MergeParameters::min_part_share)};
  k["single_view_min_part_share"] = {kFlowArguments,
                                     flowNumber (&FP::merge, &pcl_flowseg::MergeParameters::single_view_min_part_share)};
  k["separate"] = {kFlowArguments, [] (const std::string& n, const ArgumentValue& v, CallParameters& c, MP&) {
                     return toFlag (n, v, c.flow.interior.separate);
                   }};
  k["manifold_repair"] = {kFlowArguments, [] (const std::string& n, const ArgumentValue& v, CallParameters& c, MP&) {
                            return toFlag (n, v, c.flow.interior.manifold_repair);
                          }};
  k["hidden_side"] = {kFlowArguments, [] (const std::string& n, const ArgumentValue& v, CallParameters& c, MP&) {
                        return toFlag (n, v, c.flow.interior.hidden_side);
                      }};
  k["denoising"] = {kFlowArguments, flowChoice (&FP::interior, &pcl_flowseg::InteriorParameters::denoising, kModeNames)};
  k["viewpoint"] = {kFlowArguments, [] (const std::string& n, const ArgumentValue& v, CallParameters& c, MP&) {
                      return toViewpoint (n, v, c.flow.interior.viewpoint);
                    }};
  k["features"] = {kFlowArguments, [] (const std::string& n, const ArgumentValue& v, CallParameters& c, MP&) {
                     std::size_t i = 0;
                     const Conversion r = toChoice (n, v, kFeatureNames, i);
                     c.flow.features = static_cast<pcl_flowseg::FeatureSide> (i);
                     return r;
                   }};
  k["threads"] = {kFlowArguments, [] (const std::string& n, const ArgumentValue& v, CallParameters& c, MP&) {
                    std::int64_t t = 0;
                    const Conversion r = toCount (n, v, 0, std::numeric_limits<unsigned>::max (), t);
                    c.flow.execution.threads = static_cast<unsigned> (t);
                    return r;
                  }};
  k["memory_limit"] = {kFlowArguments, [] (const std::string& n, const ArgumentValue& v, CallParameters& c, MP&) {
                         std::int64_t bytes = 0;
                         const Conversion r = toCount (n, v, 0, std::numeric_limits<std::int64_t>::max (), bytes);
                         c.flow.execution.memory_limit = static_cast<std::size_t> (bytes);
                         return r;
                       }};
}

/** Significance, shape input and matching keywords. */
void
addOtherKeywords (std::map<std::string, Keyword>& k)
{
  using MP = pcl_flowseg::MatchParameters;
  k["significance"] = {kSignificanceArgument, numberSetter (&CallParameters::significance)};
  k["mesh_points"] = {kShapeInputArguments, [] (const std::string& n, const ArgumentValue& v, CallParameters& c, MP&) {
                        std::int64_t count = 0;
                        const Conversion r = toCount (n, v, 0, std::numeric_limits<std::int64_t>::max (), count);
                        c.input.mesh_points = static_cast<std::size_t> (count);
                        return r;
                      }};
  k["seed"] = {kShapeInputArguments, [] (const std::string& n, const ArgumentValue& v, CallParameters& c, MP&) {
                 std::int64_t seed = 0;
                 const Conversion r = toCount (n, v, 0, std::numeric_limits<std::uint32_t>::max (), seed);
                 c.input.seed = static_cast<std::uint32_t> (seed);
                 return r;
               }};
  k["method"] = {kMatchArguments, [] (const std::string& n, const ArgumentValue& v, CallParameters&, MP& m) {
                   std::vector<std::string> names;
                   for (pcl_flowseg::MatchMethod method : pcl_flowseg::kMatchMethods)
                     names.emplace_back (pcl_flowseg::matchMethodName (method));
                   std::size_t i = 0;
                   const Conversion r = toChoice (n, v, names, i);
                   m.method = pcl_flowseg::kMatchMethods[i];
                   return r;
                 }};
  k["threshold"] = {kMatchArguments, [] (const std::string& n, const ArgumentValue& v, CallParameters&, MP& m) {
                      return toNumber (n, v, m.paper.threshold);
                    }};
  k["allow_mirror"] = {kMatchArguments, [] (const std::string& n, const ArgumentValue& v, CallParameters&, MP& m) {
                         return toFlag (n, v, m.paper.allow_mirror);
                       }};
  k["alignment_points"] = {kMatchArguments, [] (const std::string& n, const ArgumentValue& v, CallParameters&, MP& m) {
                             std::int64_t count = 0;
                             const Conversion r = toCount (n, v, std::numeric_limits<int>::min (), std::numeric_limits<int>::max (), count);
                             m.paper.alignment_points = static_cast<int> (count);
                             return r;
                           }};
}

const std::map<std::string, Keyword>&
keywords ()
{
  static const std::map<std::string, Keyword> table = [] {
    std::map<std::string, Keyword> k;
    addFlowKeywords (k);
    addOtherKeywords (k);
    return k;
  }();
  return table;
}

/** The library's own checks of what the keywords produced, for the groups in use. */
Conversion
checkGroups (unsigned groups, const CallParameters& call, const pcl_flowseg::MatchParameters& match)
{
  pcl_flowseg::Status s;
  if ((groups & kFlowArguments) && !(s = pcl_flowseg::checkParameters (call.flow)))
    return badValue (s.message);
  if ((groups & kSignificanceArgument) && !(s = pcl_flowseg::checkSignificance (call.significance)))
    return badValue (s.message);
  if ((groups & kShapeInputArguments) && !(s = pcl_flowseg::checkShapeInputOptions (call.input)))
    return badValue (s.message);
  if ((groups & kMatchArguments) && !(s = pcl_flowseg::checkMatchParameters (match)))
    return badValue (s.message);
  return {};
}

} // namespace

Conversion
applyArguments (const Arguments& arguments, unsigned groups, CallParameters& call, pcl_flowseg::MatchParameters& match)
{
  std::set<std::string> seen;
  for (const auto& [name, value] : arguments)
  {
    const auto found = keywords ().find (name);
    if (found == keywords ().end () || !(groups & found->second.group))
      return Conversion{ArgumentError::UnknownName, "unexpected keyword argument '" + name + "'"};
    if (!seen.insert (name).second)
      return Conversion{ArgumentError::UnknownName, "keyword argument '" + name + "' given twice"};
    if (const Conversion r = found->second.set (name, value, call, match); !r)
      return r;
  }
  return checkGroups (groups, call, match);
}

Arguments
flowArguments (const pcl_flowseg::FlowParameters& p)
{
  Arguments a;
  const std::size_t dimension = p.preparation.dimension == pcl_flowseg::DimensionMode::Automatic ? 0
                                : p.preparation.dimension == pcl_flowseg::DimensionMode::Planar  ? 2
                                                                                                 : 3;
  a.emplace_back ("dimension", kDimensionNames[dimension]);
  a.emplace_back ("planar_tolerance", p.preparation.planar_tolerance);
  a.emplace_back ("outliers", kModeNames[static_cast<std::size_t> (p.preparation.outliers) % 3]);
  a.emplace_back ("smoothing", kModeNames[static_cast<std::size_t> (p.preparation.smoothing) % 3]);
  a.emplace_back ("smoothing_passes", static_cast<std::int64_t> (p.preparation.smoothing_passes));
  a.emplace_back ("rho", p.merge.rho);
  a.emplace_back ("sampling_tolerance", p.merge.sampling_tolerance);
  a.emplace_back ("stump_ratio", p.merge.stump_ratio);
  a.emplace_back ("compact_rho", p.merge.compact_rho);
  a.emplace_back ("compact_size", p.merge.compact_size);
  a.emplace_back ("min_part_share", p.merge.min_part_share);
  a.emplace_back ("single_view_min_part_share", p.merge.single_view_min_part_share);
  a.emplace_back ("separate", p.interior.separate);
  a.emplace_back ("denoising", kModeNames[static_cast<std::size_t> (p.interior.denoising) % 3]);
  a.emplace_back ("manifold_repair", p.interior.manifold_repair);
  a.emplace_back ("hidden_side", p.interior.hidden_side);
  if (p.interior.viewpoint)
    a.emplace_back ("viewpoint", std::vector<double>{p.interior.viewpoint->x (), p.interior.viewpoint->y (), p.interior.viewpoint->z ()});
  else
    a.emplace_back ("viewpoint", std::monostate ());
  a.emplace_back ("features", kFeatureNames[static_cast<std::size_t> (p.features) % 3]);
  a.emplace_back ("threads", static_cast<std::int64_t> (p.execution.threads));
  a.emplace_back ("memory_limit", static_cast<std::int64_t> (p.execution.memory_limit));
  return a;
}

Arguments
matchArguments (const pcl_flowseg::MatchParameters& m)
{
  return {{"method", std::string (pcl_flowseg::matchMethodName (m.method))},
          {"threshold", m.paper.threshold},
          {"allow_mirror", m.paper.allow_mirror},
          {"alignment_points", static_cast<std::int64_t> (m.paper.alignment_points)}};
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

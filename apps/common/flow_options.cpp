/*
 * pcl_flowseg apps - the option groups several apps share, bound to the library's parameter types.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include "common/flow_options.h"

#include <pcl_flowseg/common/flow_parameter_table.h>
#include <pcl_flowseg/signature/match_parameter_table.h>

#include <iostream>
#include <stdexcept>

namespace flowseg_app {

namespace {

/** The value's name in the help for a row of \a info's type. */
std::string
valueName (const pcl_flowseg::ParameterInfo& info)
{
  using pcl_flowseg::ParameterType;
  switch (info.type)
  {
  case ParameterType::Switch:
    return "";
  case ParameterType::Count:
    return "N";
  case ParameterType::Point:
    return "X,Y,Z";
  case ParameterType::Weights:
    return "NAME=W,...";
  case ParameterType::Choice:
  {
    std::string names;
    for (const auto& c : info.choices)
      names += (names.empty () ? "" : "|") + c;
    return names;
  }
  case ParameterType::Number:
    break;
  }
  return "F";
}

/** The help of a row: its description, then unit and range for numbers. */
std::string
helpText (const pcl_flowseg::ParameterInfo& info)
{
  std::string help = info.description;
  if (info.type == pcl_flowseg::ParameterType::Number || info.type == pcl_flowseg::ParameterType::Count)
    help += " [" + (info.unit.empty () ? "" : info.unit + "; ") + info.range + "]";
  return help;
}

/** The options of \a name (a row's name or one of its old names): --NAME, and --no-NAME for a switch. */
std::string
optionNames (const pcl_flowseg::ParameterInfo& info, const std::string& name, bool with_short)
{
  std::string names = with_short && !info.short_option.empty () ? info.short_option + ", " : "";
  names += pcl_flowseg::optionName (name);
  if (info.type == pcl_flowseg::ParameterType::Switch)
    names += ", --no-" + pcl_flowseg::optionName (name).substr (2);
  return names;
}

} // namespace

template <class Params>
void
addTableOption (OptionParser& p, const pcl_flowseg::ParameterTable<Params>& table, const std::string& name, Params& params)
{
  const pcl_flowseg::ParameterSpec<Params>* spec = pcl_flowseg::findParameter (table, name);
  if (!spec)
    throw std::logic_error ("no parameter '" + name + "' in the " + table.title + " table");
  const bool is_switch = spec->info.type == pcl_flowseg::ParameterType::Switch;
  const std::string app = p.app (), current = pcl_flowseg::optionName (spec->info.name);
  Params* target = &params;
  const auto set = [&table, spec, target, app, current, is_switch] (const std::string& used, const std::string& value) {
    const bool negated = is_switch && used.compare (0, 5, "--no-") == 0;
    const std::string current_used = negated ? "--no-" + current.substr (2) : current;
    if (used != current_used && used != spec->info.short_option)
      std::cerr << app << ": warning: " << used << " is deprecated: use " << current_used << "\n";
    std::string warning;
    const pcl_flowseg::Status s =
        pcl_flowseg::setParameter (table, *spec, *target, is_switch ? (negated ? "false" : "true") : value, &warning);
    if (!warning.empty ())
      std::cerr << app << ": warning: " << warning << "\n";
    return s ? std::string () : used + ": " + s.message;
  };
  const std::string shown = spec->get (params);
  p.custom (optionNames (spec->info, spec->info.name, true), valueName (spec->info), helpText (spec->info),
            is_switch ? (shown == "true" ? "on" : "off") : shown, set);
  for (const auto& old : spec->info.old_names)
    p.custom (optionNames (spec->info, old, false), valueName (spec->info), "", "", set, true);
}

template void addTableOption (OptionParser&, const pcl_flowseg::ParameterTable<pcl_flowseg::FlowParameters>&,
                              const std::string&, pcl_flowseg::FlowParameters&);
template void addTableOption (OptionParser&, const pcl_flowseg::ParameterTable<pcl_flowseg::SignatureParameters>&,
                              const std::string&, pcl_flowseg::SignatureParameters&);
template void addTableOption (OptionParser&, const pcl_flowseg::ParameterTable<pcl_flowseg::MatchParameters>&,
                              const std::string&, pcl_flowseg::MatchParameters&);

void
addSegmentationOptions (OptionParser& p, pcl_flowseg::FlowParameters& params)
{
  const auto& table = pcl_flowseg::flowParameterTable ();
  for (const auto& spec : table.specs)
  {
    if (spec.info.name == "viewpoint" || spec.info.name == "threads")
      continue; // addViewpointOptions, addThreadsOption: apps bind them to their own variables
    addTableOption (p, table, spec.info.name, params);
    if (spec.info.name == "single_view_min_part_share")
    {
      pcl_flowseg::MergeParameters* m = &params.merge;
      p.action ("--paper-rule", "the paper's merging rule alone: sampling tolerance, stump ratio, compact size and smallest "
                "part shares 0", [m] () { m->usePaperRule (); });
    }
  }
}

void
addThreadsOption (OptionParser& p, unsigned& threads)
{
  const auto* spec = pcl_flowseg::findParameter (pcl_flowseg::flowParameterTable (), "threads");
  unsigned* t = &threads;
  p.custom (optionNames (spec->info, spec->info.name, true), valueName (spec->info), helpText (spec->info),
            std::to_string (threads), [spec, t, app = p.app ()] (const std::string& used, const std::string& value) {
              if (used == "--jobs")
                std::cerr << app << ": warning: --jobs is deprecated: use --threads\n";
              pcl_flowseg::FlowParameters params;
              const pcl_flowseg::Status s = pcl_flowseg::setParameter (pcl_flowseg::flowParameterTable (), *spec, params, value);
              if (!s)
                return used + ": " + s.message;
              *t = params.execution.threads;
              return std::string ();
            });
  for (const auto& old : spec->info.old_names)
    p.alias (pcl_flowseg::optionName (old), "--threads");
}

void
addSignatureOptions (OptionParser& p, SignatureOptions& o)
{
  const auto& table = pcl_flowseg::signatureParameterTable ();
  for (const auto& spec : table.specs)
    if (spec.info.name != "use_sensor_origin") // addViewpointOptions, beside --viewpoint
      addTableOption (p, table, spec.info.name, o);
}

void
addMatchOptions (OptionParser& p, pcl_flowseg::MatchParameters& match)
{
  const auto& table = pcl_flowseg::matchParameterTable ();
  for (const auto& spec : table.specs)
    if (spec.info.name != "method") // addMatchMethodOption: not every app that matches offers a choice
      addTableOption (p, table, spec.info.name, match);
}

void
addMatchMethodOption (OptionParser& p, pcl_flowseg::MatchParameters& match)
{
  addTableOption (p, pcl_flowseg::matchParameterTable (), "method", match);
}

void
addViewpointOptions (OptionParser& p, std::optional<Eigen::Vector3d>& viewpoint, bool& use_sensor_origin)
{
  const auto* point = pcl_flowseg::findParameter (pcl_flowseg::flowParameterTable (), "viewpoint");
  std::optional<Eigen::Vector3d>* v = &viewpoint;
  p.custom (optionNames (point->info, point->info.name, false), valueName (point->info), helpText (point->info), "",
            [v] (const std::string& used, const std::string& text) {
              const pcl_flowseg::Status s = text.empty () ? pcl_flowseg::Status::error ("needs X,Y,Z")
                                                          : pcl_flowseg::parsePoint (text, *v);
              return s ? std::string () : used + ": viewpoint " + s.message;
            });
  const auto* origin = pcl_flowseg::findParameter (pcl_flowseg::signatureParameterTable (), "use_sensor_origin");
  bool* use = &use_sensor_origin;
  p.custom (optionNames (origin->info, origin->info.name, false), "", helpText (origin->info), use_sensor_origin ? "on" : "off",
            [use] (const std::string& used, const std::string&) {
              *use = used.compare (0, 5, "--no-") != 0;
              return std::string ();
            });
}

int
checkViewpointOptions (const OptionParser& p, const pcl_flowseg::FlowParameters& params, bool use_sensor_origin)
{
  if (params.interior.viewpoint && use_sensor_origin)
    return p.usageError ("--viewpoint and --use-sensor-origin exclude each other");
  if (!params.interior.separate &&
      (params.interior.viewpoint || use_sensor_origin || params.features != pcl_flowseg::FeatureSide::Interior))
    return p.usageError ("--no-separate-interior excludes --features, --viewpoint and --use-sensor-origin");
  if (const pcl_flowseg::Status s = pcl_flowseg::checkParameters (params); !s)
    return p.usageError (s.message);
  return kContinue;
}

} // namespace flowseg_app

/*
 * pcl_flowseg - the names of the match methods and the distances each weighs.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include <pcl_flowseg/signature/match_method.h>

#include <utility>

namespace pcl_flowseg {

namespace {

/** Each method and its name in files, options and reports. */
constexpr std::pair<MatchMethod, const char*> kMethodNames[] = {
    {MatchMethod::Combined, "flowseg"}, {MatchMethod::Paper, "paper"},         {MatchMethod::Parts, "parts"},
    {MatchMethod::Thickness, "thickness"}, {MatchMethod::InnerDistance, "inner"}, {MatchMethod::SolidDistance, "solid"},
    {MatchMethod::InnerProfile, "inner-profile"}, {MatchMethod::ThicknessProfile, "thickness-profile"},
    {MatchMethod::Contour, "contour"}, {MatchMethod::InnerContext, "inner-context"}};

} // namespace

const char*
matchMethodName (MatchMethod method)
{
  for (const auto& [m, name] : kMethodNames)
    if (m == method)
      return name;
  return "unknown";
}

DescriptionWeights
descriptionWeights (MatchMethod method, int dimension)
{
  DescriptionWeights w;
  switch (method)
  {
  case MatchMethod::Parts:
    w.parts = 1.0;
    break;
  case MatchMethod::Thickness:
    w.thickness = 1.0;
    break;
  case MatchMethod::InnerDistance:
    w.inner_distance = 1.0;
    break;
  case MatchMethod::SolidDistance:
    w.solid_distance = 1.0;
    break;
  case MatchMethod::InnerProfile:
    w.inner_profile = 1.0;
    break;
  case MatchMethod::ThicknessProfile:
    w.thickness_profile = 1.0;
    break;
  case MatchMethod::Contour:
    w.contour = 1.0;
    break;
  case MatchMethod::InnerContext:
    w.inner_context = 1.0;
    break;
  case MatchMethod::Combined:
  case MatchMethod::Paper:
    w = dimension == 2 ? kCombinedWeights2d : kCombinedWeights3d;
    break;
  }
  return w;
}

Status
parseMatchMethod (const std::string& name, MatchMethod& method)
{
  std::string names;
  for (MatchMethod m : kMatchMethods)
  {
    if (name == matchMethodName (m))
    {
      method = m;
      return Status::success ();
    }
    names += (names.empty () ? "" : ", ") + std::string (matchMethodName (m));
  }
  return Status::error ("unknown match method '" + name + "' (one of " + names + ")");
}

} // namespace pcl_flowseg

/*
 * pcl_flowseg - the names of the match methods and the default weights of the description distances.
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

const std::vector<std::pair<std::string, double DescriptionWeights::*>>&
descriptionWeightFields ()
{
  static const std::vector<std::pair<std::string, double DescriptionWeights::*>> fields = {
      {"parts", &DescriptionWeights::parts},
      {"thickness", &DescriptionWeights::thickness},
      {"inner_distance", &DescriptionWeights::inner_distance},
      {"solid_distance", &DescriptionWeights::solid_distance},
      {"inner_profile", &DescriptionWeights::inner_profile},
      {"thickness_profile", &DescriptionWeights::thickness_profile},
      {"contour", &DescriptionWeights::contour},
      {"inner_context", &DescriptionWeights::inner_context}};
  return fields;
}

DescriptionWeights
defaultDescriptionWeights (int dimension)
{
  // Chosen by grid searches over the weights: for 2D shapes the best sum of bull's eye scores on
  // Kimia-216 and Tari-1000, for 3D shapes the best sum of nearest neighbour and first tier on
  // shrec07_dev and TOSCA (docs/method.md). A weight left out here is 0.
  DescriptionWeights w;
  if (dimension == 2)
  {
    w.parts = 3.0;
    w.thickness = 0.5;
    w.inner_distance = 2.0;
    w.solid_distance = 3.0;
    w.inner_profile = 8.0;
    w.thickness_profile = 6.0;
    w.contour = 48.0;
  }
  else
  {
    w.parts = 3.0;
    w.thickness = 0.5;
    w.thickness_profile = 4.0;
    w.inner_context = 5.0;
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

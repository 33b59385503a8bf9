/*
 * pcl_flowseg - the names of the match methods.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include <pcl_flowseg/signature/match_method.h>

namespace pcl_flowseg {

const char*
matchMethodName (MatchMethod method)
{
  switch (method)
  {
  case MatchMethod::Combined:
    return "flowseg";
  case MatchMethod::Paper:
    return "paper";
  case MatchMethod::Parts:
    return "parts";
  case MatchMethod::Thickness:
    return "thickness";
  case MatchMethod::InnerDistance:
    return "inner";
  case MatchMethod::SolidDistance:
    return "solid";
  }
  return "unknown";
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

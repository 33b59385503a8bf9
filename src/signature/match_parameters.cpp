/*
 * pcl_flowseg - the parameters of matching two signatures: their checks, and the weights each
 * method sums the description distances with.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include <pcl_flowseg/signature/match_parameters.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iterator>
#include <string>
#include <utility>

namespace pcl_flowseg {

namespace {

/** Why the weights \a w (called \a set in messages) cannot be used, or success. */
Status
checkWeights (const DescriptionWeights& w, const char* set, bool combined)
{
  bool any = false;
  for (const auto& [name, field] : descriptionWeightFields ())
  {
    const double value = w.*field;
    if (!std::isfinite (value) || value < 0.0)
      return Status::error (std::string ("the match weight ") + set + "." + name + " must be a finite number >= 0, got " +
                            std::to_string (value));
    any = any || value > 0.0;
  }
  if (combined && !any)
    return Status::error (std::string ("the match weights ") + set + " are all 0: the combined method would compare nothing");
  return Status::success ();
}

} // namespace

Status
checkMatchParameters (const MatchParameters& params)
{
  if (std::find (std::begin (kMatchMethods), std::end (kMatchMethods), params.method) == std::end (kMatchMethods))
    return Status::error ("the match method is none of the known ones");
  const PaperMatchParameters& paper = params.paper;
  if (!std::isfinite (paper.threshold) || paper.threshold <= 0.0)
    return Status::error ("the matcher threshold must be a finite number > 0, got " + std::to_string (paper.threshold));
  if (paper.alignment_points < 1 || paper.alignment_points > 100)
    return Status::error ("the alignment points must be a whole number from 1 to 100, got " +
                          std::to_string (paper.alignment_points));
  const bool combined = params.method == MatchMethod::Combined;
  if (const Status s = checkWeights (params.weights_3d, "weights_3d", combined); !s)
    return s;
  return checkWeights (params.weights_2d, "weights_2d", combined);
}

DescriptionWeights
descriptionWeights (const MatchParameters& params, int dimension)
{
  DescriptionWeights w;
  switch (params.method)
  {
  case MatchMethod::Combined:
    w = dimension == 2 ? params.weights_2d : params.weights_3d;
    break;
  case MatchMethod::Paper:
    break; // compares no descriptions
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
  }
  return w;
}

} // namespace pcl_flowseg

/*
 * pcl_flowseg - the ways two signatures can be compared, their names, and the weights of the
 * description distances.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include <pcl_flowseg/common/status.h>

#include <string>
#include <utility>
#include <vector>

namespace pcl_flowseg {

/** \brief How two signatures are compared. Every method is invariant to translation, rotation,
  * mirroring and uniform scale. */
enum class MatchMethod
{
  /** The module's default ("flowseg"): a weighted sum of the description distances below, with the
    * weights MatchParameters::weights_3d or weights_2d (by default defaultDescriptionWeights). */
  Combined,
  /** The paper's: significant features as weighted points, aligned and scored (section 5). */
  Paper,
  /** Earth mover's distance between the described parts (ShapeDescription::parts). */
  Parts,
  /** L1 distance between the thickness distributions. */
  Thickness,
  /** Chi-square distance between the inner-distance distributions. */
  InnerDistance,
  /** L1 distance between the solid-distance distributions. */
  SolidDistance,
  /** Mean earth mover's distance between corresponding rows of the inner-distance profiles
    * (ShapeDescription::inner_profiles), in log distance. */
  InnerProfile,
  /** Mean difference of the thickness profiles' entries (ShapeDescription::thickness_profile), each
    * profile less its mean (in log thickness: how thickness changes from the centre out, not how
    * thick the shape is, which ShapeDescription::thickness tells). */
  ThicknessProfile,
  /** 2D only (0 in 3D): inner-distance shape context along the outline
    * (ShapeDescription::contour), matched in order by dynamic programming from any start and in
    * either direction. */
  Contour,
  /** Least-cost assignment between the inner-distance contexts of the sources
    * (ShapeDescription::inner_contexts): each source of one shape matched to one of the other's. */
  InnerContext,
};

/** \brief Every method, the default first. */
constexpr MatchMethod kMatchMethods[] = {MatchMethod::Combined, MatchMethod::Paper, MatchMethod::Parts,
                                         MatchMethod::Thickness, MatchMethod::InnerDistance, MatchMethod::SolidDistance,
                                         MatchMethod::InnerProfile, MatchMethod::ThicknessProfile, MatchMethod::Contour,
                                         MatchMethod::InnerContext};

/** \brief The method's name in files, options and reports: flowseg, paper, parts, thickness,
  * inner, solid, inner-profile, thickness-profile, contour, inner-context. */
const char*
matchMethodName (MatchMethod method);

/** \brief The method called \a name (matchMethodName), or a message listing the names. */
Status
parseMatchMethod (const std::string& name, MatchMethod& method);

/** \brief The weight of each description distance in a sum of them (MatchMethod::Combined weighs
  * the distances by MatchParameters::weights_3d or weights_2d; a single-component method weighs
  * its own distance 1 and the others 0). Finite and >= 0; a weight of 0 leaves its distance out. */
struct DescriptionWeights
{
  double parts = 0.0;             ///< MatchMethod::Parts
  double thickness = 0.0;         ///< MatchMethod::Thickness
  double inner_distance = 0.0;    ///< MatchMethod::InnerDistance
  double solid_distance = 0.0;    ///< MatchMethod::SolidDistance
  double inner_profile = 0.0;     ///< MatchMethod::InnerProfile
  double thickness_profile = 0.0; ///< MatchMethod::ThicknessProfile
  double contour = 0.0;           ///< MatchMethod::Contour (2D shapes only: 3D shapes have no contour)
  double inner_context = 0.0;     ///< MatchMethod::InnerContext
};

/** \brief Each weight of DescriptionWeights with its name in options, keywords and messages, in
  * the order of the fields. */
const std::vector<std::pair<std::string, double DescriptionWeights::*>>&
descriptionWeightFields ();

/** \brief The default weights of MatchMethod::Combined for shapes of \a dimension (2, or 3 for any
  * other value), chosen on labelled collections of such shapes (docs/method.md). */
DescriptionWeights
defaultDescriptionWeights (int dimension);

/** \brief Weights of a part's attributes in the cost of moving it onto another part (MatchMethod::Parts):
  * the distance between two parts is the Euclidean distance of (weight x attribute), with logs of
  * thickness, extent and weight. */
struct PartAttributeWeights
{
  double thickness = 1.0;      ///< log PartDescription::thickness
  double extent = 0.5;         ///< log PartDescription::extent
  double middle_ratio = 1.0;   ///< PartDescription::middle_ratio
  double smallest_ratio = 1.0; ///< PartDescription::smallest_ratio
  double weight = 0.2;         ///< log PartDescription::weight
  double remoteness = 0.5;     ///< PartDescription::remoteness
};

/** \brief The part attribute weights MatchMethod::Parts uses. */
constexpr PartAttributeWeights kPartAttributeWeights{};

/** \brief The mass a part brings to the earth mover's distance of MatchMethod::Parts: its volume
  * share raised to this power, the masses then scaled to sum to 1. Below 1 the small parts that
  * tell shapes apart (a head, a hand) weigh more against the large ones (a torso, whose split
  * varies from pose to pose). */
constexpr double kPartMassExponent = 0.3;

/** \brief Weight of the difference of two sources' log thickness in the cost of matching their inner
  * contexts (the earth mover's distance of their histograms counts 1). */
constexpr double kContextThicknessWeight = 0.5;

} // namespace pcl_flowseg

/*
 * pcl_flowseg - distances between shape descriptions, one per matching method (internal header).
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include <pcl_flowseg/signature/shape_description.h>
#include <pcl_flowseg/signature/match_method.h>

#include <Eigen/Core>

#include <vector>

namespace pcl_flowseg {

/** \brief A part as a point in the space where Euclidean distance compares parts: its attributes
  * (logs of thickness, extent and weight) times kPartAttributeWeights. */
Eigen::Matrix<double, 6, 1>
partPoint (const PartDescription& part);

/** \brief The mass of each part in partDistance: its weight to the power kPartMassExponent, the
  * masses summing to 1 (none without parts). */
std::vector<double>
partMasses (const ShapeDescription& description);

/** \brief Earth mover's distance between the parts of \a a and \a b with masses partMasses; moving
  * a part onto another costs the weighted Euclidean distance of their attributes
  * (kPartAttributeWeights). Exactly symmetric. */
double
partDistance (const ShapeDescription& a, const ShapeDescription& b);

/** \brief Mean over the rows of the inner-distance profiles of the earth mover's distance between
  * corresponding rows (in log distance); exactly symmetric. */
double
innerProfileDistance (const ShapeDescription& a, const ShapeDescription& b);

/** \brief Mean absolute difference of the thickness profiles' entries, each profile less its mean
  * (in log thickness); exactly symmetric. */
double
thicknessProfileDistance (const ShapeDescription& a, const ShapeDescription& b);

/** \brief Mean cost of the least-cost one-to-one assignment of the inner contexts of \a a to those
  * of \b b (the fewer to the more); a pair costs the earth mover's distance of their histograms (in
  * log distance) plus kContextThicknessWeight times the difference of their log thickness. Exactly
  * symmetric; 0 when either has none. */
double
innerContextDistance (const ShapeDescription& a, const ShapeDescription& b);

/** \brief The sum of the description distances between two non-empty descriptions, each weighted
  * by \a weights (descriptionWeights of the method); exactly symmetric. */
double
descriptionDistance (const DescriptionWeights& weights, const ShapeDescription& a, const ShapeDescription& b);

} // namespace pcl_flowseg

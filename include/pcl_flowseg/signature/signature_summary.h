/*
 * pcl_flowseg - short, rotation-invariant vectors that summarise a signature, for picking
 * candidates out of large databases before the full comparison.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include <pcl_flowseg/signature/signature.h>
#include <pcl_flowseg/signature/match_method.h>
#include <pcl_flowseg/signature/shape_description.h>

#include <array>

namespace pcl_flowseg {

/** \brief Length of signatureSummary(). */
constexpr std::size_t kSummarySize = 25;

/** \brief A vector that does not change under rotation, mirroring, translation and scale (the
  * signature is already normalised for the last two), so that shapes whose signatures match well
  * lie close together in it (Euclidean distance):
  *   - the weights of the 8 heaviest points (zero-padded),
  *   - their distances from the interior's centroid,
  *   - the 6 distances between the 4 heaviest points,
  *   - the square roots of the eigenvalues of the weighted second moments of all points, sorted.
  * Cheap lower-fidelity view: it orders candidates, SignatureMatcher decides. */
std::array<float, kSummarySize>
signatureSummary (const Signature& signature);

/** \brief Numbers of the contour's block in descriptionSummary(). */
constexpr std::size_t kContourSummarySize = kContourDistanceBins * kContourAngleBins / 2;
/** \brief Numbers of the inner contexts' block in descriptionSummary(). */
constexpr std::size_t kContextSummarySize = kContextBins + 1;
/** \brief Length of descriptionSummary(). */
constexpr std::size_t kDescriptionSummarySize =
    3 * kDistributionBins + 12 + 32 + kProfileRows + kContourSummarySize + kContextSummarySize;

/** \brief A vector in which shapes whose descriptions are near (in the sum of description distances
  * weighted by \a weights) lie close together (Euclidean distance): the square roots of the three
  * distributions' bins (so that Euclidean distance behaves like the L1 and chi-square distances),
  * then the mean and spread of the parts' attribute points (with the masses the parts' earth
  * mover's distance gives them, kPartMassExponent), then the inner-distance
  * profiles coarsened (4 groups of 4 rows, cumulative sums at 8 of the 32 bins), the thickness
  * profile less its mean, and the square roots of the contour's mean histogram folded onto its
  * mirror image (kContourSummarySize), the inner contexts' mean cumulative histogram (times the bin
  * width) and mean thickness (times kContextThicknessWeight) (kContextSummarySize), each block
  * scaled by its distance's weight in \a weights (for a method: descriptionWeights (parameters,
  * signature.dimension)). Zero for a signature without a description. */
std::array<float, kDescriptionSummarySize>
descriptionSummary (const Signature& signature, const DescriptionWeights& weights);

} // namespace pcl_flowseg

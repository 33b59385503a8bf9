/*
 * pcl_flowseg - a short, rotation-invariant vector that summarises a signature, for picking
 * candidates out of large databases before the full alignment search.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include <pcl_flowseg/signature/signature.h>

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

} // namespace pcl_flowseg

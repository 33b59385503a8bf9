/*
 * pcl_flowseg - the parameters of matching two signatures: the method, the weights of the
 * description distances, and the paper's alignment search.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include <pcl_flowseg/common/status.h>
#include <pcl_flowseg/signature/match_method.h>

namespace pcl_flowseg {

/** \brief The parameters of MatchMethod::Paper, the paper's alignment search; no other method uses
  * them. */
struct PaperMatchParameters
{
  /** Largest distance between partner points, in the signatures' normalised length unit
    * (interior volume^(1/d); finite, > 0). */
  double threshold = 0.4;
  /** Also try mirrored alignments: mirror images match. */
  bool allow_mirror = true;
  /** How many of the heaviest points of each signature generate alignments (1..100; all points are
    * scored). The search costs O(m^2 n^2) alignments in 3D. */
  int alignment_points = 4;
};

/** \brief How two signatures are compared. */
struct MatchParameters
{
  /** The comparison. */
  MatchMethod method = MatchMethod::Combined;
  /** MatchMethod::Combined on 3D shapes: the weight of each description distance. */
  DescriptionWeights weights_3d = defaultDescriptionWeights (3);
  /** MatchMethod::Combined on 2D shapes: the weight of each description distance. */
  DescriptionWeights weights_2d = defaultDescriptionWeights (2);
  /** MatchMethod::Paper only. */
  PaperMatchParameters paper;
};

/** \brief Why \a params cannot be used (a message naming the parameter), or success. Checks the
  * paper's parameters (whatever the method) and the weights: finite and >= 0, and for
  * MatchMethod::Combined not all 0 in either set. */
Status
checkMatchParameters (const MatchParameters& params);

/** \brief The weights with which \a params' method sums the description distances of shapes of
  * \a dimension (2 or 3): weights_2d or weights_3d for MatchMethod::Combined; 1 for the one
  * distance of a single-component method and 0 for the others; all 0 for MatchMethod::Paper, which
  * compares no descriptions. */
DescriptionWeights
descriptionWeights (const MatchParameters& params, int dimension);

} // namespace pcl_flowseg

/*
 * pcl_flowseg - shape signatures: significant features as weighted points (paper, section 5).
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include <pcl_flowseg/common/feature_significance.h>
#include <pcl_flowseg/common/flow_result.h>
#include <pcl_flowseg/common/status.h>
#include <pcl_flowseg/signature/shape_description.h>
#include <pcl_flowseg/signature/view_description.h>

#include <Eigen/Core>

#include <string>
#include <vector>

namespace pcl_flowseg {

/** \brief One significant feature: its representative point and weight. */
struct WeightedPoint
{
  Eigen::Vector3d position = Eigen::Vector3d::Zero (); ///< volume-weighted centroid, normalised frame
  double weight = 0.0;                                 ///< volume share among the significant features
};

/** \brief The signature of a shape: its significant interior features as weighted points (the
  * paper's), and the shape's description by its parts and interior (ShapeDescription).
  *
  * Normalised so that comparing two signatures is invariant to translation, rotation, mirroring and
  * uniform scale: positions are relative to the volume-weighted centroid of the whole interior and
  * divided by the length unit volume^(1/d) of the interior (a rotation-invariant scale, unlike the
  * paper's bounding boxes); weights sum to 1. Points are ordered by decreasing weight. */
struct Signature
{
  int dimension = 3;
  std::vector<WeightedPoint> points;
  double unit = 1.0;           ///< the length unit, in input units (interior volume^(1/d))
  double interior_volume = 0.0; ///< in input units
  double significance = kDefaultSignificance;
  /** Parts and interior distributions, for every method but the paper's (describeShape). */
  ShapeDescription description;
  /** How a depth camera sees the shape (3D only): rendered views of a complete shape, or the one
    * view of a single-view scan; for recognising scans (SignatureMatcher, SignatureDatabase). */
  ViewSet views;
};

/** \brief Largest coordinate a signature point may have, in the signature's unit: a feature's
  * centroid lies inside the shape, and even a needle a billion times longer than it is thick stays
  * well below this. */
constexpr double kLargestSignatureCoordinate = 1e9;

/** \brief Why \a signature is not one signatureFromSegmentation could have made (a message), or
  * success: dimension 2 or 3; unit finite and > 0; interior volume finite and >= 0; significance in
  * [0, 1); positions finite and within kLargestSignatureCoordinate; weights in [0, 1], non-increasing,
  * summing to 1; a description that checkShapeDescription accepts. Whatever is read from outside is checked with it before it is compared. */
Status
checkSignature (const Signature& signature);

/** \brief Builds the signature (points, description and views) from a segmentation with interior/exterior
  * separation. Fails when the separation was not computed or found no interior. */
Status
signatureFromSegmentation (const FlowResult& result, double significance, Signature& signature);

} // namespace pcl_flowseg

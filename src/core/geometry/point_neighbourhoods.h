/*
 * pcl_flowseg - internal: the nearest neighbours of a point sample's points, the PCA plane fits of
 * those neighbourhoods and medians over them (noise estimate, outliers, smoothing, denoising).
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include "core/support/parallel.h"

#include <Eigen/Core>

#include <cstddef>
#include <vector>

namespace pcl_flowseg {
namespace core {

/** Neighbours of the local PCA fits. */
constexpr int kNoiseNeighbours = 16;
/** The neighbour whose distance tells an isolated point (Neighbourhoods::reach): the 4th nearest
  * other point, so that a few outliers close together are still seen. */
constexpr int kIsolationNeighbour = 4;

/** \brief Neighbourhoods as compressed rows: the neighbours of the r-th query point are
  * ids[first[r]] .. ids[first[r+1]-1] (the point itself included); with every point a query, row r
  * is point r. */
struct Neighbourhoods
{
  std::vector<std::size_t> first;
  std::vector<int> ids;
  std::vector<float> reach; ///< per row: the distance to the kIsolationNeighbour-th nearest other point
};

/** \brief The kNoiseNeighbours nearest points, among all \a points, of every \a stride-th point
  * (rows for points 0, stride, 2 stride, ...; FLANN kd-tree, both cores). */
Neighbourhoods
nearestNeighbourhoods (const std::vector<Eigen::Vector3d>& points, std::size_t stride = 1);

/** \brief The PCA plane (2D: line) of a set of points. */
struct PlaneFit
{
  Eigen::Vector3d mean = Eigen::Vector3d::Zero ();
  Eigen::Vector3d normal = Eigen::Vector3d::Zero (); ///< zero when the set is too small for a fit
  /** The direction of largest spread: a curve's tangent. On a straight piece of a curve in a plane
    * the plane's and the curve's normals share one eigenvalue (0) and \a normal may be either; the
    * part of an in-plane offset across this direction is the offset from the curve. */
  Eigen::Vector3d direction = Eigen::Vector3d::Zero ();
  double variation = 0.0;       ///< smallest PCA eigenvalue over the sum of the d largest
  double normal_variance = 0.0; ///< variance of the points along the normal
};

/** \brief The PCA fit of the points \a ids[0 .. count-1] of \a points (surfaces: d = 3; curves in a
  * plane: d = 2, the normal lies in the plane). */
PlaneFit
fitPlane (const std::vector<Eigen::Vector3d>& points, const int* ids, std::size_t count, int dimension);

/** \brief Calls \a visit (i, fit) with the plane fit of the neighbourhood in every row i of \a hoods, on
  * all cores: \a visit must write only what belongs to row i. */
template <typename Visit>
void
forEachNeighbourhood (const std::vector<Eigen::Vector3d>& points, const Neighbourhoods& hoods, int dimension, Visit visit)
{
  if (hoods.first.empty ())
    return;
  parallelFor (hoods.first.size () - 1, [&] (std::size_t i) {
    visit (i, fitPlane (points, hoods.ids.data () + hoods.first[i], hoods.first[i + 1] - hoods.first[i], dimension));
  });
}

/** \brief Median over the rows of \a hoods of their surface variation: the smallest PCA eigenvalue of the
  * neighbourhood over the sum of the d largest (d = 3: surfaces; d = 2: curves in a plane, whose
  * third eigenvalue is zero). */
double
medianVariation (const std::vector<Eigen::Vector3d>& points, const Neighbourhoods& hoods, int dimension);

/** \brief Median over the rows of \a hoods of the standard deviation of their neighbourhood along its PCA
  * normal (2D: the curve's normal), in the points' unit: about the noise's standard deviation on
  * a noisy sample, near 0 on a clean dense one. */
double
medianNormalDeviation (const std::vector<Eigen::Vector3d>& points, const Neighbourhoods& hoods, int dimension);

/** \brief The median of Neighbourhoods::reach: the sample spacing. */
double
medianReach (const Neighbourhoods& hoods);

/** \brief NoiseEstimate::roughness from every \a row_step-th row of \a hoods, whose row r holds the
  * neighbours of point r * \a stride: the median standard deviation of the row's
  * kRoughnessNeighbours points nearest to its point along their PCA normal, over \a spacing
  * (medianReach of \a hoods; 0 when it is not positive). */
double
medianRoughness (const std::vector<Eigen::Vector3d>& points, const Neighbourhoods& hoods, std::size_t stride, std::size_t row_step,
                 int dimension, double spacing);

} // namespace core
} // namespace pcl_flowseg

/*
 * pcl_flowseg - internal: noise estimate and smoothing of a point sample (for in/out decisions).
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include <pcl_flowseg/common/status.h>
#include <pcl_flowseg/common/flow_result.h>

#include <string>
#include <vector>

namespace pcl_flowseg {
namespace core {

/** Median surface variation above which a sample may be noisy: between what clean and noisy samples
  * of the development meshes measure (docs/method.md). */
constexpr double kNoiseVariation = 0.04;
/** Share of samples off the boundary of the raw labelling above which it is taken as failed;
  * smoothing helps where both this and the variation are exceeded (docs/method.md). */
constexpr double kOffBoundaryShare = 0.08;
/** Neighbours of the local PCA fits. */
constexpr int kNoiseNeighbours = 16;
/** The neighbour whose distance tells an isolated point (Neighbourhoods::reach): the 4th nearest
  * other point, so that a few outliers close together are still seen. */
constexpr int kIsolationNeighbour = 4;
/** Upper bound on the passes of the interior's own smoothing (of its working copy). */
constexpr int kMaxDenoisingPasses = 4;

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

/** \brief One smoothing pass: every point is projected onto the PCA plane (2D: line) of its
  * neighbourhood, through the neighbourhood's centroid. */
std::vector<Eigen::Vector3d>
smoothPoints (const std::vector<Eigen::Vector3d>& points, const Neighbourhoods& hoods, int dimension);

/** \brief Triangulates points given in 3D (in 2D: points of one plane) into cells with their flow
  * relation. */
Status
triangulateWorking (const std::vector<Eigen::Vector3d>& points, int dimension, std::vector<FlowCell>& cells);

} // namespace core
} // namespace pcl_flowseg

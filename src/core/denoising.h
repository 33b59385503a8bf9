/*
 * pcl_flowseg - internal: noise estimate and smoothing of a point sample (for in/out decisions).
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include <pcl_flowseg/flow_result.h>

#include <string>
#include <vector>

namespace pcl_flowseg {
namespace core {

/** Median surface variation above which a sample is treated as noisy. Clean samples of the
  * development meshes measure 0.0001 to 0.009 (5k to 50k points), 0.25% noise 0.011 to 0.12, 0.5%
  * noise 0.04 to 0.16; below about 0.035 the greedy labelling of the raw sample measured better than
  * the smoothed route. */
constexpr double kNoiseVariation = 0.035;
/** Neighbours of the local PCA fits. */
constexpr int kNoiseNeighbours = 16;
/** Upper bound on smoothing passes. */
constexpr int kMaxSmoothingPasses = 4;

/** \brief Neighbourhoods as compressed rows: the neighbours of v are ids[first[v]] ..
  * ids[first[v+1]-1] (v itself included). */
struct Neighbourhoods
{
  std::vector<std::size_t> first;
  std::vector<int> ids;
};

/** \brief The kNoiseNeighbours nearest points of every point (FLANN kd-tree, both cores). */
Neighbourhoods
nearestNeighbourhoods (const std::vector<Eigen::Vector3d>& points);

/** \brief Median over the points of their surface variation: the smallest PCA eigenvalue of the
  * neighbourhood over the sum of the d largest (d = 3: surfaces; d = 2: curves in a plane, whose
  * third eigenvalue is zero). */
double
medianVariation (const std::vector<Eigen::Vector3d>& points, const Neighbourhoods& hoods, int dimension);

/** \brief One smoothing pass: every point is projected onto the PCA plane (2D: line) of its
  * neighbourhood, through the neighbourhood's centroid. */
std::vector<Eigen::Vector3d>
smoothPoints (const std::vector<Eigen::Vector3d>& points, const Neighbourhoods& hoods, int dimension);

/** \brief Triangulates points given in 3D (in 2D: points of one plane) into cells. */
bool
triangulateWorking (const std::vector<Eigen::Vector3d>& points, int dimension, std::vector<FlowCell>& cells,
                    std::string& error);

} // namespace core
} // namespace pcl_flowseg

/*
 * pcl_flowseg - internal: the interior's own smoothing of a noisy sample's working copy (for in/out
 * decisions): when it applies, its passes, the copy's triangulation.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include "core/geometry/point_neighbourhoods.h"

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
/** Upper bound on the passes of the interior's own smoothing (of its working copy). */
constexpr int kMaxDenoisingPasses = 4;

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

/*
 * pcl_flowseg evaluation - shape distributions: Osada's D2 and PCL's ESF, the global descriptors signatures are compared with.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include <pcl_flowseg/common/status.h>

#include <Eigen/Core>

#include <cstdint>
#include <vector>

namespace pcl_flowseg {

/** \brief Osada's D2 shape distribution adapted to point samples: the histogram of distances
  * between \a pairs random pairs of points, distances divided by their mean (scale invariance),
  * \a bins bins over [0, 3). Reproducible for \a seed. */
std::vector<double>
d2Distribution (const std::vector<Eigen::Vector3d>& points, std::size_t pairs = 100000, int bins = 64, std::uint32_t seed = 1);

/** \brief PCL's Ensemble of Shape Functions descriptor (pcl::ESFEstimation, 640 bins, normalised
  * to sum 1; contains a D2 part) of a point sample; fails when PCL cannot compute it. */
Status
esfDescriptor (const std::vector<Eigen::Vector3d>& points, std::vector<double>& histogram);

/** \brief Similarity of two histograms: 1 - L1 distance / 2 (1 for equal distributions). */
double
histogramSimilarity (const std::vector<double>& a, const std::vector<double>& b);

} // namespace pcl_flowseg

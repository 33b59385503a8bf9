/*
 * pcl_flowseg evaluation - a model as the views the single-view protocol's camera takes of it from
 * many directions, each described by PCL's ESF: the view-based baseline of single-view recognition.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include <pcl_flowseg/common/status.h>
#include <pcl_flowseg/io/mesh_io.h>

#include <Eigen/Core>

#include <vector>

namespace pcl_flowseg {

/** \brief The views of \a mesh that the single-view protocol's camera (singleViewProtocolScanAlong,
  * without noise) takes from each of \a directions (unit vectors), in their order. Fails, naming
  * the direction, when a view sees nothing. */
Status
renderProtocolViews (const TriangleMesh& mesh, const std::vector<Eigen::Vector3d>& directions,
                     std::vector<std::vector<Eigen::Vector3d>>& views);

/** \brief PCL's ESF descriptor (esfDescriptor) of every view of \a mesh from \a directions
  * (renderProtocolViews), in their order. */
Status
esfOfProtocolViews (const TriangleMesh& mesh, const std::vector<Eigen::Vector3d>& directions,
                    std::vector<std::vector<double>>& descriptors);

/** \brief The similarity of \a query to a model described by its views' histograms: the best
  * histogramSimilarity over \a views (the nearest view); 0 without views. */
double
bestViewSimilarity (const std::vector<double>& query, const std::vector<std::vector<double>>& views);

} // namespace pcl_flowseg

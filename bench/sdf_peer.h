/*
 * flowseg_bench_psb - the peer method: CGAL's shape-diameter-function segmentation of a mesh.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include <pcl_flowseg/io/mesh_io.h>
#include <pcl_flowseg/common/status.h>

#include <vector>

namespace flowseg_bench {

/** \brief Segments \a mesh with CGAL's shape diameter function (Shapira, Shamir, Cohen-Or 2008):
  * CGAL::sdf_values with its defaults (cone of 2/3 pi, 25 rays, post-processing) and
  * CGAL::segmentation_from_sdf_values with the documented defaults, 5 clusters and smoothing
  * lambda 0.26. \a face_labels gets one segment id per face of \a mesh, in face order;
  * \a segments the number of segments. Fails when the faces do not form a mesh CGAL's
  * Surface_mesh accepts (non-manifold edges or vertices). */
pcl_flowseg::Status
sdfSegmentation (const pcl_flowseg::TriangleMesh& mesh, std::vector<int>& face_labels, std::size_t& segments);

} // namespace flowseg_bench

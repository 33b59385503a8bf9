/*
 * Pictures of segmented meshes without a display: a small z-buffer rasteriser writing PNG.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include <pcl_flowseg/io/mesh_io.h>
#include <pcl_flowseg/common/status.h>

#include <string>
#include <vector>

namespace flowseg_bench {

/** \brief Renders \a mesh with every face coloured by its label (negative: grey), flat shaded,
  * seen along the mesh's direction of least extent with its longest axis across, and writes a
  * \a size x \a size PNG to \a path. */
pcl_flowseg::Status
renderSegmentedMesh (const pcl_flowseg::TriangleMesh& mesh, const std::vector<int>& face_labels, const std::string& path,
                     int size = 360);

} // namespace flowseg_bench

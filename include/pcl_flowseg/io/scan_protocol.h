/*
 * pcl_flowseg - the single-view protocol: the scan options with which held-out single views are
 * made, so that a development collection can be made the same way.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include <pcl_flowseg/io/mesh_io.h>
#include <pcl_flowseg/io/range_scan.h>

#include <Eigen/Core>

#include <cstdint>

namespace pcl_flowseg {

/** \brief A sensor position \a distance_in_diagonals bounding-box diagonals from the bounding-box
  * centre of \a mesh, in a direction drawn uniformly on the sphere from \a seed. The recipe, the
  * same on every platform: the first two outputs a, b of std::mt19937 seeded with \a seed give
  * u = (a + 0.5) / 2^32 and v = (b + 0.5) / 2^32; the direction is (r cos phi, r sin phi, z) with
  * z = 1 - 2u, r = sqrt (1 - z^2), phi = 2 pi v (z uniform in (-1, 1) makes it uniform on the
  * sphere). Below half a diagonal the position may fall inside the bounding sphere, which
  * scanMesh refuses. */
Eigen::Vector3d
protocolViewpoint (const TriangleMesh& mesh, double distance_in_diagonals = 2.0, std::uint32_t seed = 1);

/** \brief The sensor position \a distance_in_diagonals bounding-box diagonals from the bounding-box
  * centre of \a mesh along the unit vector \a direction (protocolViewpoint's, for a given direction). */
Eigen::Vector3d
protocolViewpointAlong (const TriangleMesh& mesh, const Eigen::Vector3d& direction, double distance_in_diagonals = 2.0);

/** \brief The scan options of the single-view protocol: a pinhole range camera of 240 x 240
  * pixels and a 50-degree field of view at protocolViewpoint (mesh, 2, seed), looking at the
  * bounding-box centre, every pixel's ray returning its first hit; Gaussian depth noise of the
  * same standard deviation along every ray, \a depth_noise times the diagonal. \a seed draws the
  * direction and the noise: the same seed with another noise gives the same rays and hits. */
RangeScanOptions
singleViewProtocolScan (const TriangleMesh& mesh, double depth_noise = 0.0, std::uint32_t seed = 1);

/** \brief singleViewProtocolScan's camera looking from the unit vector \a direction instead of a
  * random one (protocolViewpointAlong (mesh, direction, 2)): views of a mesh taken as the protocol
  * takes its scans. \a seed draws only the noise. */
RangeScanOptions
singleViewProtocolScanAlong (const TriangleMesh& mesh, const Eigen::Vector3d& direction, double depth_noise = 0.0,
                             std::uint32_t seed = 1);

} // namespace pcl_flowseg

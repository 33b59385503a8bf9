/*
 * pcl_flowseg - triangle meshes: reading, and area-uniform surface sampling with noise.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include <pcl_flowseg/common/status.h>

#include <Eigen/Core>

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace pcl_flowseg {

/** \brief A triangle mesh (polygons are split into fans when read). */
struct TriangleMesh
{
  std::vector<Eigen::Vector3d> vertices;
  std::vector<std::array<int, 3>> faces;

  /** Total surface area. */
  double area () const;
  /** Length of the bounding-box diagonal. */
  double diagonal () const;
};

/** \brief Reads an OFF, OBJ or PLY mesh. Fails with a message on a missing, malformed or empty
  * file, or on a face that refers to a vertex that does not exist. */
Status
loadTriangleMesh (const std::string& path, TriangleMesh& mesh);

/** \brief \a count points spread area-uniformly over the faces, each moved by isotropic Gaussian
  * noise of standard deviation \a noise_sigma (same unit as the mesh); reproducible for \a seed. */
std::vector<Eigen::Vector3d>
sampleMeshSurface (const TriangleMesh& mesh, std::size_t count, double noise_sigma, std::uint32_t seed);

} // namespace pcl_flowseg

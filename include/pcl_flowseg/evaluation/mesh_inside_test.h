/*
 * pcl_flowseg evaluation - is a point inside a closed triangle mesh? (ground truth for reconstructions)
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include <pcl_flowseg/io/mesh_io.h>

#include <Eigen/Core>

namespace pcl_flowseg {

/** \brief Answers "is this point inside the closed mesh?" (CGAL's Side_of_triangle_mesh: exact
  * predicates over an AABB tree). For measuring reconstructions against ground truth. */
class MeshInsideTest
{
public:
  explicit MeshInsideTest (const TriangleMesh& mesh);
  ~MeshInsideTest ();
  MeshInsideTest (const MeshInsideTest&) = delete;
  MeshInsideTest& operator= (const MeshInsideTest&) = delete;

  /** False when the mesh could not be built as a closed 2-manifold (then inside() is false). */
  bool valid () const;
  /** True when \a p lies strictly inside the mesh. */
  bool inside (const Eigen::Vector3d& p) const;

private:
  struct Impl;
  Impl* impl_;
};

} // namespace pcl_flowseg

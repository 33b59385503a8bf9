/*
 * pcl_flowseg evaluation - is a point inside a closed triangle mesh? (CGAL's Side_of_triangle_mesh)
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include <pcl_flowseg/evaluation/mesh_inside_test.h>

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Side_of_triangle_mesh.h>
#include <CGAL/Surface_mesh.h>

#include <memory>

namespace pcl_flowseg {

struct MeshInsideTest::Impl
{
  using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
  using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;
  Mesh mesh;
  std::unique_ptr<CGAL::Side_of_triangle_mesh<Mesh, Kernel>> side;
  bool valid = false;
};

MeshInsideTest::MeshInsideTest (const TriangleMesh& mesh) : impl_ (new Impl)
{
  using Mesh = Impl::Mesh;
  std::vector<Mesh::Vertex_index> ids;
  for (const auto& v : mesh.vertices)
    ids.push_back (impl_->mesh.add_vertex (Impl::Kernel::Point_3 (v.x (), v.y (), v.z ())));
  bool ok = !mesh.faces.empty ();
  for (const auto& f : mesh.faces)
    ok &= impl_->mesh.add_face (ids[static_cast<std::size_t> (f[0])], ids[static_cast<std::size_t> (f[1])],
                                ids[static_cast<std::size_t> (f[2])]) != Mesh::null_face ();
  if (ok)
  {
    impl_->side.reset (new CGAL::Side_of_triangle_mesh<Mesh, Impl::Kernel> (impl_->mesh));
    impl_->valid = true;
  }
}

MeshInsideTest::~MeshInsideTest () { delete impl_; }

bool
MeshInsideTest::valid () const
{
  return impl_->valid;
}

bool
MeshInsideTest::inside (const Eigen::Vector3d& p) const
{
  if (!impl_->valid)
    return false;
  return (*impl_->side) (Impl::Kernel::Point_3 (p.x (), p.y (), p.z ())) == CGAL::ON_BOUNDED_SIDE;
}

} // namespace pcl_flowseg

/*
 * flowseg_bench_psb - the peer method: CGAL's shape-diameter-function segmentation of a mesh.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include "sdf_peer.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/mesh_segmentation.h>

#include <exception>
#include <string>

namespace flowseg_bench {

pcl_flowseg::Status
sdfSegmentation (const pcl_flowseg::TriangleMesh& mesh, std::vector<int>& face_labels, std::size_t& segments)
{
  using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
  using SurfaceMesh = CGAL::Surface_mesh<Kernel::Point_3>;
  face_labels.clear ();
  segments = 0;
  SurfaceMesh sm;
  std::vector<SurfaceMesh::Vertex_index> vertices;
  vertices.reserve (mesh.vertices.size ());
  for (const auto& v : mesh.vertices)
    vertices.push_back (sm.add_vertex (Kernel::Point_3 (v.x (), v.y (), v.z ())));
  for (std::size_t f = 0; f < mesh.faces.size (); ++f)
  {
    const auto& t = mesh.faces[f];
    if (sm.add_face (vertices[static_cast<std::size_t> (t[0])], vertices[static_cast<std::size_t> (t[1])],
                     vertices[static_cast<std::size_t> (t[2])]) == SurfaceMesh::null_face ())
      return pcl_flowseg::Status::error ("CGAL Surface_mesh refuses face " + std::to_string (f) +
                                         " (non-manifold or degenerate)");
  }
  try
  {
    auto sdf = sm.add_property_map<SurfaceMesh::Face_index, double> ("f:sdf").first;
    CGAL::sdf_values (sm, sdf);
    auto ids = sm.add_property_map<SurfaceMesh::Face_index, std::size_t> ("f:segment").first;
    segments = CGAL::segmentation_from_sdf_values (sm, sdf, ids);
    face_labels.resize (mesh.faces.size ());
    for (SurfaceMesh::Face_index f : sm.faces ()) // faces keep their insertion order
      face_labels[static_cast<std::size_t> (f.idx ())] = static_cast<int> (ids[f]);
  }
  catch (const std::exception& e)
  {
    face_labels.clear ();
    return pcl_flowseg::Status::error (std::string ("CGAL SDF segmentation failed: ") + e.what ());
  }
  return pcl_flowseg::Status::success ();
}

} // namespace flowseg_bench

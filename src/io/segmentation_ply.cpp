/*
 * pcl_flowseg - a segmentation as PLY files a viewer shows: coloured points, the reconstructed surface.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include <pcl_flowseg/io/segmentation_ply.h>

#include <pcl_flowseg/common/interior_boundary.h>
#include <pcl_flowseg/io/atomic_file.h>
#include <pcl_flowseg/io/segment_colours.h>

#include <cmath>
#include <iomanip>
#include <ostream>

namespace pcl_flowseg {

namespace {

/** The PLY position of each label point with finite coordinates (-1: not written), and of the
  * first written copy of each vertex (for 2D faces). */
struct WrittenPoints
{
  std::vector<int> of_point;
  std::vector<int> of_vertex;
  int count = 0;
};

WrittenPoints
writtenPoints (const FlowResult& r, const pcl::PointCloud<pcl::PointXYZL>& labels)
{
  WrittenPoints w;
  w.of_point.assign (labels.size (), -1);
  w.of_vertex.assign (r.vertices.size (), -1);
  for (std::size_t i = 0; i < labels.size (); ++i)
  {
    const auto& p = labels[i];
    if (!std::isfinite (p.x) || !std::isfinite (p.y) || !std::isfinite (p.z))
      continue; // cannot be drawn: left out (and counted in the JSON summary)
    w.of_point[i] = w.count++;
    const int v = i < r.point_to_vertex.size () ? r.point_to_vertex[i] : -1;
    if (v >= 0 && w.of_vertex[static_cast<std::size_t> (v)] < 0)
      w.of_vertex[static_cast<std::size_t> (v)] = w.of_point[i];
  }
  return w;
}

std::ostream&
operator<< (std::ostream& out, const std::array<std::uint8_t, 3>& c)
{
  return out << int (c[0]) << " " << int (c[1]) << " " << int (c[2]);
}

} // namespace

Status
writeSegmentationPly (const std::string& path, const FlowResult& r, const pcl::PointCloud<pcl::PointXYZL>& labels)
{
  auto colourOf = [&] (std::uint32_t feature) {
    const bool infinity = feature != kNoSegment && feature < r.features.size () &&
                          r.segments[static_cast<std::size_t> (r.features[feature])].flows_to_infinity;
    return segmentColour (feature, infinity);
  };
  const std::vector<int> feature_of_segment = r.featureOfSegment ();
  const WrittenPoints written = writtenPoints (r, labels);
  const bool faces = r.dimension == 2;
  return writeTextFileAtomically (path, [&] (std::ostream& out) {
    out << "ply\nformat ascii 1.0\ncomment pcl_flowseg segmentation: colour = feature, grey = none or flows to infinity\n";
    out << "element vertex " << written.count << "\n";
    out << "property float x\nproperty float y\nproperty float z\n";
    out << "property uchar red\nproperty uchar green\nproperty uchar blue\n";
    if (faces)
      out << "element face " << r.cells.size () << "\nproperty list uchar int vertex_indices\n"
          << "property uchar red\nproperty uchar green\nproperty uchar blue\n";
    out << "end_header\n" << std::setprecision (9);
    for (std::size_t i = 0; i < labels.size (); ++i)
      if (written.of_point[i] >= 0)
        out << labels[i].x << " " << labels[i].y << " " << labels[i].z << " " << colourOf (labels[i].label) << "\n";
    if (!faces)
      return;
    for (const FlowCell& cell : r.cells)
    {
      // Triangles of a reported feature in its colour (as its points), the others grey.
      const int feature = feature_of_segment[static_cast<std::size_t> (cell.segment)];
      out << "3";
      for (int k = 0; k < 3; ++k)
        out << " " << written.of_vertex[static_cast<std::size_t> (cell.vertices[k])];
      out << " " << (feature < 0 ? segmentColour (kNoSegment) : colourOf (static_cast<std::uint32_t> (feature))) << "\n";
    }
  });
}

Status
writeSurfacePly (const std::string& path, const FlowResult& r)
{
  if (!r.interior.computed)
    return Status::error ("cannot write " + path + ": no interior/exterior separation was run");
  const auto facets = boundaryFacets (r);
  std::size_t inside_cells = 0;
  for (const FlowCell& c : r.cells)
    inside_cells += c.inside == 1;
  return writeTextFileAtomically (path, [&] (std::ostream& out) {
    out << "ply\nformat ascii 1.0\ncomment pcl_flowseg reconstructed surface (interior/exterior boundary)\n";
    out << "element vertex " << r.vertices.size () << "\nproperty double x\nproperty double y\nproperty double z\n";
    if (r.dimension == 3)
      out << "element face " << facets.size () << "\nproperty list uchar int vertex_indices\n";
    else
      out << "element face " << inside_cells << "\nproperty list uchar int vertex_indices\n"
          << "element edge " << facets.size () << "\nproperty int vertex1\nproperty int vertex2\n";
    out << "end_header\n" << std::setprecision (17);
    for (const auto& v : r.vertices)
      out << v.x () << " " << v.y () << " " << v.z () << "\n";
    if (r.dimension == 3)
    {
      for (const auto& t : facets)
        out << "3 " << t[0] << " " << t[1] << " " << t[2] << "\n";
      return;
    }
    for (const FlowCell& c : r.cells)
      if (c.inside == 1)
        out << "3 " << c.vertices[0] << " " << c.vertices[1] << " " << c.vertices[2] << "\n";
    for (const auto& e : facets)
      out << e[0] << " " << e[1] << "\n";
  });
}

} // namespace pcl_flowseg

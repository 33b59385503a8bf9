/*
 * pcl_flowseg - a segmentation as PLY files a viewer shows: coloured points, the reconstructed surface.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include <pcl_flowseg/io/segmentation_ply.h>

#include <pcl_flowseg/common/interior_boundary.h>
#include <pcl_flowseg/io/atomic_file.h>
#include <pcl_flowseg/io/segment_colours.h>

#include "io/output_buffer.h"

#include <cmath>
#include <cstdint>
#include <ostream>
#include <type_traits>

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

/** Writes PLY values as text (separated by spaces, a line per element) or as little-endian binary. */
class PlyValues
{
public:
  PlyValues (std::ostream& out, bool binary) : buffer_ (out), binary_ (binary) {}

  template <typename Value>
  PlyValues&
  operator<< (Value value)
  {
    if (binary_)
      buffer_.binary (value);
    else
    {
      if (!first_)
        buffer_.character (' ');
      if constexpr (std::is_floating_point_v<Value>)
        buffer_.number (value);
      else
        buffer_.integer (static_cast<std::int64_t> (value));
    }
    first_ = false;
    return *this;
  }

  PlyValues&
  operator<< (const std::array<std::uint8_t, 3>& colour)
  {
    return *this << colour[0] << colour[1] << colour[2];
  }

  /** Ends an element (a line in text). */
  void
  end ()
  {
    if (!binary_)
      buffer_.character ('\n');
    first_ = true;
  }

  OutputBuffer&
  buffer ()
  {
    return buffer_;
  }

private:
  OutputBuffer buffer_;
  bool binary_;
  bool first_ = true;
};

const char*
plyFormat (bool binary)
{
  return binary ? "format binary_little_endian 1.0\n" : "format ascii 1.0\n";
}

} // namespace

Status
writeSegmentationPly (const std::string& path, const FlowResult& r, const pcl::PointCloud<pcl::PointXYZL>& labels, bool binary)
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
    PlyValues ply (out, binary);
    ply.buffer ().text ("ply\n").text (plyFormat (binary))
        .text ("comment pcl_flowseg segmentation: colour = feature, grey = none or flows to infinity\nelement vertex ")
        .integer (written.count)
        .text ("\nproperty float x\nproperty float y\nproperty float z\nproperty uchar red\nproperty uchar green\nproperty uchar blue\n");
    if (faces)
      ply.buffer ().text ("element face ").integer (static_cast<std::int64_t> (r.cells.size ()))
          .text ("\nproperty list uchar int vertex_indices\nproperty uchar red\nproperty uchar green\nproperty uchar blue\n");
    ply.buffer ().text ("end_header\n");
    for (std::size_t i = 0; i < labels.size (); ++i)
      if (written.of_point[i] >= 0)
      {
        ply << labels[i].x << labels[i].y << labels[i].z << colourOf (labels[i].label);
        ply.end ();
      }
    if (!faces)
      return;
    for (const FlowCell& cell : r.cells)
    {
      // Triangles of a reported feature in its colour (as its points), the others grey.
      const int feature = feature_of_segment[static_cast<std::size_t> (cell.segment)];
      ply << std::uint8_t (3);
      for (int k = 0; k < 3; ++k)
        ply << std::int32_t (written.of_vertex[static_cast<std::size_t> (cell.vertices[k])]);
      ply << (feature < 0 ? segmentColour (kNoSegment) : colourOf (static_cast<std::uint32_t> (feature)));
      ply.end ();
    }
  });
}

Status
writeSurfacePly (const std::string& path, const FlowResult& r, bool binary)
{
  if (!r.interior.computed)
    return Status::error ("cannot write " + path + ": no interior/exterior separation was run");
  const auto facets = boundaryFacets (r);
  std::size_t inside_cells = 0; // the faces of a 2D surface (one pass over all cells: not in 3D)
  if (r.dimension == 2)
    for (const FlowCell& c : r.cells)
      inside_cells += c.inside == 1;
  return writeTextFileAtomically (path, [&] (std::ostream& out) {
    PlyValues ply (out, binary);
    ply.buffer ().text ("ply\n").text (plyFormat (binary))
        .text ("comment pcl_flowseg reconstructed surface (interior/exterior boundary)\nelement vertex ")
        .integer (static_cast<std::int64_t> (r.vertices.size ()))
        .text ("\nproperty double x\nproperty double y\nproperty double z\nelement face ")
        .integer (static_cast<std::int64_t> (r.dimension == 3 ? facets.size () : inside_cells))
        .text ("\nproperty list uchar int vertex_indices\n");
    if (r.dimension == 2)
      ply.buffer ().text ("element edge ").integer (static_cast<std::int64_t> (facets.size ()))
          .text ("\nproperty int vertex1\nproperty int vertex2\n");
    ply.buffer ().text ("end_header\n");
    for (const auto& v : r.vertices)
    {
      ply << v.x () << v.y () << v.z ();
      ply.end ();
    }
    if (r.dimension == 3)
    {
      for (const auto& t : facets)
      {
        ply << std::uint8_t (3) << std::int32_t (t[0]) << std::int32_t (t[1]) << std::int32_t (t[2]);
        ply.end ();
      }
      return;
    }
    for (const FlowCell& c : r.cells)
      if (c.inside == 1)
      {
        ply << std::uint8_t (3) << std::int32_t (c.vertices[0]) << std::int32_t (c.vertices[1]) << std::int32_t (c.vertices[2]);
        ply.end ();
      }
    for (const auto& e : facets)
    {
      ply << std::int32_t (e[0]) << std::int32_t (e[1]);
      ply.end ();
    }
  });
}

} // namespace pcl_flowseg

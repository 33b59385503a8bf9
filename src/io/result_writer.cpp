/*
 * pcl_flowseg - writing segmentation results: labelled PCD, JSON summary, coloured PLY.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include <pcl_flowseg/io/result_writer.h>

#include <pcl_flowseg/io/atomic_file.h>

#include <pcl/io/pcd_io.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <sstream>

namespace pcl_flowseg {

namespace {

/** Number as JSON: non-finite values become null. */
std::string
num (double v)
{
  if (!std::isfinite (v))
    return "null";
  std::ostringstream s;
  s << std::setprecision (10) << v;
  return s.str ();
}

std::string
vec (const Eigen::Vector3d& v, int dimension)
{
  std::string s = "[" + num (v.x ()) + ", " + num (v.y ());
  if (dimension != 2 || v.z () != 0.0)
    s += ", " + num (v.z ());
  return s + "]";
}

std::string
quoted (const std::string& text)
{
  std::string s = "\"";
  for (const char c : text)
  {
    switch (c)
    {
      case '"': s += "\\\""; break;
      case '\\': s += "\\\\"; break;
      case '\n': s += "\\n"; break;
      case '\t': s += "\\t"; break;
      default:
        if (static_cast<unsigned char> (c) < 0x20)
        {
          char buf[8];
          std::snprintf (buf, sizeof (buf), "\\u%04x", c);
          s += buf;
        }
        else
          s += c;
    }
  }
  return s + "\"";
}

const char*
sideName (FeatureSide side)
{
  return side == FeatureSide::Interior ? "interior" : side == FeatureSide::Exterior ? "exterior" : "both";
}

/** The parameters of a result as one JSON object, in the groups of FlowParameters. */
std::string
parametersJson (const FlowParameters& p)
{
  const DimensionMode d = p.preparation.dimension;
  const Denoising n = p.interior.denoising;
  std::string s = "{\"preparation\": {\"dimension\": ";
  s += d == DimensionMode::Automatic ? "\"auto\"" : d == DimensionMode::Planar ? "2" : "3";
  s += ", \"planar_tolerance\": " + num (p.preparation.planar_tolerance) + "}";
  s += ", \"merge\": {\"rho\": " + num (p.merge.rho) + ", \"sampling_tolerance\": " + num (p.merge.sampling_tolerance) +
       ", \"stump_ratio\": " + num (p.merge.stump_ratio) + ", \"compact_rho\": " + num (p.merge.compact_rho) +
       ", \"compact_size\": " + num (p.merge.compact_size) + "}";
  s += ", \"interior\": {\"separate\": " + std::string (p.interior.separate ? "true" : "false") + ", \"denoising\": ";
  s += n == Denoising::Automatic ? "\"auto\"" : n == Denoising::Off ? "\"off\"" : "\"always\"";
  s += ", \"viewpoint\": " + (p.interior.viewpoint ? vec (*p.interior.viewpoint, 3) : std::string ("null")) + "}";
  s += ", \"features\": \"" + std::string (sideName (p.features)) + "\"";
  s += ", \"execution\": {\"threads\": " + std::to_string (p.execution.threads) +
       ", \"memory_limit\": " + std::to_string (p.execution.memory_limit) + "}}";
  return s;
}

Status
finish (std::ofstream& out)
{
  out.flush ();
  return out.good () ? Status::success () : Status::error ("write failed (disk full?)");
}

} // namespace

std::array<std::uint8_t, 3>
segmentColour (std::uint32_t id, bool infinity)
{
  if (id == kNoSegment || infinity)
    return {{160, 160, 160}};
  const double h = std::fmod (0.13 + 0.618033988749895 * id, 1.0) * 6.0;
  const double s = 0.75, v = 0.95;
  const int sector = static_cast<int> (h);
  const double f = h - sector, p = v * (1 - s), q = v * (1 - s * f), t = v * (1 - s * (1 - f));
  double r, g, b;
  switch (sector % 6)
  {
    case 0: r = v; g = t; b = p; break;
    case 1: r = q; g = v; b = p; break;
    case 2: r = p; g = v; b = t; break;
    case 3: r = p; g = q; b = v; break;
    case 4: r = t; g = p; b = v; break;
    default: r = v; g = p; b = q; break;
  }
  return {{static_cast<std::uint8_t> (r * 255), static_cast<std::uint8_t> (g * 255), static_cast<std::uint8_t> (b * 255)}};
}

Status
writeLabelCloud (const std::string& path, const pcl::PointCloud<pcl::PointXYZL>& labels, bool binary)
{
  return writeFileAtomically (path, [&] (const std::string& tmp) {
    pcl::PCDWriter writer;
    const int rc = binary ? writer.writeBinary (tmp, labels) : writer.writeASCII (tmp, labels, 8);
    return rc == 0 ? Status::success () : Status::error ("PCD writer failed");
  });
}

Status
writePointCloud (const std::string& path, const pcl::PointCloud<pcl::PointXYZ>& cloud, bool binary)
{
  return writeFileAtomically (path, [&] (const std::string& tmp) {
    pcl::PCDWriter writer;
    const int rc = binary ? writer.writeBinary (tmp, cloud) : writer.writeASCII (tmp, cloud, 7);
    return rc == 0 ? Status::success () : Status::error ("PCD writer failed");
  });
}

Status
writeSegmentationJson (const std::string& path, const FlowResult& r, const RunInfo& info)
{
  return writeFileAtomically (path, [&] (const std::string& tmp) {
    std::ofstream out (tmp);
    if (!out)
      return Status::error ("cannot create file");
    const int d = r.dimension;
    out << "{\n";
    out << "  \"input\": " << quoted (info.input) << ",\n";
    out << "  \"dimension\": " << d << ",\n";
    out << "  \"rho\": " << num (r.parameters.merge.rho) << ",\n";
    out << "  \"parameters\": " << parametersJson (r.parameters) << ",\n";
    out << "  \"points\": " << r.input_points << ",\n";
    out << "  \"non_finite_points\": " << r.non_finite_points << ",\n";
    out << "  \"duplicate_points\": " << r.duplicate_points << ",\n";
    out << "  \"vertices\": " << r.vertices.size () << ",\n";
    out << "  \"cells\": " << r.cells.size () << ",\n";
    out << "  \"maxima\": " << r.maxima.size () << ",\n";
    out << "  \"stable_manifolds\": " << r.manifolds.size () << ",\n";
    out << "  \"segment_count\": " << r.segments.size () << ",\n";
    std::size_t unlabelled = 0;
    for (std::size_t i = 0; i < r.point_labels.size (); ++i)
      unlabelled += r.point_labels[i] == kNoSegment && r.point_to_vertex[i] >= 0;
    out << "  \"unlabelled_points\": " << unlabelled << ",\n";
    const char* side = sideName (r.parameters.features);
    out << "  \"features\": {\"side\": \"" << (r.interior.computed ? side : "all") << "\", \"segments\": [";
    for (std::size_t k = 0; k < r.features.size (); ++k)
      out << (k ? ", " : "") << r.features[k];
    out << "]},\n";
    const InteriorReport& in = r.interior;
    out << "  \"interior\": {\"computed\": " << (in.computed ? "true" : "false");
    if (in.computed)
      out << ", \"inside_volume\": " << num (in.inside_volume) << ", \"inside_cells\": " << in.inside_cells
          << ", \"boundary_facets\": " << in.boundary_facets << ", \"closed\": " << (in.closed ? "true" : "false")
          << ", \"manifold\": " << (in.manifold ? "true" : "false") << ", \"nonmanifold_edges\": " << in.nonmanifold_edges
          << ", \"nonmanifold_vertices\": " << in.nonmanifold_vertices << ", \"vertices_off_boundary\": " << in.vertices_off_boundary
          << ", \"surface_variation\": " << (in.surface_variation < 0 ? std::string ("null") : num (in.surface_variation)) << ", \"smoothing_passes\": " << in.smoothing_passes
          << ", \"ray_cells\": " << in.ray_cells;
    out << "},\n";
    double reported = 0.0;
    for (int k : r.features)
      reported += r.segments[static_cast<std::size_t> (k)].volume;
    std::vector<char> is_feature (r.segments.size (), 0);
    for (int k : r.features)
      is_feature[static_cast<std::size_t> (k)] = 1;
    out << "  \"significance\": " << num (info.significance) << ",\n";
    out << "  \"segments\": [";
    for (std::size_t k = 0; k < r.segments.size (); ++k)
    {
      const FlowSegment& s = r.segments[k];
      out << (k ? ",\n" : "\n") << "    {\"id\": " << k << ", \"flows_to_infinity\": " << (s.flows_to_infinity ? "true" : "false")
          << ", \"interior\": " << (s.interior == 1 ? "true" : s.interior == 0 ? "false" : "null")
          << ", \"significant\": " << (is_feature[k] && s.volume > info.significance * reported ? "true" : "false")
          << ", \"volume\": " << num (s.volume) << ", \"centroid\": " << vec (s.centroid, d)
          << ", \"point_count\": " << s.point_count << ", \"cell_count\": " << s.cell_count
          << ", \"maxima_merged\": " << s.maxima.size () << ", \"maximum_height\": " << num (s.maximum.height);
      if (!s.flows_to_infinity)
        out << ", \"maximum_location\": " << vec (s.maximum.location, d);
      out << "}";
    }
    out << "\n  ],\n";
    out << "  \"adjacency\": [";
    for (std::size_t k = 0; k < r.segment_adjacency.size (); ++k)
    {
      const SaddleFacet& s = r.segment_adjacency[k];
      out << (k ? ",\n" : "\n") << "    {\"a\": " << s.segment_a << ", \"b\": " << s.segment_b
          << ", \"saddle_height\": " << num (s.squared_radius) << ", \"saddle_location\": " << vec (s.location, d) << "}";
    }
    out << "\n  ],\n";
    const StageTimings& t = r.timings;
    out << "  \"timings_ms\": {\"read\": " << num (info.read_ms) << ", \"preparation\": " << num (t.preparation_ms)
        << ", \"delaunay\": " << num (t.delaunay_ms) << ", \"flow\": " << num (t.flow_ms)
        << ", \"manifolds\": " << num (t.manifolds_ms)
        << ", \"interior\": " << num (t.interior_ms) << ", \"merge\": " << num (t.merge_ms)
        << ", \"labels\": " << num (t.labels_ms) << ", \"total\": " << num (t.total_ms) << "},\n";
    out << "  \"warnings\": [";
    for (std::size_t k = 0; k < r.warnings.size (); ++k)
      out << (k ? ", " : "") << quoted (r.warnings[k]);
    out << "]\n}\n";
    return finish (out);
  });
}

Status
writeSegmentationPly (const std::string& path, const FlowResult& r, const pcl::PointCloud<pcl::PointXYZL>& labels)
{
  return writeFileAtomically (path, [&] (const std::string& tmp) {
    std::ofstream out (tmp, std::ios::binary);
    if (!out)
      return Status::error ("cannot create file");
    auto isInfinity = [&] (std::uint32_t l) {
      return l != kNoSegment && l < r.features.size () && r.segments[static_cast<std::size_t> (r.features[l])].flows_to_infinity;
    };
    std::vector<int> feature_of_segment (r.segments.size (), -1);
    for (std::size_t k = 0; k < r.features.size (); ++k)
      feature_of_segment[static_cast<std::size_t> (r.features[k])] = static_cast<int> (k);
    const bool faces = r.dimension == 2;
    // Points with non-finite coordinates cannot be drawn: they are left out of the PLY (and
    // counted in the JSON summary); faces index the first written copy of each vertex.
    std::vector<int> written (labels.size (), -1);
    std::vector<int> vertex_point (r.vertices.size (), -1);
    int count = 0;
    for (std::size_t i = 0; i < labels.size (); ++i)
    {
      const auto& p = labels[i];
      if (!std::isfinite (p.x) || !std::isfinite (p.y) || !std::isfinite (p.z))
        continue;
      written[i] = count++;
      const int v = i < r.point_to_vertex.size () ? r.point_to_vertex[i] : -1;
      if (v >= 0 && vertex_point[static_cast<std::size_t> (v)] < 0)
        vertex_point[static_cast<std::size_t> (v)] = written[i];
    }
    out << "ply\nformat ascii 1.0\ncomment pcl_flowseg segmentation: colour = feature, grey = none or flows to infinity\n";
    out << "element vertex " << count << "\n";
    out << "property float x\nproperty float y\nproperty float z\n";
    out << "property uchar red\nproperty uchar green\nproperty uchar blue\n";
    if (faces)
    {
      out << "element face " << r.cells.size () << "\n";
      out << "property list uchar int vertex_indices\n";
      out << "property uchar red\nproperty uchar green\nproperty uchar blue\n";
    }
    out << "end_header\n";
    out << std::setprecision (9);
    for (std::size_t i = 0; i < labels.size (); ++i)
    {
      if (written[i] < 0)
        continue;
      const auto& p = labels[i];
      const auto c = segmentColour (p.label, isInfinity (p.label));
      out << p.x << " " << p.y << " " << p.z << " " << int (c[0]) << " " << int (c[1]) << " " << int (c[2]) << "\n";
    }
    if (faces)
    {
      for (const FlowCell& cell : r.cells)
      {
        // Triangles of a reported feature in its colour (as its points), the others grey.
        const int feature = feature_of_segment[static_cast<std::size_t> (cell.segment)];
        const auto c = feature < 0 ? segmentColour (kNoSegment) : segmentColour (static_cast<std::uint32_t> (feature), isInfinity (static_cast<std::uint32_t> (feature)));
        out << "3";
        for (int k = 0; k < 3; ++k)
          out << " " << vertex_point[static_cast<std::size_t> (cell.vertices[k])];
        out << " " << int (c[0]) << " " << int (c[1]) << " " << int (c[2]) << "\n";
      }
    }
    return finish (out);
  });
}

Status
writeSegmentationSvg (const std::string& path, const FlowResult& r)
{
  if (r.dimension != 2)
    return Status::error ("cannot write " + path + ": SVG output is for 2D results");
  // Plane coordinates: an orthonormal basis of the points' plane (the z = const plane when it is one).
  Eigen::Vector3d o = r.vertices.front (), u = Eigen::Vector3d::UnitX (), v = Eigen::Vector3d::UnitY ();
  if (!r.cells.empty ())
  {
    const FlowCell& c = r.cells.front ();
    const Eigen::Vector3d n = (r.vertices[static_cast<std::size_t> (c.vertices[1])] - r.vertices[static_cast<std::size_t> (c.vertices[0])])
                                  .cross (r.vertices[static_cast<std::size_t> (c.vertices[2])] - r.vertices[static_cast<std::size_t> (c.vertices[0])])
                                  .normalized ();
    if (std::abs (n.z ()) < 0.999)
    {
      u = n.cross (Eigen::Vector3d::UnitZ ()).normalized ();
      v = n.cross (u).normalized ();
    }
  }
  std::vector<Eigen::Vector2d> p2;
  Eigen::Vector2d lo (1e300, 1e300), hi (-1e300, -1e300);
  for (const auto& x : r.vertices)
  {
    p2.emplace_back ((x - o).dot (u), (x - o).dot (v));
    lo = lo.cwiseMin (p2.back ());
    hi = hi.cwiseMax (p2.back ());
  }
  const double span = std::max ({hi.x () - lo.x (), hi.y () - lo.y (), 1e-300});
  const double scale = 760.0 / span;
  auto X = [&] (int i) { return 20 + (p2[static_cast<std::size_t> (i)].x () - lo.x ()) * scale; };
  auto Y = [&] (int i) { return 20 + (hi.y () - p2[static_cast<std::size_t> (i)].y ()) * scale; };
  std::vector<int> feature_of_segment (r.segments.size (), -1);
  for (std::size_t k = 0; k < r.features.size (); ++k)
    feature_of_segment[static_cast<std::size_t> (r.features[k])] = static_cast<int> (k);
  return writeFileAtomically (path, [&] (const std::string& tmp) {
    std::ofstream out (tmp);
    if (!out)
      return Status::error ("cannot create file");
    const int w = static_cast<int> (40 + (hi.x () - lo.x ()) * scale), h = static_cast<int> (40 + (hi.y () - lo.y ()) * scale);
    out << std::fixed << std::setprecision (2);
    out << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << w << "\" height=\"" << h << "\" viewBox=\"0 0 " << w << " " << h
        << "\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n<g stroke-width=\"0.4\">\n";
    for (const FlowCell& c : r.cells)
    {
      const int f = feature_of_segment[static_cast<std::size_t> (c.segment)];
      const auto col = f < 0 ? std::array<std::uint8_t, 3>{{235, 235, 235}} : segmentColour (static_cast<std::uint32_t> (f), r.segments[static_cast<std::size_t> (c.segment)].flows_to_infinity);
      out << "<polygon points=\"" << X (c.vertices[0]) << "," << Y (c.vertices[0]) << " " << X (c.vertices[1]) << "," << Y (c.vertices[1]) << " "
          << X (c.vertices[2]) << "," << Y (c.vertices[2]) << "\" fill=\"rgb(" << int (col[0]) << "," << int (col[1]) << "," << int (col[2])
          << ")\" stroke=\"rgb(" << int (col[0]) << "," << int (col[1]) << "," << int (col[2]) << ")\"/>\n";
    }
    out << "</g>\n<g stroke=\"black\" stroke-width=\"0.6\">\n";
    for (const FlowCell& c : r.cells)
      for (int i = 0; i < 3; ++i)
      {
        const int nb = c.neighbors[i];
        if (nb < 0 || r.cells[static_cast<std::size_t> (nb)].manifold == c.manifold || &c > &r.cells[static_cast<std::size_t> (nb)])
          continue;
        const int a = c.vertices[(i + 1) % 3], b = c.vertices[(i + 2) % 3];
        out << "<line x1=\"" << X (a) << "\" y1=\"" << Y (a) << "\" x2=\"" << X (b) << "\" y2=\"" << Y (b) << "\"/>\n";
      }
    out << "</g>\n<g stroke=\"#1f4fd0\" stroke-width=\"1.6\">\n";
    for (const auto& e : boundaryFacets (r))
      out << "<line x1=\"" << X (e[0]) << "\" y1=\"" << Y (e[0]) << "\" x2=\"" << X (e[1]) << "\" y2=\"" << Y (e[1]) << "\"/>\n";
    out << "</g>\n<g fill=\"black\">\n";
    for (std::size_t i = 0; i < p2.size (); ++i)
      out << "<circle cx=\"" << X (static_cast<int> (i)) << "\" cy=\"" << Y (static_cast<int> (i)) << "\" r=\"1\"/>\n";
    out << "</g>\n<g fill=\"#d02020\">\n";
    for (int k : r.features)
    {
      const FlowSegment& s = r.segments[static_cast<std::size_t> (k)];
      for (int m : s.maxima)
      {
        const Eigen::Vector3d& x = r.maxima[static_cast<std::size_t> (m)].location;
        out << "<circle cx=\"" << 20 + ((x - o).dot (u) - lo.x ()) * scale << "\" cy=\"" << 20 + (hi.y () - (x - o).dot (v)) * scale
            << "\" r=\"2.5\"/>\n";
      }
    }
    out << "</g>\n</svg>\n";
    return finish (out);
  });
}

std::vector<std::array<int, 3>>
boundaryFacets (const FlowResult& r)
{
  std::vector<std::array<int, 3>> out;
  if (!r.interior.computed)
    return out;
  const int d = r.dimension, f = d + 1;
  for (const FlowCell& c : r.cells)
  {
    if (c.inside != 1)
      continue;
    for (int i = 0; i < f; ++i)
    {
      const int nb = c.neighbors[i];
      if (nb >= 0 && r.cells[static_cast<std::size_t> (nb)].inside == 1)
        continue;
      std::array<int, 3> t{{c.vertices[(i + 1) % f], c.vertices[(i + 2) % f], d == 3 ? c.vertices[(i + 3) % f] : -1}};
      // Orient away from the cell: the apex must lie behind the facet.
      const Eigen::Vector3d& apex = r.vertices[static_cast<std::size_t> (c.vertices[i])];
      const Eigen::Vector3d& a = r.vertices[static_cast<std::size_t> (t[0])];
      const Eigen::Vector3d& b = r.vertices[static_cast<std::size_t> (t[1])];
      if (d == 3)
      {
        const Eigen::Vector3d& e = r.vertices[static_cast<std::size_t> (t[2])];
        if ((b - a).cross (e - a).dot (apex - a) > 0)
          std::swap (t[1], t[2]);
      }
      else
      {
        // In the cells' plane: the interior (apex) on the left of a -> b.
        const Eigen::Vector3d normal = (b - a).cross (apex - a);
        const Eigen::Vector3d& p0 = r.vertices[static_cast<std::size_t> (c.vertices[0])];
        const Eigen::Vector3d& p1 = r.vertices[static_cast<std::size_t> (c.vertices[1])];
        const Eigen::Vector3d& p2 = r.vertices[static_cast<std::size_t> (c.vertices[2])];
        const Eigen::Vector3d plane = (p1 - p0).cross (p2 - p0); // CGAL faces are counter-clockwise
        if (normal.dot (plane) < 0)
          std::swap (t[0], t[1]);
      }
      out.push_back (t);
    }
  }
  return out;
}

Status
writeSurfacePly (const std::string& path, const FlowResult& r)
{
  if (!r.interior.computed)
    return Status::error ("cannot write " + path + ": no interior/exterior separation was run");
  const auto facets = boundaryFacets (r);
  return writeFileAtomically (path, [&] (const std::string& tmp) {
    std::ofstream out (tmp, std::ios::binary);
    if (!out)
      return Status::error ("cannot create file");
    std::size_t inside_cells = 0;
    for (const FlowCell& c : r.cells)
      inside_cells += c.inside == 1;
    out << "ply\nformat ascii 1.0\ncomment pcl_flowseg reconstructed surface (interior/exterior boundary)\n";
    out << "element vertex " << r.vertices.size () << "\nproperty double x\nproperty double y\nproperty double z\n";
    if (r.dimension == 3)
      out << "element face " << facets.size () << "\nproperty list uchar int vertex_indices\n";
    else
    {
      out << "element face " << inside_cells << "\nproperty list uchar int vertex_indices\n";
      out << "element edge " << facets.size () << "\nproperty int vertex1\nproperty int vertex2\n";
    }
    out << "end_header\n" << std::setprecision (17);
    for (const auto& v : r.vertices)
      out << v.x () << " " << v.y () << " " << v.z () << "\n";
    if (r.dimension == 3)
      for (const auto& t : facets)
        out << "3 " << t[0] << " " << t[1] << " " << t[2] << "\n";
    else
    {
      for (const FlowCell& c : r.cells)
        if (c.inside == 1)
          out << "3 " << c.vertices[0] << " " << c.vertices[1] << " " << c.vertices[2] << "\n";
      for (const auto& e : facets)
        out << e[0] << " " << e[1] << "\n";
    }
    return finish (out);
  });
}

} // namespace pcl_flowseg

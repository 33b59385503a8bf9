/*
 * pcl_flowseg - the JSON summary of a segmentation: parameters, counts, features, segments, saddles.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include <pcl_flowseg/io/segmentation_json.h>

#include <pcl_flowseg/common/flow_parameter_table.h>
#include <pcl_flowseg/io/atomic_file.h>
#include <pcl_flowseg/io/json_text.h>

#include <cstdlib>
#include <optional>
#include <ostream>
#include <vector>

namespace pcl_flowseg {

namespace {

std::string
num (double v)
{
  return jsonNumber (v);
}

/** A point as [x, y] in 2D (when z is 0) or [x, y, z]. */
std::string
vec (const Eigen::Vector3d& v, int dimension)
{
  std::string s = "[" + num (v.x ()) + ", " + num (v.y ());
  if (dimension != 2 || v.z () != 0.0)
    s += ", " + num (v.z ());
  return s + "]";
}

const char*
sideName (FeatureSide side)
{
  return side == FeatureSide::Interior ? "interior" : side == FeatureSide::Exterior ? "exterior" : "both";
}

/** The value of a parameter table row's \a text as JSON. */
std::string
parameterJson (const ParameterInfo& info, const std::string& text)
{
  switch (info.type)
  {
  case ParameterType::Number:
    return num (std::strtod (text.c_str (), nullptr));
  case ParameterType::Count:
  case ParameterType::Switch:
    return text;
  case ParameterType::Point:
  {
    std::optional<Eigen::Vector3d> point;
    parsePoint (text, point);
    return point ? vec (*point, 3) : std::string ("null");
  }
  case ParameterType::Choice:
  case ParameterType::Weights:
    break;
  }
  return jsonString (text);
}

/** The parameters as one JSON object, a member per row of flowParameterTable (its name and
  * spelling), in the table's groups; a group of one row of the same name is that member alone. */
std::string
parametersJson (const FlowParameters& p)
{
  std::string s = "{", group;
  for (const auto& spec : flowParameterTable ().specs)
  {
    const std::string value = parameterJson (spec.info, spec.get (p));
    if (spec.info.group != group)
    {
      s += group.empty () || group == "features" ? "" : "}";
      s += (group.empty () ? "\"" : ", \"") + spec.info.group + "\": ";
      group = spec.info.group;
      if (spec.info.name == group)
      {
        s += value;
        continue;
      }
      s += "{";
    }
    else
      s += ", ";
    s += "\"" + spec.info.name + "\": " + value;
  }
  return s + (group == "features" ? "}" : "}}");
}

void
writeCounts (std::ostream& out, const FlowResult& r, const RunInfo& info)
{
  out << "  \"input\": " << jsonString (info.input) << ",\n";
  out << "  \"dimension\": " << r.dimension << ",\n";
  out << "  \"rho\": " << num (r.parameters.merge.rho) << ",\n";
  out << "  \"parameters\": " << parametersJson (r.parameters) << ",\n";
  out << "  \"points\": " << r.input_points << ",\n";
  out << "  \"non_finite_points\": " << r.non_finite_points << ",\n";
  out << "  \"duplicate_points\": " << r.duplicate_points << ",\n";
  out << "  \"outlier_points\": " << r.outlier_points << ",\n";
  out << "  \"hidden_side_vertices\": " << r.hidden_side_vertices << ",\n";
  out << "  \"smoothing_passes\": " << r.smoothing_passes << ",\n";
  out << "  \"vertices\": " << r.vertices.size () << ",\n";
  out << "  \"cells\": " << r.cells.size () << ",\n";
  out << "  \"maxima\": " << r.maxima.size () << ",\n";
  out << "  \"stable_manifolds\": " << r.manifolds.size () << ",\n";
  out << "  \"segment_count\": " << r.segments.size () << ",\n";
  out << "  \"unlabelled_points\": " << r.unlabelledPoints () << ",\n";
  out << "  \"features\": {\"side\": \"" << (r.interior.computed ? sideName (r.parameters.features) : "all") << "\", \"segments\": [";
  for (std::size_t k = 0; k < r.features.size (); ++k)
    out << (k ? ", " : "") << r.features[k];
  out << "]},\n";
}

void
writeInterior (std::ostream& out, const InteriorReport& in)
{
  out << "  \"interior\": {\"computed\": " << jsonBool (in.computed);
  if (in.computed)
    out << ", \"inside_volume\": " << num (in.inside_volume) << ", \"inside_cells\": " << in.inside_cells
        << ", \"boundary_facets\": " << in.boundary_facets << ", \"closed\": " << jsonBool (in.closed)
        << ", \"manifold\": " << jsonBool (in.manifold) << ", \"nonmanifold_edges\": " << in.nonmanifold_edges
        << ", \"nonmanifold_vertices\": " << in.nonmanifold_vertices << ", \"vertices_off_boundary\": " << in.vertices_off_boundary
        << ", \"surface_variation\": " << (in.surface_variation < 0 ? std::string ("null") : num (in.surface_variation))
        << ", \"smoothing_passes\": " << in.smoothing_passes << ", \"ray_cells\": " << in.ray_cells << ", \"opening_cells\": " << in.opening_cells
        << ", \"repaired_cells\": " << in.repaired_cells << ", \"island_cells\": " << in.island_cells;
  out << "},\n";
}

void
writeSegments (std::ostream& out, const FlowResult& r, double significance)
{
  std::vector<char> significant (r.segments.size (), 0);
  for (int k : significantSegments (r, r.features, significance))
    significant[static_cast<std::size_t> (k)] = 1;
  out << "  \"significance\": " << num (significance) << ",\n";
  out << "  \"segments\": [";
  for (std::size_t k = 0; k < r.segments.size (); ++k)
  {
    const FlowSegment& s = r.segments[k];
    out << (k ? ",\n" : "\n") << "    {\"id\": " << k << ", \"flows_to_infinity\": " << jsonBool (s.flows_to_infinity)
        << ", \"interior\": " << (s.interior == 1 ? "true" : s.interior == 0 ? "false" : "null")
        << ", \"significant\": " << jsonBool (significant[k]) << ", \"volume\": " << num (s.volume)
        << ", \"centroid\": " << vec (s.centroid, r.dimension) << ", \"point_count\": " << s.point_count
        << ", \"cell_count\": " << s.cell_count << ", \"maxima_merged\": " << s.maxima.size ()
        << ", \"maximum_height\": " << num (s.maximum.height);
    if (!s.flows_to_infinity)
      out << ", \"maximum_location\": " << vec (s.maximum.location, r.dimension);
    out << "}";
  }
  out << "\n  ],\n";
}

void
writeAdjacency (std::ostream& out, const FlowResult& r)
{
  out << "  \"adjacency\": [";
  for (std::size_t k = 0; k < r.segment_adjacency.size (); ++k)
  {
    const SaddleFacet& s = r.segment_adjacency[k];
    out << (k ? ",\n" : "\n") << "    {\"a\": " << s.segment_a << ", \"b\": " << s.segment_b
        << ", \"saddle_height\": " << num (s.squared_radius) << ", \"saddle_location\": " << vec (s.location, r.dimension) << "}";
  }
  out << "\n  ],\n";
}

void
writeTimingsAndWarnings (std::ostream& out, const FlowResult& r, const RunInfo& info)
{
  const StageTimings& t = r.timings;
  out << "  \"timings_ms\": {\"read\": " << num (info.read_ms) << ", \"preparation\": " << num (t.preparation_ms)
      << ", \"noise\": " << num (t.noise_ms)
      << ", \"delaunay\": " << num (t.delaunay_ms) << ", \"flow\": " << num (t.flow_ms)
      << ", \"manifolds\": " << num (t.manifolds_ms) << ", \"interior\": " << num (t.interior_ms)
      << ", \"merge\": " << num (t.merge_ms) << ", \"labels\": " << num (t.labels_ms) << ", \"total\": " << num (t.total_ms)
      << "},\n";
  out << "  \"warnings\": [";
  for (std::size_t k = 0; k < r.warnings.size (); ++k)
    out << (k ? ", " : "") << jsonString (r.warnings[k]);
  out << "]\n";
}

} // namespace

Status
writeSegmentationJson (const std::string& path, const FlowResult& r, const RunInfo& info)
{
  return writeTextFileAtomically (path, [&] (std::ostream& out) {
    out << "{\n";
    writeCounts (out, r, info);
    out << "  \"noise\": {\"sigma\": " << num (r.noise.sigma) << ", \"share\": " << num (r.noise.share)
        << ", \"isolated_share\": " << num (r.noise.isolated_share)
        << ", \"detached_share\": " << num (r.noise.detached_share) << ", \"roughness\": " << num (r.noise.roughness)
        << ", \"points_used\": " << r.noise.points_used
        << "},\n";
    writeInterior (out, r.interior);
    writeSegments (out, r, info.significance);
    writeAdjacency (out, r);
    writeTimingsAndWarnings (out, r, info);
    out << "}\n";
  });
}

} // namespace pcl_flowseg

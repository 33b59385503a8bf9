/*
 * flowseg_segment: segments a point sample (PCD, PLY, XYZ/TXT, OFF/OBJ vertices) by flow
 * discretization and writes labels (PCD), a summary (JSON), coloured PLY, the surface and, in 2D, SVG.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include "common/flow_options.h"
#include "common/huge_page_malloc.h"
#include "common/options.h"

#include <pcl_flowseg/common/feature_significance.h>
#include <pcl_flowseg/io/point_cloud_writer.h>
#include <pcl_flowseg/io/point_io.h>
#include <pcl_flowseg/io/segmentation_json.h>
#include <pcl_flowseg/io/segmentation_ply.h>
#include <pcl_flowseg/io/segmentation_svg.h>
#include <pcl_flowseg/segmentation/flow_segmentation.h>

#include <pcl/console/print.h>

#include <chrono>
#include <cstdio>
#include <future>
#include <iostream>
#include <string>
#include <thread>
#include <vector>

namespace {

using flowseg_app::OptionParser;

struct Options
{
  std::string input, prefix;
  pcl_flowseg::FlowParameters params;
  double significance = pcl_flowseg::kDefaultSignificance;
  bool use_normals = false, use_sensor_origin = false, binary = false, quiet = false, surface = true;
};

OptionParser
makeParser (Options& o)
{
  OptionParser p ("flowseg_segment", "flowseg_segment INPUT [options]",
                  "Segments a point sample of a closed curve (2D) or surface (3D) into features by the flow of\n"
                  "its distance function (Dey, Giesen, Goswami 2003).\n\n"
                  "INPUT  .pcd | .ply | .xyz/.txt/.csv (x y [z] per line) | .off/.obj (mesh vertices)");
  flowseg_app::addSegmentationOptions (p, o.params);
  p.number ("--significance", "F", "features above this share of the reported volume are marked\n\"significant\" in the JSON and counted in the summary",
            o.significance, [] (double v) { return pcl_flowseg::checkSignificance (v); });
  p.flag ("--use-normals", "use the file's normals (must point outwards) as in/out evidence", o.use_normals);
  flowseg_app::addViewpointOptions (p, o.params.interior.viewpoint, o.use_sensor_origin);
  p.text ("-o, --output", "PREFIX", "output prefix (default: INPUT without its extension)", o.prefix);
  p.flag ("--binary", "write the label PCD and the PLY files in binary: smaller, faster to\nwrite and read (default ASCII, which any tool reads and a diff shows)", o.binary);
  bool* surface = &o.surface;
  p.action ("--no-surface", "do not write PREFIX.surface.ply", [surface] () { *surface = false; });
  flowseg_app::addThreadsOption (p, o.params.execution.threads);
  p.flag ("-q, --quiet", "no progress or summary on stderr", o.quiet);
  p.epilogue (
      "The result is the same for every number of threads.\n\n"
      "Writes PREFIX.labels.pcd (PointXYZL, one point per input point, in input order; label = feature\n"
      "index, 4294967295 = none), PREFIX.json (parameters, counts, features, segments, adjacency,\n"
      "interior/exterior summary, timings in ms), PREFIX.ply (points, and 2D triangles, coloured by\n"
      "feature), PREFIX.surface.ply (the reconstructed surface: 3D triangles, 2D interior triangles\n"
      "and the curve) and, for 2D input, PREFIX.svg (triangles coloured by feature, Gabriel edges,\n"
      "curve, maxima).\n"
      "Exit status: 0 on success, 1 when the input cannot be read or segmented, 2 on bad options.");
  return p;
}

/** Checks what single options cannot: the input, options that exclude each other. */
int
checkOptions (const OptionParser& p, const std::vector<std::string>& inputs, Options& o)
{
  if (inputs.empty ())
    return p.usageError ("no input file given");
  if (inputs.size () > 1)
    return p.usageError ("more than one input file ('" + inputs[0] + "', '" + inputs[1] + "')");
  o.input = inputs[0];
  if (!o.params.interior.separate && o.use_normals)
    return p.usageError ("--no-separate-interior excludes --use-normals");
  if (const int status = flowseg_app::checkViewpointOptions (p, o.params, o.use_sensor_origin); status != flowseg_app::kContinue)
    return status;
  if (o.prefix.empty ())
  {
    const std::size_t slash = o.input.find_last_of ('/'), dot = o.input.find_last_of ('.');
    o.prefix = (dot == std::string::npos || (slash != std::string::npos && dot < slash)) ? o.input : o.input.substr (0, dot);
  }
  return flowseg_app::kContinue;
}

/** Every output file; the first failure's message, or "". */
std::string
writeOutputs (const Options& o, const pcl::FlowSegmentation<pcl::PointNormal>& seg, double read_ms)
{
  const pcl_flowseg::FlowResult& result = seg.getResult ();
  pcl::PointCloud<pcl::PointXYZL> labels;
  seg.getLabelCloud (labels);
  pcl_flowseg::RunInfo info;
  info.input = o.input;
  info.read_ms = read_ms;
  info.significance = o.significance;
  // The surface, the largest file, is written beside the others when a second thread is allowed.
  const bool surface = o.surface && o.params.interior.separate;
  const bool beside = o.params.execution.threads != 1 && std::thread::hardware_concurrency () > 1;
  std::future<pcl_flowseg::Status> surface_written;
  if (surface && beside)
    surface_written = std::async (std::launch::async, [&] () {
      return pcl_flowseg::writeSurfacePly (o.prefix + ".surface.ply", result, o.binary);
    });
  std::vector<pcl_flowseg::Status> written = {pcl_flowseg::writeLabelCloud (o.prefix + ".labels.pcd", labels, o.binary),
                                              pcl_flowseg::writeSegmentationJson (o.prefix + ".json", result, info),
                                              pcl_flowseg::writeSegmentationPly (o.prefix + ".ply", result, labels, o.binary)};
  if (surface)
    written.push_back (beside ? surface_written.get () : pcl_flowseg::writeSurfacePly (o.prefix + ".surface.ply", result, o.binary));
  if (result.dimension == 2)
    written.push_back (pcl_flowseg::writeSegmentationSvg (o.prefix + ".svg", result));
  for (const auto& s : written)
    if (!s)
      return s.message;
  return std::string ();
}

void
printSummary (const Options& o, const pcl_flowseg::FlowResult& r, double read_ms)
{
  std::size_t interior = 0;
  for (const auto& s : r.segments)
    interior += s.interior == 1;
  const std::size_t significant = pcl_flowseg::significantSegments (r, r.features, o.significance).size ();
  std::fprintf (stderr,
                "%dD: %zu points (%zu non-finite, %zu duplicates, %zu outliers), %zu cells, %zu maxima, "
                "%zu segments after merging with rho=%g (%zu interior), %zu features reported (%zu significant), %zu points unlabelled\n",
                r.dimension, r.input_points, r.non_finite_points, r.duplicate_points, r.outlier_points, r.cells.size (), r.maxima.size (),
                r.segments.size (), r.parameters.merge.rho, interior, r.features.size (), significant, r.unlabelledPoints ());
  std::fprintf (stderr, "noise: estimated sigma %.4g (%.3f%% of the bounding-box diagonal), roughness %.3f, %.3f%% of the points isolated, %.3f%% detached, %u smoothing pass(es) before the triangulation\n",
                r.noise.sigma, 100.0 * r.noise.share, r.noise.roughness, 100.0 * r.noise.isolated_share,
                100.0 * r.noise.detached_share, r.smoothing_passes);
  if (r.interior.computed)
    std::fprintf (stderr, "interior: %.4g volume in %zu cells, boundary %zu facets, %s, %s (%zu cells relabelled), %zu samples off the boundary, %d smoothing pass(es), %zu vertices guessed on the hidden side\n",
                  r.interior.inside_volume, r.interior.inside_cells, r.interior.boundary_facets,
                  r.interior.closed ? "closed" : "NOT closed", r.interior.manifold ? "manifold" : "not manifold",
                  r.interior.repaired_cells, r.interior.vertices_off_boundary, r.interior.smoothing_passes,
                  r.hidden_side_vertices);
  const auto& t = r.timings;
  std::fprintf (stderr, "time ms: read %.1f, preparation %.1f, noise %.1f, delaunay %.1f, flow %.1f, manifolds %.1f, interior %.1f, merge %.1f, labels %.1f, total %.1f\n",
                read_ms, t.preparation_ms, t.noise_ms, t.delaunay_ms, t.flow_ms, t.manifolds_ms, t.interior_ms, t.merge_ms, t.labels_ms, t.total_ms);
  std::fprintf (stderr, "wrote %s.labels.pcd, %s.json, %s.ply%s%s\n", o.prefix.c_str (), o.prefix.c_str (), o.prefix.c_str (),
                o.surface && o.params.interior.separate ? (", " + o.prefix + ".surface.ply").c_str () : "",
                r.dimension == 2 ? (", " + o.prefix + ".svg").c_str () : "");
}

} // namespace

int
main (int argc, char** argv)
{
  flowseg_app::relaunchWithHugePageMalloc (argv);
  Options o;
  const OptionParser parser = makeParser (o);
  std::vector<std::string> inputs;
  if (const int status = parser.parse (argc, argv, inputs); status != flowseg_app::kContinue)
    return status;
  if (const int status = checkOptions (parser, inputs, o); status != flowseg_app::kContinue)
    return status;
  if (o.quiet)
    pcl::console::setVerbosityLevel (pcl::console::L_ALWAYS);

  if (o.use_sensor_origin && !pcl_flowseg::carriesSensorOrigin (o.input))
    return parser.failure (o.input + ": --use-sensor-origin given, but the file carries no sensor origin (only PCD files "
                                     "do, in their VIEWPOINT line)");
  const auto t0 = std::chrono::steady_clock::now ();
  pcl::PointCloud<pcl::PointNormal>::Ptr cloud (new pcl::PointCloud<pcl::PointNormal>);
  bool has_normals = false;
  if (const pcl_flowseg::Status s = pcl_flowseg::loadPointCloud (o.input, *cloud, has_normals); !s)
    return parser.failure (s.message);
  if (o.use_normals && !has_normals)
    return parser.failure (o.input + ": --use-normals given, but the file has no normals");
  // The viewpoint travels as the cloud's sensor origin, as it does for PCL users.
  const bool use_viewpoint = o.params.interior.viewpoint.has_value () || o.use_sensor_origin;
  if (o.params.interior.viewpoint)
  {
    const Eigen::Vector3f v = o.params.interior.viewpoint->cast<float> ();
    cloud->sensor_origin_ = Eigen::Vector4f (v.x (), v.y (), v.z (), 0.0f);
  }
  const double read_ms = std::chrono::duration<double, std::milli> (std::chrono::steady_clock::now () - t0).count ();
  if (!o.quiet)
    std::cerr << "read " << cloud->size () << " points from " << o.input << " (" << read_ms << " ms)\n";

  pcl::FlowSegmentation<pcl::PointNormal> seg;
  seg.setInputCloud (cloud);
  seg.setParameters (o.params);
  seg.setUseNormals (o.use_normals);
  seg.setUseSensorOrigin (use_viewpoint);
  if (!o.quiet)
    seg.setProgressCallback ([] (const std::string& stage, double f) {
      std::cerr << "  [" << static_cast<int> (f * 100) << "%] " << stage << "\n";
    });
  std::vector<pcl::PointIndices> segments;
  if (!seg.segment (segments))
    return parser.failure (o.input + ": " + seg.getLastError ());
  if (const std::string error = writeOutputs (o, seg, read_ms); !error.empty ())
    return parser.failure (error);
  if (!o.quiet)
    printSummary (o, seg.getResult (), read_ms);
  return flowseg_app::kExitSuccess;
}

/*
 * flowseg_segment: segments a point sample (PCD, PLY, XYZ/TXT, OFF/OBJ vertices) by flow
 * discretization and writes labels (PCD), a summary (JSON) and a coloured PLY.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include "app_common.h"

#include <pcl_flowseg/segmentation/flow_segmentation.h>
#include <pcl_flowseg/io/point_io.h>
#include <pcl_flowseg/io/point_cloud_writer.h>
#include <pcl_flowseg/io/segmentation_json.h>
#include <pcl_flowseg/io/segmentation_ply.h>
#include <pcl_flowseg/io/segmentation_svg.h>

#include <pcl/console/print.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <string>

namespace {

void
printHelp ()
{
  std::cout <<
R"(Usage: flowseg_segment INPUT [options]

Segments a point sample of a closed curve (2D) or surface (3D) into features by the flow of
its distance function (Dey, Giesen, Goswami 2003).

INPUT  .pcd | .ply | .xyz/.txt/.csv (x y [z] per line) | .off/.obj (mesh vertices)

Options:
  -r, --rho R            merge threshold rho > 0 (default )" << pcl_flowseg::MergeParameters ().rho << R"(); < 1 merges nothing
      --tolerance T      merge tolerance in local sample spacings >= 0 (default )" << pcl_flowseg::MergeParameters ().sampling_tolerance << R"();
      --stump-ratio R    thin parts take back their stumps from parts R times thicker
                         (default )" << pcl_flowseg::MergeParameters ().stump_ratio << R"(; 0 = off)
      --compact-rho R    merge threshold for compact segments, > 0 (default )" << pcl_flowseg::MergeParameters ().compact_rho << R"(;
                         acts only above rho)
      --compact-size S   largest compact segment, in balls of its saddle's radius, >= 0
                         (default )" << pcl_flowseg::MergeParameters ().compact_size << R"(; 0 = off)
      --paper-rule       the paper's merging rule alone: tolerance, stump ratio and compact
                         size 0
  -d, --dimension D      auto | 2 | 3 (default auto: 2D when all points lie on one plane)
  -f, --features SIDE    interior | exterior | both (default interior: the shape's features)
      --significance F   features above this share of the reported volume are marked
                         "significant" in the JSON and counted in the summary (default )" << pcl_flowseg::kDefaultSignificance << R"()
      --no-interior      skip interior/exterior separation: the paper's raw segmentation of the
                         whole convex hull, every segment reported
      --denoise MODE     auto | off | on: smooth noisy samples before separating interior and
                         exterior (default auto: when the surface variation shows noise)
      --use-normals      use the file's normals (must point outwards) as in/out evidence
      --viewpoint X,Y,Z  sensor position of a single-view scan: space in front is outside
      --use-sensor-origin  take the viewpoint from the PCD file's VIEWPOINT
  -o, --output PREFIX    output prefix (default: INPUT without its extension)
      --binary           write the label PCD in binary (default ASCII)
      --no-surface       do not write PREFIX.surface.ply
  -j, --threads N        worker threads (default 0 = all cores; 1 = sequential); the result is
                         the same for every N
  -q, --quiet            no progress or summary on stderr
  -h, --help             this help

Writes PREFIX.labels.pcd (PointXYZL, one point per input point, in input order; label = feature
index, 4294967295 = none), PREFIX.json (counts, features, segments, adjacency, interior/exterior
summary, timings in ms), PREFIX.ply (points, and 2D triangles, coloured by feature) and
PREFIX.surface.ply (the reconstructed surface: 3D triangles, 2D interior triangles and the curve)
and, for 2D input, PREFIX.svg (triangles coloured by feature, Gabriel edges, curve, maxima).
Exit status: 0 on success, 1 when the input cannot be read or segmented, 2 on bad options.
)";
}

std::string
stripExtension (const std::string& path)
{
  const std::size_t slash = path.find_last_of ('/');
  const std::size_t dot = path.find_last_of ('.');
  return (dot == std::string::npos || (slash != std::string::npos && dot < slash)) ? path : path.substr (0, dot);
}

int
usageError (const std::string& message)
{
  return flowseg_app::usageError ("flowseg_segment", message);
}

} // namespace

int
main (int argc, char** argv)
{
  std::string input, prefix;
  double rho = pcl_flowseg::MergeParameters ().rho;
  double tolerance = pcl_flowseg::MergeParameters ().sampling_tolerance, stump_ratio = pcl_flowseg::MergeParameters ().stump_ratio;
  double compact_rho = pcl_flowseg::MergeParameters ().compact_rho, compact_size = pcl_flowseg::MergeParameters ().compact_size;
  int dimension = 0;
  bool binary = false, quiet = false, separate = true, use_normals = false, use_sensor_origin = false, surface = true;
  pcl_flowseg::FeatureSide side = pcl_flowseg::FeatureSide::Interior;
  pcl_flowseg::Denoising denoise = pcl_flowseg::Denoising::Automatic;
  bool has_viewpoint = false;
  double significance = pcl_flowseg::kDefaultSignificance;
  unsigned threads = 0;
  Eigen::Vector3f viewpoint = Eigen::Vector3f::Zero ();

  for (int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    auto value = [&] (std::string& out) {
      if (i + 1 >= argc)
        return false;
      out = argv[++i];
      return true;
    };
    std::string v;
    if (arg == "-h" || arg == "--help")
    {
      printHelp ();
      return 0;
    }
    else if (arg == "-r" || arg == "--rho")
    {
      if (!value (v) || !flowseg_app::parseNumber (v, rho) || rho <= 0.0)
        return usageError ("--rho needs a finite number > 0, got '" + v + "'");
    }
    else if (arg == "--tolerance")
    {
      if (!value (v) || !flowseg_app::parseNumber (v, tolerance) || tolerance < 0.0)
        return usageError ("--tolerance needs a finite number >= 0, got '" + v + "'");
    }
    else if (arg == "--stump-ratio")
    {
      if (!value (v) || !flowseg_app::parseNumber (v, stump_ratio) || (stump_ratio != 0.0 && stump_ratio < 1.0))
        return usageError ("--stump-ratio needs 0 (off) or a number >= 1, got '" + v + "'");
    }
    else if (arg == "--compact-rho")
    {
      if (!value (v) || !flowseg_app::parseNumber (v, compact_rho) || compact_rho <= 0.0)
        return usageError ("--compact-rho needs a finite number > 0, got '" + v + "'");
    }
    else if (arg == "--compact-size")
    {
      if (!value (v) || !flowseg_app::parseNumber (v, compact_size) || compact_size < 0.0)
        return usageError ("--compact-size needs a finite number >= 0, got '" + v + "'");
    }
    else if (arg == "--paper-rule")
      tolerance = stump_ratio = compact_size = 0.0;
    else if (arg == "-d" || arg == "--dimension")
    {
      if (!value (v))
        return usageError ("--dimension needs auto, 2 or 3");
      if (v == "auto") dimension = 0;
      else if (v == "2") dimension = 2;
      else if (v == "3") dimension = 3;
      else return usageError ("--dimension must be auto, 2 or 3, got '" + v + "'");
    }
    else if (arg == "-o" || arg == "--output")
    {
      if (!value (prefix) || prefix.empty ())
        return usageError ("--output needs a prefix");
    }
    else if (arg == "-f" || arg == "--features")
    {
      if (!value (v))
        return usageError ("--features needs interior, exterior or both");
      if (v == "interior") side = pcl_flowseg::FeatureSide::Interior;
      else if (v == "exterior") side = pcl_flowseg::FeatureSide::Exterior;
      else if (v == "both") side = pcl_flowseg::FeatureSide::Both;
      else return usageError ("--features must be interior, exterior or both, got '" + v + "'");
    }
    else if (arg == "--significance")
    {
      if (!value (v) || !flowseg_app::parseNumber (v, significance) || significance < 0 || significance >= 1)
        return usageError ("--significance needs a fraction in [0, 1), got '" + v + "'");
    }
    else if (arg == "--no-interior")
      separate = false;
    else if (arg == "--denoise")
    {
      if (!value (v))
        return usageError ("--denoise needs auto, off or on");
      if (v == "auto") denoise = pcl_flowseg::Denoising::Automatic;
      else if (v == "off") denoise = pcl_flowseg::Denoising::Off;
      else if (v == "on") denoise = pcl_flowseg::Denoising::Always;
      else return usageError ("--denoise must be auto, off or on, got '" + v + "'");
    }
    else if (arg == "--use-normals")
      use_normals = true;
    else if (arg == "--viewpoint")
    {
      double x, y, z;
      char c1 = 0, c2 = 0, extra = 0;
      if (!value (v) || std::sscanf (v.c_str (), "%lf%c%lf%c%lf%c", &x, &c1, &y, &c2, &z, &extra) != 5 || c1 != ',' ||
          c2 != ',' || !std::isfinite (x) || !std::isfinite (y) || !std::isfinite (z))
        return usageError ("--viewpoint needs X,Y,Z (three finite numbers), got '" + v + "'");
      viewpoint = Eigen::Vector3f (static_cast<float> (x), static_cast<float> (y), static_cast<float> (z));
      has_viewpoint = true;
    }
    else if (arg == "--use-sensor-origin")
      use_sensor_origin = true;
    else if (arg == "--no-surface")
      surface = false;
    else if (arg == "--binary")
      binary = true;
    else if (arg == "-q" || arg == "--quiet")
      quiet = true;
    else if (arg == "-j" || arg == "--threads")
    {
      double t = 0;
      if (!value (v) || !flowseg_app::parseNumber (v, t) || t < 0 || t > 1024 || t != static_cast<int> (t))
        return usageError ("--threads needs a whole number from 0 to 1024, got '" + v + "'");
      threads = static_cast<unsigned> (t);
    }
    else if (!arg.empty () && arg[0] == '-' && arg != "-")
      return usageError ("unknown option '" + arg + "'");
    else if (input.empty ())
      input = arg;
    else
      return usageError ("more than one input file ('" + input + "', '" + arg + "')");
  }
  if (input.empty ())
    return usageError ("no input file given");
  if (has_viewpoint && use_sensor_origin)
    return usageError ("--viewpoint and --use-sensor-origin exclude each other");
  if (!separate && (use_normals || has_viewpoint || use_sensor_origin || side != pcl_flowseg::FeatureSide::Interior))
    return usageError ("--no-interior excludes --features, --use-normals, --viewpoint and --use-sensor-origin");
  if (prefix.empty ())
    prefix = stripExtension (input);
  if (quiet)
    pcl::console::setVerbosityLevel (pcl::console::L_ALWAYS);

  const auto t0 = std::chrono::steady_clock::now ();
  pcl::PointCloud<pcl::PointXYZ> xyz;
  std::vector<Eigen::Vector3d> normals;
  const pcl_flowseg::Status loaded = pcl_flowseg::loadPointCloud (input, xyz, normals);
  if (!loaded)
  {
    std::cerr << "flowseg_segment: " << loaded.message << "\n";
    return 1;
  }
  if (use_normals && normals.empty ())
  {
    std::cerr << "flowseg_segment: " << input << ": --use-normals given, but the file has no normals\n";
    return 1;
  }
  // PointNormal carries the optional normals to the segmentation.
  pcl::PointCloud<pcl::PointNormal>::Ptr cloud (new pcl::PointCloud<pcl::PointNormal>);
  cloud->resize (xyz.size ());
  for (std::size_t i = 0; i < xyz.size (); ++i)
  {
    pcl::PointNormal& p = (*cloud)[i];
    p.x = xyz[i].x;
    p.y = xyz[i].y;
    p.z = xyz[i].z;
    const Eigen::Vector3d n = normals.empty () ? Eigen::Vector3d::Zero () : normals[i];
    p.normal_x = static_cast<float> (n.x ());
    p.normal_y = static_cast<float> (n.y ());
    p.normal_z = static_cast<float> (n.z ());
  }
  cloud->sensor_origin_ = xyz.sensor_origin_;
  if (has_viewpoint)
    cloud->sensor_origin_ = Eigen::Vector4f (viewpoint.x (), viewpoint.y (), viewpoint.z (), 0.0f);
  const double read_ms = std::chrono::duration<double, std::milli> (std::chrono::steady_clock::now () - t0).count ();
  if (!quiet)
    std::cerr << "read " << cloud->size () << " points from " << input << " (" << read_ms << " ms)\n";

  pcl::FlowSegmentation<pcl::PointNormal> seg;
  seg.setInputCloud (cloud);
  seg.setRho (rho);
  seg.setSamplingTolerance (tolerance);
  seg.setStumpRatio (stump_ratio);
  seg.setCompactRho (compact_rho);
  seg.setCompactSize (compact_size);
  seg.setDimension (dimension);
  seg.setSeparateInterior (separate);
  seg.setFeatureSide (side);
  seg.setDenoising (denoise);
  seg.setNumberOfThreads (threads);
  seg.setUseNormals (use_normals);
  seg.setUseSensorOrigin (has_viewpoint || use_sensor_origin);
  if (!quiet)
    seg.setProgressCallback ([] (const std::string& stage, double f) {
      std::cerr << "  [" << static_cast<int> (f * 100) << "%] " << stage << "\n";
    });
  std::vector<pcl::PointIndices> segments;
  if (!seg.segment (segments))
  {
    std::cerr << "flowseg_segment: " << input << ": " << seg.getLastError () << "\n";
    return 1;
  }
  const pcl_flowseg::FlowResult& result = seg.getResult ();
  pcl::PointCloud<pcl::PointXYZL> labels;
  seg.getLabelCloud (labels);

  pcl_flowseg::RunInfo info;
  info.input = input;
  info.read_ms = read_ms;
  info.significance = significance;
  std::vector<pcl_flowseg::Status> written = {pcl_flowseg::writeLabelCloud (prefix + ".labels.pcd", labels, binary),
                                              pcl_flowseg::writeSegmentationJson (prefix + ".json", result, info),
                                              pcl_flowseg::writeSegmentationPly (prefix + ".ply", result, labels)};
  if (surface && separate)
    written.push_back (pcl_flowseg::writeSurfacePly (prefix + ".surface.ply", result));
  if (result.dimension == 2)
    written.push_back (pcl_flowseg::writeSegmentationSvg (prefix + ".svg", result));
  for (const auto& st : written)
  {
    if (!st)
    {
      std::cerr << "flowseg_segment: " << st.message << "\n";
      return 1;
    }
  }

  if (!quiet)
  {
    const auto& t = result.timings;
    std::size_t interior = 0;
    const std::size_t unlabelled = result.unlabelledPoints ();
    const std::size_t significant = pcl_flowseg::significantSegments (result, result.features, significance).size ();
    for (const auto& s : result.segments)
      interior += s.interior == 1;
    std::fprintf (stderr,
                  "%dD: %zu points (%zu non-finite, %zu duplicates), %zu cells, %zu maxima, "
                  "%zu segments after merging with rho=%g (%zu interior), %zu features reported (%zu significant), %zu points unlabelled\n",
                  result.dimension, result.input_points, result.non_finite_points, result.duplicate_points,
                  result.cells.size (), result.maxima.size (), result.segments.size (), rho, interior,
                  result.features.size (), significant, unlabelled);
    if (result.interior.computed)
      std::fprintf (stderr, "interior: %.4g volume in %zu cells, boundary %zu facets, %s, %s, %zu samples off the boundary, %d smoothing pass(es)\n",
                    result.interior.inside_volume, result.interior.inside_cells, result.interior.boundary_facets,
                    result.interior.closed ? "closed" : "NOT closed", result.interior.manifold ? "manifold" : "not manifold",
                    result.interior.vertices_off_boundary, result.interior.smoothing_passes);
    std::fprintf (stderr, "time ms: read %.1f, preparation %.1f, delaunay %.1f, flow %.1f, manifolds %.1f, interior %.1f, merge %.1f, labels %.1f, total %.1f\n",
                  read_ms, t.preparation_ms, t.delaunay_ms, t.flow_ms, t.manifolds_ms, t.interior_ms, t.merge_ms, t.labels_ms, t.total_ms);
    std::fprintf (stderr, "wrote %s.labels.pcd, %s.json, %s.ply%s%s\n", prefix.c_str (), prefix.c_str (), prefix.c_str (),
                  surface && separate ? (", " + prefix + ".surface.ply").c_str () : "",
                  result.dimension == 2 ? (", " + prefix + ".svg").c_str () : "");
  }
  return 0;
}

/*
 * flowseg_segment: segments a point sample (PCD, PLY, XYZ/TXT, OFF/OBJ vertices) by flow
 * discretization and writes labels (PCD), a summary (JSON) and a coloured PLY.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include <pcl_flowseg/flow_segmentation.h>
#include <pcl_flowseg/point_io.h>
#include <pcl_flowseg/result_writer.h>

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
  -r, --rho R          merge threshold rho > 0 (default )" << pcl_flowseg::kDefaultRho << R"(); < 1 merges nothing
  -d, --dimension D    auto | 2 | 3 (default auto: 2D when all points lie on one plane)
  -o, --output PREFIX  output prefix (default: INPUT without its extension)
      --binary         write the label PCD in binary (default ASCII)
  -q, --quiet          no progress or summary on stderr
  -h, --help           this help

Writes PREFIX.labels.pcd (PointXYZL, one point per input point, in input order; label
4294967295 = no segment), PREFIX.json (counts, segments, adjacency, timings in ms) and
PREFIX.ply (points, and 2D triangles, coloured by segment; grey = flows out of the hull).
Exit status: 0 on success, 1 when the input cannot be read or segmented, 2 on bad options.
)";
}

bool
parseDouble (const std::string& text, double& value)
{
  char* end = nullptr;
  value = std::strtod (text.c_str (), &end);
  return !text.empty () && end && *end == '\0' && std::isfinite (value);
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
  std::cerr << "flowseg_segment: " << message << "\n(see flowseg_segment --help)\n";
  return 2;
}

} // namespace

int
main (int argc, char** argv)
{
  std::string input, prefix;
  double rho = pcl_flowseg::kDefaultRho;
  int dimension = 0;
  bool binary = false, quiet = false;

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
      if (!value (v) || !parseDouble (v, rho) || rho <= 0.0)
        return usageError ("--rho needs a finite number > 0, got '" + v + "'");
    }
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
    else if (arg == "--binary")
      binary = true;
    else if (arg == "-q" || arg == "--quiet")
      quiet = true;
    else if (!arg.empty () && arg[0] == '-' && arg != "-")
      return usageError ("unknown option '" + arg + "'");
    else if (input.empty ())
      input = arg;
    else
      return usageError ("more than one input file ('" + input + "', '" + arg + "')");
  }
  if (input.empty ())
    return usageError ("no input file given");
  if (prefix.empty ())
    prefix = stripExtension (input);
  if (quiet)
    pcl::console::setVerbosityLevel (pcl::console::L_ALWAYS);

  const auto t0 = std::chrono::steady_clock::now ();
  pcl::PointCloud<pcl::PointXYZ>::Ptr cloud (new pcl::PointCloud<pcl::PointXYZ>);
  const pcl_flowseg::Status loaded = pcl_flowseg::loadPointCloud (input, *cloud);
  if (!loaded)
  {
    std::cerr << "flowseg_segment: " << loaded.message << "\n";
    return 1;
  }
  const double read_ms = std::chrono::duration<double, std::milli> (std::chrono::steady_clock::now () - t0).count ();
  if (!quiet)
    std::cerr << "read " << cloud->size () << " points from " << input << " (" << read_ms << " ms)\n";

  pcl::FlowSegmentation<pcl::PointXYZ> seg;
  seg.setInputCloud (cloud);
  seg.setRho (rho);
  seg.setDimension (dimension);
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
  info.rho = rho;
  info.read_ms = read_ms;
  for (const auto& st : {pcl_flowseg::writeLabelCloud (prefix + ".labels.pcd", labels, binary),
                         pcl_flowseg::writeSegmentationJson (prefix + ".json", result, info),
                         pcl_flowseg::writeSegmentationPly (prefix + ".ply", result, labels)})
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
    std::size_t finite_segments = 0;
    for (const auto& s : result.segments)
      finite_segments += s.flows_to_infinity ? 0 : 1;
    std::fprintf (stderr,
                  "%dD: %zu points (%zu non-finite, %zu duplicates), %zu cells, %zu maxima, "
                  "%zu segments after merging with rho=%g (%zu finite + %s)\n",
                  result.dimension, result.input_points, result.non_finite_points, result.duplicate_points,
                  result.cells.size (), result.maxima.size (), result.segments.size (), rho, finite_segments,
                  finite_segments < result.segments.size () ? "1 at infinity" : "none at infinity");
    std::fprintf (stderr, "time ms: read %.1f, preparation %.1f, delaunay %.1f, flow %.1f, merge %.1f, labels %.1f, total %.1f\n",
                  read_ms, t.preparation_ms, t.delaunay_ms, t.flow_ms, t.merge_ms, t.labels_ms, t.total_ms);
    std::fprintf (stderr, "wrote %s.labels.pcd, %s.json, %s.ply\n", prefix.c_str (), prefix.c_str (), prefix.c_str ());
  }
  return 0;
}

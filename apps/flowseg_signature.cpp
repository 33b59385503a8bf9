/*
 * flowseg_signature: prints the signature of a shape (its significant features as weighted points).
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include <pcl_flowseg/segmentation/flow_pipeline.h>
#include <pcl_flowseg/io/shape_input.h>
#include <pcl_flowseg/signature/shape_signature.h>
#include <pcl_flowseg/signature/signature.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <string>

int
main (int argc, char** argv)
{
  std::string input;
  double rho = pcl_flowseg::MergeParameters ().rho, significance = pcl_flowseg::kDefaultSignificance;
  pcl_flowseg::ShapeInputOptions in;
  bool json = false;
  for (int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    char* end = nullptr;
    if (a == "-h" || a == "--help")
    {
      std::cout << "Usage: flowseg_signature INPUT [--rho R (" << pcl_flowseg::MergeParameters ().rho << ")] [--significance F ("
                << pcl_flowseg::kDefaultSignificance << ")] [--mesh-points N (5000)] [--json]\n\n"
                << "Prints the shape's significant features as weighted points in the normalised frame (positions\n"
                << "relative to the interior's centroid, in units of interior volume^(1/d); weights sum to 1).\n"
                << "Exit status: 0 success, 1 unreadable or unsegmentable input, 2 bad options.\n";
      return 0;
    }
    else if (a == "--rho" && i + 1 < argc && (rho = std::strtod (argv[i + 1], &end), *end == '\0') && std::isfinite (rho) && rho > 0)
      ++i;
    else if (a == "--significance" && i + 1 < argc && (significance = std::strtod (argv[i + 1], &end), *end == '\0') &&
             significance >= 0 && significance < 1)
      ++i;
    else if (a == "--mesh-points" && i + 1 < argc && (in.mesh_points = std::strtoul (argv[i + 1], &end, 10), *end == '\0') &&
             in.mesh_points >= 4 && argv[i + 1][0] != '-')
      ++i;
    else if (a == "--json")
      json = true;
    else if (!a.empty () && a[0] == '-')
    {
      std::cerr << "flowseg_signature: bad, incomplete or unknown option '" << a << "' (see --help)\n";
      return 2;
    }
    else if (input.empty ())
      input = a;
    else
    {
      std::cerr << "flowseg_signature: more than one input (see --help)\n";
      return 2;
    }
  }
  if (input.empty ())
  {
    std::cerr << "flowseg_signature: no input file given (see --help)\n";
    return 2;
  }
  pcl_flowseg::Signature s;
  pcl_flowseg::FlowParameters params;
  params.merge.rho = rho;
  const pcl_flowseg::Status st = pcl_flowseg::signatureOfShapeFile (input, in, params, significance, s);
  if (!st.ok)
  {
    std::cerr << "flowseg_signature: " << st.message << "\n";
    return 1;
  }
  if (json)
  {
    std::printf ("{\"input\": \"%s\", \"dimension\": %d, \"unit\": %.10g, \"interior_volume\": %.10g, \"significance\": %g, \"points\": [",
                 input.c_str (), s.dimension, s.unit, s.interior_volume, s.significance);
    for (std::size_t k = 0; k < s.points.size (); ++k)
      std::printf ("%s{\"position\": [%.6f, %.6f, %.6f], \"weight\": %.6f}", k ? ", " : "", s.points[k].position.x (),
                   s.points[k].position.y (), s.points[k].position.z (), s.points[k].weight);
    std::printf ("]}\n");
  }
  else
  {
    std::printf ("%s: %dD, %zu significant features (unit %.6g, interior volume %.6g)\n", input.c_str (), s.dimension, s.points.size (),
                 s.unit, s.interior_volume);
    std::printf ("weight\tx\ty\tz\n");
    for (const auto& p : s.points)
      std::printf ("%.4f\t%.4f\t%.4f\t%.4f\n", p.weight, p.position.x (), p.position.y (), p.position.z ());
  }
  return 0;
}

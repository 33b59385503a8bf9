/*
 * flowseg_match: compares two shapes by their signatures; prints the similarity and the alignment.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include <pcl_flowseg/segmentation/flow_pipeline.h>
#include <pcl_flowseg/io/shape_input.h>
#include <pcl_flowseg/signature/shape_signature.h>
#include <pcl_flowseg/signature/signature.h>
#include <pcl_flowseg/signature/signature_matcher.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <string>

namespace {
bool
signatureOf (const std::string& path, double rho, double significance, const pcl_flowseg::ShapeInputOptions& in, pcl_flowseg::Signature& s)
{
  pcl_flowseg::FlowParameters params;
  params.merge.rho = rho;
  const auto st = pcl_flowseg::signatureOfShapeFile (path, in, params, significance, s);
  if (!st.ok)
    std::cerr << "flowseg_match: " << st.message << "\n";
  return st.ok;
}
} // namespace

int
main (int argc, char** argv)
{
  std::vector<std::string> inputs;
  double rho = pcl_flowseg::MergeParameters ().rho, significance = pcl_flowseg::kDefaultSignificance;
  pcl::SignatureMatcher matcher;
  pcl_flowseg::ShapeInputOptions in;
  for (int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    char* end = nullptr;
    double v = 0;
    const bool value = i + 1 < argc && (v = std::strtod (argv[i + 1], &end), *end == '\0') && std::isfinite (v);
    if (a == "-h" || a == "--help")
    {
      std::cout << "Usage: flowseg_match A B [--threshold T (" << matcher.getThreshold () << ")] [--no-mirror] [--rho R ("
                << pcl_flowseg::MergeParameters ().rho << ")] [--significance F (" << pcl_flowseg::kDefaultSignificance
                << ")] [--mesh-points N (5000)]\n\n"
                << "Prints the similarity (1 = identical signatures), the paper's score, the matched features and\n"
                << "the transformation mapping B's normalised signature onto A's.\n"
                << "Exit status: 0 success, 1 unreadable or unsegmentable input, 2 bad options.\n";
      return 0;
    }
    else if (a == "--threshold" && value && v > 0)
      matcher.setThreshold (v), ++i;
    else if (a == "--rho" && value && v > 0)
      rho = v, ++i;
    else if (a == "--significance" && value && v >= 0 && v < 1)
      significance = v, ++i;
    else if (a == "--mesh-points" && value && v >= 4 && v <= 1e8)
      in.mesh_points = static_cast<std::size_t> (v), ++i;
    else if (a == "--no-mirror")
      matcher.setAllowMirror (false);
    else if (!a.empty () && a[0] == '-')
    {
      std::cerr << "flowseg_match: bad, incomplete or unknown option '" << a << "' (see --help)\n";
      return 2;
    }
    else
      inputs.push_back (a);
  }
  if (inputs.size () != 2)
  {
    std::cerr << "flowseg_match: need exactly two inputs A B (see --help)\n";
    return 2;
  }
  pcl_flowseg::Signature a, b;
  if (!signatureOf (inputs[0], rho, significance, in, a) || !signatureOf (inputs[1], rho, significance, in, b))
    return 1;
  const auto m = matcher.match (a, b);
  std::printf ("similarity %.4f\nscore %.4f (A: %zu features, B: %zu)\nmirrored %s\n", m.similarity, m.score, a.points.size (),
               b.points.size (), m.mirrored ? "yes" : "no");
  std::printf ("pairs (A feature, B feature):");
  for (const auto& p : m.pairs)
    std::printf (" (%d,%d)", p.first, p.second);
  std::printf ("\nlinear\n");
  for (int r = 0; r < 3; ++r)
    std::printf ("  %9.5f %9.5f %9.5f\n", m.linear (r, 0), m.linear (r, 1), m.linear (r, 2));
  std::printf ("translation %.5f %.5f %.5f\n", m.translation.x (), m.translation.y (), m.translation.z ());
  return 0;
}

/*
 * flowseg_match: compares two shapes by their signatures; prints the similarity and the alignment.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include "common/flow_options.h"
#include "common/huge_page_malloc.h"
#include "common/options.h"

#include <pcl_flowseg/signature/shape_signature.h>
#include <pcl_flowseg/signature/signature_matcher.h>

#include <pcl/console/print.h>

#include <cstdio>
#include <string>
#include <vector>

namespace {

void
printAlignment (const pcl::SignatureMatcher::Result& m, const pcl_flowseg::Signature& a, const pcl_flowseg::Signature& b)
{
  std::printf ("similarity %.4f\nscore %.4f (A: %zu features, B: %zu)\nmirrored %s\n", m.similarity, m.paper_score, a.points.size (),
               b.points.size (), m.mirrored ? "yes" : "no");
  std::printf ("pairs (A feature, B feature):");
  for (const auto& pair : m.pairs)
    std::printf (" (%d,%d)", pair.first, pair.second);
  std::printf ("\nlinear\n");
  for (int r = 0; r < 3; ++r)
    std::printf ("  %9.5f %9.5f %9.5f\n", m.linear (r, 0), m.linear (r, 1), m.linear (r, 2));
  std::printf ("translation %.5f %.5f %.5f\n", m.translation.x (), m.translation.y (), m.translation.z ());
}

/** The description methods: similarity, distance, and every component's distance. */
void
printDescriptionMatch (const pcl::SignatureMatcher::Result& m, const pcl_flowseg::Signature& a, const pcl_flowseg::Signature& b,
                       const pcl_flowseg::MatchParameters& match)
{
  std::printf ("similarity %.4f\ndistance %.4f (A: %zu parts, B: %zu)\ncomponents", m.similarity, m.distance,
               a.description.parts.size (), b.description.parts.size ());
  for (pcl_flowseg::MatchMethod method : pcl_flowseg::kMatchMethods)
    if (method != pcl_flowseg::MatchMethod::Combined && method != pcl_flowseg::MatchMethod::Paper)
    {
      pcl::SignatureMatcher component;
      component.setParameters (match);
      component.setMethod (method);
      std::printf (" %s %.4f", pcl_flowseg::matchMethodName (method), component.match (a, b).distance);
    }
  std::printf ("\n");
}

} // namespace

int
main (int argc, char** argv)
{
  flowseg_app::relaunchWithHugePageMalloc (argv);
  pcl_flowseg::FlowParameters params;
  flowseg_app::SignatureOptions signature;
  pcl_flowseg::MatchParameters match;
  bool quiet = false;
  flowseg_app::OptionParser p ("flowseg_match", "flowseg_match A B [options]",
                               "Prints the method and the similarity (1 = identical signatures). With --method paper also the\n"
                               "paper's score, the matched features and the transformation mapping B's normalised signature onto\n"
                               "A's; with the other methods the distance (similarity = exp(-distance)) and each component's.");
  flowseg_app::addMatchMethodOption (p, match);
  flowseg_app::addMatchOptions (p, match);
  flowseg_app::addSegmentationOptions (p, params);
  flowseg_app::addViewpointOptions (p, params.interior.viewpoint, signature.input.use_sensor_origin);
  flowseg_app::addSignatureOptions (p, signature);
  flowseg_app::addThreadsOption (p, params.execution.threads);
  p.flag ("-q, --quiet", "no messages on stderr but errors", quiet);
  p.epilogue ("--viewpoint places the sensor of both scans; with --use-sensor-origin each of A and B has its own\n"
              "file's VIEWPOINT.\n\n"
              "Exit status: 0 success, 1 unreadable or unsegmentable input, 2 bad options.");
  std::vector<std::string> inputs;
  if (const int status = p.parse (argc, argv, inputs); status != flowseg_app::kContinue)
    return status;
  if (inputs.size () != 2)
    return p.usageError ("need exactly two inputs A B");
  if (const int status = flowseg_app::checkViewpointOptions (p, params, signature.input.use_sensor_origin);
      status != flowseg_app::kContinue)
    return status;
  if (quiet)
    pcl::console::setVerbosityLevel (pcl::console::L_ALWAYS);
  pcl_flowseg::Signature a, b;
  for (auto* s : {&a, &b})
  {
    const std::string& path = inputs[s == &a ? 0 : 1];
    if (const pcl_flowseg::Status st = pcl_flowseg::signatureOfShapeFile (path, signature.input, params, signature.significance, *s); !st)
      return p.failure (st.message);
  }
  pcl::SignatureMatcher matcher;
  matcher.setParameters (match);
  const pcl::SignatureMatcher::Result m = matcher.match (a, b);
  if (!m.status)
    return p.failure (m.status.message);
  std::printf ("method %s\n", pcl_flowseg::matchMethodName (match.method));
  if (match.method == pcl_flowseg::MatchMethod::Paper)
    printAlignment (m, a, b);
  else
    printDescriptionMatch (m, a, b, match);
  return flowseg_app::kExitSuccess;
}

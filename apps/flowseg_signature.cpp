/*
 * flowseg_signature: prints the signature of a shape (its significant features as weighted points,
 * its described parts, interior distributions and profiles).
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include "common/flow_options.h"
#include "common/huge_page_malloc.h"
#include "common/options.h"

#include <pcl_flowseg/io/json_text.h>
#include <pcl_flowseg/signature/shape_signature.h>

#include <pcl/console/print.h>

#include <cstdio>
#include <string>
#include <utility>
#include <vector>

namespace {

/** The description's distributions with their names, in file order. */
std::vector<std::pair<const char*, const pcl_flowseg::Distribution*>>
distributions (const pcl_flowseg::ShapeDescription& d)
{
  return {{"thickness", &d.thickness}, {"inner_distance", &d.inner_distance}, {"solid_distance", &d.solid_distance}};
}

/** A JSON array of \a values. */
template <typename Values>
void
printJsonArray (const Values& values)
{
  std::printf ("[");
  for (std::size_t k = 0; k < values.size (); ++k)
    std::printf ("%s%s", k ? ", " : "", pcl_flowseg::jsonNumber (values[k]).c_str ());
  std::printf ("]");
}

void
printJson (const std::string& input, const pcl_flowseg::Signature& s)
{
  using pcl_flowseg::jsonNumber;
  std::printf ("{\"input\": %s, \"dimension\": %d, \"unit\": %s, \"interior_volume\": %s, \"significance\": %s, \"points\": [",
               pcl_flowseg::jsonString (input).c_str (), s.dimension, jsonNumber (s.unit).c_str (),
               jsonNumber (s.interior_volume).c_str (), jsonNumber (s.significance).c_str ());
  for (std::size_t k = 0; k < s.points.size (); ++k)
    std::printf ("%s{\"position\": [%s, %s, %s], \"weight\": %s}", k ? ", " : "", jsonNumber (s.points[k].position.x ()).c_str (),
                 jsonNumber (s.points[k].position.y ()).c_str (), jsonNumber (s.points[k].position.z ()).c_str (),
                 jsonNumber (s.points[k].weight).c_str ());
  std::printf ("], \"parts\": [");
  const pcl_flowseg::ShapeDescription& d = s.description;
  for (std::size_t k = 0; k < d.parts.size (); ++k)
  {
    const pcl_flowseg::PartDescription& q = d.parts[k];
    std::printf ("%s{\"weight\": %s, \"thickness\": %s, \"extent\": %s, \"middle_ratio\": %s, \"smallest_ratio\": %s, \"remoteness\": %s}",
                 k ? ", " : "", jsonNumber (q.weight).c_str (), jsonNumber (q.thickness).c_str (), jsonNumber (q.extent).c_str (),
                 jsonNumber (q.middle_ratio).c_str (), jsonNumber (q.smallest_ratio).c_str (), jsonNumber (q.remoteness).c_str ());
  }
  std::printf ("], \"distributions\": {");
  const char* separator = "";
  for (const auto& [name, bins] : distributions (d))
  {
    std::printf ("%s\"%s\": ", separator, name);
    separator = ", ";
    printJsonArray (*bins);
  }
  std::printf ("}, \"inner_profiles\": [");
  for (std::size_t r = 0; r < d.inner_profiles.size (); ++r)
  {
    std::printf ("%s", r ? ", " : "");
    printJsonArray (d.inner_profiles[r]);
  }
  std::printf ("], \"thickness_profile\": ");
  printJsonArray (d.thickness_profile);
  std::printf (", \"contour\": [");
  for (std::size_t r = 0; r < d.contour.size (); ++r)
  {
    std::printf ("%s", r ? ", " : "");
    printJsonArray (d.contour[r]);
  }
  std::printf ("], \"inner_contexts\": [");
  for (std::size_t r = 0; r < d.inner_contexts.size (); ++r)
  {
    std::printf ("%s{\"thickness\": %s, \"distances\": ", r ? ", " : "", jsonNumber (d.inner_contexts[r].thickness).c_str ());
    printJsonArray (d.inner_contexts[r].distances);
    std::printf ("}");
  }
  std::printf ("]}\n");
}

void
printTable (const std::string& input, const pcl_flowseg::Signature& s)
{
  std::printf ("%s: %dD, %zu significant features (unit %.6g, interior volume %.6g)\n", input.c_str (), s.dimension,
               s.points.size (), s.unit, s.interior_volume);
  std::printf ("weight\tx\ty\tz\n");
  for (const auto& p : s.points)
    std::printf ("%.4f\t%.4f\t%.4f\t%.4f\n", p.weight, p.position.x (), p.position.y (), p.position.z ());
  std::printf ("\n%zu described parts\nweight\tthickness\textent\tmiddle\tsmallest\tremoteness\n", s.description.parts.size ());
  for (const auto& q : s.description.parts)
    std::printf ("%.4f\t%.4f\t%.4f\t%.4f\t%.4f\t%.4f\n", q.weight, q.thickness, q.extent, q.middle_ratio, q.smallest_ratio, q.remoteness);
  for (const auto& [name, bins] : distributions (s.description))
  {
    std::printf ("\n%s distribution (%zu bins):", name, bins->size ());
    for (double v : *bins)
      std::printf (" %.4f", v);
  }
  std::printf ("\n\ninner-distance profiles (%zu rows, from the centre out):", s.description.inner_profiles.size ());
  for (const auto& row : s.description.inner_profiles)
  {
    std::printf ("\n");
    for (double v : row)
      std::printf (" %.4f", v);
  }
  std::printf ("\n\nthickness profile (log thickness over the unit, from the centre out):");
  for (double v : s.description.thickness_profile)
    std::printf (" %.4f", v);
  std::printf ("\n\ncontour (%zu points along the outline, %zu rings x %zu sectors each):", s.description.contour.size (),
               pcl_flowseg::kContourDistanceBins, pcl_flowseg::kContourAngleBins);
  for (const auto& row : s.description.contour)
  {
    std::printf ("\n");
    for (float v : row)
      std::printf (" %.4f", static_cast<double> (v));
  }
  std::printf ("\n\ninner contexts (%zu sources: log thickness over the unit, then %zu bins of log inner distance over "
               "the mean):",
               s.description.inner_contexts.size (), pcl_flowseg::kContextBins);
  for (const auto& context : s.description.inner_contexts)
  {
    std::printf ("\n%.4f\t", static_cast<double> (context.thickness));
    for (float v : context.distances)
      std::printf (" %.4f", static_cast<double> (v));
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
  bool json = false, quiet = false;
  flowseg_app::OptionParser p ("flowseg_signature", "flowseg_signature INPUT [options]",
                               "Prints the shape's significant features as weighted points in the normalised frame (positions\n"
                               "relative to the interior's centroid, in units of interior volume^(1/d); weights sum to 1), then its\n"
                               "description: the parts (volume share, thickness, extent, axis ratios, remoteness: mean inner\n"
                               "distance from the shape's sources, in the same unit) and the thickness, inner- and\n"
                               "solid-distance distributions (32 bins each).");
  flowseg_app::addSegmentationOptions (p, params);
  flowseg_app::addViewpointOptions (p, params.interior.viewpoint, signature.input.use_sensor_origin);
  flowseg_app::addSignatureOptions (p, signature);
  flowseg_app::addThreadsOption (p, params.execution.threads);
  p.flag ("--json", "print JSON instead of a table", json);
  p.flag ("-q, --quiet", "no messages on stderr but errors", quiet);
  p.epilogue ("Exit status: 0 success, 1 unreadable or unsegmentable input, 2 bad options.");
  std::vector<std::string> inputs;
  if (const int status = p.parse (argc, argv, inputs); status != flowseg_app::kContinue)
    return status;
  if (inputs.size () != 1)
    return p.usageError (inputs.empty () ? "no input file given" : "more than one input");
  if (const int status = flowseg_app::checkViewpointOptions (p, params, signature.input.use_sensor_origin);
      status != flowseg_app::kContinue)
    return status;
  if (quiet)
    pcl::console::setVerbosityLevel (pcl::console::L_ALWAYS);
  pcl_flowseg::Signature s;
  if (const pcl_flowseg::Status st = pcl_flowseg::signatureOfShapeFile (inputs[0], signature.input, params, signature.significance, s); !st)
    return p.failure (st.message);
  if (json)
    printJson (inputs[0], s);
  else
    printTable (inputs[0], s);
  return flowseg_app::kExitSuccess;
}

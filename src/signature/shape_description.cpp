/*
 * pcl_flowseg - checks of shape descriptions.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include <pcl_flowseg/signature/shape_description.h>

#include <array>
#include <cmath>
#include <string>
#include <vector>

namespace pcl_flowseg {

namespace {

constexpr double kLargestLength = 1e9; ///< in the unit: larger means a broken description

Status
checkDistribution (const Distribution& d, const char* name)
{
  double sum = 0.0;
  for (double v : d)
  {
    if (!(v >= 0.0 && v <= 1.0))
      return Status::error (std::string ("the ") + name + " distribution has an entry outside [0, 1]");
    sum += v;
  }
  if (std::abs (sum - 1.0) > 1e-9)
    return Status::error (std::string ("the ") + name + " distribution sums to " + std::to_string (sum) + ", not 1");
  return Status::success ();
}

Status
checkPart (const PartDescription& p, std::size_t k)
{
  const std::string which = "part " + std::to_string (k + 1);
  if (!(p.weight > 0.0 && p.weight <= 1.0))
    return Status::error (which + " has a weight outside (0, 1]");
  if (!(p.thickness > 0.0 && p.thickness <= kLargestLength) || !(p.extent > 0.0 && p.extent <= kLargestLength) ||
      !(p.remoteness >= 0.0 && p.remoteness <= kLargestLength))
    return Status::error (which + " has a thickness, extent or remoteness that is not a finite length");
  if (!(p.middle_ratio >= 0.0 && p.middle_ratio <= 1.0) || !(p.smallest_ratio >= 0.0 && p.smallest_ratio <= 1.0))
    return Status::error (which + " has an axis ratio outside [0, 1]");
  return Status::success ();
}

/** Floats summing to 1 only as closely as a stored float (9 digits) keeps them. */
template <std::size_t N>
Status
checkFloatHistogram (const std::array<float, N>& h, const std::string& what)
{
  double sum = 0.0;
  for (float v : h)
  {
    if (!(v >= 0.0f && v <= 1.0f))
      return Status::error (what + " has an entry outside [0, 1]");
    sum += static_cast<double> (v);
  }
  if (std::abs (sum - 1.0) > 1e-4)
    return Status::error (what + " sums to " + std::to_string (sum) + ", not 1");
  return Status::success ();
}

Status
checkContour (const std::vector<ContourHistogram>& contour)
{
  if (!contour.empty () && contour.size () != kContourPoints)
    return Status::error ("the contour has " + std::to_string (contour.size ()) + " histograms, not 0 or " +
                          std::to_string (kContourPoints));
  for (const ContourHistogram& h : contour)
    if (const Status s = checkFloatHistogram (h, "a contour histogram"); !s)
      return s;
  return Status::success ();
}

Status
checkInnerContexts (const std::vector<InnerContext>& contexts)
{
  if (contexts.empty () || contexts.size () > kDistanceSources)
    return Status::error ("the description has " + std::to_string (contexts.size ()) + " inner contexts, not 1 to " +
                          std::to_string (kDistanceSources));
  for (const InnerContext& c : contexts)
  {
    if (!(c.thickness >= kThicknessLogLow && c.thickness <= kThicknessLogHigh))
      return Status::error ("an inner context's thickness is outside the thickness range");
    if (const Status s = checkFloatHistogram (c.distances, "an inner-context histogram"); !s)
      return s;
  }
  return Status::success ();
}

} // namespace

Status
checkShapeDescription (const ShapeDescription& description)
{
  const ShapeDescription& d = description;
  if (d.parts.empty ())
  {
    std::vector<const Distribution*> all{&d.thickness, &d.inner_distance, &d.solid_distance};
    for (const Distribution& row : d.inner_profiles)
      all.push_back (&row);
    for (const Distribution* h : all)
      for (double v : *h)
        if (v != 0.0)
          return Status::error ("a description without parts must have empty distributions");
    for (double v : d.thickness_profile)
      if (v != 0.0)
        return Status::error ("a description without parts must have an empty thickness profile");
    if (!d.contour.empty () || !d.inner_contexts.empty ())
      return Status::error ("a description without parts must have no contour and no inner contexts");
    return Status::success ();
  }
  if (d.parts.size () > kMaxParts)
    return Status::error ("more than " + std::to_string (kMaxParts) + " parts");
  double total = 0.0;
  for (std::size_t k = 0; k < d.parts.size (); ++k)
  {
    if (const Status s = checkPart (d.parts[k], k); !s)
      return s;
    if (k > 0 && d.parts[k].weight > d.parts[k - 1].weight)
      return Status::error ("the parts are not ordered by decreasing weight");
    total += d.parts[k].weight;
  }
  if (std::abs (total - 1.0) > 1e-9)
    return Status::error ("the part weights sum to " + std::to_string (total) + ", not 1");
  for (const auto& [h, name] : {std::pair<const Distribution*, const char*> (&d.thickness, "thickness"),
                                {&d.inner_distance, "inner-distance"}, {&d.solid_distance, "solid-distance"}})
    if (const Status s = checkDistribution (*h, name); !s)
      return s;
  for (const Distribution& row : d.inner_profiles)
    if (const Status s = checkDistribution (row, "inner-distance profile"); !s)
      return s;
  for (double v : d.thickness_profile)
    if (!(v >= kThicknessLogLow && v <= kThicknessLogHigh))
      return Status::error ("the thickness profile has an entry outside [" + std::to_string (kThicknessLogLow) + ", " +
                            std::to_string (kThicknessLogHigh) + "]");
  if (const Status s = checkContour (d.contour); !s)
    return s;
  return checkInnerContexts (d.inner_contexts);
}

} // namespace pcl_flowseg

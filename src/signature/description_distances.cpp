/*
 * pcl_flowseg - distances between shape descriptions: parts and inner-distance profiles by earth
 * mover's distance, distributions by L1 or chi-square, and their weighted sum.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include "description_distances.h"

#include "contour_matching.h"
#include "transport_distance.h"

#include <algorithm>
#include <cmath>
#include <tuple>

namespace pcl_flowseg {

namespace {

double
l1Distance (const Distribution& a, const Distribution& b)
{
  double sum = 0.0;
  for (std::size_t k = 0; k < kDistributionBins; ++k)
    sum += std::abs (a[k] - b[k]);
  return sum;
}

double
chiSquareDistance (const Distribution& a, const Distribution& b)
{
  double sum = 0.0;
  for (std::size_t k = 0; k < kDistributionBins; ++k)
    if (a[k] + b[k] > 0.0)
      sum += (a[k] - b[k]) * (a[k] - b[k]) / (a[k] + b[k]);
  return sum;
}

/** Earth mover's distance between two histograms over the inner-distance range, in units of log
  * distance: the L1 distance of their cumulative sums times the bin width. */
double
transportDistance1d (const Distribution& a, const Distribution& b)
{
  double sum = 0.0, below_a = 0.0, below_b = 0.0;
  for (std::size_t k = 0; k < kDistributionBins; ++k)
  {
    below_a += a[k];
    below_b += b[k];
    sum += std::abs (below_a - below_b);
  }
  return sum * (kInnerLogHigh - kInnerLogLow) / static_cast<double> (kDistributionBins);
}

} // namespace

double
innerProfileDistance (const ShapeDescription& a, const ShapeDescription& b)
{
  double sum = 0.0;
  for (std::size_t r = 0; r < kProfileRows; ++r)
    sum += transportDistance1d (a.inner_profiles[r], b.inner_profiles[r]);
  return sum / static_cast<double> (kProfileRows);
}

double
thicknessProfileDistance (const ShapeDescription& a, const ShapeDescription& b)
{
  double mean_a = 0.0, mean_b = 0.0;
  for (std::size_t r = 0; r < kProfileRows; ++r)
  {
    mean_a += a.thickness_profile[r] / static_cast<double> (kProfileRows);
    mean_b += b.thickness_profile[r] / static_cast<double> (kProfileRows);
  }
  double sum = 0.0;
  for (std::size_t r = 0; r < kProfileRows; ++r)
    sum += std::abs ((a.thickness_profile[r] - mean_a) - (b.thickness_profile[r] - mean_b));
  return sum / static_cast<double> (kProfileRows);
}

Eigen::Matrix<double, 6, 1>
partPoint (const PartDescription& p)
{
  const PartAttributeWeights& w = kPartAttributeWeights;
  Eigen::Matrix<double, 6, 1> x;
  x << w.thickness * std::log (p.thickness), w.extent * std::log (p.extent), w.middle_ratio * p.middle_ratio,
      w.smallest_ratio * p.smallest_ratio, w.weight * std::log (p.weight), w.offset * p.offset;
  return x;
}

double
partDistance (const ShapeDescription& first, const ShapeDescription& second)
{
  // The transport is solved in one fixed order of the two part lists, so that rounding cannot make
  // the distance from a to b differ from the distance from b to a.
  const auto key = [] (const PartDescription& p) {
    return std::make_tuple (p.weight, p.thickness, p.extent, p.middle_ratio, p.smallest_ratio, p.offset);
  };
  const bool swap = std::lexicographical_compare (second.parts.begin (), second.parts.end (), first.parts.begin (), first.parts.end (),
                                                  [&] (const PartDescription& x, const PartDescription& y) { return key (x) < key (y); });
  const ShapeDescription& a = swap ? second : first;
  const ShapeDescription& b = swap ? first : second;
  std::vector<double> wa, wb;
  std::vector<Eigen::Matrix<double, 6, 1>> pa, pb;
  for (const PartDescription& p : a.parts)
  {
    wa.push_back (p.weight);
    pa.push_back (partPoint (p));
  }
  for (const PartDescription& p : b.parts)
  {
    wb.push_back (p.weight);
    pb.push_back (partPoint (p));
  }
  Eigen::MatrixXd cost (static_cast<Eigen::Index> (pa.size ()), static_cast<Eigen::Index> (pb.size ()));
  for (std::size_t i = 0; i < pa.size (); ++i)
    for (std::size_t j = 0; j < pb.size (); ++j)
      cost (static_cast<Eigen::Index> (i), static_cast<Eigen::Index> (j)) = (pa[i] - pb[j]).norm ();
  return transportDistance (wa, wb, cost);
}

double
descriptionDistance (MatchMethod method, const ShapeDescription& a, const ShapeDescription& b, int dimension)
{
  const DescriptionWeights w = descriptionWeights (method, dimension);
  double sum = 0.0;
  if (w.parts > 0.0)
    sum += w.parts * partDistance (a, b);
  if (w.thickness > 0.0)
    sum += w.thickness * l1Distance (a.thickness, b.thickness);
  if (w.inner_distance > 0.0)
    sum += w.inner_distance * chiSquareDistance (a.inner_distance, b.inner_distance);
  if (w.solid_distance > 0.0)
    sum += w.solid_distance * l1Distance (a.solid_distance, b.solid_distance);
  if (w.inner_profile > 0.0)
    sum += w.inner_profile * innerProfileDistance (a, b);
  if (w.thickness_profile > 0.0)
    sum += w.thickness_profile * thicknessProfileDistance (a, b);
  if (w.contour > 0.0)
    sum += w.contour * contourDistance (a, b);
  return sum;
}

} // namespace pcl_flowseg

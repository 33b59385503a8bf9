/*
 * pcl_flowseg - distances between shape descriptions: parts and inner-distance profiles by earth
 * mover's distance, inner contexts by least-cost assignment, distributions by L1 or chi-square,
 * and their weighted sum.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include "description_distances.h"

#include "assignment_cost.h"
#include "contour_matching.h"
#include "transport_distance.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <tuple>
#include <vector>

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
      w.smallest_ratio * p.smallest_ratio, w.weight * std::log (p.weight), w.remoteness * p.remoteness;
  return x;
}

std::vector<double>
partMasses (const ShapeDescription& description)
{
  std::vector<double> masses;
  double total = 0.0;
  for (const PartDescription& p : description.parts)
  {
    masses.push_back (std::pow (p.weight, kPartMassExponent));
    total += masses.back ();
  }
  for (double& m : masses)
    m /= total;
  return masses;
}

double
partDistance (const ShapeDescription& first, const ShapeDescription& second)
{
  // The transport is solved in one fixed order of the two part lists, so that rounding cannot make
  // the distance from a to b differ from the distance from b to a.
  const auto key = [] (const PartDescription& p) {
    return std::make_tuple (p.weight, p.thickness, p.extent, p.middle_ratio, p.smallest_ratio, p.remoteness);
  };
  const bool swap = std::lexicographical_compare (second.parts.begin (), second.parts.end (), first.parts.begin (), first.parts.end (),
                                                  [&] (const PartDescription& x, const PartDescription& y) { return key (x) < key (y); });
  const ShapeDescription& a = swap ? second : first;
  const ShapeDescription& b = swap ? first : second;
  std::vector<Eigen::Matrix<double, 6, 1>> pa, pb;
  for (const PartDescription& p : a.parts)
    pa.push_back (partPoint (p));
  for (const PartDescription& p : b.parts)
    pb.push_back (partPoint (p));
  Eigen::MatrixXd cost (static_cast<Eigen::Index> (pa.size ()), static_cast<Eigen::Index> (pb.size ()));
  for (std::size_t i = 0; i < pa.size (); ++i)
    for (std::size_t j = 0; j < pb.size (); ++j)
      cost (static_cast<Eigen::Index> (i), static_cast<Eigen::Index> (j)) = (pa[i] - pb[j]).norm ();
  return transportDistance (partMasses (a), partMasses (b), cost);
}

namespace {

/** Cumulative sums of each context's histogram: the earth mover's distance between two is then
  * the L1 distance of their rows times the bin width. */
std::vector<std::array<double, kContextBins>>
cumulativeContexts (const std::vector<InnerContext>& contexts)
{
  std::vector<std::array<double, kContextBins>> rows (contexts.size ());
  for (std::size_t i = 0; i < contexts.size (); ++i)
  {
    double sum = 0.0;
    for (std::size_t k = 0; k < kContextBins; ++k)
      rows[i][k] = sum += static_cast<double> (contexts[i].distances[k]);
  }
  return rows;
}

bool
contextLess (const InnerContext& a, const InnerContext& b)
{
  return std::tie (a.thickness, a.distances) < std::tie (b.thickness, b.distances);
}

} // namespace

double
innerContextDistance (const ShapeDescription& first, const ShapeDescription& second)
{
  // Solved in one fixed order of the two (the fewer contexts as rows), so that rounding cannot
  // make the distance from a to b differ from b to a.
  const std::vector<InnerContext>& x = first.inner_contexts;
  const std::vector<InnerContext>& y = second.inner_contexts;
  const bool swap = y.size () != x.size () ? y.size () < x.size ()
                                           : std::lexicographical_compare (y.begin (), y.end (), x.begin (), x.end (), contextLess);
  const std::vector<InnerContext>& rows = swap ? y : x;
  const std::vector<InnerContext>& columns = swap ? x : y;
  if (rows.empty ())
    return 0.0;
  const auto row_sums = cumulativeContexts (rows), column_sums = cumulativeContexts (columns);
  const double bin_width = (kContextLogHigh - kContextLogLow) / static_cast<double> (kContextBins);
  std::vector<double> cost (rows.size () * columns.size ());
  for (std::size_t i = 0; i < rows.size (); ++i)
    for (std::size_t j = 0; j < columns.size (); ++j)
    {
      double moved = 0.0;
      for (std::size_t k = 0; k < kContextBins; ++k)
        moved += std::abs (row_sums[i][k] - column_sums[j][k]);
      const double thicker = std::abs (static_cast<double> (rows[i].thickness) - static_cast<double> (columns[j].thickness));
      cost[i * columns.size () + j] = moved * bin_width + kContextThicknessWeight * thicker;
    }
  return leastAssignmentCost (cost, rows.size (), columns.size ()) / static_cast<double> (rows.size ());
}

double
descriptionDistance (const DescriptionWeights& w, const ShapeDescription& a, const ShapeDescription& b)
{
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
  if (w.inner_context > 0.0)
    sum += w.inner_context * innerContextDistance (a, b);
  return sum;
}

} // namespace pcl_flowseg

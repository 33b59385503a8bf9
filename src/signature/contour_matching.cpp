/*
 * pcl_flowseg - matching two 2D contours (inner-distance shape contexts along their outlines) by
 * dynamic programming, from any start and in either direction.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include "contour_matching.h"

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <utility>

namespace pcl_flowseg {

namespace {

/** Cost of leaving a contour point unmatched (an occlusion or a part one shape lacks): matched
  * pairs cost a Hellinger distance in [0, 1]. */
constexpr double kSkipCost = 0.2;
/** Starting offsets tried by the dynamic programme: the best of all circular shifts by the cost
  * of matching point i to point i + shift. */
constexpr std::size_t kStarts = 4;
static_assert (kStarts <= kContourPoints, "more starts than contour points");

/** The contour's histograms as rows of their square roots: the Hellinger distance of two
  * histograms, 1 - sum sqrt(a b), is then one minus a dot product, and the costs of all pairs of
  * points one matrix product. */
using RootRows = Eigen::Matrix<float, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

RootRows
rootRows (const std::vector<ContourHistogram>& contour)
{
  RootRows rows (static_cast<Eigen::Index> (contour.size ()), static_cast<Eigen::Index> (kContourBins));
  for (std::size_t i = 0; i < contour.size (); ++i)
    for (std::size_t k = 0; k < kContourBins; ++k)
      rows (static_cast<Eigen::Index> (i), static_cast<Eigen::Index> (k)) = std::sqrt (contour[i][k]);
  return rows;
}

/** Least cost of an order-keeping matching of the rows to the columns of \a cost (row-major,
  * n x n) started at column shifts[t], for each of the kStarts shifts at once: the programmes
  * are independent, so interleaved they run side by side instead of waiting on each other. */
double
alignedCost (const std::vector<float>& cost, std::size_t n, const std::array<std::size_t, kStarts>& shifts)
{
  const auto skip = static_cast<float> (kSkipCost);
  std::vector<float> previous ((n + 1) * kStarts), current ((n + 1) * kStarts);
  for (std::size_t j = 0; j <= n; ++j)
    for (std::size_t t = 0; t < kStarts; ++t)
      previous[j * kStarts + t] = skip * static_cast<float> (j);
  for (std::size_t i = 1; i <= n; ++i)
  {
    const float* row = &cost[(i - 1) * n];
    for (std::size_t t = 0; t < kStarts; ++t)
      current[t] = skip * static_cast<float> (i);
    std::array<std::size_t, kStarts> column = shifts;
    for (std::size_t j = 1; j <= n; ++j)
      for (std::size_t t = 0; t < kStarts; ++t)
      {
        const float matched = previous[(j - 1) * kStarts + t] + row[column[t]];
        current[j * kStarts + t] = std::min (matched, skip + std::min (previous[j * kStarts + t], current[(j - 1) * kStarts + t]));
        column[t] = column[t] + 1 == n ? 0 : column[t] + 1;
      }
    std::swap (previous, current);
  }
  float best = previous[n * kStarts];
  for (std::size_t t = 1; t < kStarts; ++t)
    best = std::min (best, previous[n * kStarts + t]);
  return best;
}

/** The cost of matching \a a to \a b (root rows, as many in each and at least kStarts): the
  * dynamic programme from the kStarts most promising shifts (by the cost of matching point i to
  * point i + shift), over the number of points. */
double
bestAlignment (const RootRows& a, const RootRows& b)
{
  const auto n = static_cast<std::size_t> (a.rows ());
  std::vector<float> cost (n * n);
  Eigen::Map<Eigen::Matrix<float, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>> costs (cost.data (), a.rows (), b.rows ());
  costs.noalias () = a.lazyProduct (b.transpose ()); // coefficient-wise: no threads for so small a product
  for (float& c : cost)
    c = std::max (0.0f, 1.0f - c); // Hellinger distance, in [0, 1]
  std::vector<float> diagonal (n, 0.0f);
  for (std::size_t i = 0; i < n; ++i)
  {
    const float* row = &cost[i * n];
    for (std::size_t j = i; j < n; ++j)
      diagonal[j - i] += row[j];
    for (std::size_t j = 0; j < i; ++j)
      diagonal[j + n - i] += row[j];
  }
  std::vector<std::pair<float, std::size_t>> ranked (n);
  for (std::size_t s = 0; s < n; ++s)
    ranked[s] = {diagonal[s], s};
  std::partial_sort (ranked.begin (), ranked.begin () + static_cast<std::ptrdiff_t> (kStarts), ranked.end ());
  std::array<std::size_t, kStarts> shifts;
  for (std::size_t t = 0; t < kStarts; ++t)
    shifts[t] = ranked[t].second;
  return alignedCost (cost, n, shifts) / static_cast<double> (n);
}

} // namespace

std::vector<ContourHistogram>
mirroredContour (const std::vector<ContourHistogram>& contour)
{
  std::vector<ContourHistogram> out (contour.rbegin (), contour.rend ());
  for (ContourHistogram& h : out)
  {
    const ContourHistogram in = h;
    for (std::size_t ring = 0; ring < kContourDistanceBins; ++ring)
      for (std::size_t sector = 0; sector < kContourAngleBins; ++sector)
        h[ring * kContourAngleBins + mirroredSector (sector)] = in[ring * kContourAngleBins + sector];
  }
  return out;
}

double
contourDistance (const ShapeDescription& a, const ShapeDescription& b)
{
  if (a.contour.size () != kContourPoints || b.contour.size () != kContourPoints)
    return 0.0;
  // Equal contours are at 0 exactly (the matrix product's rounding would leave about 1e-7). Others
  // are solved in one fixed order of the two, so that rounding cannot make the distance from a to
  // b differ from the distance from b to a.
  if (a.contour == b.contour)
    return 0.0;
  const bool swap = b.contour < a.contour;
  const RootRows first = rootRows (swap ? b.contour : a.contour);
  const std::vector<ContourHistogram>& second = swap ? a.contour : b.contour;
  return std::min (bestAlignment (first, rootRows (second)), bestAlignment (first, rootRows (mirroredContour (second))));
}

} // namespace pcl_flowseg

/*
 * pcl_flowseg - distributions measured inside a shape: thickness, inner distances (also by the
 * remoteness of their source, and as each source's own context) and solid distances between
 * volume-weighted random interior cells.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include "interior_distributions.h"

#include "interior_graph.h"

#include <pcl_flowseg/common/parallel_jobs.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>

namespace pcl_flowseg {

namespace {

/** A small, portable generator (splitmix64): the same draws with every compiler and library. */
class Draws
{
public:
  /** Uniform in [0, 1). */
  double next ()
  {
    std::uint64_t z = (state_ += 0x9E3779B97F4A7C15ULL);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    return static_cast<double> ((z ^ (z >> 31)) >> 11) * 0x1.0p-53;
  }

private:
  std::uint64_t state_ = 1;
};

/** kInteriorSamples interior cells drawn with probability proportional to their volume. The cells
  * are put in an order that does not depend on the frame (by volume and circumradius, which
  * rotation, translation and scale keep up to rounding), so that a moved copy of a sample draws
  * the same cells: the description is then invariant, not only in distribution. */
std::vector<int>
drawInteriorCells (const FlowResult& result)
{
  std::vector<int> inside;
  for (std::size_t i = 0; i < result.cells.size (); ++i)
    if (result.cells[i].inside == 1)
      inside.push_back (static_cast<int> (i));
  std::sort (inside.begin (), inside.end (), [&] (int a, int b) {
    const FlowCell& ca = result.cells[static_cast<std::size_t> (a)];
    const FlowCell& cb = result.cells[static_cast<std::size_t> (b)];
    if (ca.volume != cb.volume)
      return ca.volume > cb.volume;
    if (ca.squared_radius != cb.squared_radius)
      return ca.squared_radius > cb.squared_radius;
    return a < b;
  });
  std::vector<double> cumulative;
  double total = 0.0;
  for (int c : inside)
  {
    total += result.cells[static_cast<std::size_t> (c)].volume;
    cumulative.push_back (total);
  }
  std::vector<int> drawn;
  if (inside.empty ())
    return drawn;
  Draws draws;
  for (std::size_t k = 0; k < kInteriorSamples; ++k)
  {
    const auto at = std::upper_bound (cumulative.begin (), cumulative.end (), draws.next () * total) - cumulative.begin ();
    drawn.push_back (inside[std::min (static_cast<std::size_t> (at), inside.size () - 1)]);
  }
  return drawn;
}

/** Adds \a weight at \a value to a histogram over [low, high] (outside values go to the end bins). */
void
addToBins (Distribution& bins, double value, double low, double high, double weight = 1.0)
{
  const double at = (value - low) / (high - low) * static_cast<double> (kDistributionBins);
  const double clamped = std::isnan (at) ? 0.0 : std::clamp (at, 0.0, static_cast<double> (kDistributionBins - 1));
  bins[static_cast<std::size_t> (clamped)] += weight;
}

/** Divides by the total; an empty histogram becomes all mass in the first bin. */
void
normalise (Distribution& bins)
{
  double total = 0.0;
  for (double v : bins)
    total += v;
  if (total <= 0.0)
    bins[0] = total = 1.0;
  for (double& v : bins)
    v /= total;
}

/** Inner distances from the centroid of cell \a source: to each sample point by the shortest path
  * through the interior edges (starting at the cell's corners), infinity where they do not reach. */
void
innerDistancesFrom (const FlowResult& result, const InteriorEdges& edges, int source, std::vector<double>& distance)
{
  const FlowCell& cell = result.cells[static_cast<std::size_t> (source)];
  std::vector<std::pair<int, double>> corners;
  for (int k = 0; k <= result.dimension; ++k)
  {
    const int v = cell.vertices[static_cast<std::size_t> (k)];
    corners.emplace_back (v, (result.vertices[static_cast<std::size_t> (v)] - cell.centroid).norm ());
  }
  shortestPaths (edges, corners, distance);
}

/** The inner distance to the centroid of cell \a target, through its nearest corner by path. */
double
innerDistanceTo (const FlowResult& result, const std::vector<double>& distance, int target)
{
  const FlowCell& cell = result.cells[static_cast<std::size_t> (target)];
  double best = std::numeric_limits<double>::infinity ();
  for (int k = 0; k <= result.dimension; ++k)
  {
    const int v = cell.vertices[static_cast<std::size_t> (k)];
    best = std::min (best, distance[static_cast<std::size_t> (v)] + (result.vertices[static_cast<std::size_t> (v)] - cell.centroid).norm ());
  }
  return best;
}

/** Sources spread over the drawn cells (farthest points by centroid distance, from the first
  * drawn), each weighted by the share of drawn cells nearest to it: pairs from a few sources then
  * stand for all pairs with far less variance than from the first few drawn (a dumbbell's sources
  * fall into both bulbs in their proportion). */
void
spreadSources (const FlowResult& result, const std::vector<int>& drawn, std::vector<int>& sources, std::vector<double>& weights)
{
  const auto centroid = [&] (std::size_t k) -> const Eigen::Vector3d& { return result.cells[static_cast<std::size_t> (drawn[k])].centroid; };
  std::vector<double> nearest (drawn.size (), std::numeric_limits<double>::infinity ());
  std::vector<std::size_t> owner (drawn.size (), 0);
  std::size_t next = 0;
  for (std::size_t s = 0; s < std::min (kDistanceSources, drawn.size ()); ++s)
  {
    sources.push_back (drawn[next]);
    const Eigen::Vector3d from = centroid (next);
    std::size_t farthest = 0;
    for (std::size_t k = 0; k < drawn.size (); ++k)
    {
      const double d = (centroid (k) - from).norm ();
      if (d < nearest[k])
      {
        nearest[k] = d;
        owner[k] = s;
      }
      if (nearest[k] > nearest[farthest])
        farthest = k;
    }
    next = farthest;
  }
  weights.assign (sources.size (), 0.0);
  for (std::size_t k = 0; k < drawn.size (); ++k)
    weights[owner[k]] += 1.0 / static_cast<double> (drawn.size ());
}

/** Row s: the inner distance from source s to each drawn cell, in the order of \a drawn. The
  * sources' shortest-path searches are independent and run on the result's worker threads. */
std::vector<std::vector<double>>
innerDistanceRows (const FlowResult& result, const InteriorEdges& edges, const std::vector<int>& sources, const std::vector<int>& drawn)
{
  std::vector<std::vector<double>> rows (sources.size ());
  runParallelJobs (sources.size (), result.parameters.execution.threads, [&] (std::size_t s) {
    std::vector<double> distance (result.vertices.size ());
    innerDistancesFrom (result, edges, sources[s], distance);
    rows[s].reserve (drawn.size ());
    for (int target : drawn)
      rows[s].push_back (target == sources[s] ? 0.0 : innerDistanceTo (result, distance, target));
  });
  return rows;
}

/** The mean bin of a histogram: orders sources from the most central to the most remote. */
double
meanBin (const Distribution& bins)
{
  double mean = 0.0, total = 0.0;
  for (std::size_t b = 0; b < kDistributionBins; ++b)
  {
    mean += static_cast<double> (b) * bins[b];
    total += bins[b];
  }
  return total > 0.0 ? mean / total : 0.0;
}

/** Cuts the sources, ordered by the mean of their histogram \a seen[s], into kProfileRows equal
  * shares of their weight; each row gets the histograms of its sources in proportion to the
  * weight they have in its share. */
void
fillInnerProfiles (const std::vector<Distribution>& seen, const std::vector<double>& weights, InnerProfiles& profiles)
{
  std::vector<std::size_t> order (seen.size ());
  std::vector<double> mean (seen.size ());
  for (std::size_t s = 0; s < seen.size (); ++s)
  {
    order[s] = s;
    mean[s] = meanBin (seen[s]);
  }
  std::stable_sort (order.begin (), order.end (), [&] (std::size_t a, std::size_t b) { return mean[a] < mean[b]; });
  double total = 0.0;
  for (double w : weights)
    total += w;
  const double rows = static_cast<double> (kProfileRows);
  double start = 0.0;
  for (std::size_t s : order)
  {
    const double end = start + (total > 0.0 ? weights[s] / total : 0.0);
    for (std::size_t r = 0; r < kProfileRows; ++r)
    {
      const double overlap = std::min (end, static_cast<double> (r + 1) / rows) - std::max (start, static_cast<double> (r) / rows);
      for (std::size_t b = 0; overlap > 0.0 && b < kDistributionBins; ++b)
        profiles[r][b] += overlap * seen[s][b];
    }
    start = end;
  }
  for (Distribution& row : profiles)
    normalise (row);
}

/** Entry r: the mean log circumradius over \a unit of the drawn cells in the r-th equal share of
  * them by remoteness (their mean inner distance from the sources, \a remoteness[k]), each clamped
  * to the thickness range (a nearly flat cell's circumradius can be arbitrarily large). */
void
fillThicknessProfile (const FlowResult& result, const std::vector<int>& drawn, const std::vector<double>& remoteness, double unit,
                      ThicknessProfile& profile)
{
  std::vector<std::size_t> order (drawn.size ());
  for (std::size_t k = 0; k < order.size (); ++k)
    order[k] = k;
  std::stable_sort (order.begin (), order.end (), [&] (std::size_t a, std::size_t b) { return remoteness[a] < remoteness[b]; });
  std::array<double, kProfileRows> count{};
  profile.fill (0.0);
  for (std::size_t i = 0; i < order.size (); ++i)
  {
    const std::size_t r = i * kProfileRows / order.size ();
    const double radius = 0.5 * std::log (result.cells[static_cast<std::size_t> (drawn[order[i]])].squared_radius) - std::log (unit);
    profile[r] += std::clamp (radius, kThicknessLogLow, kThicknessLogHigh);
    count[r] += 1.0;
  }
  for (std::size_t r = 0; r < kProfileRows; ++r)
    profile[r] = count[r] > 0.0 ? profile[r] / count[r] : kThicknessLogLow;
}

/** One inner context per source (InnerContext): its cells' share by log inner distance over the
  * weighted mean of all inner distances in \a rows (finite), and its own log thickness. */
void
fillInnerContexts (const FlowResult& result, const std::vector<int>& sources, const std::vector<double>& weights,
                   const std::vector<std::vector<double>>& rows, double unit, std::vector<InnerContext>& contexts)
{
  double mean = 0.0;
  for (std::size_t s = 0; s < rows.size (); ++s)
    for (double d : rows[s])
      mean += weights[s] * d / static_cast<double> (rows[s].size ());
  contexts.assign (sources.size (), InnerContext{});
  for (std::size_t s = 0; s < sources.size (); ++s)
  {
    InnerContext& context = contexts[s];
    const double share = 1.0 / static_cast<double> (rows[s].size ());
    for (double d : rows[s])
    {
      const double at = d > 0.0 && mean > 0.0 ? std::log (d / mean) : kContextLogLow;
      const double bin = (at - kContextLogLow) / (kContextLogHigh - kContextLogLow) * static_cast<double> (kContextBins);
      const double clamped = std::isnan (bin) ? 0.0 : std::clamp (bin, 0.0, static_cast<double> (kContextBins - 1));
      context.distances[static_cast<std::size_t> (clamped)] += static_cast<float> (share);
    }
    const double radius = 0.5 * std::log (result.cells[static_cast<std::size_t> (sources[s])].squared_radius) - std::log (unit);
    context.thickness = static_cast<float> (std::clamp (radius, kThicknessLogLow, kThicknessLogHigh));
  }
}

/** The remoteness of each part (PartDescription::remoteness): the weighted mean over the sources
  * of the inner distance to the centroid of the part's maximum cell, the straight distance where
  * the interior falls apart. \a part_rows[s][p] is the inner distance from source s to part p. */
void
fillPartRemoteness (const FlowResult& result, const std::vector<int>& sources, const std::vector<double>& weights,
                    const std::vector<std::vector<double>>& part_rows, const std::vector<int>& part_maxima, double unit,
                    std::vector<PartDescription>& parts)
{
  double total = 0.0;
  for (double w : weights)
    total += w;
  for (std::size_t p = 0; p < parts.size () && p < part_maxima.size (); ++p)
  {
    const Eigen::Vector3d& at = result.cells[static_cast<std::size_t> (part_maxima[p])].centroid;
    double sum = 0.0;
    for (std::size_t s = 0; s < sources.size (); ++s)
    {
      const double inner = part_rows[s][p];
      sum += weights[s] * (std::isfinite (inner) ? inner : (at - result.cells[static_cast<std::size_t> (sources[s])].centroid).norm ());
    }
    parts[p].remoteness = total > 0.0 ? sum / total / unit : 0.0;
  }
}

void
measureDistances (const FlowResult& result, const InteriorEdges& edges, const std::vector<int>& drawn,
                  const std::vector<int>& part_maxima, double unit, ShapeDescription& description)
{
  std::vector<int> sources;
  std::vector<double> weights, solid, solid_weight;
  spreadSources (result, drawn, sources, weights);
  // One search per source reaches the drawn cells and the parts' maxima alike.
  std::vector<int> targets (drawn);
  targets.insert (targets.end (), part_maxima.begin (), part_maxima.end ());
  std::vector<std::vector<double>> inner_rows = innerDistanceRows (result, edges, sources, targets);
  std::vector<std::vector<double>> part_rows (sources.size ());
  for (std::size_t s = 0; s < sources.size (); ++s)
  {
    part_rows[s].assign (inner_rows[s].begin () + static_cast<std::ptrdiff_t> (drawn.size ()), inner_rows[s].end ());
    inner_rows[s].resize (drawn.size ());
  }
  fillPartRemoteness (result, sources, weights, part_rows, part_maxima, unit, description.parts);
  std::vector<Distribution> seen (sources.size (), Distribution{});
  std::vector<double> remoteness (drawn.size (), 0.0);
  for (std::size_t s = 0; s < sources.size (); ++s)
  {
    const Eigen::Vector3d& from = result.cells[static_cast<std::size_t> (sources[s])].centroid;
    for (std::size_t k = 0; k < drawn.size (); ++k)
    {
      const double straight = (result.cells[static_cast<std::size_t> (drawn[k])].centroid - from).norm ();
      // Where the interior falls apart (a gap in the labelling of a thin neck) the straight
      // distance stands in: dropping the pair would change the distribution far more.
      double& inner = inner_rows[s][k];
      if (!std::isfinite (inner))
        inner = straight;
      remoteness[k] += weights[s] * inner;
      // A distance of 0 (the source itself) goes to the first bin of its source's histogram, as
      // does any below the range; the distribution of all pairs leaves it out.
      const double log_inner = inner > 0.0 ? std::log (inner / unit) : kInnerLogLow;
      addToBins (seen[s], log_inner, kInnerLogLow, kInnerLogHigh);
      if (inner > 0.0)
        addToBins (description.inner_distance, log_inner, kInnerLogLow, kInnerLogHigh, weights[s]);
      solid.push_back (straight);
      solid_weight.push_back (weights[s]);
    }
  }
  fillInnerProfiles (seen, weights, description.inner_profiles);
  fillInnerContexts (result, sources, weights, inner_rows, unit, description.inner_contexts);
  fillThicknessProfile (result, drawn, remoteness, unit, description.thickness_profile);
  double mean = 0.0, total = 0.0;
  for (std::size_t k = 0; k < solid.size (); ++k)
  {
    mean += solid_weight[k] * solid[k];
    total += solid_weight[k];
  }
  mean = total > 0.0 ? mean / total : 0.0;
  for (std::size_t k = 0; k < solid.size (); ++k)
    addToBins (description.solid_distance, mean > 0.0 ? solid[k] / mean : 0.0, 0.0, kSolidHigh, solid_weight[k]);
}

} // namespace

void
describeInteriorDistributions (const FlowResult& result, const InteriorFrame& frame, const InteriorEdges& edges,
                               const std::vector<int>& part_maxima, ShapeDescription& description)
{
  const std::vector<int> drawn = drawInteriorCells (result);
  for (int c : drawn)
    addToBins (description.thickness, 0.5 * std::log (result.cells[static_cast<std::size_t> (c)].squared_radius) - std::log (frame.unit),
               kThicknessLogLow, kThicknessLogHigh);
  measureDistances (result, edges, drawn, part_maxima, frame.unit, description);
  normalise (description.thickness);
  normalise (description.inner_distance);
  normalise (description.solid_distance);
}

} // namespace pcl_flowseg

/*
 * pcl_flowseg - inner-distance shape context along the outline of a 2D shape.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include "contour_context.h"

#include "interior_graph.h"

#include <pcl_flowseg/common/parallel_jobs.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

namespace pcl_flowseg {

namespace {

constexpr double kPi = 3.14159265358979323846;
/** Distance bins span [1/8, 2] times the mean inner distance, log-spaced (as in shape context). */
constexpr double kNearShare = 0.125, kFarShare = 2.0;

double
cross2 (const Eigen::Vector3d& a, const Eigen::Vector3d& b)
{
  return a.x () * b.y () - a.y () * b.x ();
}

/** Boundary edges of the interior (to an outside cell or the hull), directed with the interior on
  * their left: next[v] lists the ends of the edges that start at v. */
std::vector<std::vector<int>>
boundaryEdges (const FlowResult& result)
{
  const auto& p = result.vertices;
  std::vector<std::vector<int>> next (p.size ());
  for (const FlowCell& c : result.cells)
  {
    if (c.inside != 1)
      continue;
    const auto at = [&] (int k) -> const Eigen::Vector3d& { return p[static_cast<std::size_t> (c.vertices[static_cast<std::size_t> (k)])]; };
    const bool ccw = cross2 (at (1) - at (0), at (2) - at (0)) > 0.0;
    for (int i = 0; i < 3; ++i)
    {
      const int nb = c.neighbors[static_cast<std::size_t> (i)];
      if (nb >= 0 && result.cells[static_cast<std::size_t> (nb)].inside == 1)
        continue;
      int a = c.vertices[static_cast<std::size_t> ((i + 1) % 3)], b = c.vertices[static_cast<std::size_t> ((i + 2) % 3)];
      if (!ccw)
        std::swap (a, b);
      next[static_cast<std::size_t> (a)].push_back (b);
    }
  }
  return next;
}

/** The closed loop of boundary edges that encloses the largest area (the outline; holes run
  * clockwise and enclose a negative area), counter-clockwise. Empty when there is none. */
std::vector<int>
outerLoop (const FlowResult& result)
{
  const auto& p = result.vertices;
  std::vector<std::vector<int>> next = boundaryEdges (result);
  std::vector<int> best;
  double best_area = 0.0;
  for (std::size_t start = 0; start < p.size (); ++start)
    while (!next[start].empty ())
    {
      std::vector<int> loop;
      std::size_t v = start;
      double area = 0.0;
      do
      {
        const int w = next[v].back ();
        next[v].pop_back ();
        loop.push_back (static_cast<int> (v));
        area += cross2 (p[v], p[static_cast<std::size_t> (w)]);
        v = static_cast<std::size_t> (w);
      } while (v != start && !next[v].empty ());
      if (v == start && area > best_area)
      {
        best_area = area;
        best = std::move (loop);
      }
    }
  return best;
}

/** Positions in \a loop of kContourPoints points at equal steps of arc length; each loop vertex's
  * share of the loop's length (half of each adjacent edge) in \a share. */
std::vector<std::size_t>
samplePositions (const std::vector<Eigen::Vector3d>& p, const std::vector<int>& loop, std::vector<double>& share)
{
  const std::size_t m = loop.size ();
  std::vector<double> edge (m), at (m + 1, 0.0);
  for (std::size_t k = 0; k < m; ++k)
  {
    edge[k] = (p[static_cast<std::size_t> (loop[(k + 1) % m])] - p[static_cast<std::size_t> (loop[k])]).norm ();
    at[k + 1] = at[k] + edge[k];
  }
  share.assign (m, 0.0);
  for (std::size_t k = 0; k < m; ++k)
    share[k] = 0.5 * (edge[k] + edge[(k + m - 1) % m]) / at[m];
  std::vector<std::size_t> positions;
  std::size_t k = 0;
  for (std::size_t s = 0; s < kContourPoints; ++s)
  {
    const double target = at[m] * static_cast<double> (s) / static_cast<double> (kContourPoints);
    while (k + 1 < m && std::abs (at[k + 1] - target) < std::abs (at[k] - target))
      ++k;
    positions.push_back (k);
  }
  return positions;
}

/** What one contour point sees of the loop: per loop vertex its inner distance (< 0: unreached or
  * the point itself) and its direction, the angle in [0, 2 pi) from the loop's tangent there. */
struct View
{
  std::vector<double> distance, angle;
};

View
viewFrom (const FlowResult& result, const InteriorEdges& edges, const std::vector<int>& loop, std::size_t k)
{
  const auto& p = result.vertices;
  const std::size_t m = loop.size ();
  std::vector<double> distance (p.size ());
  shortestPaths (edges, {{loop[k], 0.0}}, distance);
  const Eigen::Vector3d& from = p[static_cast<std::size_t> (loop[k])];
  const Eigen::Vector3d tangent = p[static_cast<std::size_t> (loop[(k + 1) % m])] - p[static_cast<std::size_t> (loop[(k + m - 1) % m])];
  View view;
  for (std::size_t t = 0; t < m; ++t)
  {
    const std::size_t v = static_cast<std::size_t> (loop[t]);
    const Eigen::Vector3d to = p[v] - from;
    double angle = std::atan2 (cross2 (tangent, to), tangent.x () * to.x () + tangent.y () * to.y ());
    if (angle < 0.0)
      angle += 2.0 * kPi;
    view.distance.push_back (t != k && std::isfinite (distance[v]) && distance[v] > 0.0 ? distance[v] : -1.0);
    view.angle.push_back (angle);
  }
  return view;
}

/** The histogram of \a view, distances over \a mean, each loop vertex weighted by its \a share. */
ContourHistogram
histogramOf (const View& view, const std::vector<double>& share, double mean)
{
  const double low = std::log (kNearShare), high = std::log (kFarShare);
  std::array<double, kContourBins> bins{};
  double total = 0.0;
  for (std::size_t t = 0; t < view.distance.size (); ++t)
  {
    if (view.distance[t] < 0.0)
      continue;
    const double at = (std::log (view.distance[t] / mean) - low) / (high - low) * static_cast<double> (kContourDistanceBins);
    const auto ring = static_cast<std::size_t> (std::clamp (at, 0.0, static_cast<double> (kContourDistanceBins - 1)));
    const auto sector = std::min (kContourAngleBins - 1, static_cast<std::size_t> (view.angle[t] / (2.0 * kPi) * kContourAngleBins));
    bins[ring * kContourAngleBins + sector] += share[t];
    total += share[t];
  }
  if (!(total > 0.0))
    return ContourHistogram{};
  ContourHistogram h;
  for (std::size_t k = 0; k < kContourBins; ++k)
    h[k] = static_cast<float> (bins[k] / total);
  return h;
}

} // namespace

void
describeContour (const FlowResult& result, const InteriorEdges& edges, ShapeDescription& description)
{
  description.contour.clear ();
  if (result.dimension != 2)
    return;
  const std::vector<int> loop = outerLoop (result);
  if (loop.size () < 3)
    return;
  std::vector<double> share;
  const std::vector<std::size_t> positions = samplePositions (result.vertices, loop, share);
  std::vector<View> views (kContourPoints);
  runParallelJobs (kContourPoints, result.parameters.execution.threads,
                   [&] (std::size_t s) { views[s] = viewFrom (result, edges, loop, positions[s]); });
  double mean = 0.0, weight = 0.0;
  for (const View& view : views)
    for (std::size_t t = 0; t < loop.size (); ++t)
      if (view.distance[t] > 0.0)
      {
        mean += share[t] * view.distance[t];
        weight += share[t];
      }
  if (!(weight > 0.0 && mean > 0.0))
    return;
  for (const View& view : views)
    description.contour.push_back (histogramOf (view, share, mean / weight));
}

} // namespace pcl_flowseg

/*
 * pcl_flowseg - internal: the hidden side of a single-view scan, guessed by mirroring.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include "core/preparation/hidden_side.h"

#include "core/geometry/view_image.h"
#include "core/support/parallel.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <set>

namespace pcl_flowseg {
namespace core {

namespace {

/** The samples as the sensor sees them: image position, range, and kRimNeighbours image neighbours. */
struct SensorView
{
  std::vector<Eigen::Vector2d> image;
  std::vector<double> range;
  std::vector<int> ids;            ///< row s: sample s itself, then its neighbours, nearest first
  std::vector<double> distances;   ///< image distances of \a ids
  double footprint = 0.0;          ///< median image spacing: range x footprint is a sample's size
  static constexpr std::size_t kRow = static_cast<std::size_t> (kRimNeighbours) + 1;
};

bool
seeSamples (const std::vector<Eigen::Vector3d>& samples, const Eigen::Vector3d& viewpoint, SensorView& out)
{
  const std::size_t n = samples.size ();
  const ViewImage view = viewImage (samples, viewpoint);
  out.image.resize (n);
  out.range.resize (n);
  for (std::size_t s = 0; s < n; ++s)
  {
    if (!view.project (samples[s], out.image[s]))
      return false;
    out.range[s] = (samples[s] - viewpoint).norm ();
  }
  nearestImagePoints (out.image, out.image, kRimNeighbours + 1, out.ids, out.distances);
  std::vector<double> reach (n);
  for (std::size_t s = 0; s < n; ++s)
    reach[s] = out.distances[s * SensorView::kRow + 4];
  std::nth_element (reach.begin (), reach.begin () + static_cast<long> (n / 2), reach.end ());
  out.footprint = reach[n / 2];
  return out.footprint > 0 && std::isfinite (out.footprint);
}

/** An occlusion edge at \a s: a neighbour much deeper, by a step much steeper than the others. */
bool
onOcclusionEdge (std::size_t s, const SensorView& v)
{
  std::vector<double> slopes;
  double steepest = 0.0, jump = 0.0;
  for (std::size_t j = 1; j < SensorView::kRow; ++j) // column 0: the sample itself
  {
    const int o = v.ids[s * SensorView::kRow + j];
    const double distance = v.distances[s * SensorView::kRow + j];
    if (o < 0 || !(distance > 0))
      continue;
    const double step = v.range[static_cast<std::size_t> (o)] - v.range[s];
    slopes.push_back (std::abs (step) / distance);
    if (step / distance > steepest)
    {
      steepest = step / distance;
      jump = step;
    }
  }
  if (slopes.empty () || jump <= kRimDepthJump * v.footprint * v.range[s])
    return false;
  std::nth_element (slopes.begin (), slopes.begin () + static_cast<long> (slopes.size () / 2), slopes.end ());
  return steepest > kRimSteepness * slopes[slopes.size () / 2];
}

/** On the silhouette at \a s: its image neighbours leave a wide angular gap around it. */
bool
onSilhouette (std::size_t s, const SensorView& v)
{
  std::vector<double> angles;
  for (std::size_t j = 1; j < SensorView::kRow; ++j)
  {
    const int o = v.ids[s * SensorView::kRow + j];
    if (o < 0 || !(v.distances[s * SensorView::kRow + j] > 0))
      continue;
    const Eigen::Vector2d e = v.image[static_cast<std::size_t> (o)] - v.image[s];
    angles.push_back (std::atan2 (e.y (), e.x ()));
  }
  if (angles.size () < 3)
    return true;
  std::sort (angles.begin (), angles.end ());
  double gap = angles.front () + 2.0 * M_PI - angles.back ();
  for (std::size_t j = 1; j < angles.size (); ++j)
    gap = std::max (gap, angles[j] - angles[j - 1]);
  return gap > kRimGapAngle;
}

/** Per sample, the mean range of the rim samples near it in the image that lie deeper than it by
  * at least kMinMirrorDepth footprints; NaN where there is none. */
std::vector<double>
rimRanges (const SensorView& v)
{
  const std::size_t n = v.range.size ();
  std::vector<std::size_t> rim;
  std::vector<Eigen::Vector2d> rim_image;
  for (std::size_t s = 0; s < n; ++s)
    if (onSilhouette (s, v) || onOcclusionEdge (s, v))
    {
      rim.push_back (s);
      rim_image.push_back (v.image[s]);
    }
  std::vector<double> rim_range (n, std::nan (""));
  std::vector<int> ids;
  std::vector<double> distances;
  nearestImagePoints (rim_image, v.image, kRimCandidates, ids, distances);
  const std::size_t row = static_cast<std::size_t> (kRimCandidates);
  for (std::size_t s = 0; s < n; ++s)
  {
    double sum = 0.0;
    int count = 0;
    for (std::size_t j = 0; j < row; ++j)
    {
      const int r = ids[s * row + j];
      if (r < 0 || distances[s * row + j] > kRimReach * distances[s * row] + v.footprint)
        break;
      const double range = v.range[rim[static_cast<std::size_t> (r)]];
      if (range - v.range[s] > kMinMirrorDepth * v.footprint * v.range[s])
      {
        sum += range;
        ++count;
      }
    }
    if (count > 0)
      rim_range[s] = sum / count;
  }
  return rim_range;
}

/** Averages \a rim_range over image neighbours (kRimSmoothingPasses passes), never across an
  * occlusion edge and never in front of the sample itself. */
void
smoothRimRanges (const SensorView& v, std::vector<double>& rim_range)
{
  const std::size_t n = v.range.size ();
  // The neighbours each sample averages over (itself included), gathered once.
  std::vector<std::size_t> first (n + 1, 0);
  std::vector<std::size_t> partners;
  for (std::size_t s = 0; s < n; ++s)
  {
    if (!std::isnan (rim_range[s]))
      for (std::size_t j = 0; j < SensorView::kRow; ++j)
      {
        const int o = v.ids[s * SensorView::kRow + j];
        if (o < 0)
          continue;
        const std::size_t u = static_cast<std::size_t> (o);
        if (!std::isnan (rim_range[u]) && std::abs (v.range[u] - v.range[s]) < kRimDepthJump * v.footprint * v.range[s])
          partners.push_back (u);
      }
    first[s + 1] = partners.size ();
  }
  std::vector<double> next (rim_range);
  for (int pass = 0; pass < kRimSmoothingPasses; ++pass)
  {
    parallelFor (n, [&] (std::size_t s) {
      if (first[s + 1] == first[s])
        return;
      double sum = 0.0;
      for (std::size_t k = first[s]; k < first[s + 1]; ++k)
        sum += rim_range[partners[k]];
      next[s] = std::max (sum / static_cast<double> (first[s + 1] - first[s]), v.range[s]);
    });
    rim_range.swap (next);
  }
}

} // namespace

std::vector<Eigen::Vector3d>
mirroredHiddenSide (const std::vector<Eigen::Vector3d>& samples, const Eigen::Vector3d& viewpoint)
{
  std::vector<Eigen::Vector3d> mirrored;
  SensorView v;
  if (samples.size () <= static_cast<std::size_t> (kRimNeighbours) || !seeSamples (samples, viewpoint, v))
    return mirrored;
  std::vector<double> rim_range = rimRanges (v);
  smoothRimRanges (v, rim_range);
  for (std::size_t s = 0; s < samples.size (); ++s)
  {
    const double depth = rim_range[s] - v.range[s]; // NaN: no rim behind the sample
    if (depth > kMinMirrorDepth * v.footprint * v.range[s])
      mirrored.push_back (viewpoint + (samples[s] - viewpoint) * ((rim_range[s] + depth) / v.range[s]));
  }
  return withoutCopies (samples, mirrored);
}

std::vector<Eigen::Vector3d>
withoutCopies (const std::vector<Eigen::Vector3d>& samples, const std::vector<Eigen::Vector3d>& mirrored)
{
  std::set<std::array<double, 3>> taken;
  for (const Eigen::Vector3d& p : samples)
    taken.insert ({p.x (), p.y (), p.z ()});
  std::vector<Eigen::Vector3d> kept;
  for (const Eigen::Vector3d& m : mirrored)
    if (taken.insert ({m.x (), m.y (), m.z ()}).second)
      kept.push_back (m);
  return kept;
}

} // namespace core
} // namespace pcl_flowseg

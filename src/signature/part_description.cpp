/*
 * pcl_flowseg - the interior features of a shape as parts with attributes (size, thickness,
 * principal extents, place).
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include "part_description.h"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <numeric>

namespace pcl_flowseg {

namespace {

/** Shortest length a part attribute takes, in the unit: degenerate parts (a flat cell) stay valid. */
constexpr double kShortestLength = 1e-9;

/** The interior segments described as parts, largest first. */
std::vector<int>
chooseParts (const FlowResult& result, const InteriorFrame& frame)
{
  std::vector<int> order = frame.segments;
  std::stable_sort (order.begin (), order.end (), [&] (int a, int b) {
    return result.segments[static_cast<std::size_t> (a)].volume > result.segments[static_cast<std::size_t> (b)].volume;
  });
  std::size_t kept = 0;
  while (kept < order.size () && kept < kMaxParts &&
         result.segments[static_cast<std::size_t> (order[kept])].volume >= kPartShare * frame.volume)
    ++kept;
  order.resize (std::max<std::size_t> (kept, std::min<std::size_t> (1, order.size ())));
  return order;
}

/** Volume-weighted second moments of each chosen segment's cells about its centroid. */
std::vector<Eigen::Matrix3d>
partMoments (const FlowResult& result, const std::vector<int>& chosen)
{
  std::vector<int> part_of_segment (result.segments.size (), -1);
  for (std::size_t p = 0; p < chosen.size (); ++p)
    part_of_segment[static_cast<std::size_t> (chosen[p])] = static_cast<int> (p);
  std::vector<Eigen::Matrix3d> moments (chosen.size (), Eigen::Matrix3d::Zero ());
  for (const FlowCell& c : result.cells)
  {
    const int p = c.segment < 0 ? -1 : part_of_segment[static_cast<std::size_t> (c.segment)];
    if (p < 0)
      continue;
    const Eigen::Vector3d d = c.centroid - result.segments[static_cast<std::size_t> (c.segment)].centroid;
    moments[static_cast<std::size_t> (p)] += c.volume * d * d.transpose ();
  }
  return moments;
}

PartDescription
describePart (const FlowSegment& segment, const Eigen::Matrix3d& moments, const InteriorFrame& frame, int dimension)
{
  PartDescription part;
  const Eigen::Vector3d e =
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> (moments / segment.volume, Eigen::EigenvaluesOnly).eigenvalues ();
  const double largest = std::max (0.0, e[2]);
  const auto ratio = [&] (double v) { return largest > 0.0 ? std::clamp (std::sqrt (std::max (0.0, v) / largest), 0.0, 1.0) : 0.0; };
  part.thickness = std::max (kShortestLength, std::sqrt (std::max (0.0, segment.maximum.height)) / frame.unit);
  part.extent = std::max (kShortestLength, std::sqrt (largest) / frame.unit);
  part.middle_ratio = ratio (e[1]);
  part.smallest_ratio = dimension == 3 ? ratio (e[0]) : 0.0;
  return part;
}

} // namespace

std::vector<PartDescription>
describeParts (const FlowResult& result, const InteriorFrame& frame, std::vector<int>& maximum_cells)
{
  const std::vector<int> chosen = chooseParts (result, frame);
  const std::vector<Eigen::Matrix3d> moments = partMoments (result, chosen);
  double total = 0.0;
  for (int k : chosen)
    total += result.segments[static_cast<std::size_t> (k)].volume;
  std::vector<PartDescription> parts;
  maximum_cells.clear ();
  for (std::size_t p = 0; p < chosen.size (); ++p)
  {
    const FlowSegment& segment = result.segments[static_cast<std::size_t> (chosen[p])];
    parts.push_back (describePart (segment, moments[p], frame, result.dimension));
    parts.back ().weight = segment.volume / total;
    maximum_cells.push_back (segment.maximum.cell);
  }
  return parts;
}

} // namespace pcl_flowseg

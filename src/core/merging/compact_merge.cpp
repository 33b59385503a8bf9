/*
 * pcl_flowseg - internal: the compact pass: shallow bulges no bigger than their neck merge.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include "core/merging/compact_merge.h"

#include "core/merging/union_find.h"

#include <algorithm>
#include <cmath>

namespace pcl_flowseg {
namespace core {

namespace {
/** Volume (area in 2D) of the ball (disc) of squared radius \a r2 in \a dimension. */
double
ballVolume (double r2, int dimension)
{
  constexpr double kPi = 3.14159265358979323846;
  return dimension == 3 ? 4.0 / 3.0 * kPi * r2 * std::sqrt (r2) : kPi * r2;
}
} // namespace

void
mergeCompactGroups (const FlowResult& result, std::vector<const SaddleFacet*>& candidates, double size,
                    std::vector<int>& parent)
{
  std::vector<double> volume (parent.size (), 0.0);
  for (std::size_t k = 0; k < parent.size (); ++k)
    volume[static_cast<std::size_t> (findRoot (parent, static_cast<int> (k)))] += result.manifolds[k].volume;
  auto depth = [&] (const SaddleFacet* s) {
    return std::max (result.manifolds[static_cast<std::size_t> (s->segment_a)].maximum.height,
                     result.manifolds[static_cast<std::size_t> (s->segment_b)].maximum.height) /
           s->squared_radius;
  };
  std::stable_sort (candidates.begin (), candidates.end (),
                    [&] (const SaddleFacet* x, const SaddleFacet* y) { return depth (x) < depth (y); });
  for (const SaddleFacet* s : candidates)
  {
    const int ra = findRoot (parent, s->segment_a), rb = findRoot (parent, s->segment_b);
    if (ra == rb)
      continue;
    const std::size_t lo = static_cast<std::size_t> (std::min (ra, rb)), hi = static_cast<std::size_t> (std::max (ra, rb));
    if (std::min (volume[lo], volume[hi]) <= size * ballVolume (s->squared_radius, result.dimension))
    {
      joinRoots (parent, ra, rb);
      volume[lo] += volume[hi];
    }
  }
}

} // namespace core
} // namespace pcl_flowseg

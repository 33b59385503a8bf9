/*
 * pcl_flowseg - internal: rho-merging of stable manifolds into segments.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include "core/merging/manifold_merging.h"

#include <pcl_flowseg/common/feature_significance.h>

#include "core/flow/cell_groups.h"
#include "core/geometry/cell_geometry.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <queue>
#include <unordered_map>

namespace pcl_flowseg {
namespace core {

namespace {
int
findRoot (std::vector<int>& parent, int x)
{
  while (parent[static_cast<std::size_t> (x)] != x)
  {
    parent[static_cast<std::size_t> (x)] = parent[static_cast<std::size_t> (parent[static_cast<std::size_t> (x)])];
    x = parent[static_cast<std::size_t> (x)];
  }
  return x;
}

/** Smallest cell a stump may take, as a share of the circumradius of the saddle between the two
  * segments: keeps the flood in the core of the thin part's tube instead of letting it run along the
  * thick part's surface, where the cells are small. (PSB error 0.151 with 0 and with 0.5, 0.152
  * with 0.65, 0.158 with 1; TOSCA retrieval first tier 0.577 with 0, 0.596 with 0.5.) */
constexpr double kStumpFloor = 0.5;

/** Thin parts take back their stumps (see mergeManifolds). \a group_of_cell is updated; a group's
  * height is that of its highest maximum (\a height, squared radius; negative: the group takes no
  * part: no maximum of its own, or the one at infinity). */
void
reclaimStumps (const FlowResult& result, const std::vector<double>& height, double ratio, std::vector<int>& group_of_cell)
{
  const std::size_t n = result.cells.size ();
  const int facets = result.dimension + 1;
  const double ratio2 = ratio * ratio;
  std::vector<char> fixed (n, 0); // maxima never move (segments keep their maxima's cells)
  for (const FlowSegment& man : result.manifolds)
    if (!man.flows_to_infinity && man.maximum.cell >= 0)
      fixed[static_cast<std::size_t> (man.maximum.cell)] = 1;
  const std::vector<int> original (group_of_cell);
  std::unordered_map<std::uint64_t, double> saddle; // (a < b) -> squared radius of their saddle
  auto key = [] (int a, int b) {
    return (static_cast<std::uint64_t> (std::min (a, b)) << 32) | static_cast<std::uint32_t> (std::max (a, b));
  };
  for (const SaddleFacet& s : highestSharedFacets (result, original))
    saddle[key (s.segment_a, s.segment_b)] = s.squared_radius;
  const double floor2 = kStumpFloor * kStumpFloor;
  // May thin group x take cell c (of its original group, a neighbour of x)? Only from a group more
  // than ratio times thicker, and only cells no larger than x's own maximum and not much smaller
  // than the saddle between the two.
  auto takes = [&] (int x, std::size_t c) {
    const int y = original[c];
    const double hx = height[static_cast<std::size_t> (x)], hy = height[static_cast<std::size_t> (y)];
    if (x == y || fixed[c] || !(hx > 0.0) || !(hy > 0.0) || !(ratio2 * hx < hy))
      return false;
    const double h = result.cells[c].squared_radius;
    const auto s = saddle.find (key (x, y));
    return h <= hx && s != saddle.end () && h >= floor2 * s->second;
  };
  // Lowest cells first (ties: lower cell, then lower group): a deterministic flood from every
  // boundary between a thin and a thick group at once.
  using Entry = std::pair<double, std::pair<int, int>>; // cell height, (cell, thin group)
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> queue;
  for (std::size_t c = 0; c < n; ++c)
    for (int i = 0; i < facets; ++i)
    {
      const int nb = result.cells[c].neighbors[i];
      if (nb < 0 || result.cells[static_cast<std::size_t> (nb)].inside != result.cells[c].inside)
        continue;
      const int x = original[static_cast<std::size_t> (nb)];
      if (takes (x, c))
        queue.emplace (result.cells[c].squared_radius, std::make_pair (static_cast<int> (c), x));
    }
  std::vector<char> taken (n, 0);
  while (!queue.empty ())
  {
    const Entry e = queue.top ();
    queue.pop ();
    const std::size_t c = static_cast<std::size_t> (e.second.first);
    const int x = e.second.second;
    if (taken[c])
      continue;
    taken[c] = 1;
    group_of_cell[c] = x;
    for (int i = 0; i < facets; ++i)
    {
      const int nb = result.cells[c].neighbors[i];
      if (nb >= 0 && !taken[static_cast<std::size_t> (nb)] && original[static_cast<std::size_t> (nb)] == original[c] &&
          takes (x, static_cast<std::size_t> (nb)))
        queue.emplace (result.cells[static_cast<std::size_t> (nb)].squared_radius, std::make_pair (nb, x));
    }
  }
}

/** Volume (area in 2D) of the ball (disc) of squared radius \a r2 in \a dimension. */
double
ballVolume (double r2, int dimension)
{
  constexpr double kPi = 3.14159265358979323846;
  return dimension == 3 ? 4.0 / 3.0 * kPi * r2 * std::sqrt (r2) : kPi * r2;
}

/** The compact pass of mergeManifolds: \a candidates (saddles that pass the merge rule at
  * compact_rho, not at rho) are visited from the shallowest (lowest ratio of the higher maximum
  * to the saddle) on; the two groups of \a parent they join merge when the smaller holds no more
  * than \a size balls of the saddle's radius. Ties keep the adjacency order, so the result is
  * deterministic. */
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
      parent[hi] = static_cast<int> (lo);
      volume[lo] += volume[hi];
    }
  }
}
} // namespace

std::vector<double>
nearestNeighbourDistances (const FlowResult& result)
{
  const int facets = result.dimension + 1;
  std::vector<double> nearest (result.vertices.size (), std::numeric_limits<double>::infinity ());
  for (const FlowCell& cell : result.cells)
    for (int i = 0; i < facets; ++i)
      for (int j = i + 1; j < facets; ++j)
      {
        const std::size_t a = static_cast<std::size_t> (cell.vertices[i]);
        const std::size_t b = static_cast<std::size_t> (cell.vertices[j]);
        const double length = (result.vertices[a] - result.vertices[b]).norm ();
        nearest[a] = std::min (nearest[a], length);
        nearest[b] = std::min (nearest[b], length);
      }
  return nearest;
}

double
saddleSpacing (const SaddleFacet& saddle, const std::vector<double>& nearest, int dimension)
{
  double sum = 0.0;
  for (int k = 0; k < dimension; ++k) // a facet has d vertices
    sum += nearest[static_cast<std::size_t> (saddle.vertices[static_cast<std::size_t> (k)])];
  return sum / dimension;
}

void
mergeManifolds (const MergeParameters& params, FlowResult& result)
{
  const double rho = params.rho, sampling_tolerance = params.sampling_tolerance, stump_ratio = params.stump_ratio;
  const double compact_rho = params.compact_rho, compact_size = params.compact_size;
  const bool sided = result.interior.computed;
  const int m = static_cast<int> (result.manifolds.size ());
  // Side of a manifold: the side of its maximum (the maximum at infinity is outside).
  std::vector<std::int8_t> side (static_cast<std::size_t> (m), -1);
  if (sided)
    for (int k = 0; k < m; ++k)
    {
      const FlowSegment& man = result.manifolds[static_cast<std::size_t> (k)];
      side[static_cast<std::size_t> (k)] =
          man.flows_to_infinity ? 0 : result.cells[static_cast<std::size_t> (man.maximum.cell)].inside;
    }

  std::vector<int> parent (static_cast<std::size_t> (m));
  std::iota (parent.begin (), parent.end (), 0);
  const double rho2 = rho * rho;
  // rho < 1 merges nothing, whatever the tolerance or compact pass (the paper's "no merging", Figure 6).
  const bool tolerant = sampling_tolerance > 0.0 && rho >= 1.0;
  const std::vector<double> nearest = tolerant ? nearestNeighbourDistances (result) : std::vector<double> ();
  // The compact pass (see the header): saddles that fail the rule at rho but pass it at compact_rho.
  const bool compact = compact_size > 0.0 && compact_rho > rho && rho >= 1.0;
  std::vector<const SaddleFacet*> compact_candidates;
  for (const SaddleFacet& s : result.manifold_adjacency)
  {
    const FlowSegment& a = result.manifolds[static_cast<std::size_t> (s.segment_a)];
    const FlowSegment& b = result.manifolds[static_cast<std::size_t> (s.segment_b)];
    if (a.flows_to_infinity || b.flows_to_infinity ||
        side[static_cast<std::size_t> (s.segment_a)] != side[static_cast<std::size_t> (s.segment_b)])
      continue;
    bool mergeable;
    const double tolerance_term = tolerant ? sampling_tolerance * saddleSpacing (s, nearest, result.dimension) : 0.0;
    if (tolerant)
    {
      const double limit = rho * std::sqrt (s.squared_radius) + tolerance_term;
      mergeable = std::sqrt (a.maximum.height) < limit && std::sqrt (b.maximum.height) < limit;
    }
    else
    {
      // The paper's rule, in squared radii (bit for bit the result without a tolerance).
      const double limit = rho2 * s.squared_radius;
      mergeable = a.maximum.height < limit && b.maximum.height < limit;
    }
    if (!mergeable && compact)
    {
      const double limit = compact_rho * std::sqrt (s.squared_radius) + tolerance_term;
      if (std::sqrt (a.maximum.height) < limit && std::sqrt (b.maximum.height) < limit)
        compact_candidates.push_back (&s);
    }
    if (mergeable)
    {
      const int ra = findRoot (parent, s.segment_a), rb = findRoot (parent, s.segment_b);
      if (ra != rb)
        parent[static_cast<std::size_t> (std::max (ra, rb))] = std::min (ra, rb);
    }
  }

  if (!compact_candidates.empty ())
    mergeCompactGroups (result, compact_candidates, compact_size, parent);

  std::vector<int> component (static_cast<std::size_t> (m), -1);
  std::vector<std::int8_t> component_side;
  int count = 0;
  for (int k = 0; k < m; ++k)
  {
    const int r = findRoot (parent, k);
    if (component[static_cast<std::size_t> (r)] < 0)
    {
      component[static_cast<std::size_t> (r)] = count++;
      component_side.push_back (side[static_cast<std::size_t> (r)]);
    }
    component[static_cast<std::size_t> (k)] = component[static_cast<std::size_t> (r)];
  }

  // Cells on the side of their segment keep it; the others join a segment of their own side.
  const std::size_t n = result.cells.size ();
  const int facets = result.dimension + 1;
  std::vector<int> provisional (n, -1);
  using Entry = std::pair<double, std::pair<int, int>>; // facet height, (cell, segment)
  std::priority_queue<Entry> queue;
  for (std::size_t c = 0; c < n; ++c)
  {
    const int comp = component[static_cast<std::size_t> (result.cells[c].manifold)];
    if (!sided || component_side[static_cast<std::size_t> (comp)] == result.cells[c].inside)
      provisional[c] = comp;
  }
  auto offer = [&] (std::size_t c) {
    for (int i = 0; i < facets; ++i)
    {
      const int nb = result.cells[c].neighbors[i];
      if (nb >= 0 && provisional[static_cast<std::size_t> (nb)] < 0 &&
          result.cells[static_cast<std::size_t> (nb)].inside == result.cells[c].inside)
        queue.emplace (facetSquaredRadius (result.vertices, result.cells[c], i, result.dimension),
                       std::make_pair (nb, provisional[c]));
    }
  };
  if (sided)
  {
    for (std::size_t c = 0; c < n; ++c)
      if (provisional[c] >= 0)
        offer (c);
    std::size_t next_cell = 0;
    while (true)
    {
      while (!queue.empty ())
      {
        const Entry e = queue.top ();
        queue.pop ();
        const std::size_t c = static_cast<std::size_t> (e.second.first);
        if (provisional[c] >= 0)
          continue;
        provisional[c] = e.second.second;
        offer (c);
      }
      // A region of one side that no segment of that side reaches (its cells all flow across the
      // boundary) becomes a segment of its own.
      while (next_cell < n && provisional[next_cell] >= 0)
        ++next_cell;
      if (next_cell == n)
        break;
      provisional[next_cell] = count++;
      component_side.push_back (result.cells[next_cell].inside);
      offer (next_cell);
    }
  }

  // Thin parts take back their stumps. A group's height is that of its highest maximum (-1: no
  // maximum of its own, or the group at infinity: it takes no part).
  if (stump_ratio > 0.0)
  {
    std::vector<double> height (static_cast<std::size_t> (count), -1.0);
    for (int k = 0; k < m; ++k)
    {
      const FlowSegment& man = result.manifolds[static_cast<std::size_t> (k)];
      double& h = height[static_cast<std::size_t> (component[static_cast<std::size_t> (k)])];
      if (!man.flows_to_infinity)
        h = std::max (h, man.maximum.height);
    }
    for (int k = 0; k < m; ++k)
      if (result.manifolds[static_cast<std::size_t> (k)].flows_to_infinity)
        height[static_cast<std::size_t> (component[static_cast<std::size_t> (k)])] = -1.0;
    reclaimStumps (result, height, stump_ratio, provisional);
  }

  std::vector<FlowSegment> segs = summariseCells (result.cells, provisional, count);
  for (int k = 0; k < m; ++k)
  {
    const FlowSegment& man = result.manifolds[static_cast<std::size_t> (k)];
    FlowSegment& seg = segs[static_cast<std::size_t> (component[static_cast<std::size_t> (k)])];
    if (man.flows_to_infinity)
    {
      seg.flows_to_infinity = true;
      seg.maximum = man.maximum;
      continue;
    }
    seg.maxima.insert (seg.maxima.end (), man.maxima.begin (), man.maxima.end ());
    if (seg.maxima.size () == man.maxima.size () || man.maximum.height > seg.maximum.height)
      seg.maximum = man.maximum;
  }
  for (int g = 0; g < count; ++g)
    segs[static_cast<std::size_t> (g)].interior = component_side[static_cast<std::size_t> (g)];
  // Segments without a maximum of their own: report their highest cell.
  for (std::size_t c = 0; c < n; ++c)
  {
    FlowSegment& seg = segs[static_cast<std::size_t> (provisional[c])];
    if (seg.maxima.empty () && !seg.flows_to_infinity &&
        (seg.maximum.cell < 0 || result.cells[c].squared_radius > seg.maximum.height))
    {
      seg.maximum.cell = static_cast<int> (c);
      seg.maximum.height = result.cells[c].squared_radius;
    }
  }
  for (auto& seg : segs)
    if (seg.maxima.empty () && !seg.flows_to_infinity && seg.maximum.cell >= 0)
      seg.maximum.location = result.cells[static_cast<std::size_t> (seg.maximum.cell)].centroid;

  // Interior segments by decreasing volume (then height), then exterior ones, infinity last.
  std::vector<int> order;
  for (int g = 0; g < count; ++g)
    if (segs[static_cast<std::size_t> (g)].cell_count > 0) // the one at infinity may have lost all
      order.push_back (g);
  std::sort (order.begin (), order.end (), [&] (int x, int y) {
    const FlowSegment& a = segs[static_cast<std::size_t> (x)];
    const FlowSegment& b = segs[static_cast<std::size_t> (y)];
    if (a.flows_to_infinity != b.flows_to_infinity)
      return b.flows_to_infinity;
    if (a.interior != b.interior)
      return a.interior > b.interior;
    if (a.volume != b.volume)
      return a.volume > b.volume;
    if (a.maximum.height != b.maximum.height)
      return a.maximum.height > b.maximum.height;
    return x < y;
  });
  std::vector<int> rank (static_cast<std::size_t> (count), -1);
  result.segments.clear ();
  result.segments.reserve (order.size ());
  for (int r = 0; r < static_cast<int> (order.size ()); ++r)
  {
    rank[static_cast<std::size_t> (order[static_cast<std::size_t> (r)])] = r;
    result.segments.push_back (segs[static_cast<std::size_t> (order[static_cast<std::size_t> (r)])]);
    std::sort (result.segments.back ().maxima.begin (), result.segments.back ().maxima.end ());
  }
  std::vector<int> segment_of_cell (n);
  for (std::size_t c = 0; c < n; ++c)
  {
    result.cells[c].segment = rank[static_cast<std::size_t> (provisional[c])];
    segment_of_cell[c] = result.cells[c].segment;
  }
  result.segment_adjacency = highestSharedFacets (result, segment_of_cell);

  result.features = segmentsOnSide (result, result.parameters.features);
}

} // namespace core
} // namespace pcl_flowseg

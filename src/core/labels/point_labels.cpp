/*
 * pcl_flowseg - internal: per-point labels from cell segments.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include "core/labels/point_labels.h"

#include "core/geometry/cell_geometry.h"
#include "core/support/parallel.h"

#include <algorithm>

namespace pcl_flowseg {
namespace core {

void
labelPoints (FlowResult& result)
{
  const std::size_t nv = result.vertices.size ();
  const VertexIncidence inc = vertexIncidence (result.cells, nv, result.dimension);
  std::vector<int> feature_of_segment (result.segments.size (), -1);
  for (std::size_t k = 0; k < result.features.size (); ++k)
    feature_of_segment[static_cast<std::size_t> (result.features[k])] = static_cast<int> (k);

  // Per vertex: total incident volume per segment, the largest wins (ties: lower segment id).
  std::vector<std::uint32_t> vertex_label (nv, kNoSegment);
  parallelFor (nv, [&] (std::size_t v) {
    thread_local std::vector<std::pair<int, double>> sums;
    sums.clear ();
    for (std::size_t k = inc.first[v]; k < inc.first[v + 1]; ++k)
    {
      const FlowCell& cell = result.cells[static_cast<std::size_t> (inc.cells[k])];
      const int feature = feature_of_segment[static_cast<std::size_t> (cell.segment)];
      if (feature < 0)
        continue;
      auto it = std::find_if (sums.begin (), sums.end (), [&] (const auto& e) { return e.first == feature; });
      if (it == sums.end ())
        sums.emplace_back (feature, cell.volume);
      else
        it->second += cell.volume;
    }
    int best = -1;
    double best_volume = -1.0;
    for (const auto& e : sums)
      if (e.second > best_volume || (e.second == best_volume && e.first < best))
      {
        best = e.first;
        best_volume = e.second;
      }
    if (best >= 0)
      vertex_label[v] = static_cast<std::uint32_t> (best);
  });

  for (FlowSegment& s : result.segments)
    s.point_count = 0;
  result.point_labels.assign (result.point_to_vertex.size (), kNoSegment);
  for (std::size_t i = 0; i < result.point_to_vertex.size (); ++i)
  {
    const int v = result.point_to_vertex[i];
    if (v < 0)
      continue;
    const std::uint32_t label = vertex_label[static_cast<std::size_t> (v)];
    result.point_labels[i] = label;
    if (label != kNoSegment)
      ++result.segments[static_cast<std::size_t> (result.features[label])].point_count;
  }
}

} // namespace core
} // namespace pcl_flowseg

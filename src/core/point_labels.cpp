/*
 * pcl_flowseg - internal: per-point labels from cell segments.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include "point_labels.h"

#include <algorithm>

namespace pcl_flowseg {
namespace core {

void
labelPoints (FlowResult& result)
{
  const int facets = result.dimension + 1;
  const std::size_t nv = result.vertices.size ();

  // Incident cells of every vertex (compressed rows, built by counting).
  std::vector<std::size_t> first (nv + 1, 0);
  for (const FlowCell& cell : result.cells)
    for (int i = 0; i < facets; ++i)
      ++first[static_cast<std::size_t> (cell.vertices[i]) + 1];
  for (std::size_t v = 0; v < nv; ++v)
    first[v + 1] += first[v];
  std::vector<int> incident (first[nv]);
  std::vector<std::size_t> fill (first.begin (), first.end () - 1);
  for (std::size_t c = 0; c < result.cells.size (); ++c)
    for (int i = 0; i < facets; ++i)
      incident[fill[static_cast<std::size_t> (result.cells[c].vertices[i])]++] = static_cast<int> (c);

  // Per vertex: total incident volume per segment, the largest wins (ties: lower segment id).
  std::vector<std::uint32_t> vertex_label (nv, kNoSegment);
  std::vector<std::pair<int, double>> sums;
  for (std::size_t v = 0; v < nv; ++v)
  {
    sums.clear ();
    for (std::size_t k = first[v]; k < first[v + 1]; ++k)
    {
      const FlowCell& cell = result.cells[static_cast<std::size_t> (incident[k])];
      auto it = std::find_if (sums.begin (), sums.end (), [&] (const auto& e) { return e.first == cell.segment; });
      if (it == sums.end ())
        sums.emplace_back (cell.segment, cell.volume);
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
  }

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
      ++result.segments[label].point_count;
  }
}

} // namespace core
} // namespace pcl_flowseg

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
  struct Share
  {
    int vertex;
    int segment;
    double volume;
  };
  const int facets = result.dimension + 1;
  std::vector<Share> shares;
  shares.reserve (result.cells.size () * static_cast<std::size_t> (facets));
  for (const FlowCell& cell : result.cells)
    for (int i = 0; i < facets; ++i)
      shares.push_back (Share{cell.vertices[i], cell.segment, cell.volume});
  std::sort (shares.begin (), shares.end (), [] (const Share& a, const Share& b) {
    return a.vertex != b.vertex ? a.vertex < b.vertex : a.segment < b.segment;
  });

  std::vector<std::uint32_t> vertex_label (result.vertices.size (), kNoSegment);
  for (std::size_t k = 0; k < shares.size ();)
  {
    const int v = shares[k].vertex;
    int best = -1;
    double best_volume = -1.0;
    while (k < shares.size () && shares[k].vertex == v)
    {
      const int s = shares[k].segment;
      double sum = 0.0;
      for (; k < shares.size () && shares[k].vertex == v && shares[k].segment == s; ++k)
        sum += shares[k].volume;
      if (sum > best_volume) // segments come in increasing order: ties keep the lower id
      {
        best_volume = sum;
        best = s;
      }
    }
    vertex_label[static_cast<std::size_t> (v)] = static_cast<std::uint32_t> (best);
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

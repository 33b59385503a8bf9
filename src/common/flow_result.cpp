/*
 * pcl_flowseg - queries on a flow segmentation result.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include <pcl_flowseg/common/flow_result.h>

namespace pcl_flowseg {

std::size_t
FlowResult::unlabelledPoints () const
{
  std::size_t count = 0;
  for (std::size_t i = 0; i < point_labels.size (); ++i)
    count += point_labels[i] == kNoSegment && point_to_vertex[i] >= 0;
  return count;
}

std::vector<int>
FlowResult::featureOfSegment () const
{
  std::vector<int> feature (segments.size (), -1);
  for (std::size_t k = 0; k < features.size (); ++k)
    feature[static_cast<std::size_t> (features[k])] = static_cast<int> (k);
  return feature;
}

} // namespace pcl_flowseg

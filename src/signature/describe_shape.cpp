/*
 * pcl_flowseg - describing a shape by its interior features and its interior triangulation.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include <pcl_flowseg/signature/describe_shape.h>

#include <pcl_flowseg/common/feature_significance.h>

#include "contour_context.h"
#include "interior_distributions.h"
#include "part_description.h"

#include <cmath>

namespace pcl_flowseg {

Status
describeShape (const FlowResult& result, ShapeDescription& description)
{
  description = ShapeDescription ();
  if (!result.interior.computed)
    return Status::error ("a shape description needs interior/exterior separation");
  InteriorFrame frame;
  frame.segments = segmentsOnSide (result, FeatureSide::Interior);
  for (int k : frame.segments)
  {
    const FlowSegment& s = result.segments[static_cast<std::size_t> (k)];
    frame.volume += s.volume;
    frame.centre += s.volume * s.centroid;
  }
  if (!(frame.volume > 0.0))
    return Status::error ("the shape has no interior: nothing to describe");
  frame.centre /= frame.volume;
  frame.unit = std::pow (frame.volume, 1.0 / result.dimension);
  description.parts = describeParts (result, frame);
  // One graph of the interior's edges for every inner distance measured.
  const InteriorEdges edges (result);
  describeInteriorDistributions (result, frame, edges, description);
  describeContour (result, edges, description);
  return checkShapeDescription (description);
}

} // namespace pcl_flowseg

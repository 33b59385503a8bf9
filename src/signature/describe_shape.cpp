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
    frame.volume += result.segments[static_cast<std::size_t> (k)].volume;
  if (!(frame.volume > 0.0))
    return Status::error ("the shape has no interior: nothing to describe");
  frame.unit = std::pow (frame.volume, 1.0 / result.dimension);
  std::vector<int> part_maxima;
  description.parts = describeParts (result, frame, part_maxima);
  for (int cell : part_maxima)
    if (cell < 0 || static_cast<std::size_t> (cell) >= result.cells.size ())
    {
      description = ShapeDescription ();
      return Status::error ("an interior segment without a maximum cell: the segmentation is inconsistent");
    }
  // One graph of the interior's edges for every inner distance measured.
  const InteriorEdges edges (result);
  describeInteriorDistributions (result, frame, edges, part_maxima, description);
  describeContour (result, edges, description);
  return checkShapeDescription (description);
}

} // namespace pcl_flowseg

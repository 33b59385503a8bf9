/*
 * pcl_flowseg - inner-distance shape context along the outline of a 2D shape (internal header).
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include <pcl_flowseg/common/flow_result.h>
#include <pcl_flowseg/signature/shape_description.h>

#include "interior_graph.h"

namespace pcl_flowseg {

/** \brief Fills \a description.contour for a 2D shape with an interior (nothing in 3D or without
  * an outline): kContourPoints points at equal steps of arc length along the longest boundary loop
  * of the interior, counter-clockwise, each with its histogram of the boundary vertices of that loop
  * by inner distance (over the mean) and direction (from the loop's tangent), each vertex weighted
  * by its share of the loop's length. Inner distances run along \a edges (the result's). */
void
describeContour (const FlowResult& result, const InteriorEdges& edges, ShapeDescription& description);

} // namespace pcl_flowseg

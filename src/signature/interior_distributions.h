/*
 * pcl_flowseg - thickness, inner-distance and solid-distance distributions of a shape's interior
 * (internal header).
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include "interior_frame.h"
#include "interior_graph.h"

#include <pcl_flowseg/common/flow_result.h>
#include <pcl_flowseg/signature/shape_description.h>

namespace pcl_flowseg {

/** \brief Fills the distributions of \a description (thickness, inner and solid distances, inner-
  * distance profiles and contexts, thickness profile) from kInteriorSamples interior cells drawn by
  * volume with a fixed seed, and the remoteness of its parts, whose maxima are the cells
  * \a part_maxima (describeParts); inner distances run along \a edges (the result's). */
void
describeInteriorDistributions (const FlowResult& result, const InteriorFrame& frame, const InteriorEdges& edges,
                               const std::vector<int>& part_maxima, ShapeDescription& description);

} // namespace pcl_flowseg

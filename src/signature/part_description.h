/*
 * pcl_flowseg - the interior features of a shape as parts with attributes (internal header).
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include "interior_frame.h"

#include <pcl_flowseg/common/flow_result.h>
#include <pcl_flowseg/signature/shape_description.h>

#include <vector>

namespace pcl_flowseg {

/** \brief The parts of ShapeDescription::parts, measured on the cells of each described segment;
  * \a maximum_cells gets the cell of each part's maximum (in the parts' order). Their remoteness is
  * left 0: describeInteriorDistributions measures it, by inner distances. */
std::vector<PartDescription>
describeParts (const FlowResult& result, const InteriorFrame& frame, std::vector<int>& maximum_cells);

} // namespace pcl_flowseg

/*
 * pcl_flowseg - every parameter of a flow segmentation (FlowParameters), described once.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include <pcl_flowseg/common/flow_parameters.h>
#include <pcl_flowseg/common/parameter_table.h>

namespace pcl_flowseg {

/** \brief The parameters of FlowParameters, in the order of the pipeline: the apps' options, the
  * Python keywords and docs/parameters.md are made from it. Checked by checkParameters. */
const ParameterTable<FlowParameters>&
flowParameterTable ();

} // namespace pcl_flowseg

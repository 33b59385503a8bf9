/*
 * pcl_flowseg - every parameter of matching (MatchParameters), described once.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include <pcl_flowseg/common/parameter_table.h>
#include <pcl_flowseg/signature/match_parameters.h>

namespace pcl_flowseg {

/** \brief The parameters of MatchParameters: the method, the description weights of each dimension
  * and the paper's alignment parameters (see flowParameterTable). Checked by checkMatchParameters. */
const ParameterTable<MatchParameters>&
matchParameterTable ();

} // namespace pcl_flowseg

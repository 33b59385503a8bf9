/*
 * pcl_flowseg - the signature of a shape file: read (or sample), segment, keep the significant features.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include <pcl_flowseg/common/flow_parameters.h>
#include <pcl_flowseg/common/status.h>
#include <pcl_flowseg/io/shape_input.h>
#include <pcl_flowseg/signature/signature.h>

#include <string>

namespace pcl_flowseg {

/** \brief The signature of a shape file (anything loadShapeSample reads): sample, segment with
  * \a params, keep the features above \a significance. The message names the file on failure. */
Status
signatureOfShapeFile (const std::string& path, const ShapeInputOptions& input, const FlowParameters& params,
                      double significance, Signature& signature);

} // namespace pcl_flowseg

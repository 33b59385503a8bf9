/*
 * pcl_flowseg - the signature of a shape file: read (or sample), segment, keep the significant features.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include <pcl_flowseg/common/flow_parameters.h>
#include <pcl_flowseg/common/status.h>
#include <pcl_flowseg/io/shape_input.h>
#include <pcl_flowseg/signature/signature.h>

#include <functional>
#include <string>
#include <vector>

namespace pcl_flowseg {

/** \brief The signature of a shape file (anything loadShapeSample reads): sample, segment with
  * \a params, keep the features above \a significance. With input.use_sensor_origin the file's
  * own sensor origin is the viewpoint (params.interior.viewpoint must then be unset). Without any
  * viewpoint, a file whose points look like a single view from its sensor origin
  * (looksLikeSingleView) gets a warning (PCL_WARN) that single-view matching needs the viewpoint.
  * The message names the file on failure. */
Status
signatureOfShapeFile (const std::string& path, const ShapeInputOptions& input, const FlowParameters& params,
                      double significance, Signature& signature);

/** \brief The signatures of many shape files, on \a threads threads (0 = all cores; see
  * threadsPerJob), in the order of \a paths, with each file's Status in \a statuses: a file that
  * fails gets an empty signature and its message; \a progress (optional) is told after each file
  * how many are done and which file (with its Status) was the last. */
void
signaturesOfShapeFiles (const std::vector<std::string>& paths, const ShapeInputOptions& input, const FlowParameters& params,
                        double significance, unsigned threads, std::vector<Signature>& signatures,
                        std::vector<Status>& statuses,
                        const std::function<void (std::size_t done, const std::string& path, const Status& status)>& progress = {});

} // namespace pcl_flowseg

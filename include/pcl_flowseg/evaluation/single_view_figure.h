/*
 * pcl_flowseg evaluation - the figure of single-view recognition: scans, their parts, their best
 * matches.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include <pcl_flowseg/evaluation/single_view_recognition.h>

#include <string>

namespace pcl_flowseg {

/** \brief Writes \a path (PNG, writeSingleViewMatchesPng): the first scan of each of up to \a rows
  * classes of \a queries, segmented with params.flow as seen from its viewpoint (its own sensor
  * origin with params.signature.input.use_sensor_origin), then its \a k best models of \a models
  * by \a result's similarity rows. */
Status
writeSingleViewFigure (const std::string& path, const ShapeCollection& models, const ShapeCollection& queries,
                       const SingleViewRecognitionParameters& params, const MethodRecognition& result, std::size_t rows = 8,
                       int k = 5);

} // namespace pcl_flowseg

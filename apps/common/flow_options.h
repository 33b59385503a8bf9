/*
 * pcl_flowseg apps - the option groups several apps share, bound to the library's parameter types.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include "common/options.h"

#include <pcl_flowseg/common/feature_significance.h>
#include <pcl_flowseg/common/flow_parameters.h>
#include <pcl_flowseg/io/shape_input.h>
#include <pcl_flowseg/signature/signature_matcher.h>
#include <pcl_flowseg/signature/signature_parameters.h>

namespace flowseg_app {

/** \brief The option of the row \a name of \a table (its old names accepted with a warning),
  * writing into \a params, which must outlive the parser. */
template <class Params>
void
addTableOption (OptionParser& parser, const pcl_flowseg::ParameterTable<Params>& table, const std::string& name,
                Params& params);

/** \brief Every segmentation option of flowParameterTable() but the viewpoint and the threads
  * (addViewpointOptions, addThreadsOption), and --paper-rule. */
void
addSegmentationOptions (OptionParser& parser, pcl_flowseg::FlowParameters& params);

/** \brief -j/--threads N as flowParameterTable() describes it, into \a threads. */
void
addThreadsOption (OptionParser& parser, unsigned& threads);

/** \brief How shape files become signatures. */
using SignatureOptions = pcl_flowseg::SignatureParameters;

/** \brief Every option of signatureParameterTable(): --significance, --mesh-points, --seed, ... */
void
addSignatureOptions (OptionParser& parser, SignatureOptions& options);

/** \brief Every option of matchParameterTable() but --method: the weights and the paper's. */
void
addMatchOptions (OptionParser& parser, pcl_flowseg::MatchParameters& match);

/** \brief --method M, as matchParameterTable() describes it. */
void
addMatchMethodOption (OptionParser& parser, pcl_flowseg::MatchParameters& match);

/** \brief --viewpoint X,Y,Z and --use-sensor-origin: the sensor position of a single-view scan,
  * given or taken from the PCD file's VIEWPOINT. */
void
addViewpointOptions (OptionParser& parser, std::optional<Eigen::Vector3d>& viewpoint, bool& use_sensor_origin);

/** \brief What single options cannot check: --viewpoint and --use-sensor-origin exclude each other,
  * --no-interior excludes them and --features; then the library's checkParameters.
  * \return kContinue, or kExitUsage after reporting the error. */
int
checkViewpointOptions (const OptionParser& parser, const pcl_flowseg::FlowParameters& params, bool use_sensor_origin);

} // namespace flowseg_app

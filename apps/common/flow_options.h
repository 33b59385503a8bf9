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

namespace flowseg_app {

/** \brief -r/--rho, --tolerance, --stump-ratio, --compact-rho, --compact-size, --paper-rule. */
void
addMergeOptions (OptionParser& parser, pcl_flowseg::MergeParameters& merge);

/** \brief The merge options and -d/--dimension, -f/--features, --no-interior, --denoise. */
void
addSegmentationOptions (OptionParser& parser, pcl_flowseg::FlowParameters& params);

/** \brief -j/--threads N (also --jobs N), described the same way in every app. */
void
addThreadsOption (OptionParser& parser, unsigned& threads);

/** \brief How shape files become signatures. */
struct SignatureOptions
{
  double significance = pcl_flowseg::kDefaultSignificance;
  pcl_flowseg::ShapeInputOptions input;
};

/** \brief --significance F and --mesh-points N. */
void
addSignatureOptions (OptionParser& parser, SignatureOptions& options);

/** \brief --threshold T, --alignment-points N, --no-mirror. */
void
addMatchOptions (OptionParser& parser, pcl_flowseg::MatchParameters& match);

/** \brief --method M (flowseg, paper, parts, thickness, inner, solid, inner-profile, thickness-profile). */
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

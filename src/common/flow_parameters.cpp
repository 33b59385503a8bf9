/*
 * pcl_flowseg - checking the parameters of a flow segmentation.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include <pcl_flowseg/common/flow_parameters.h>

#include <cmath>
#include <string>

namespace pcl_flowseg {

namespace {
std::string
got (double value)
{
  return ", got " + std::to_string (value);
}
} // namespace

Status
checkMergeParameters (const MergeParameters& m)
{
  if (!std::isfinite (m.rho) || m.rho <= 0.0)
    return Status::error ("rho must be a finite number > 0" + got (m.rho));
  if (!std::isfinite (m.sampling_tolerance) || m.sampling_tolerance < 0.0)
    return Status::error ("the sampling tolerance must be a finite number >= 0" + got (m.sampling_tolerance));
  if (!std::isfinite (m.stump_ratio) || (m.stump_ratio != 0.0 && m.stump_ratio < 1.0))
    return Status::error ("the stump ratio must be 0 (off) or a finite number >= 1" + got (m.stump_ratio));
  if (!std::isfinite (m.compact_rho) || m.compact_rho <= 0.0)
    return Status::error ("the compact rho must be a finite number > 0" + got (m.compact_rho));
  if (!std::isfinite (m.compact_size) || m.compact_size < 0.0)
    return Status::error ("the compact size must be a finite number >= 0" + got (m.compact_size));
  if (!(m.min_part_share >= 0.0 && m.min_part_share < 1.0))
    return Status::error ("the smallest part share must be a number in [0, 1)" + got (m.min_part_share));
  if (!(m.single_view_min_part_share >= 0.0 && m.single_view_min_part_share < 1.0))
    return Status::error ("the smallest part share of single views must be a number in [0, 1)" +
                          got (m.single_view_min_part_share));
  return Status::success ();
}

Status
checkParameters (const FlowParameters& p)
{
  const DimensionMode d = p.preparation.dimension;
  if (d != DimensionMode::Automatic && d != DimensionMode::Planar && d != DimensionMode::Spatial)
    return Status::error ("dimension must be 0 (automatic), 2 or 3, got " + std::to_string (static_cast<int> (d)));
  if (!std::isfinite (p.preparation.planar_tolerance) || p.preparation.planar_tolerance < 0.0)
    return Status::error ("planar tolerance must be a finite number >= 0" + got (p.preparation.planar_tolerance));
  const OutlierRemoval o = p.preparation.outliers;
  if (o != OutlierRemoval::Automatic && o != OutlierRemoval::Off && o != OutlierRemoval::Always)
    return Status::error ("outlier removal must be automatic, off or always");
  const Smoothing m = p.preparation.smoothing;
  if (m != Smoothing::Automatic && m != Smoothing::Off && m != Smoothing::Always)
    return Status::error ("smoothing must be automatic, off or always");
  if (p.preparation.smoothing_passes < 1 || p.preparation.smoothing_passes > kMaxSmoothingPasses)
    return Status::error ("smoothing passes must be 1 to " + std::to_string (kMaxSmoothingPasses) + ", got " +
                          std::to_string (p.preparation.smoothing_passes) + " (smoothing off: Smoothing::Off)");
  if (const Status merge = checkMergeParameters (p.merge); !merge)
    return merge;
  const Denoising n = p.interior.denoising;
  if (n != Denoising::Automatic && n != Denoising::Off && n != Denoising::Always)
    return Status::error ("denoising must be automatic, off or always");
  const double opening = p.interior.exterior_opening;
  if (!std::isfinite (opening) || (opening != 0.0 && opening < kMinExteriorOpening))
    return Status::error ("the exterior opening must be 0 (off) or a finite number of sample spacings >= " +
                          std::to_string (static_cast<int> (kMinExteriorOpening)) + got (opening));
  if (p.interior.viewpoint && !p.interior.viewpoint->allFinite ())
    return Status::error ("the viewpoint has non-finite coordinates");
  if (p.features != FeatureSide::Interior && p.features != FeatureSide::Exterior && p.features != FeatureSide::Both)
    return Status::error ("features must be interior, exterior or both");
  if (p.execution.threads > kMaxThreads)
    return Status::error ("threads must be at most " + std::to_string (kMaxThreads) + ", got " + std::to_string (p.execution.threads));
  return Status::success ();
}

} // namespace pcl_flowseg

/*
 * pcl_flowseg apps - the option groups several apps share, bound to the library's parameter types.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include "common/flow_options.h"

#include <limits>

namespace flowseg_app {

namespace {
/** A check of one merge value by the library's own rule (the other values at their defaults). */
std::function<pcl_flowseg::Status (double)>
mergeCheck (double pcl_flowseg::MergeParameters::*field)
{
  return [field] (double v) {
    pcl_flowseg::MergeParameters m;
    m.*field = v;
    return pcl_flowseg::checkMergeParameters (m);
  };
}
} // namespace

void
addMergeOptions (OptionParser& p, pcl_flowseg::MergeParameters& merge)
{
  using M = pcl_flowseg::MergeParameters;
  p.number ("-r, --rho", "R", "merge threshold rho > 0; < 1 merges nothing", merge.rho, mergeCheck (&M::rho));
  p.number ("--tolerance", "T", "merge tolerance in local sample spacings, >= 0", merge.sampling_tolerance,
            mergeCheck (&M::sampling_tolerance));
  p.number ("--stump-ratio", "R", "thin parts take back their stumps from parts R times thicker;\n0 = off, else >= 1",
            merge.stump_ratio, mergeCheck (&M::stump_ratio));
  p.number ("--compact-rho", "R", "merge threshold for compact segments, > 0; acts only above rho", merge.compact_rho,
            mergeCheck (&M::compact_rho));
  p.number ("--compact-size", "S", "largest compact segment, in balls of its saddle's radius, >= 0;\n0 = off",
            merge.compact_size, mergeCheck (&M::compact_size));
  p.number ("--min-part-share", "F",
            "smallest part, as a share of its side's volume in [0, 1): smaller\nsegments join the neighbour across their widest saddle; 0 = keep all",
            merge.min_part_share, mergeCheck (&M::min_part_share));
  p.number ("--single-view-min-part-share", "F",
            "smallest part on a single view whose hidden side is guessed\n(--use-sensor-origin), in [0, 1), in place of --min-part-share",
            merge.single_view_min_part_share, mergeCheck (&M::single_view_min_part_share));
  pcl_flowseg::MergeParameters* m = &merge;
  p.action ("--paper-rule", "the paper's merging rule alone: tolerance, stump ratio, compact\nsize and smallest part shares 0",
            [m] () { m->usePaperRule (); });
}

void
addSegmentationOptions (OptionParser& p, pcl_flowseg::FlowParameters& params)
{
  using pcl_flowseg::DimensionMode;
  addMergeOptions (p, params.merge);
  p.choice ("-d, --dimension", "D", "auto | 2 | 3; auto: 2D when all points lie on one plane", params.preparation.dimension,
            std::vector<std::pair<std::string, DimensionMode>>{
                {"auto", DimensionMode::Automatic}, {"2", DimensionMode::Planar}, {"3", DimensionMode::Spatial}});
  p.choice ("-f, --features", "SIDE", "interior | exterior | both: which segments are reported", params.features,
            std::vector<std::pair<std::string, pcl_flowseg::FeatureSide>>{{"interior", pcl_flowseg::FeatureSide::Interior},
                                                                           {"exterior", pcl_flowseg::FeatureSide::Exterior},
                                                                           {"both", pcl_flowseg::FeatureSide::Both}});
  p.choice ("--outliers", "MODE", "auto | off | on: leave out outliers (PCL's statistical outlier\nremoval, then points off the surface their neighbours sample);\nauto: when the sample shows isolated or detached points",
            params.preparation.outliers,
            std::vector<std::pair<std::string, pcl_flowseg::OutlierRemoval>>{{"auto", pcl_flowseg::OutlierRemoval::Automatic},
                                                                              {"off", pcl_flowseg::OutlierRemoval::Off},
                                                                              {"on", pcl_flowseg::OutlierRemoval::Always}});
  p.choice ("--smooth", "MODE", "auto | off | on: smooth a 3D sample before the triangulation (thin\nwalls keep their sides); auto: when the sample is rough (noisy)",
            params.preparation.smoothing,
            std::vector<std::pair<std::string, pcl_flowseg::Smoothing>>{{"auto", pcl_flowseg::Smoothing::Automatic},
                                                                         {"off", pcl_flowseg::Smoothing::Off},
                                                                         {"on", pcl_flowseg::Smoothing::Always}});
  p.count ("--smooth-passes", "N", "smoothing passes: the most (auto) or exactly N (on)", params.preparation.smoothing_passes, 1u,
           pcl_flowseg::kMaxSmoothingPasses);
  pcl_flowseg::InteriorParameters* in = &params.interior;
  p.action ("--no-interior", "skip interior/exterior separation: the paper's raw segmentation of\nthe whole convex hull, every segment reported",
            [in] () { in->separate = false; });
  p.action ("--no-manifold-repair", "keep the interior/exterior boundary as the labelling left it, also\nwhere it is not a manifold (3D)",
            [in] () { in->manifold_repair = false; });
  p.action ("--no-hidden-side", "with a viewpoint: do not guess the side of the single view the sensor\ncannot see (the hidden volume then joins the seen parts into few features)",
            [in] () { in->hidden_side = false; });
  p.choice ("--denoise", "MODE", "auto | off | on: smooth noisy samples before separating interior\nand exterior",
            params.interior.denoising,
            std::vector<std::pair<std::string, pcl_flowseg::Denoising>>{{"auto", pcl_flowseg::Denoising::Automatic},
                                                                         {"off", pcl_flowseg::Denoising::Off},
                                                                         {"on", pcl_flowseg::Denoising::Always}});
}

void
addThreadsOption (OptionParser& p, unsigned& threads)
{
  p.count ("-j, --threads", "N", "worker threads: 0 = all cores, 1 = sequential", threads, 0, pcl_flowseg::kMaxThreads);
  p.alias ("--jobs", "--threads");
}

void
addSignatureOptions (OptionParser& p, SignatureOptions& o)
{
  p.number ("--significance", "F", "features above this share of the interior volume are significant", o.significance,
            [] (double v) { return pcl_flowseg::checkSignificance (v); });
  p.count ("--mesh-points", "N", "points sampled on a mesh's faces", o.input.mesh_points, 0, kLargestCount,
           [] (long long v) {
             pcl_flowseg::ShapeInputOptions input;
             input.mesh_points = static_cast<std::size_t> (v);
             return pcl_flowseg::checkShapeInputOptions (input);
           });
}

void
addMatchOptions (OptionParser& p, pcl_flowseg::MatchParameters& match)
{
  p.number ("--threshold", "T", "largest distance between matched features, in the signatures'\nnormalised unit (paper)",
            match.paper.threshold, [] (double v) {
              pcl_flowseg::MatchParameters m;
              m.paper.threshold = v;
              return pcl_flowseg::checkMatchParameters (m);
            });
  p.count ("--alignment-points", "N", "heaviest features that generate alignments (paper)", match.paper.alignment_points, 0,
           std::numeric_limits<int>::max (), [] (long long v) {
             pcl_flowseg::MatchParameters m;
             m.paper.alignment_points = static_cast<int> (v);
             return pcl_flowseg::checkMatchParameters (m);
           });
  bool* mirror = &match.paper.allow_mirror;
  p.action ("--no-mirror", "do not match mirror images (paper)", [mirror] () { *mirror = false; });
}

void
addMatchMethodOption (OptionParser& p, pcl_flowseg::MatchParameters& match)
{
  std::vector<std::pair<std::string, pcl_flowseg::MatchMethod>> choices;
  for (pcl_flowseg::MatchMethod m : pcl_flowseg::kMatchMethods)
    choices.emplace_back (pcl_flowseg::matchMethodName (m), m);
  p.choice ("--method", "M",
            "how shapes are compared: flowseg (the components below combined; the best\n"
            "measured), paper (the paper's weighted points and alignment; --threshold,\n"
            "--alignment-points and --no-mirror apply to it only), or one component:\n"
            "parts, thickness, inner, solid, inner-profile, thickness-profile, contour (2D only),\n"
            "inner-context",
            match.method, choices);
}

} // namespace flowseg_app

/*
 * pcl_flowseg - every parameter of a flow segmentation (FlowParameters), described once.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include <pcl_flowseg/common/flow_parameter_table.h>
#include <pcl_flowseg/common/parameter_fields.h>

#include <limits>

namespace pcl_flowseg {

namespace {

using Spec = ParameterSpec<FlowParameters>;
using FP = FlowParameters;

/** The spellings of the Automatic / Off / Always modes, and their Python spellings before. */
template <class Mode>
std::vector<std::pair<std::string, Mode>>
modeChoices ()
{
  return {{"auto", Mode::Automatic}, {"off", Mode::Off}, {"on", Mode::Always}};
}
const std::vector<std::pair<std::string, std::string>> kOldModeValues = {{"automatic", "auto"}, {"always", "on"}};

void
addPreparation (std::vector<Spec>& t)
{
  t.push_back (choiceField<FP, DimensionMode> (
      {"dimension", "-d", "preparation", ParameterType::Choice, "", "auto, 2, 3",
       "2D or 3D flow; auto: 2D when all points lie on one plane (planar_tolerance); 2 projects the points onto their plane", {}, {},
       {{"automatic", "auto"}, {"planar", "2"}, {"spatial", "3"}}},
      [] (FP& p) -> DimensionMode& { return p.preparation.dimension; },
      {{"auto", DimensionMode::Automatic}, {"2", DimensionMode::Planar}, {"3", DimensionMode::Spatial}}));
  t.push_back (numberField<FP> ({"planar_tolerance", "", "preparation", ParameterType::Number, "share of the bounding-box diagonal",
                                 "finite, >= 0", "auto dimension: 2D when the points' spread normal to their best-fit plane is at most this"},
                                [] (FP& p) -> double& { return p.preparation.planar_tolerance; }));
  t.push_back (choiceField<FP, OutlierRemoval> (
      {"outliers", "", "preparation", ParameterType::Choice, "", "auto, off, on",
       "leave out outliers (PCL's statistical outlier removal, then points detached from the surface their neighbours sample); auto: when the sample shows them",
       {}, {}, kOldModeValues},
      [] (FP& p) -> OutlierRemoval& { return p.preparation.outliers; }, modeChoices<OutlierRemoval> ()));
  t.push_back (choiceField<FP, Smoothing> (
      {"smoothing", "", "preparation", ParameterType::Choice, "", "auto, off, on",
       "smooth a 3D sample before the triangulation, so that thin walls keep their sides; auto: when the sample is rough (noisy)",
       {}, {"smooth"}, kOldModeValues},
      [] (FP& p) -> Smoothing& { return p.preparation.smoothing; }, modeChoices<Smoothing> ()));
  t.push_back (countField<FP, unsigned> ({"smoothing_passes", "", "preparation", ParameterType::Count, "passes",
                                          "1 to " + std::to_string (kMaxSmoothingPasses),
                                          "the most smoothing passes (smoothing auto) or exactly this many (on)", {}, {"smooth_passes"}},
                                         [] (FP& p) -> unsigned& { return p.preparation.smoothing_passes; }, kMaxSmoothingPasses));
}

void
addMerge (std::vector<Spec>& t)
{
  const auto merge = [&t] (const char* name, const char* short_option, const char* unit, const char* range,
                           const char* description, double& (*field) (FP&), std::vector<std::string> old_names = {}) {
    t.push_back (numberField<FP> ({name, short_option, "merge", ParameterType::Number, unit, range, description, {}, std::move (old_names)},
                                  field));
  };
  merge ("rho", "-r", "", "finite, > 0",
         "the paper's threshold: manifolds sharing a facet t merge when both maxima's circumradii are below rho R(t) + sampling_tolerance s(t); below 1 nothing merges",
         [] (FP& p) -> double& { return p.merge.rho; });
  merge ("sampling_tolerance", "", "local sample spacings s(t)", "finite, >= 0",
         "additive slack of the merge rule (heights measured on a sample err by about the spacing); ignored when rho < 1",
         [] (FP& p) -> double& { return p.merge.sampling_tolerance; }, {"tolerance"});
  merge ("stump_ratio", "", "circumradius ratio", "0 (off), or finite >= 1",
         "thin parts take back their stumps from parts more than this many times thicker",
         [] (FP& p) -> double& { return p.merge.stump_ratio; });
  merge ("compact_rho", "", "", "finite, > 0", "threshold of the compact pass: acts only above rho",
         [] (FP& p) -> double& { return p.merge.compact_rho; });
  merge ("compact_size", "", "balls (2D: discs) of the saddle's radius", "finite, >= 0 (0 = no compact pass)",
         "largest segment the compact pass merges", [] (FP& p) -> double& { return p.merge.compact_size; });
  merge ("min_part_share", "", "share of the volume (2D: area) of its side", "[0, 1)",
         "smallest part: a smaller segment joins the neighbour across its widest saddle; 0 keeps every segment",
         [] (FP& p) -> double& { return p.merge.min_part_share; });
  merge ("single_view_min_part_share", "", "share of the volume of its side", "[0, 1)",
         "smallest part of a single view whose hidden side was guessed, in place of min_part_share",
         [] (FP& p) -> double& { return p.merge.single_view_min_part_share; });
}

void
addInterior (std::vector<Spec>& t)
{
  t.push_back (switchField<FP> ({"separate_interior", "", "interior", ParameterType::Switch, "", "true, false",
                                 "separate interior and exterior; off: the paper's raw segmentation of the whole convex hull, every segment reported",
                                 {}, {"separate", "interior"}},
                                [] (FP& p) -> bool& { return p.interior.separate; }));
  t.push_back (choiceField<FP, Denoising> (
      {"denoising", "", "interior", ParameterType::Choice, "", "auto, off, on",
       "decide inside and outside on a smoothed copy of a noisy sample (the flow uses the sample as is); auto: when the sample shows noise",
       {}, {"denoise"}, kOldModeValues},
      [] (FP& p) -> Denoising& { return p.interior.denoising; }, modeChoices<Denoising> ()));
  t.push_back (pointField<FP> ({"viewpoint", "", "interior", ParameterType::Point, "input units", "finite, outside the object",
                                "sensor position of a single-view scan: the space between it and the points is outside"},
                               [] (FP& p) -> std::optional<Eigen::Vector3d>& { return p.interior.viewpoint; }));
  t.push_back (switchField<FP> ({"manifold_repair", "", "interior", ParameterType::Switch, "", "true, false",
                                 "3D: relabel cells until the interior's boundary is a manifold (not applied with a viewpoint)"},
                                [] (FP& p) -> bool& { return p.interior.manifold_repair; }));
  t.push_back (switchField<FP> ({"hidden_side", "", "interior", ParameterType::Switch, "", "true, false",
                                 "3D, with a viewpoint: guess the side the sensor cannot see, so that seen parts get a volume and features of their own"},
                                [] (FP& p) -> bool& { return p.interior.hidden_side; }));
  t.push_back (numberField<FP> ({"exterior_opening", "", "interior", ParameterType::Number, "sample spacings (median nearest-sample distance)",
                                 "0 (off), or finite >= 3",
                                 "3D, no viewpoint: space reached from beyond the hull through openings this wide is outside (cavities, space under tables), even past noisy thin walls"},
                                [] (FP& p) -> double& { return p.interior.exterior_opening; }));
}

void
addReportAndExecution (std::vector<Spec>& t)
{
  t.push_back (choiceField<FP, FeatureSide> (
      {"features", "-f", "features", ParameterType::Choice, "", "interior, exterior, both",
       "which segments are reported as features: the shape's parts, the pockets outside it, or all"},
      [] (FP& p) -> FeatureSide& { return p.features; },
      {{"interior", FeatureSide::Interior}, {"exterior", FeatureSide::Exterior}, {"both", FeatureSide::Both}}));
  t.push_back (countField<FP, unsigned> ({"threads", "-j", "execution", ParameterType::Count, "threads",
                                          "0 to " + std::to_string (kMaxThreads),
                                          "worker threads: 0 = all cores, 1 = sequential; the result is the same for every value", {}, {"jobs"}},
                                         [] (FP& p) -> unsigned& { return p.execution.threads; }, kMaxThreads));
  t.push_back (countField<FP, std::size_t> ({"memory_limit", "", "execution", ParameterType::Count, "bytes", ">= 0",
                                             "memory the run may use, 0 = what the system reports available; larger inputs are refused before any work"},
                                            [] (FP& p) -> std::size_t& { return p.execution.memory_limit; },
                                            std::numeric_limits<std::int64_t>::max ()));
}

} // namespace

const ParameterTable<FlowParameters>&
flowParameterTable ()
{
  static const ParameterTable<FlowParameters> table = [] {
    ParameterTable<FlowParameters> t;
    t.title = "segmentation (FlowParameters)";
    addPreparation (t.specs);
    addMerge (t.specs);
    addInterior (t.specs);
    addReportAndExecution (t.specs);
    t.check = [] (const FlowParameters& p) { return checkParameters (p); };
    return t;
  }();
  return table;
}

} // namespace pcl_flowseg

/*
 * flowseg_bench_psb: segmentation quality against the Princeton Segmentation Benchmark (PSB).
 *
 * For every model of DIR/labels.csv: sample the mesh, segment the sample (interior features) at
 * each rho, give every face the label of the samples near it, and score the faces with the PSB's
 * Rand-index error against each human segmentation of the model (averaged). In the same run: one
 * segment for the whole model, every human against the other humans of the model, and CGAL's
 * shape-diameter-function segmentation of the mesh itself. Then the project's generated shapes
 * with known parts, scored on their points. Prints one line per model and a table per category.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include <pcl_flowseg/common/feature_significance.h>
#include <pcl_flowseg/io/atomic_file.h>
#include "mesh_picture.h"
#include "mls_prepass.h"
#include "sdf_peer.h"

#include <pcl_flowseg/segmentation/flow_pipeline.h>
#include <pcl_flowseg/io/mesh_io.h>
#include <pcl_flowseg/io/range_scan.h>
#include <pcl_flowseg/io/sample_outliers.h>
#include <pcl_flowseg/evaluation/segmentation_evaluation.h>
#include <pcl_flowseg/evaluation/shape_generator.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;
using pcl_flowseg::Status;
constexpr double kMissing = std::numeric_limits<double>::quiet_NaN ();
constexpr std::size_t kGeneratedPoints = pcl_flowseg::kSamplePoints3D;

struct Options
{
  std::string data = "../shared/data/psb_dev";
  std::size_t points = 10000;
  std::vector<double> rhos = {1.1, 1.2, 1.3, 1.5};
  std::uint32_t seed = 1;
  std::set<std::string> models; // empty: all
  bool sdf = true;
  std::string csv;
  std::string pictures; // folder for PNG pictures of each model's segmentations; empty: none
  pcl_flowseg::FlowParameters flow; // every flowseg run; rho is set per run from \a rhos
  double significance = 0.0; // > 0: only features above this share of the feature volume label faces
  double noise = 0.0;        // Gaussian noise, standard deviation as a share of the mesh's bounding-box diagonal
  double outliers = 0.0;     // share of the sample replaced by points uniform in its bounding box
  double mls_radius = 0.0;   // > 0: PCL's MovingLeastSquares before flowseg, radius in sample spacings
  std::vector<Eigen::Vector3d> scan_directions; // non-empty: single views from these directions
};

/** Sensor distance of the single views, in bounding radii of the mesh from its centre. */
constexpr double kScanDistance = 3.0;

const char* const kUsage =
  "usage: flowseg_bench_psb [--data DIR (../shared/data/psb_dev)] [--points N (10000)]\n"
  "                         [--rho LIST (1.1,1.2,1.3,1.5)] [--seed S (1)] [--models ID,ID]\n"
  "                         [--no-sdf] [--csv FILE] [--pictures DIR]\n"
  "                         [--tolerance T] [--stump-ratio S] [--compact-rho R] [--compact-size S]\n"
  "                         [--paper-rule]   (merge parameters: the library's defaults unless given)\n"
  "                         [--significance F (0: every feature)] [--min-part-share F]\n"
  "                         [--single-view-min-part-share F]\n"
  "                         [--noise F (0)] [--outliers F (0)] [--scan-from six|X,Y,Z]\n"
  "                         [--outlier-removal auto|off|on (auto)] [--smooth auto|off|on (auto)] [--smooth-passes N (6)]\n"
  "                         [--mls R (0)] [--exterior-opening S (4)]\n"
  "  --noise F: Gaussian noise of standard deviation F times the bounding-box diagonal\n"
  "  --outliers F: that share of the sample replaced by points uniform in its bounding box\n"
  "  --scan-from: single views instead of whole samples, the sensor 3 bounding radii from the centre\n"
  "               in the direction X,Y,Z or in each of the six axis directions (six); --noise is\n"
  "               then depth noise; the error counts only the faces the scan sees, averaged over views\n"
  "  --outlier-removal, --smooth, --smooth-passes: PreparationParameters::outliers, ::smoothing, ::smoothing_passes\n"
  "  --mls R: PCL's MovingLeastSquares (quadratic) on each sample before flowseg, radius R sample\n"
  "           spacings (0: none), to weigh it against the module's smoothing (--smooth); its\n"
  "           time is counted in flowseg's\n"
  "  --exterior-opening S: InteriorParameters::exterior_opening in sample spacings (0: off)\n"
  "  --paper-rule: the paper's merging rule alone (tolerance, stump ratio, compact size 0)\n"
  "  --significance F: only features above F of the features' volume label faces; the faces of the\n"
  "                    others take the label of the nearest significant samples\n"
  "  --pictures DIR: DIR/<id>_human.png, <id>_flowseg_rho<R>.png, <id>_sdf.png for every model\n";

std::vector<std::string>
splitList (const std::string& text)
{
  std::vector<std::string> items;
  std::stringstream in (text);
  for (std::string item; std::getline (in, item, ',');)
    if (!item.empty ())
      items.push_back (item);
  return items;
}

/** "six" (the six axis directions) or one direction X,Y,Z (normalised). */
bool
parseScanDirections (const std::string& value, std::vector<Eigen::Vector3d>& directions)
{
  directions.clear ();
  if (value == "six")
  {
    for (int axis = 0; axis < 3; ++axis)
      for (double sign : {1.0, -1.0})
        directions.push_back (sign * Eigen::Vector3d::Unit (axis));
    return true;
  }
  const auto items = splitList (value);
  if (items.size () != 3)
    return false;
  Eigen::Vector3d d;
  for (std::size_t k = 0; k < 3; ++k)
  {
    char* end = nullptr;
    d[static_cast<long> (k)] = std::strtod (items[k].c_str (), &end);
    if (*end)
      return false;
  }
  if (!d.allFinite () || d.norm () == 0.0)
    return false;
  directions.push_back (d.normalized ());
  return true;
}

bool
parseRhoList (const std::string& list, std::vector<double>& rhos, std::string& error)
{
  rhos.clear ();
  for (const auto& item : splitList (list))
  {
    char* end = nullptr;
    const double rho = std::strtod (item.c_str (), &end);
    if (*end || !std::isfinite (rho) || rho <= 0)
      return error = "--rho: not a number > 0: " + item, false;
    rhos.push_back (rho);
  }
  if (rhos.empty ())
    return error = "--rho needs at least one value", false;
  return true;
}

/** An auto | off | on option's value as the library's Automatic / Off / Always mode. */
template <typename Mode>
bool
parseMode (const std::string& option, const std::string& value, Mode& mode, std::string& error)
{
  if (value != "auto" && value != "off" && value != "on")
    return error = option + " needs auto, off or on", false;
  mode = value == "auto" ? Mode::Automatic : value == "off" ? Mode::Off : Mode::Always;
  return true;
}

bool
parseOptions (int argc, char** argv, Options& o, std::string& error)
{
  for (int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    const bool has_value = i + 1 < argc;
    if (a == "--no-sdf")
      o.sdf = false;
    else if (a == "--data" && has_value)
      o.data = argv[++i];
    else if (a == "--csv" && has_value)
      o.csv = argv[++i];
    else if (a == "--pictures" && has_value)
      o.pictures = argv[++i];
    else if (a == "--points" && has_value)
    {
      const long n = std::strtol (argv[++i], nullptr, 10);
      if (n < 4)
        return error = "--points needs a number >= 4", false;
      o.points = static_cast<std::size_t> (n);
    }
    else if (a == "--scan-from" && has_value)
    {
      if (!parseScanDirections (argv[++i], o.scan_directions))
        return error = "--scan-from needs six or a direction X,Y,Z", false;
    }
    else if ((a == "--noise" || a == "--outliers" || a == "--min-part-share" || a == "--single-view-min-part-share") &&
             has_value)
    {
      char* end = nullptr;
      const double v = std::strtod (argv[++i], &end);
      if (*end || !(v >= 0.0 && v < 1.0))
        return error = a + " needs a number in [0, 1)", false;
      (a == "--noise"              ? o.noise
       : a == "--outliers"         ? o.outliers
       : a == "--min-part-share"   ? o.flow.merge.min_part_share
                                   : o.flow.merge.single_view_min_part_share) = v;
    }
    else if ((a == "--tolerance" || a == "--stump-ratio" || a == "--compact-rho" || a == "--compact-size" || a == "--exterior-opening") &&
             has_value)
    {
      char* end = nullptr;
      const double v = std::strtod (argv[++i], &end);
      if (*end || !std::isfinite (v) || v < 0)
        return error = a + " needs a finite number >= 0", false;
      (a == "--tolerance"     ? o.flow.merge.sampling_tolerance
       : a == "--stump-ratio" ? o.flow.merge.stump_ratio
       : a == "--compact-rho" ? o.flow.merge.compact_rho
       : a == "--compact-size" ? o.flow.merge.compact_size
                               : o.flow.interior.exterior_opening) = v;
    }
    else if (a == "--significance" && has_value)
    {
      char* end = nullptr;
      o.significance = std::strtod (argv[++i], &end);
      if (*end)
        return error = "--significance needs a number", false;
      if (const pcl_flowseg::Status s = pcl_flowseg::checkSignificance (o.significance); !s)
        return error = "--significance: " + s.message, false;
    }
    else if (a == "--paper-rule")
      o.flow.merge.sampling_tolerance = o.flow.merge.stump_ratio = o.flow.merge.compact_size = 0.0;
    else if (a == "--seed" && has_value)
      o.seed = static_cast<std::uint32_t> (std::strtoul (argv[++i], nullptr, 10));
    else if (a == "--models" && has_value)
    {
      const auto ids = splitList (argv[++i]);
      o.models = std::set<std::string> (ids.begin (), ids.end ());
    }
    else if (a == "--rho" && has_value)
    {
      if (!parseRhoList (argv[++i], o.rhos, error))
        return false;
    }
    else if ((a == "--smooth" || a == "--outlier-removal") && has_value)
    {
      const std::string mode = argv[++i];
      if (!(a == "--smooth" ? parseMode (a, mode, o.flow.preparation.smoothing, error) : parseMode (a, mode, o.flow.preparation.outliers, error)))
        return false;
    }
    else if (a == "--smooth-passes" && has_value)
      o.flow.preparation.smoothing_passes = static_cast<unsigned> (std::strtoul (argv[++i], nullptr, 10));
    else if (a == "--mls" && has_value)
    {
      char* end = nullptr;
      o.mls_radius = std::strtod (argv[++i], &end);
      if (*end || !std::isfinite (o.mls_radius) || o.mls_radius < 0.0)
        return error = "--mls needs a finite number >= 0", false;
    }
    else
      return error = "unknown or incomplete option " + a, false;
  }
  return true;
}

struct Model
{
  std::string file, id, category;
};

Status
readModelList (const std::string& path, std::vector<Model>& models)
{
  std::ifstream in (path);
  if (!in)
    return Status::error ("cannot open " + path);
  std::string line;
  std::getline (in, line); // header: file,model_id,category,num_human_segs
  for (std::size_t number = 2; std::getline (in, line); ++number)
  {
    if (!line.empty () && line.back () == '\r')
      line.pop_back ();
    if (line.empty ())
      continue;
    const auto fields = splitList (line);
    if (fields.size () < 3)
      return Status::error (path + ":" + std::to_string (number) + ": expected file,model_id,category,...");
    models.push_back (Model{fields[0], fields[1], fields[2]});
  }
  return Status::success ();
}

/** A segmentation's error against references: area-weighted (as reported) and with every face
  * weighing 1 (as the PSB's own segEval computes it), each averaged over the references. */
struct Score
{
  double area = kMissing;
  double faces = kMissing;
};

/** The Rand-index error, or NaN (a missing cell of the table) when it cannot be computed. */
double
errorOf (const std::vector<double>& weights, const std::vector<int>& a, const std::vector<int>& b)
{
  double e = 0.0;
  return pcl_flowseg::randIndexError (weights, a, b, e) ? e : kMissing;
}

Score
meanError (const std::vector<double>& areas, const std::vector<int>& labels, const std::vector<std::vector<int>>& references,
           const std::vector<double>& counted = {})
{
  const std::vector<double> ones = counted.empty () ? std::vector<double> (areas.size (), 1.0) : counted;
  Score s{0.0, 0.0};
  for (const auto& ref : references)
  {
    s.area += errorOf (areas, labels, ref) / references.size ();
    s.faces += errorOf (ones, labels, ref) / references.size ();
  }
  return s;
}

/** Every human segmentation against every other one of the same model (unordered pairs). */
Score
humanAgreement (const std::vector<double>& areas, const std::vector<std::vector<int>>& humans)
{
  Score s{0.0, 0.0};
  std::size_t pairs = 0;
  for (std::size_t i = 0; i < humans.size (); ++i)
    for (std::size_t j = i + 1; j < humans.size (); ++j, ++pairs)
    {
      const Score one = meanError (areas, humans[i], {humans[j]});
      s.area += one.area;
      s.faces += one.faces;
    }
  if (pairs == 0)
    return Score{};
  return Score{s.area / pairs, s.faces / pairs};
}

/** Distinct labels among the faces (points) with a non-zero weight in \a counted (all if empty). */
std::size_t
distinctLabels (const std::vector<int>& labels, const std::vector<double>& counted = {})
{
  std::set<int> distinct;
  for (std::size_t k = 0; k < labels.size (); ++k)
    if (counted.empty () || counted[k] > 0.0)
      distinct.insert (labels[k]);
  return distinct.size ();
}

double
secondsSince (std::chrono::steady_clock::time_point start)
{
  return std::chrono::duration<double> (std::chrono::steady_clock::now () - start).count ();
}

/** One method on one model. */
struct MethodResult
{
  Score score;
  double segments = kMissing; ///< distinct labels of the scored elements (faces or points)
  double features = kMissing; ///< flowseg: reported features (FlowResult::features)
  double seconds = 0.0;
  std::string error;
  std::vector<int> labels; ///< flowseg: the face labels of the (first) view
};

struct ModelResult
{
  Model model;
  std::size_t faces = 0, humans = 0;
  std::vector<MethodResult> flow; // one per rho
  MethodResult sdf;
  Score one_segment, human;
  double transfer_seconds = 0.0;
  std::string error; // the model could not be evaluated at all
};

Status
readHumanSegmentations (const fs::path& dir, std::size_t faces, std::vector<std::vector<int>>& humans)
{
  std::error_code ec;
  std::vector<fs::path> files;
  for (fs::directory_iterator it (dir, ec), end; !ec && it != end; it.increment (ec))
    if (it->path ().extension () == ".seg")
      files.push_back (it->path ());
  if (ec)
    return Status::error ("cannot list " + dir.string () + ": " + ec.message ());
  std::sort (files.begin (), files.end ());
  for (const auto& file : files)
  {
    std::vector<int> labels;
    const Status st = pcl_flowseg::readFaceSegmentation (file.string (), faces, labels);
    if (!st)
      return st;
    humans.push_back (std::move (labels));
  }
  if (humans.empty ())
    return Status::error ("no .seg file in " + dir.string ());
  return Status::success ();
}

/** Features (indices into FlowResult::features, as in point_labels) holding less than \a share of
  * the features' total volume; none when \a share is 0. */
std::vector<std::uint32_t>
insignificantFeatures (const pcl_flowseg::FlowResult& result, double share)
{
  std::vector<std::uint32_t> out;
  if (!(share > 0.0))
    return out;
  const std::vector<int> significant = pcl_flowseg::significantSegments (result, result.features, share);
  for (std::size_t k = 0; k < result.features.size (); ++k)
    if (std::find (significant.begin (), significant.end (), result.features[k]) == significant.end ())
      out.push_back (static_cast<std::uint32_t> (k));
  return out;
}

/** What flowseg sees of a model: a whole sample, or a single view with its sensor position and
  * the faces it sees (the only ones its error counts). */
struct ModelView
{
  std::vector<Eigen::Vector3d> points;
  std::optional<Eigen::Vector3d> viewpoint;
  std::vector<double> area_weights, face_weights; // per face: area or 1 where counted, else 0
  double prepass_seconds = 0.0;                   // MovingLeastSquares before flowseg (--mls)
};

/** The views of \a mesh the options ask for: one whole sample (noise, outliers), or one scan per
  * direction (depth noise, outliers). */
std::vector<ModelView>
modelViews (const pcl_flowseg::TriangleMesh& mesh, const std::vector<double>& areas, const Options& o)
{
  std::vector<ModelView> views;
  if (o.scan_directions.empty ())
  {
    ModelView v;
    v.points = pcl_flowseg::sampleMeshSurface (mesh, o.points, o.noise * mesh.diagonal (), o.seed);
    v.area_weights = areas;
    v.face_weights.assign (areas.size (), 1.0);
    views.push_back (std::move (v));
  }
  Eigen::Vector3d lo = mesh.vertices.front (), hi = lo;
  for (const auto& p : mesh.vertices)
    lo = lo.cwiseMin (p), hi = hi.cwiseMax (p);
  double radius = 0.0;
  for (const auto& p : mesh.vertices)
    radius = std::max (radius, (p - 0.5 * (lo + hi)).norm ());
  for (const Eigen::Vector3d& direction : o.scan_directions)
  {
    pcl_flowseg::RangeScanOptions scan;
    scan.viewpoint = 0.5 * (lo + hi) + kScanDistance * radius * direction;
    scan.points = o.points;
    scan.depth_noise = o.noise;
    scan.seed = o.seed;
    ModelView v;
    std::vector<int> faces;
    if (!pcl_flowseg::scanMesh (mesh, scan, v.points, faces))
      continue;
    v.viewpoint = scan.viewpoint;
    v.area_weights.assign (areas.size (), 0.0);
    v.face_weights.assign (areas.size (), 0.0);
    for (int f : faces)
    {
      v.area_weights[static_cast<std::size_t> (f)] = areas[static_cast<std::size_t> (f)];
      v.face_weights[static_cast<std::size_t> (f)] = 1.0;
    }
    views.push_back (std::move (v));
  }
  for (ModelView& v : views)
  {
    pcl_flowseg::replaceWithOutliers (v.points, o.outliers, o.seed + 1);
    if (o.mls_radius > 0.0)
      v.points = flowseg_bench::movingLeastSquares (v.points, o.mls_radius, &v.prepass_seconds);
  }
  return views;
}

/** Segments \a points at \a rho (the options' parameters otherwise, the sensor at \a viewpoint
  * when given) into \a result, timed. */
MethodResult
runFlow (const std::vector<Eigen::Vector3d>& points, double rho, const Options& o, pcl_flowseg::FlowResult& result,
         const std::optional<Eigen::Vector3d>& viewpoint = std::nullopt)
{
  MethodResult m;
  pcl_flowseg::FlowParameters params = o.flow;
  params.merge.rho = rho;
  params.interior.viewpoint = viewpoint;
  const auto start = std::chrono::steady_clock::now ();
  const Status st = pcl_flowseg::runFlowSegmentation (points, params, result);
  m.seconds = secondsSince (start);
  if (!st)
    m.error = st.message;
  else
    m.features = static_cast<double> (result.features.size ());
  return m;
}

/** flowseg at \a rho on each view, scored on the faces the view counts; scores, segments and
  * features averaged over the views, times summed. Labels: those of the first view. */
MethodResult
scoreViews (const pcl_flowseg::TriangleMesh& mesh, const std::vector<std::vector<int>>& humans, const std::vector<ModelView>& views,
            double rho, const Options& o, double& transfer_seconds)
{
  MethodResult total;
  total.score = Score{0.0, 0.0};
  total.segments = total.features = 0.0;
  for (const ModelView& v : views)
  {
    pcl_flowseg::FlowResult result;
    const MethodResult m = runFlow (v.points, rho, o, result, v.viewpoint);
    if (!m.error.empty ())
      return m;
    const auto start = std::chrono::steady_clock::now ();
    std::vector<int> labels;
    pcl_flowseg::transferPointLabelsToFaces (mesh, v.points, result.point_labels, labels,
                                             insignificantFeatures (result, o.significance)); // sizes match
    transfer_seconds += secondsSince (start);
    const Score s = meanError (v.area_weights, labels, humans, v.face_weights);
    const double n = static_cast<double> (views.size ());
    total.score.area += s.area / n;
    total.score.faces += s.faces / n;
    total.segments += static_cast<double> (distinctLabels (labels, v.face_weights)) / n;
    total.features += m.features / n;
    total.seconds += m.seconds + v.prepass_seconds;
    if (total.labels.empty ())
    {
      for (std::size_t f = 0; f < labels.size (); ++f)
        labels[f] = v.face_weights[f] > 0.0 ? labels[f] : -1; // unseen faces grey in pictures
      total.labels = std::move (labels);
    }
  }
  if (views.empty ())
    total.error = "no view of the model";
  return total;
}

ModelResult
evaluateModel (const Model& model, const Options& o)
{
  ModelResult r;
  r.model = model;
  pcl_flowseg::TriangleMesh mesh;
  Status st = pcl_flowseg::loadTriangleMesh ((fs::path (o.data) / model.file).string (), mesh);
  std::vector<std::vector<int>> humans;
  if (st)
    st = readHumanSegmentations (fs::path (o.data) / "seg_human" / model.id, mesh.faces.size (), humans);
  if (!st)
  {
    r.error = st.message;
    return r;
  }
  r.faces = mesh.faces.size ();
  r.humans = humans.size ();
  const auto areas = pcl_flowseg::faceAreas (mesh);
  r.human = humanAgreement (areas, humans);
  r.one_segment = meanError (areas, std::vector<int> (r.faces, 0), humans);
  if (!o.pictures.empty ())
  {
    fs::create_directories (o.pictures);
    flowseg_bench::renderSegmentedMesh (mesh, humans.front (), (fs::path (o.pictures) / (model.id + "_human.png")).string ());
  }

  const std::vector<ModelView> views = modelViews (mesh, areas, o);
  if (!o.scan_directions.empty () && !views.empty ()) // one segment on the faces each view sees
  {
    r.one_segment = Score{0.0, 0.0};
    for (const ModelView& v : views)
    {
      const Score s = meanError (v.area_weights, std::vector<int> (r.faces, 0), humans, v.face_weights);
      r.one_segment.area += s.area / static_cast<double> (views.size ());
      r.one_segment.faces += s.faces / static_cast<double> (views.size ());
    }
  }
  for (double rho : o.rhos)
  {
    std::fprintf (stderr, "  model %s: flowseg rho %g\n", model.id.c_str (), rho);
    r.flow.push_back (scoreViews (mesh, humans, views, rho, o, r.transfer_seconds));
    if (!o.pictures.empty () && !r.flow.back ().labels.empty ())
    {
      char name[64];
      std::snprintf (name, sizeof (name), "_flowseg_rho%g.png", rho);
      flowseg_bench::renderSegmentedMesh (mesh, r.flow.back ().labels, (fs::path (o.pictures) / (model.id + name)).string ());
    }
  }
  if (o.sdf)
  {
    std::fprintf (stderr, "  model %s: CGAL SDF\n", model.id.c_str ());
    std::vector<int> labels;
    std::size_t segments = 0;
    const auto start = std::chrono::steady_clock::now ();
    st = flowseg_bench::sdfSegmentation (mesh, labels, segments);
    r.sdf.seconds = secondsSince (start);
    if (!st)
      r.sdf.error = st.message;
    else
    {
      r.sdf.score = meanError (areas, labels, humans);
      r.sdf.segments = static_cast<double> (distinctLabels (labels));
      if (!o.pictures.empty ())
        flowseg_bench::renderSegmentedMesh (mesh, labels, (fs::path (o.pictures) / (model.id + "_sdf.png")).string ());
    }
  }
  return r;
}

/** The project's generated shape: flowseg's point labels against the parts (unweighted). */
struct GeneratedResult
{
  std::string name;
  std::vector<MethodResult> flow;
  Score one_segment;
};

GeneratedResult
evaluateGenerated (const pcl_flowseg::BlobShape& shape, const Options& o)
{
  GeneratedResult g;
  g.name = shape.name;
  const auto points = pcl_flowseg::sampleBoundary (shape, kGeneratedPoints, o.seed);
  std::vector<int> truth;
  for (const auto& p : points)
    truth.push_back (shape.nearestPart (p));
  const std::vector<double> ones (points.size (), 1.0);
  const double one = errorOf (ones, std::vector<int> (points.size (), 0), truth);
  g.one_segment = Score{one, one};
  for (double rho : o.rhos)
  {
    pcl_flowseg::FlowResult result;
    MethodResult m = runFlow (points, rho, o, result);
    if (m.error.empty ())
    {
      std::vector<int> labels;
      for (std::uint32_t l : result.point_labels)
        labels.push_back (l == pcl_flowseg::kNoSegment ? -1 : static_cast<int> (l));
      const double e = errorOf (ones, labels, truth);
      m.score = Score{e, e};
      m.segments = static_cast<double> (distinctLabels (labels));
    }
    g.flow.push_back (m);
  }
  return g;
}

std::string
number (double v, const char* format = "%.3f")
{
  if (!std::isfinite (v))
    return "-";
  char text[32];
  std::snprintf (text, sizeof (text), format, v);
  return text;
}

void
printModelLine (const ModelResult& r, const Options& o)
{
  if (!r.error.empty ())
  {
    std::printf ("%-5s %-9s FAILED: %s\n", r.model.id.c_str (), r.model.category.c_str (), r.error.c_str ());
    return;
  }
  std::printf ("%-5s %-9s faces %6zu humans %2zu |", r.model.id.c_str (), r.model.category.c_str (), r.faces, r.humans);
  for (std::size_t k = 0; k < o.rhos.size (); ++k)
  {
    const auto& m = r.flow[k];
    if (!m.error.empty ())
      std::printf (" rho %g FAILED (%s) |", o.rhos[k], m.error.c_str ());
    else
      std::printf (" rho %g %s (%s seg, %s feat) |", o.rhos[k], number (m.score.area).c_str (), number (m.segments, "%.0f").c_str (),
                   number (m.features, "%.0f").c_str ());
  }
  if (o.sdf)
    std::printf (" sdf %s (%s seg) |", r.sdf.error.empty () ? number (r.sdf.score.area).c_str () : ("FAILED: " + r.sdf.error).c_str (),
                 number (r.sdf.segments, "%.0f").c_str ());
  std::printf (" one %s | human %s\n", number (r.one_segment.area).c_str (), number (r.human.area).c_str ());
  for (std::size_t k = 0; k < o.rhos.size (); ++k)
    if (r.flow[k].error.empty () && r.flow[k].features == 0)
      std::printf ("      note: flowseg reported no feature at rho %g (every face unlabelled: one segment)\n", o.rhos[k]);
  std::fflush (stdout);
}

/** Mean of the finite values; \a missing counts the others. */
struct Mean
{
  double sum = 0.0;
  int count = 0, missing = 0;
  void add (double v)
  {
    if (std::isfinite (v))
    {
      sum += v;
      ++count;
    }
    else
      ++missing;
  }
  std::string text (const char* format = "%.3f") const
  {
    if (count == 0)
      return "-";
    return number (sum / count, format) + (missing ? "*" : "");
  }
};

/** One table row: the columns of the table for a set of models. */
struct Row
{
  std::string name;
  int models = 0;
  std::vector<Mean> flow, flow_segments;
  Mean sdf, sdf_segments, one_segment, human;
};

Row
summarise (const std::string& name, const std::vector<const ModelResult*>& results, std::size_t rhos, bool by_area)
{
  Row row;
  row.name = name;
  row.flow.resize (rhos);
  row.flow_segments.resize (rhos);
  for (const ModelResult* r : results)
  {
    ++row.models;
    for (std::size_t k = 0; k < rhos; ++k)
    {
      row.flow[k].add (by_area ? r->flow[k].score.area : r->flow[k].score.faces);
      row.flow_segments[k].add (r->flow[k].segments);
    }
    row.sdf.add (by_area ? r->sdf.score.area : r->sdf.score.faces);
    row.sdf_segments.add (r->sdf.segments);
    row.one_segment.add (by_area ? r->one_segment.area : r->one_segment.faces);
    row.human.add (by_area ? r->human.area : r->human.faces);
  }
  return row;
}

void
printTable (const std::vector<Row>& rows, const Options& o)
{
  std::printf ("\n| category | models |");
  for (double rho : o.rhos)
    std::printf (" flowseg rho %g |", rho);
  std::printf (" CGAL SDF | one segment | human vs human |");
  for (double rho : o.rhos)
    std::printf (" segs rho %g |", rho);
  std::printf (" segs SDF |\n|---|---|");
  for (std::size_t k = 0; k < 2 * o.rhos.size () + 4; ++k)
    std::printf ("---|");
  std::printf ("\n");
  for (const Row& row : rows)
  {
    std::printf ("| %s | %d |", row.name.c_str (), row.models);
    for (const auto& m : row.flow)
      std::printf (" %s |", m.text ().c_str ());
    std::printf (" %s | %s | %s |", row.sdf.text ().c_str (), row.one_segment.text ().c_str (), row.human.text ().c_str ());
    for (const auto& m : row.flow_segments)
      std::printf (" %s |", m.text ("%.1f").c_str ());
    std::printf (" %s |\n", row.sdf_segments.text ("%.1f").c_str ());
  }
}

Row
generatedRow (const GeneratedResult& g, std::size_t rhos)
{
  Row row;
  row.name = "generated " + g.name + " (points)";
  row.models = 1;
  row.flow.resize (rhos);
  row.flow_segments.resize (rhos);
  for (std::size_t k = 0; k < rhos; ++k)
  {
    row.flow[k].add (g.flow[k].score.area);
    row.flow_segments[k].add (g.flow[k].segments);
  }
  row.one_segment.add (g.one_segment.area);
  return row;
}

Status
writeCsv (const std::string& path, const std::vector<ModelResult>& results, const std::vector<GeneratedResult>& generated,
          const Options& o)
{
  return pcl_flowseg::writeFileAtomically (path, [&] (const std::string& tmp) {
    std::ofstream out (tmp);
    out << "model_id,category,faces,humans";
    for (double rho : o.rhos)
      out << ",flow_" << rho << ",flow_" << rho << "_unweighted,flow_" << rho << "_segments,flow_" << rho << "_features,flow_"
          << rho << "_seconds";
    out << ",sdf,sdf_unweighted,sdf_segments,sdf_seconds,one_segment,one_segment_unweighted,human,human_unweighted,error\n";
    auto csvNumber = [] (double v) { return std::isfinite (v) ? number (v, "%.6g") : std::string (); };
    for (const auto& r : results)
    {
      out << r.model.id << ',' << r.model.category << ',' << r.faces << ',' << r.humans;
      std::string error = r.error;
      for (std::size_t k = 0; k < o.rhos.size (); ++k)
      {
        const MethodResult m = k < r.flow.size () ? r.flow[k] : MethodResult{};
        out << ',' << csvNumber (m.score.area) << ',' << csvNumber (m.score.faces) << ',' << csvNumber (m.segments) << ','
            << csvNumber (m.features) << ',' << csvNumber (m.seconds);
        if (!m.error.empty ())
          error += " flowseg rho " + number (o.rhos[k], "%g") + ": " + m.error;
      }
      if (!r.sdf.error.empty ())
        error += " sdf: " + r.sdf.error;
      std::replace (error.begin (), error.end (), ',', ';');
      out << ',' << csvNumber (r.sdf.score.area) << ',' << csvNumber (r.sdf.score.faces) << ',' << csvNumber (r.sdf.segments) << ','
          << csvNumber (r.sdf.seconds) << ',' << csvNumber (r.one_segment.area) << ',' << csvNumber (r.one_segment.faces) << ','
          << csvNumber (r.human.area) << ',' << csvNumber (r.human.faces) << ',' << error << '\n';
    }
    for (const auto& g : generated)
    {
      out << g.name << ",generated," << 0 << ',' << 0;
      for (const auto& m : g.flow)
        out << ',' << csvNumber (m.score.area) << ',' << csvNumber (m.score.faces) << ',' << csvNumber (m.segments) << ','
            << csvNumber (m.features) << ',' << csvNumber (m.seconds);
      out << ",,,,," << csvNumber (g.one_segment.area) << ',' << csvNumber (g.one_segment.faces) << ",,,\n";
    }
    out.flush ();
    return out ? Status::success () : Status::error ("write error");
  });
}

/** The table's rows: categories in the order of the list, then all models, then the generated shapes. */
std::vector<Row>
tableRows (const std::vector<ModelResult>& results, const std::vector<GeneratedResult>& generated, const Options& o)
{
  std::vector<std::string> categories;
  std::vector<const ModelResult*> evaluated;
  for (const auto& r : results)
    if (r.error.empty ())
    {
      evaluated.push_back (&r);
      if (std::find (categories.begin (), categories.end (), r.model.category) == categories.end ())
        categories.push_back (r.model.category);
    }
  std::vector<Row> rows;
  for (const auto& category : categories)
  {
    std::vector<const ModelResult*> in;
    for (const ModelResult* r : evaluated)
      if (r->model.category == category)
        in.push_back (r);
    rows.push_back (summarise (category, in, o.rhos.size (), true));
  }
  rows.push_back (summarise ("**all**", evaluated, o.rhos.size (), true));
  rows.push_back (summarise ("all, every face weighing 1 (PSB segEval)", evaluated, o.rhos.size (), false));
  for (const auto& g : generated)
    rows.push_back (generatedRow (g, o.rhos.size ()));
  return rows;
}

/** The time line: flowseg, label transfer, SDF and the whole run since \a start. */
void
printTimes (const std::vector<ModelResult>& results, const Options& o, std::chrono::steady_clock::time_point start)
{
  std::size_t evaluated = 0;
  for (const auto& r : results)
    evaluated += r.error.empty ();
  double flow_seconds = 0.0, sdf_seconds = 0.0, transfer_seconds = 0.0;
  for (const auto& r : results)
  {
    for (const auto& m : r.flow)
      flow_seconds += m.seconds;
    sdf_seconds += r.sdf.seconds;
    transfer_seconds += r.transfer_seconds;
  }
  std::printf ("\nTime: flowseg %.1f s (%zu runs of %zu points), label transfer %.1f s, CGAL SDF %.1f s, whole run %.1f s\n",
               flow_seconds, evaluated * o.rhos.size () * std::max<std::size_t> (1, o.scan_directions.size ()), o.points,
               transfer_seconds, sdf_seconds, secondsSince (start));
  if (!o.scan_directions.empty ())
    std::printf ("Single views from %zu direction(s): flowseg and one segment scored on the faces each view sees, averaged over "
                 "the views; human vs human on whole models.\n", o.scan_directions.size ());

}

/** Prints every failure; \return how many models failed. */
int
reportFailures (const std::vector<ModelResult>& results, const Options& o)
{
  int failures = 0;
  for (const auto& r : results)
  {
    if (!r.error.empty ())
      ++failures, std::printf ("failed: model %s: %s\n", r.model.id.c_str (), r.error.c_str ());
    for (std::size_t k = 0; k < r.flow.size (); ++k)
      if (!r.flow[k].error.empty ())
        std::printf ("failed: model %s: flowseg rho %g: %s\n", r.model.id.c_str (), o.rhos[k], r.flow[k].error.c_str ());
    if (!r.sdf.error.empty ())
      std::printf ("failed: model %s: SDF: %s\n", r.model.id.c_str (), r.sdf.error.c_str ());
  }
  return failures;
}

} // namespace

int
main (int argc, char** argv)
{
  Options o;
  std::string error;
  if (argc > 1 && (std::string (argv[1]) == "-h" || std::string (argv[1]) == "--help"))
  {
    std::fputs (kUsage, stdout);
    return 0;
  }
  if (!parseOptions (argc, argv, o, error))
  {
    std::fprintf (stderr, "flowseg_bench_psb: %s\n%s", error.c_str (), kUsage);
    return 2;
  }
  const fs::path list = fs::path (o.data) / "labels.csv";
  if (!fs::is_directory (o.data) || !fs::is_regular_file (list))
  {
    std::fprintf (stderr, "flowseg_bench_psb: no PSB data: %s is missing (give the data directory with --data DIR)\n",
                  list.string ().c_str ());
    return 1;
  }
  std::vector<Model> models;
  if (const Status st = readModelList (list.string (), models); !st)
  {
    std::fprintf (stderr, "flowseg_bench_psb: %s\n", st.message.c_str ());
    return 1;
  }
  if (!o.models.empty ())
    models.erase (std::remove_if (models.begin (), models.end (), [&] (const Model& m) { return !o.models.count (m.id); }),
                  models.end ());

  const auto start = std::chrono::steady_clock::now ();
  std::printf ("PSB: %zu models from %s, %zu points per model, seed %u, rho", models.size (), o.data.c_str (), o.points, o.seed);
  for (double rho : o.rhos)
    std::printf (" %g", rho);
  std::printf (", sampling tolerance %g, stump ratio %g, compact rho %g, compact size %g, smallest part share %g "
               "(single views %g), significance %g, noise %g, outliers %g, MovingLeastSquares radius %g",
               o.flow.merge.sampling_tolerance, o.flow.merge.stump_ratio, o.flow.merge.compact_rho, o.flow.merge.compact_size,
               o.flow.merge.min_part_share, o.flow.merge.single_view_min_part_share, o.significance, o.noise, o.outliers,
               o.mls_radius);
  std::printf ("; errors: area-weighted Rand-index error, mean over the model's human segmentations\n\n");
  std::vector<ModelResult> results;
  for (std::size_t i = 0; i < models.size (); ++i)
  {
    std::fprintf (stderr, "[%zu/%zu] model %s (%s)\n", i + 1, models.size (), models[i].id.c_str (), models[i].category.c_str ());
    results.push_back (evaluateModel (models[i], o));
    printModelLine (results.back (), o);
  }

  std::vector<GeneratedResult> generated;
  for (const auto& shape : pcl_flowseg::sampleShapes ())
    if (shape.dimension == 3)
    {
      std::fprintf (stderr, "generated shape %s\n", shape.name.c_str ());
      generated.push_back (evaluateGenerated (shape, o));
    }

  const std::vector<Row> rows = tableRows (results, generated, o);
  printTable (rows, o);
  std::printf ("\nErrors: 1 - Rand index, faces weighted by area (pairs i < j, weight area_i * area_j), mean over the\n"
               "model's human segmentations, then over the models. Generated shapes: %zu points, every point weighing 1,\n"
               "against their parts. segs: distinct face (point) labels. *: some models missing (failed) in that cell.\n",
               kGeneratedPoints);

  printTimes (results, o, start);
  const int failures = reportFailures (results, o);
  if (!o.csv.empty ())
  {
    if (const Status st = writeCsv (o.csv, results, generated, o); !st)
    {
      std::fprintf (stderr, "flowseg_bench_psb: %s\n", st.message.c_str ());
      return 1;
    }
    std::printf ("per-model rows: %s\n", o.csv.c_str ());
  }
  return failures ? 1 : 0;
}

/*
 * pcl_flowseg Python bindings - segment(): the flow segmentation of a numpy array, and its result.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include "bindings.h"
#include "python_values.h"

#include <pcl_flowseg/common/feature_significance.h>
#include <pcl_flowseg/segmentation/flow_pipeline.h>
#include <pcl_flowseg/signature/signature.h>

#include <pybind11/stl.h>

#include <cmath>
#include <memory>
#include <set>

namespace pcl_flowseg_python {
namespace {

/** A finished segmentation and the significance its features are judged by. */
struct Segmentation
{
  std::shared_ptr<const pcl_flowseg::FlowResult> result;
  double significance = pcl_flowseg::kDefaultSignificance;
};

/** One reported feature, as Python sees it. */
struct Feature
{
  int index = 0;          ///< position in Segmentation.features (the label of its points)
  int segment = 0;        ///< index among all segments
  double volume = 0.0;
  double share = 0.0;     ///< volume over the total volume of the features
  bool significant = false;
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero ();
  Eigen::Vector3d maximum = Eigen::Vector3d::Zero ();
  double radius = 0.0;    ///< circumradius of the highest maximum
  std::size_t point_count = 0;
  std::size_t cell_count = 0;
  int interior = -1;
};

std::vector<Feature>
features (const Segmentation& s)
{
  const pcl_flowseg::FlowResult& r = *s.result;
  double total = 0.0;
  for (int segment : r.features)
    total += r.segments[static_cast<std::size_t> (segment)].volume;
  const std::vector<int> significant = pcl_flowseg::significantSegments (r, r.features, s.significance);
  const std::set<int> is_significant (significant.begin (), significant.end ());
  std::vector<Feature> out;
  for (std::size_t i = 0; i < r.features.size (); ++i)
  {
    const pcl_flowseg::FlowSegment& seg = r.segments[static_cast<std::size_t> (r.features[i])];
    Feature f;
    f.index = static_cast<int> (i);
    f.segment = r.features[i];
    f.volume = seg.volume;
    f.share = total > 0.0 ? seg.volume / total : 0.0;
    f.significant = is_significant.count (f.segment) > 0;
    f.centroid = seg.centroid;
    f.maximum = seg.maximum.location;
    f.radius = std::sqrt (seg.maximum.height);
    f.point_count = seg.point_count;
    f.cell_count = seg.cell_count;
    f.interior = seg.interior;
    out.push_back (f);
  }
  return out;
}

py::array_t<std::int64_t>
labels (const Segmentation& s)
{
  const auto& point_labels = s.result->point_labels;
  py::array_t<std::int64_t> out (static_cast<py::ssize_t> (point_labels.size ()));
  auto view = out.mutable_unchecked<1> ();
  for (std::size_t i = 0; i < point_labels.size (); ++i)
    view (static_cast<py::ssize_t> (i)) = point_labels[i] == pcl_flowseg::kNoSegment ? -1 : static_cast<std::int64_t> (point_labels[i]);
  return out;
}

/** Saddles between two reported features: (feature a, feature b, saddle radius). */
py::tuple
adjacency (const Segmentation& s)
{
  const pcl_flowseg::FlowResult& r = *s.result;
  const std::vector<int> feature_of = r.featureOfSegment ();
  std::vector<std::array<std::int64_t, 2>> pairs;
  std::vector<double> radii;
  for (const pcl_flowseg::SaddleFacet& saddle : r.segment_adjacency)
  {
    const int a = feature_of[static_cast<std::size_t> (saddle.segment_a)], b = feature_of[static_cast<std::size_t> (saddle.segment_b)];
    if (a >= 0 && b >= 0)
    {
      pairs.push_back ({std::min (a, b), std::max (a, b)});
      radii.push_back (std::sqrt (saddle.squared_radius));
    }
  }
  py::array_t<std::int64_t> pair_array ({static_cast<py::ssize_t> (pairs.size ()), py::ssize_t (2)});
  auto view = pair_array.mutable_unchecked<2> ();
  for (std::size_t i = 0; i < pairs.size (); ++i)
    for (int c = 0; c < 2; ++c)
      view (static_cast<py::ssize_t> (i), c) = pairs[i][static_cast<std::size_t> (c)];
  return py::make_tuple (pair_array, py::array_t<double> (static_cast<py::ssize_t> (radii.size ()), radii.data ()));
}

py::dict
timings (const pcl_flowseg::StageTimings& t)
{
  py::dict d;
  d["preparation"] = t.preparation_ms;
  d["noise"] = t.noise_ms;
  d["delaunay"] = t.delaunay_ms;
  d["flow"] = t.flow_ms;
  d["manifolds"] = t.manifolds_ms;
  d["interior"] = t.interior_ms;
  d["merge"] = t.merge_ms;
  d["labels"] = t.labels_ms;
  d["total"] = t.total_ms;
  return d;
}

py::dict
interiorReport (const pcl_flowseg::InteriorReport& r)
{
  py::dict d;
  d["computed"] = r.computed;
  d["inside_volume"] = r.inside_volume;
  d["inside_cells"] = r.inside_cells;
  d["boundary_facets"] = r.boundary_facets;
  d["closed"] = r.closed;
  d["manifold"] = r.manifold;
  d["nonmanifold_edges"] = r.nonmanifold_edges;
  d["nonmanifold_vertices"] = r.nonmanifold_vertices;
  d["vertices_off_boundary"] = r.vertices_off_boundary;
  d["ray_cells"] = r.ray_cells;
  d["opening_cells"] = r.opening_cells;
  d["repaired_cells"] = r.repaired_cells;
  d["island_cells"] = r.island_cells;
  d["surface_variation"] = r.surface_variation;
  d["smoothing_passes"] = r.smoothing_passes;
  return d;
}

py::dict
parameters (const Segmentation& s)
{
  py::dict d = argumentsToDict (flowArguments (s.result->parameters));
  d["significance"] = s.significance;
  return d;
}

/** Runs the pipeline without the GIL; \a progress (a Python callable or None) is called with it. */
Segmentation
segment (const py::object& points_object, const py::object& normals_object, const py::object& progress, const py::kwargs& kwargs)
{
  CallParameters call;
  pcl_flowseg::MatchParameters unused;
  applyKwargs (kwargs, kFlowArguments | kSignificanceArgument, call, unused);
  const std::vector<Eigen::Vector3d> points = pointsFromPython (points_object, "points", false);
  std::vector<Eigen::Vector3d> normals;
  if (!normals_object.is_none ())
  {
    normals = pointsFromPython (normals_object, "normals", true);
    if (normals.size () != points.size ())
      throw py::value_error ("normals: needs one row per point (" + std::to_string (points.size ()) + "), got " +
                             std::to_string (normals.size ()));
  }
  if (!progress.is_none () && !PyCallable_Check (progress.ptr ()))
    throw py::type_error ("progress: needs a callable (stage, fraction) or None");
  pcl_flowseg::ProgressCallback report;
  std::unique_ptr<py::error_already_set> progress_error;
  if (!progress.is_none ())
    report = [&progress, &progress_error] (const std::string& stage, double fraction) {
      py::gil_scoped_acquire gil;
      if (progress_error)
        return;
      try
      {
        progress (stage, fraction);
      }
      catch (py::error_already_set& e)
      {
        progress_error = std::make_unique<py::error_already_set> (std::move (e));
      }
    };
  auto result = std::make_shared<pcl_flowseg::FlowResult> ();
  pcl_flowseg::Status status;
  {
    py::gil_scoped_release release;
    status = pcl_flowseg::runFlowSegmentation (points, normals, call.flow, *result, report);
  }
  if (progress_error)
    throw std::move (*progress_error);
  raiseIfFailed (status);
  return Segmentation{result, call.significance};
}

/** A copy merged again with other merge parameters (the triangulation and flow are reused). */
Segmentation
remerge (const Segmentation& s, const py::kwargs& kwargs)
{
  static const std::set<std::string> merge_names = {"rho",          "sampling_tolerance", "stump_ratio",
                                                     "compact_rho",  "compact_size",       "min_part_share",
                                                     "single_view_min_part_share"};
  for (const auto& item : kwargs)
    if (!merge_names.count (py::str (item.first)))
      throw py::type_error ("remerge: unexpected keyword argument '" + std::string (py::str (item.first)) +
                            "' (only rho, sampling_tolerance, stump_ratio, compact_rho, compact_size, min_part_share, "
                            "single_view_min_part_share)");
  CallParameters call;
  call.flow = s.result->parameters;
  pcl_flowseg::MatchParameters unused;
  applyKwargs (kwargs, kFlowArguments, call, unused);
  auto result = std::make_shared<pcl_flowseg::FlowResult> (*s.result);
  pcl_flowseg::Status status;
  {
    py::gil_scoped_release release;
    status = pcl_flowseg::remergeFlowSegmentation (call.flow.merge, *result);
  }
  raiseIfFailed (status);
  return Segmentation{result, s.significance};
}

void
bindFeature (py::module_& m)
{
  py::class_<Feature> (m, "Feature", "One reported feature (segment) of a segmentation.")
      .def_readonly ("index", &Feature::index, "Its position in Segmentation.features: the label of its points.")
      .def_readonly ("segment", &Feature::segment, "Its index among all segments of the run (interior and exterior).")
      .def_readonly ("volume", &Feature::volume, "Volume (area in 2D), in input units cubed (squared).")
      .def_readonly ("share", &Feature::share, "Volume over the total volume of the reported features.")
      .def_readonly ("significant", &Feature::significant, "share above the segmentation's significance.")
      .def_property_readonly ("centroid", [] (const Feature& f) { return rowsToArray ({f.centroid}).attr ("reshape") (3); },
                              "Volume-weighted centroid, input frame.")
      .def_property_readonly ("maximum", [] (const Feature& f) { return rowsToArray ({f.maximum}).attr ("reshape") (3); },
                              "Location of its highest maximum of the distance function (a circumcentre).")
      .def_readonly ("radius", &Feature::radius, "Circumradius of that maximum, in input units.")
      .def_readonly ("point_count", &Feature::point_count, "Input points labelled with it.")
      .def_readonly ("cell_count", &Feature::cell_count, "Delaunay cells it holds.")
      .def_readonly ("interior", &Feature::interior, "1 interior, 0 exterior, -1 not separated.")
      .def ("__repr__", [] (const Feature& f) {
        return "<Feature " + std::to_string (f.index) + " volume=" + std::to_string (f.volume) + " points=" +
               std::to_string (f.point_count) + (f.significant ? " significant>" : ">");
      });
}

void
bindResult (py::module_& m)
{
  py::class_<Segmentation> (m, "Segmentation", "The result of segment(): labels, features, adjacency, timings.")
      .def_property_readonly ("labels", &labels,
                              "Per input point (in input order) the index of its feature in features, -1 for none "
                              "(non-finite points, outliers left out, points touching no reported feature). int64 array.")
      .def_property_readonly ("features", &features, "The reported features (interior ones by decreasing volume).")
      .def_property_readonly ("significant", [] (const Segmentation& s) {
            std::vector<int> out;
            for (const Feature& f : features (s))
              if (f.significant)
                out.push_back (f.index);
            return out;
          }, "Indices of the significant features.")
      .def_property_readonly ("adjacency", &adjacency,
                              "(pairs, radii): (m, 2) int64 array of adjacent features (a < b) and the radius of "
                              "the saddle between them.")
      .def_property_readonly ("timings", [] (const Segmentation& s) { return timings (s.result->timings); },
                              "Wall-clock milliseconds per stage and in total.")
      .def_property_readonly ("parameters", &parameters, "Every parameter the run used (segment()'s keywords).")
      .def_property_readonly ("dimension", [] (const Segmentation& s) { return s.result->dimension; })
      .def_property_readonly ("input_points", [] (const Segmentation& s) { return s.result->input_points; })
      .def_property_readonly ("non_finite_points", [] (const Segmentation& s) { return s.result->non_finite_points; })
      .def_property_readonly ("duplicate_points", [] (const Segmentation& s) { return s.result->duplicate_points; })
      .def_property_readonly ("outlier_points", [] (const Segmentation& s) { return s.result->outlier_points; },
                              "Points left out as outliers, isolated or detached from the surface (label -1).")
      .def_property_readonly ("hidden_side_vertices", [] (const Segmentation& s) { return s.result->hidden_side_vertices; },
                              "Vertices added behind a single view (hidden_side=True with a viewpoint); they label no point.")
      .def_property_readonly ("unlabelled_points", [] (const Segmentation& s) { return s.result->unlabelledPoints (); })
      .def_property_readonly ("noise", [] (const Segmentation& s) {
        py::dict d;
        d["sigma"] = s.result->noise.sigma;
        d["share"] = s.result->noise.share;
        d["roughness"] = s.result->noise.roughness;
        d["isolated_share"] = s.result->noise.isolated_share;
        d["detached_share"] = s.result->noise.detached_share;
        d["points_used"] = s.result->noise.points_used;
        return d;
      }, "The sample's estimated noise: sigma (input units), share (of the bounding-box diagonal), roughness "
         "(in sample spacings; above 0.1 automatic smoothing acts), isolated_share (share of the points far from "
         "their neighbours), detached_share (share lying off the surface their neighbours sample; either share "
         "above its threshold starts the automatic outlier removal), points_used.")
      .def_property_readonly ("smoothing_passes", [] (const Segmentation& s) { return s.result->smoothing_passes; },
                              "Smoothing passes made before the triangulation (0: the vertices are the points).")
      .def_property_readonly ("interior", [] (const Segmentation& s) { return interiorReport (s.result->interior); },
                              "What the interior/exterior separation found.")
      .def_property_readonly ("warnings", [] (const Segmentation& s) { return s.result->warnings; })
      .def ("signature", [] (const Segmentation& s, const py::object& significance) {
            const double fraction = significance.is_none () ? s.significance : significance.cast<double> ();
            raiseIfFailed (pcl_flowseg::checkSignificance (fraction));
            pcl_flowseg::Signature signature;
            raiseIfFailed (pcl_flowseg::signatureFromSegmentation (*s.result, fraction, signature));
            return signature;
          }, py::arg ("significance") = py::none (),
          "The shape's signature: its significant interior features as weighted points (needs separate=True).")
      .def ("remerge", &remerge,
            "A copy merged again with other merge parameters (rho, sampling_tolerance, stump_ratio, compact_rho, "
            "compact_size, min_part_share, single_view_min_part_share); cheap: the triangulation and flow are reused.")
      .def ("__repr__", [] (const Segmentation& s) {
        return "<Segmentation " + std::to_string (s.result->dimension) + "D, " + std::to_string (s.result->input_points) +
               " points, " + std::to_string (s.result->features.size ()) + " features>";
      });
}

} // namespace

void
bindSegmentation (py::module_& m)
{
  bindFeature (m);
  bindResult (m);
  m.def ("segment", &segment, py::arg ("points"), py::arg ("normals") = py::none (), py::kw_only (),
         py::arg ("progress") = py::none (),
         R"doc(Segments a point sample into features by the flow of its Delaunay triangulation.

points: (n, 2) or (n, 3) float32/float64 array (2 columns: a 2D shape). NaN/Inf rows are skipped
    and counted (label -1); duplicates take the label of their first copy.
normals: None or (n, 3) array of outward normals (evidence for the interior/exterior separation).
progress: None or a callable(stage: str, fraction: float), called during the run.
Keywords (see defaults()): dimension, planar_tolerance, outliers, smoothing, smoothing_passes, rho, sampling_tolerance, stump_ratio,
    compact_rho, compact_size, min_part_share, single_view_min_part_share, separate, denoising, viewpoint, manifold_repair, hidden_side, exterior_opening, features, threads, memory_limit,
    significance.
Raises ValueError for input that cannot be segmented or a parameter out of range, TypeError for
an unknown keyword. The GIL is released during the computation.)doc");
}

} // namespace pcl_flowseg_python

/*
 * pcl_flowseg Python bindings - signatures of arrays and shape files, and matching two of them.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include "bindings.h"
#include "python_values.h"

#include <pcl_flowseg/segmentation/flow_pipeline.h>
#include <pcl_flowseg/signature/shape_signature.h>
#include <pcl_flowseg/signature/signature.h>
#include <pcl_flowseg/signature/signature_matcher.h>

#include <pybind11/eigen.h>
#include <pybind11/stl.h>

#include <cmath>

namespace pcl_flowseg_python {
namespace {

using pcl_flowseg::Signature;

/** A signature from its arrays, checked as one read from a file would be. */
Signature
makeSignature (const py::object& points, const py::object& weights, int dimension, double unit, double interior_volume,
               double significance)
{
  Signature s;
  s.dimension = dimension;
  s.unit = unit;
  s.interior_volume = interior_volume;
  s.significance = significance;
  const std::vector<Eigen::Vector3d> positions = pointsFromPython (points, "points", true);
  const std::vector<double> w = weights.cast<std::vector<double>> ();
  if (w.size () != positions.size ())
    throw py::value_error ("weights: needs one weight per point (" + std::to_string (positions.size ()) + "), got " +
                           std::to_string (w.size ()));
  for (std::size_t i = 0; i < positions.size (); ++i)
    s.points.push_back ({positions[i], w[i]});
  raiseIfFailed (pcl_flowseg::checkSignature (s));
  return s;
}

Signature
signatureOfArray (const py::object& points_object, const py::kwargs& kwargs)
{
  CallParameters call;
  pcl_flowseg::MatchParameters unused;
  applyKwargs (kwargs, kFlowArguments | kSignificanceArgument, call, unused);
  const std::vector<Eigen::Vector3d> points = pointsFromPython (points_object, "points", false);
  Signature signature;
  pcl_flowseg::Status status;
  {
    py::gil_scoped_release release;
    pcl_flowseg::FlowResult result;
    status = pcl_flowseg::runFlowSegmentation (points, call.flow, result);
    if (status)
      status = pcl_flowseg::signatureFromSegmentation (result, call.significance, signature);
  }
  raiseIfFailed (status);
  return signature;
}

Signature
signatureOfFile (const std::string& path, const py::kwargs& kwargs)
{
  CallParameters call;
  pcl_flowseg::MatchParameters unused;
  applyKwargs (kwargs, kFlowArguments | kSignificanceArgument | kShapeInputArguments, call, unused);
  Signature signature;
  pcl_flowseg::Status status;
  {
    py::gil_scoped_release release;
    status = pcl_flowseg::signatureOfShapeFile (path, call.input, call.flow, call.significance, signature);
  }
  raiseOsErrorIfFailed (status);
  return signature;
}

pcl::SignatureMatcher::Result
match (const Signature& a, const Signature& b, const py::kwargs& kwargs)
{
  CallParameters unused;
  pcl_flowseg::MatchParameters params;
  applyKwargs (kwargs, kMatchArguments, unused, params);
  pcl::SignatureMatcher matcher;
  matcher.setParameters (params);
  pcl::SignatureMatcher::Result result;
  {
    py::gil_scoped_release release;
    result = matcher.match (a, b);
  }
  raiseIfFailed (result.status);
  return result;
}

void
bindSignatureClass (py::module_& m)
{
  py::class_<Signature> (m, "Signature",
                         "A shape's significant interior features as weighted points, and its description by parts and "
                         "interior distributions; normalised for translation, rotation, mirroring and scale.")
      .def (py::init (&makeSignature), py::arg ("points"), py::arg ("weights"), py::arg ("dimension") = 3, py::arg ("unit") = 1.0,
            py::arg ("interior_volume") = 0.0, py::arg ("significance") = pcl_flowseg::kDefaultSignificance,
            "A signature from its weighted points (checked: weights in [0, 1], non-increasing, summing to 1; ...). "
            "It has no description: compare it with method='paper'.")
      .def_readonly ("dimension", &Signature::dimension)
      .def_property_readonly ("points", [] (const Signature& s) {
            std::vector<Eigen::Vector3d> rows;
            for (const auto& p : s.points)
              rows.push_back (p.position);
            return rowsToArray (rows);
          }, "(k, 3) positions, in the signature's unit, relative to the interior's centroid.")
      .def_property_readonly ("weights", [] (const Signature& s) {
            std::vector<double> w;
            for (const auto& p : s.points)
              w.push_back (p.weight);
            return py::array_t<double> (static_cast<py::ssize_t> (w.size ()), w.data ());
          }, "(k,) volume shares, decreasing, summing to 1.")
      .def_property_readonly ("parts", [] (const Signature& s) {
            const auto& parts = s.description.parts;
            py::array_t<double> out ({static_cast<py::ssize_t> (parts.size ()), static_cast<py::ssize_t> (6)});
            auto rows = out.mutable_unchecked<2> ();
            for (std::size_t i = 0; i < parts.size (); ++i)
            {
              const auto& p = parts[i];
              const double values[6] = {p.weight, p.thickness, p.extent, p.middle_ratio, p.smallest_ratio, p.remoteness};
              for (py::ssize_t k = 0; k < 6; ++k)
                rows (static_cast<py::ssize_t> (i), k) = values[k];
            }
            return out;
          }, "(k, 6) described parts, by decreasing weight: weight, thickness, extent, middle_ratio, smallest_ratio, "
             "remoteness (lengths in the signature's unit). Empty for signatures built from arrays.")
      .def_property_readonly ("distributions", [] (const Signature& s) {
            py::dict out;
            const auto& d = s.description;
            for (const auto& [name, bins] : {std::pair<const char*, const pcl_flowseg::Distribution*> ("thickness", &d.thickness),
                                             {"inner_distance", &d.inner_distance}, {"solid_distance", &d.solid_distance}})
              out[name] = py::array_t<double> (static_cast<py::ssize_t> (bins->size ()), bins->data ());
            py::array_t<double> profiles ({static_cast<py::ssize_t> (pcl_flowseg::kProfileRows), static_cast<py::ssize_t> (pcl_flowseg::kDistributionBins)});
            auto rows = profiles.mutable_unchecked<2> ();
            for (std::size_t r = 0; r < pcl_flowseg::kProfileRows; ++r)
              for (std::size_t b = 0; b < pcl_flowseg::kDistributionBins; ++b)
                rows (static_cast<py::ssize_t> (r), static_cast<py::ssize_t> (b)) = d.inner_profiles[r][b];
            out["inner_profiles"] = profiles;
            out["thickness_profile"] = py::array_t<double> (static_cast<py::ssize_t> (d.thickness_profile.size ()), d.thickness_profile.data ());
            py::array_t<float> contour ({static_cast<py::ssize_t> (d.contour.size ()), static_cast<py::ssize_t> (pcl_flowseg::kContourBins)});
            auto cells = contour.mutable_unchecked<2> ();
            for (std::size_t r = 0; r < d.contour.size (); ++r)
              for (std::size_t b = 0; b < pcl_flowseg::kContourBins; ++b)
                cells (static_cast<py::ssize_t> (r), static_cast<py::ssize_t> (b)) = d.contour[r][b];
            out["contour"] = contour;
            py::array_t<float> contexts ({static_cast<py::ssize_t> (d.inner_contexts.size ()), static_cast<py::ssize_t> (pcl_flowseg::kContextBins + 1)});
            auto context_rows = contexts.mutable_unchecked<2> ();
            for (std::size_t r = 0; r < d.inner_contexts.size (); ++r)
            {
              context_rows (static_cast<py::ssize_t> (r), 0) = d.inner_contexts[r].thickness;
              for (std::size_t b = 0; b < pcl_flowseg::kContextBins; ++b)
                context_rows (static_cast<py::ssize_t> (r), static_cast<py::ssize_t> (b + 1)) = d.inner_contexts[r].distances[b];
            }
            out["inner_contexts"] = contexts;
            return out;
          }, "The interior distributions (thickness, inner_distance, solid_distance), 32 bins each summing to 1, and "
             "inner_profiles, (16, 32): the inner distances from the most central to the most remote sources, each row summing to 1, "
             "thickness_profile, (16,): the mean log thickness over the unit from the most central to the most remote cells, "
             "and contour, (64, 60) in 2D and (0, 60) in 3D: the inner-distance shape context at 64 points along the outline "
             "(5 rings of log inner distance x 12 sectors of direction), each row summing to 1, "
             "and inner_contexts, (64, 17): per source of inner distances its log thickness over the unit, then its histogram "
             "of log inner distance over the shape's mean (16 bins summing to 1).")
      .def_readonly ("unit", &Signature::unit, "The length unit: interior volume^(1/d), input units.")
      .def_readonly ("interior_volume", &Signature::interior_volume)
      .def_readonly ("significance", &Signature::significance)
      .def_property_readonly (
          "single_view", [] (const Signature& s) { return s.views.single_view; },
          "True for a single-view scan's signature (computed with its viewpoint): queries align it with the stored "
          "shapes' views.")
      .def_property_readonly (
          "view_count", [] (const Signature& s) { return s.views.views.size (); },
          "Views the signature carries: rendered ones of a complete 3D shape, 1 for a scan, 0 in 2D.")
      .def ("without_views", [] (const Signature& s) {
            Signature copy = s;
            copy.views = pcl_flowseg::ViewSet ();
            return copy;
          },
          "A copy without its views, as flowseg_db --no-views stores shapes: about 20 KB per 3D shape in a database "
          "file in place of 270 KB; complete-shape queries score the same, single-view scans find it no more.")
      .def ("__len__", [] (const Signature& s) { return s.points.size (); })
      .def ("__repr__", [] (const Signature& s) {
        return "<Signature " + std::to_string (s.dimension) + "D, " + std::to_string (s.points.size ()) + " features>";
      });
}

void
bindMatchResult (py::module_& m)
{
  using Result = pcl::SignatureMatcher::Result;
  py::class_<Result> (m, "MatchResult", "The comparison of two signatures by match().")
      .def_readonly ("similarity", &Result::similarity,
                     "How similar, higher = more similar, 1 for identical signatures (what databases rank by). Description "
                     "methods: exp(-distance); paper: paper_score over the larger number of points.")
      .def_readonly ("distance", &Result::distance,
                     "Description methods: the distance between the descriptions (0 = identical); NaN for 'paper'.")
      .def_readonly ("paper_score", &Result::paper_score,
                     "'paper': the paper's raw score of the best alignment (higher = more similar); NaN for the other methods.")
      .def_property_readonly ("score", [] (const Result& r) {
            warnDeprecated ("MatchResult.score is deprecated: use distance (description methods) or paper_score ('paper')");
            return std::isnan (r.paper_score) ? r.distance : r.paper_score;
          }, "Deprecated: paper_score for 'paper', distance for the other methods.")
      .def_readonly ("linear", &Result::linear, "3x3 rotation (mirrored when its determinant is -1) mapping b onto a.")
      .def_readonly ("translation", &Result::translation)
      .def_readonly ("mirrored", &Result::mirrored)
      .def_readonly ("pairs", &Result::pairs, "Matched (index in a, index in b).")
      .def_readonly ("alignments", &Result::alignments, "Alignments scored.")
      .def ("__repr__", [] (const Result& r) { return "<MatchResult similarity=" + std::to_string (r.similarity) + ">"; });
}

} // namespace

void
bindSignature (py::module_& m)
{
  bindSignatureClass (m);
  bindMatchResult (m);
  m.def ("signature", &signatureOfArray, py::arg ("points"),
         "The signature of a point sample: segment() with the same keywords, then its significant interior features.");
  m.def ("signature_of_file", &signatureOfFile, py::arg ("path"),
         "The signature of a shape file (points, meshes sampled with mesh_points and seed, silhouette images), "
         "as flowseg_db computes it. Raises OSError when the file cannot be read or segmented.");
  m.def ("match", &match, py::arg ("a"), py::arg ("b"),
         "Compares two signatures; keywords method ('flowseg' default, 'paper', 'parts', 'thickness', 'inner', 'solid', 'inner-profile', 'thickness-profile', 'contour'), "
         "and for 'paper' threshold, allow_mirror, alignment_points (MatchParameters::paper). match(a, b) equals match(b, a) in similarity.");
}

} // namespace pcl_flowseg_python

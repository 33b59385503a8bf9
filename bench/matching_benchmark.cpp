/*
 * flowseg_bench_matching: how fast a signature database answers queries, and what picking
 * candidates by signature summary costs in retrieval quality.
 *
 * 1. Real signatures (the TOSCA point samples, when ../shared is there, or the shapes of --shapes DIR,
 *    2D silhouettes among them): leave-one-out retrieval
 *    (nearest neighbour, first tier) with every stored shape aligned and with the candidate index
 *    at several candidate counts, and the time per query.
 * 2. Databases of 1,000 to 100,000 signatures made from those (or from generated shapes) by random
 *    rotations, mirroring, position jitter, weight and description changes: the share of the exact
 *    top 10 (every stored shape compared) that the candidate index finds, per candidate count.
 * 3. Time per query with the default candidates, and with every shape compared where that
 *    finishes in reasonable time.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include <pcl_flowseg/evaluation/shape_generator.h>
#include <pcl_flowseg/segmentation/flow_pipeline.h>
#include <pcl_flowseg/io/shape_input.h>
#include <pcl_flowseg/signature/shape_signature.h>
#include <pcl_flowseg/signature/signature.h>
#include <pcl_flowseg/signature/signature_database.h>
#include <pcl_flowseg/signature/signature_matcher.h>

#include "signature/contour_matching.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <random>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;
using pcl_flowseg::Signature;

double
msSince (Clock::time_point t)
{
  return std::chrono::duration<double, std::milli> (Clock::now () - t).count ();
}

struct Labelled
{
  std::string label;
  Signature signature;
};

/** Signatures of the shapes in DIR/<class>/ files; empty when DIR is missing. */
std::vector<Labelled>
signaturesIn (const std::string& dir)
{
  std::vector<Labelled> out;
  if (!fs::is_directory (dir))
    return out;
  std::vector<fs::path> files;
  for (const auto& e : fs::recursive_directory_iterator (dir))
    if (e.is_regular_file () && pcl_flowseg::isShapeFile (e.path ().string ()))
      files.push_back (e.path ());
  std::sort (files.begin (), files.end ());
  for (const auto& f : files)
  {
    Labelled l;
    l.label = f.parent_path ().filename ().string ();
    const auto st = pcl_flowseg::signatureOfShapeFile (f.string (), pcl_flowseg::ShapeInputOptions (), pcl_flowseg::FlowParameters (),
                                                       pcl_flowseg::kDefaultSignificance, l.signature);
    if (!st)
    {
      std::fprintf (stderr, "skipped %s: %s\n", f.c_str (), st.message.c_str ());
      continue;
    }
    l.signature.views = pcl_flowseg::ViewSet (); // complete shapes compare by descriptions; 100,000 copies of views would take 15 GB
    out.push_back (l);
    std::fprintf (stderr, "\rsignatures: %zu/%zu", out.size (), files.size ());
  }
  std::fprintf (stderr, "\n");
  return out;
}

/** Signatures of the generated 3D shapes with their parts moved about: a stand-in collection. */
std::vector<Labelled>
generatedSignatures (std::size_t count)
{
  std::vector<Labelled> out;
  std::mt19937 rng (5);
  std::normal_distribution<double> jitter (0.0, 0.15);
  for (std::size_t k = 0; out.size () < count && k < 4 * count; ++k)
    for (auto shape : pcl_flowseg::sampleShapes ())
    {
      if (shape.dimension != 3 || out.size () >= count)
        continue;
      for (auto& part : shape.parts)
      {
        part.centre += Eigen::Vector3d (jitter (rng), jitter (rng), jitter (rng)) * part.radii.minCoeff ();
        part.radii *= 1.0 + jitter (rng);
      }
      pcl_flowseg::FlowParameters params;
      pcl_flowseg::FlowResult result;
      Labelled l;
      l.label = shape.name;
      if (pcl_flowseg::runFlowSegmentation (pcl_flowseg::sampleBoundary (shape, 3000, static_cast<std::uint32_t> (k + 1)), params, result) &&
          pcl_flowseg::signatureFromSegmentation (result, pcl_flowseg::kDefaultSignificance, l.signature))
        out.push_back (l);
    }
  return out;
}

/** Each entry of a float histogram moved by a factor 1 + \a gauss, then the histogram summed to 1. */
template <std::size_t N>
void
perturbFloats (std::array<float, N>& h, std::normal_distribution<double>& gauss, std::mt19937& rng)
{
  double sum = 0.0;
  for (float& v : h)
    sum += (v = static_cast<float> (std::max (0.0, v * (1.0 + gauss (rng)))));
  for (float& v : h)
    v = static_cast<float> (v / sum);
}

/** Changes a description as sampling the shape again would: part attributes and weights by up
  * to 10%, each distribution bin by Gaussian noise of 10% of its value (then renormalised). */
void
perturbDescription (pcl_flowseg::ShapeDescription& d, std::mt19937& rng)
{
  if (d.empty ())
    return;
  std::uniform_real_distribution<double> factor (0.9, 1.1);
  std::normal_distribution<double> gauss (0.0, 0.1);
  double total = 0.0;
  for (auto& p : d.parts)
  {
    for (double* v : {&p.weight, &p.thickness, &p.extent, &p.remoteness})
      *v *= factor (rng);
    p.middle_ratio = std::min (1.0, p.middle_ratio * factor (rng));
    p.smallest_ratio = std::min (1.0, p.smallest_ratio * factor (rng));
    total += p.weight;
  }
  for (auto& p : d.parts)
    p.weight /= total;
  std::stable_sort (d.parts.begin (), d.parts.end (), [] (const auto& a, const auto& b) { return a.weight > b.weight; });
  std::vector<pcl_flowseg::Distribution*> distributions{&d.thickness, &d.inner_distance, &d.solid_distance};
  for (pcl_flowseg::Distribution& row : d.inner_profiles)
    distributions.push_back (&row);
  for (pcl_flowseg::Distribution* h : distributions)
  {
    double sum = 0.0;
    for (double& v : *h)
      sum += (v = std::max (0.0, v * (1.0 + gauss (rng))));
    for (double& v : *h)
      v /= sum;
  }
  // A 2D contour starts elsewhere on the outline, and its bins change likewise.
  if (!d.contour.empty ())
    std::rotate (d.contour.begin (), d.contour.begin () + static_cast<std::ptrdiff_t> (rng () % d.contour.size ()), d.contour.end ());
  for (pcl_flowseg::ContourHistogram& h : d.contour)
    perturbFloats (h, gauss, rng);
  // The inner contexts come from other sources, in another order.
  std::shuffle (d.inner_contexts.begin (), d.inner_contexts.end (), rng);
  for (pcl_flowseg::InnerContext& c : d.inner_contexts)
  {
    perturbFloats (c.distances, gauss, rng);
    const double thickness = static_cast<double> (c.thickness) + gauss (rng);
    c.thickness = static_cast<float> (std::clamp (thickness, pcl_flowseg::kThicknessLogLow, pcl_flowseg::kThicknessLogHigh));
  }
}

/** A copy of \a s turned by a random rotation (mirrored half of the time), its points moved by
  * Gaussian jitter and its weights changed by up to 10%: the same shape, sampled again. */
Signature
variant (const Signature& s, std::mt19937& rng)
{
  std::normal_distribution<double> gauss (0.0, 1.0);
  std::uniform_real_distribution<double> unit (0.9, 1.1);
  Eigen::Quaterniond q (gauss (rng), gauss (rng), gauss (rng), gauss (rng));
  Eigen::Matrix3d r = q.normalized ().toRotationMatrix ();
  if (s.dimension == 2)
    r = Eigen::AngleAxisd (gauss (rng), Eigen::Vector3d::UnitZ ()).toRotationMatrix ();
  const bool mirror = rng () % 2;
  if (mirror)
    r.col (0) *= -1.0;
  Signature v = s;
  if (mirror)
    v.description.contour = pcl_flowseg::mirroredContour (v.description.contour);
  double total = 0.0;
  for (auto& p : v.points)
  {
    p.position = r * p.position + 0.03 * Eigen::Vector3d (gauss (rng), gauss (rng), s.dimension == 2 ? 0.0 : gauss (rng));
    p.weight *= unit (rng);
    total += p.weight;
  }
  for (auto& p : v.points)
    p.weight /= total;
  std::stable_sort (v.points.begin (), v.points.end (), [] (const auto& a, const auto& b) { return a.weight > b.weight; });
  perturbDescription (v.description, rng);
  return v;
}

/** Leave-one-out retrieval over \a shapes with the given candidate count. */
void
retrieval (const std::vector<Labelled>& shapes, std::size_t candidates, const pcl::SignatureMatcher& matcher)
{
  pcl_flowseg::SignatureDatabase db;
  db.setCandidates (candidates);
  std::map<std::string, int> class_size;
  for (std::size_t i = 0; i < shapes.size (); ++i)
  {
    db.add (pcl_flowseg::ShapeEntry{std::to_string (i), shapes[i].label, shapes[i].signature});
    ++class_size[shapes[i].label];
  }
  double nn = 0.0, ft = 0.0, ms = 0.0;
  for (std::size_t i = 0; i < shapes.size (); ++i)
  {
    const auto start = Clock::now ();
    auto hits = db.query (shapes[i].signature, 0, matcher);
    ms += msSince (start);
    hits.erase (std::remove_if (hits.begin (), hits.end (), [&] (const auto& h) { return h.entry == i; }), hits.end ());
    const int tier = class_size[shapes[i].label] - 1;
    if (tier <= 0 || hits.empty ())
      continue;
    nn += db.entries ()[hits[0].entry].label == shapes[i].label;
    int same = 0;
    for (int r = 0; r < tier && r < static_cast<int> (hits.size ()); ++r)
      same += db.entries ()[hits[static_cast<std::size_t> (r)].entry].label == shapes[i].label;
    ft += static_cast<double> (same) / tier;
  }
  const double n = static_cast<double> (shapes.size ());
  std::printf ("| %s | %zu | %.3f | %.3f | %.3f |\n", candidates ? std::to_string (candidates).c_str () : "all", shapes.size (), nn / n,
               ft / n, ms / n);
}

/** Mean time per query against \a size stored variants of \a base, with \a candidates. */
double
queryTime (const std::vector<Labelled>& base, std::size_t size, std::size_t candidates, int queries,
           const pcl::SignatureMatcher& matcher, double& build_ms)
{
  std::mt19937 rng (11);
  pcl_flowseg::SignatureDatabase db;
  for (std::size_t i = 0; i < size; ++i)
    db.add (pcl_flowseg::ShapeEntry{"shape" + std::to_string (i), base[i % base.size ()].label, variant (base[i % base.size ()].signature, rng)});
  db.setCandidates (candidates);
  auto start = Clock::now ();
  db.query (base[0].signature, 1, matcher); // builds the candidate index
  build_ms = msSince (start);
  start = Clock::now ();
  for (int q = 0; q < queries; ++q)
    db.query (variant (base[static_cast<std::size_t> (q) % base.size ()].signature, rng), 10, matcher);
  return msSince (start) / queries;
}

/** A database of \a size variants of \a base (the first copy of each base shape unchanged). */
pcl_flowseg::SignatureDatabase
variantDatabase (const std::vector<Labelled>& base, std::size_t size, std::mt19937& rng)
{
  pcl_flowseg::SignatureDatabase db;
  for (std::size_t i = 0; i < size; ++i)
  {
    const Labelled& b = base[i % base.size ()];
    db.add (pcl_flowseg::ShapeEntry{"shape" + std::to_string (i), b.label, i < base.size () ? b.signature : variant (b.signature, rng)});
  }
  return db;
}

/** Share of the exact top 10 (every stored shape compared) that the candidate index finds, and
  * the time per query, against \a size stored variants of \a base. */
void
candidateRecall (const std::vector<Labelled>& base, std::size_t size, std::size_t candidates, int queries,
                 const pcl::SignatureMatcher& matcher)
{
  std::mt19937 rng (13);
  pcl_flowseg::SignatureDatabase db = variantDatabase (base, size, rng);
  db.query (base[0].signature, 1, matcher, candidates); // builds the candidate index
  double found = 0.0, ms = 0.0;
  for (int q = 0; q < queries; ++q)
  {
    const Signature query = variant (base[static_cast<std::size_t> (q) % base.size ()].signature, rng);
    const auto start = Clock::now ();
    const auto fast = db.query (query, 10, matcher, candidates);
    ms += msSince (start);
    const auto exact = db.query (query, 10, matcher, 0);
    for (const auto& e : exact)
      found += std::any_of (fast.begin (), fast.end (), [&] (const pcl_flowseg::QueryHit& h) { return h.entry == e.entry; }) ? 0.1 : 0.0;
  }
  std::printf ("| %zu | %zu | %.3f | %.3f | %d |\n", size, candidates, found / queries, ms / queries, queries);
  std::fflush (stdout);
}

} // namespace

int
main (int argc, char** argv)
{
  std::string dir = "../shared/data/tosca_points";
  pcl::SignatureMatcher matcher;
  for (int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    pcl_flowseg::MatchMethod method;
    if (a == "--shapes" && i + 1 < argc)
      dir = argv[++i];
    else if (a == "--method" && i + 1 < argc && pcl_flowseg::parseMatchMethod (argv[i + 1], method))
    {
      matcher.setMethod (method);
      ++i;
    }
    else
    {
      std::fprintf (stderr, "usage: flowseg_bench_matching [--shapes DIR (../shared/data/tosca_points; class = folder)]\n"
                            "                              [--method M (flowseg, paper, parts, thickness, inner, solid, inner-profile, thickness-profile, contour, inner-context; default flowseg)]\n");
      return 2;
    }
  }
  std::printf ("method %s\n", pcl_flowseg::matchMethodName (matcher.getMethod ()));
  std::vector<Labelled> base = signaturesIn (dir);
  std::string source = dir;
  if (base.empty ())
  {
    std::fprintf (stderr, "flowseg_bench_matching: no shapes in %s, using generated shapes\n", dir.c_str ());
    base = generatedSignatures (60);
    source = "generated shapes (animal3d, dumbbell3d, snowman3d with moved parts)";
  }
  if (base.empty ())
  {
    std::fprintf (stderr, "flowseg_bench_matching: no signatures\n");
    return 1;
  }
  double mean_points = 0.0;
  for (const auto& b : base)
    mean_points += static_cast<double> (b.signature.points.size ()) / static_cast<double> (base.size ());
  std::printf ("signatures of %s: %zu, %.1f points each on average\n\n", source.c_str (), base.size (), mean_points);

  std::printf ("Leave-one-out retrieval (a query ranks every other shape)\n\n");
  std::printf ("| candidates aligned | shapes | nearest neighbour | first tier | ms per query |\n|---|---|---|---|---|\n");
  for (std::size_t c : {std::size_t (0), std::size_t (8), std::size_t (16), std::size_t (24), std::size_t (32)})
    retrieval (base, c, matcher);

  std::printf ("\nCandidate index: share of the exact top 10 found, against databases of re-sampled copies\n\n");
  std::printf ("| stored signatures | candidates compared | exact top 10 found | ms per query | queries |\n|---|---|---|---|---|\n");
  struct Recall { std::size_t size, candidates; int queries; };
  for (const Recall& r : {Recall{1000, 24, 50}, Recall{1000, 200, 50}, Recall{10000, 200, 20}, Recall{10000, 1000, 20},
                          Recall{100000, 200, 20}, Recall{100000, 1000, 20}})
    candidateRecall (base, r.size, r.candidates, r.queries, matcher);

  std::printf ("\nQueries (top 10) against databases of randomly rotated, mirrored and jittered copies\n\n");
  std::printf ("| stored signatures | candidates aligned | ms per query | queries per second | index build ms |\n|---|---|---|---|---|\n");
  struct Run { std::size_t size, candidates; int queries; };
  for (const Run& run : {Run{300, 0, 20}, Run{300, pcl_flowseg::kDefaultCandidates, 200}, Run{100000, pcl_flowseg::kDefaultCandidates, 200},
                         Run{100000, 0, 2}})
  {
    double build = 0.0;
    const double ms = queryTime (base, run.size, run.candidates, run.queries, matcher, build);
    std::printf ("| %zu | %s | %.3f | %.0f | %.1f |\n", run.size, run.candidates ? std::to_string (run.candidates).c_str () : "all", ms,
                 1000.0 / ms, build);
    std::fflush (stdout);
  }
  return 0;
}

/*
 * flowseg_bench_single_view: single-view queries against databases of growing size, timed, and how
 * often their candidates hold the exact top 10.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include <pcl_flowseg/io/shape_input.h>
#include <pcl_flowseg/signature/shape_signature.h>
#include <pcl_flowseg/signature/signature_database.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <vector>

using namespace pcl_flowseg;

namespace {

/** A stored shape as another shape of its kind might look: its views' and surface points moved by
  * \a jitter (view units; input units times the view's scale for the surface), its histograms' bins
  * by 10% noise. */
ShapeEntry
perturbedCopy (const ShapeEntry& e, std::size_t copy, double jitter, std::mt19937& rng)
{
  ShapeEntry c = e;
  c.name = "copy" + std::to_string (copy) + "/" + e.name;
  std::normal_distribution<float> noise (0.0f, static_cast<float> (jitter));
  std::uniform_real_distribution<float> factor (0.9f, 1.1f);
  float scale = 0.0f;
  for (ViewDescription& v : c.signature.views.views)
  {
    for (auto& p : v.points)
      p += Eigen::Vector3f (noise (rng), noise (rng), noise (rng));
    float sum = 0.0f;
    for (float& b : v.histogram)
      sum += (b *= factor (rng));
    for (float& b : v.histogram)
      b *= 2.0f / sum;
    scale = std::max (scale, v.scale);
  }
  for (auto& p : c.signature.views.shape_points)
    p += scale * Eigen::Vector3f (noise (rng), noise (rng), noise (rng));
  return c;
}

double
msSince (std::chrono::steady_clock::time_point t0)
{
  return std::chrono::duration<double, std::milli> (std::chrono::steady_clock::now () - t0).count ();
}

std::vector<std::size_t>
parseCounts (const std::string& text)
{
  std::vector<std::size_t> counts;
  std::stringstream in (text);
  for (std::string item; std::getline (in, item, ',');)
    counts.push_back (std::stoul (item));
  return counts;
}

/** Share of \a exact's first 10 names that \a fast's first 10 hold. */
double
topTenFound (const std::vector<QueryHit>& exact, const std::vector<QueryHit>& fast)
{
  std::set<std::string> wanted;
  for (std::size_t r = 0; r < std::min<std::size_t> (10, exact.size ()); ++r)
    wanted.insert (exact[r].name);
  std::size_t found = 0;
  for (std::size_t r = 0; r < std::min<std::size_t> (10, fast.size ()); ++r)
    found += wanted.count (fast[r].name);
  return wanted.empty () ? 1.0 : static_cast<double> (found) / static_cast<double> (wanted.size ());
}

} // namespace

int
main (int argc, char** argv)
{
  if (argc < 3)
  {
    std::fprintf (stderr, "usage: flowseg_bench_single_view DB SCANS [STORED,... (default 200,2000,10000)] [QUERIES (default 20)]\n"
                          "  DB: a flowseg_db database of complete shapes; SCANS: single-view scans (PCD with VIEWPOINT).\n"
                          "  Databases of each size hold DB's shapes and perturbed copies of them. Prints per size the\n"
                          "  time of a query (default view candidates, all cores) and, from up to 5 queries, how often\n"
                          "  its top 10 holds the exact top 10 (every stored shape aligned).\n");
    return 2;
  }
  SignatureDatabase source;
  if (const Status s = source.load (argv[1]); !s)
    return std::fprintf (stderr, "%s\n", s.message.c_str ()), 1;
  const std::vector<std::size_t> sizes = parseCounts (argc > 3 ? argv[3] : "200,2000,10000");
  const std::size_t wanted_queries = argc > 4 ? std::stoul (argv[4]) : 20;
  std::vector<std::string> files;
  if (const Status s = listShapeFiles (argv[2], files); !s || files.empty ())
    return std::fprintf (stderr, "no scans below %s\n", argv[2]), 1;
  ShapeInputOptions input;
  input.use_sensor_origin = true;
  std::vector<Signature> queries;
  for (std::size_t i = 0; i < files.size () && queries.size () < wanted_queries; i += std::max<std::size_t> (1, files.size () / wanted_queries))
  {
    Signature s;
    if (signatureOfShapeFile (std::string (argv[2]) + "/" + files[i], input, FlowParameters (), kDefaultSignificance, s))
      queries.push_back (s);
  }
  const pcl::SignatureMatcher matcher;
  std::printf ("stored\tview candidates\tms per query\texact top 10 found\tqueries checked\n");
  for (std::size_t stored : sizes)
  {
    SignatureDatabase db;
    std::mt19937 rng (7);
    const std::vector<ShapeEntry>& originals = source.entries ();
    for (std::size_t i = 0; i < stored; ++i)
      db.add (i < originals.size () ? originals[i] : perturbedCopy (originals[i % originals.size ()], i / originals.size (), 0.05, rng));
    double ms = 0.0;
    for (const Signature& q : queries)
    {
      const auto t0 = std::chrono::steady_clock::now ();
      db.query (q, 10, matcher);
      ms += msSince (t0);
    }
    double found = 0.0;
    const std::size_t checked = std::min<std::size_t> (queries.size (), 5);
    for (std::size_t k = 0; k < checked; ++k)
      found += topTenFound (db.query (queries[k], 10, matcher, 0), db.query (queries[k], 10, matcher));
    std::printf ("%zu\t%zu\t%.1f\t%.3f\t%zu\n", stored, db.getViewCandidates (), ms / static_cast<double> (queries.size ()),
                 checked ? found / static_cast<double> (checked) : 0.0, checked);
    std::fflush (stdout);
  }
  return 0;
}

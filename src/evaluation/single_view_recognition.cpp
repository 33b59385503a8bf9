/*
 * pcl_flowseg evaluation - single-view recognition: the models described once, each query described
 * and compared with every model by every method, the rankings scored.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include <pcl_flowseg/evaluation/single_view_recognition.h>

#include <pcl_flowseg/common/parallel_jobs.h>
#include <pcl_flowseg/evaluation/query_models.h>
#include <pcl_flowseg/evaluation/rendered_views.h>
#include <pcl_flowseg/evaluation/shape_distributions.h>
#include <pcl_flowseg/signature/view_sphere.h>
#include <pcl_flowseg/io/mesh_io.h>
#include <pcl_flowseg/io/shape_input.h>
#include <pcl_flowseg/segmentation/flow_pipeline.h>
#include <pcl_flowseg/signature/signature.h>
#include <pcl_flowseg/signature/signature_database.h>
#include <pcl_flowseg/signature/signature_matcher.h>

#include <algorithm>
#include <array>
#include <ctime>
#include <limits>
#include <map>
#include <optional>

namespace pcl_flowseg {

namespace {

/** The CPU time of the calling thread, in ms: what describing and comparing cost, whatever else
  * shares the cores (every job runs on one thread). */
double
threadMs ()
{
  timespec t{};
  clock_gettime (CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double> (t.tv_sec) * 1e3 + static_cast<double> (t.tv_nsec) * 1e-6;
}

double
msSince (double start)
{
  return threadMs () - start;
}

/** The descriptions of a model or query, by what describes them (RecognitionMethodKind). */
enum DescriptionKind : std::size_t { kSignatureKind = 0, kEsfKind = 1, kViewsKind = 2 };

std::size_t
kindIndex (RecognitionMethodKind kind)
{
  return kind == RecognitionMethodKind::kSignature ? kSignatureKind : kind == RecognitionMethodKind::kEsf ? kEsfKind : kViewsKind;
}

/** What the methods know of the models, and what they cost. */
struct ModelDatabase
{
  std::array<bool, 3> needed{{false, false, false}}; ///< by DescriptionKind
  std::vector<std::string> labels, errors;
  std::vector<Signature> signatures;
  std::vector<std::vector<double>> esf;
  std::vector<std::vector<std::vector<double>>> views;
  std::vector<std::array<double, 3>> ms;   ///< per model, by DescriptionKind
  std::vector<char> renderable;             ///< a mesh (esf-views can render it)
  /** The signatures as a database: single-view queries go through its candidates, as
    * flowseg_db query does. */
  SignatureDatabase signature_db;
  std::vector<Eigen::Vector3d> directions; ///< of the rendered views
};

/** The signature of \a points, segmented with \a params. */
Status
signatureOfPoints (const std::vector<Eigen::Vector3d>& points, const FlowParameters& params, double significance,
                   Signature& signature)
{
  FlowResult r;
  Status s = runFlowSegmentation (points, params, r);
  if (s)
    s = signatureFromSegmentation (r, significance, signature);
  return s;
}

/** The ESF of each view of the model at \a path, or renderable = false when it is no mesh. */
Status
describeViews (const std::string& path, const std::vector<Eigen::Vector3d>& directions, char& renderable,
               std::vector<std::vector<double>>& views)
{
  const std::string ext = path.substr (path.rfind ('.') == std::string::npos ? path.size () : path.rfind ('.') + 1);
  std::string lower = ext;
  std::transform (lower.begin (), lower.end (), lower.begin (), [] (unsigned char c) { return static_cast<char> (std::tolower (c)); });
  renderable = lower == "off" || lower == "obj" || lower == "ply";
  if (!renderable)
    return Status::success ();
  TriangleMesh mesh;
  if (const Status m = loadTriangleMesh (path, mesh); !m)
  {
    renderable = false;
    return lower == "ply" ? Status::success () : m; // a PLY without faces is a point sample
  }
  return esfOfProtocolViews (mesh, directions, views);
}

/** Reads model \a i and describes it as the methods need. */
void
describeModel (const ShapeCollection& models, const SingleViewRecognitionParameters& params, std::size_t i, ModelDatabase& db)
{
  const std::string path = models.root + "/" + models.files[i];
  db.labels[i] = shapeLabel (models.files[i]);
  ShapeInputOptions input = params.signature.input;
  input.use_sensor_origin = false; // complete models, seen from nowhere
  std::vector<Eigen::Vector3d> points;
  Status s = loadShapeSample (path, input, points);
  if (s && db.needed[kSignatureKind])
  {
    const double t0 = threadMs ();
    FlowParameters flow = params.flow;
    flow.interior.viewpoint.reset ();
    flow.execution.threads = 1; // the jobs share the cores; the thread's CPU time is the cost
    s = signatureOfPoints (points, flow, params.signature.significance, db.signatures[i]);
    db.ms[i][kSignatureKind] = msSince (t0);
  }
  if (s && db.needed[kEsfKind])
  {
    const double t0 = threadMs ();
    s = esfDescriptor (points, db.esf[i]);
    db.ms[i][kEsfKind] = msSince (t0);
  }
  if (s && db.needed[kViewsKind])
  {
    const double t0 = threadMs ();
    s = describeViews (path, db.directions, db.renderable[i], db.views[i]);
    db.ms[i][kViewsKind] = msSince (t0);
  }
  if (!s)
    db.errors[i] = s.message.find (path) == std::string::npos ? path + ": " + s.message : s.message;
}

/** Describes every model in parallel; fails with the first model's error. */
Status
describeModels (const ShapeCollection& models, const SingleViewRecognitionParameters& params, ModelDatabase& db,
                const RecognitionProgress& progress)
{
  const std::size_t n = models.files.size ();
  db.labels.assign (n, std::string ());
  db.errors.assign (n, std::string ());
  db.signatures.assign (n, Signature ());
  db.esf.assign (n, {});
  db.views.assign (n, {});
  db.ms.assign (n, {{0.0, 0.0, 0.0}});
  db.renderable.assign (n, 1);
  if (db.needed[kViewsKind])
    if (const Status s = viewSphereDirections (params.views, db.directions); !s)
      return s;
  runParallelJobs (
      n, params.threads, [&] (std::size_t i) { describeModel (models, params, i, db); },
      [&] (std::size_t done, std::size_t) {
        if (progress)
          progress ("describing models", done, n);
      });
  for (const auto& e : db.errors)
    if (!e.empty ())
      return Status::error (e);
  if (db.needed[kSignatureKind])
    for (std::size_t i = 0; i < n; ++i)
      db.signature_db.add (ShapeEntry{models.files[i], db.labels[i], db.signatures[i]});
  db.signature_db.setQueryThreads (1); // queries run side by side
  return Status::success ();
}

/** Why each method cannot run on these models, or "": esf-views on point samples, contour
  * without 2D models. */
std::vector<std::string>
skippedMethods (const std::vector<RecognitionMethod>& methods, const ShapeCollection& models, const ModelDatabase& db)
{
  std::vector<std::string> skipped (methods.size ());
  const auto point_sample = std::find (db.renderable.begin (), db.renderable.end (), 0);
  const bool planar = std::any_of (db.signatures.begin (), db.signatures.end (), [] (const Signature& s) { return s.dimension == 2; });
  for (std::size_t m = 0; m < methods.size (); ++m)
  {
    if (methods[m].kind == RecognitionMethodKind::kEsfViews && point_sample != db.renderable.end ())
      skipped[m] = "it renders views of meshes, and the model " +
                   models.files[static_cast<std::size_t> (point_sample - db.renderable.begin ())] +
                   " is a point sample, which cannot be rendered";
    if (methods[m].kind == RecognitionMethodKind::kSignature && methods[m].match == MatchMethod::Contour && !planar)
      skipped[m] = "it compares the outlines of 2D shapes, and no model is 2D";
  }
  return skipped;
}

/** One query against every model by every method that runs. */
struct QueryRows
{
  std::vector<std::vector<double>> similarity; ///< per method, one entry per model
  std::vector<double> ms;                      ///< per method: describing the query and comparing it
  std::string error;
};

/** What a query is compared by: the methods that run, with their matchers. */
struct QueryPlan
{
  std::vector<RecognitionMethod> methods;
  std::vector<std::string> skipped;             ///< per method
  std::vector<pcl::SignatureMatcher> matchers;  ///< per method (signature methods)
  std::array<bool, 3> needed{{false, false, false}}; ///< by DescriptionKind, of the methods that run
};

/** The query's descriptions (those \a plan needs) and what each took. */
struct QueryDescription
{
  Signature signature;
  std::vector<double> esf;
  std::array<double, 3> ms{{0.0, 0.0, 0.0}}; ///< by DescriptionKind; the ESF serves both ESF methods
};

Status
describeQuery (const std::string& path, const QueryPlan& plan, const SingleViewRecognitionParameters& params,
               QueryDescription& d)
{
  std::vector<Eigen::Vector3d> points;
  std::optional<Eigen::Vector3d> origin;
  Status s = loadShapeSample (path, params.signature.input, points, &origin);
  if (s && plan.needed[kSignatureKind])
  {
    const double t0 = threadMs ();
    FlowParameters flow = params.flow;
    if (params.signature.input.use_sensor_origin)
      flow.interior.viewpoint = origin; // this scan's own
    flow.execution.threads = 1; // the jobs share the cores; the thread's CPU time is the cost
    s = signatureOfPoints (points, flow, params.signature.significance, d.signature);
    d.ms[kSignatureKind] = msSince (t0);
  }
  if (s && (plan.needed[kEsfKind] || plan.needed[kViewsKind]))
  {
    const double t0 = threadMs ();
    s = esfDescriptor (points, d.esf);
    d.ms[kEsfKind] = d.ms[kViewsKind] = msSince (t0);
  }
  return s;
}

/** The similarity of \a query to every model as the database ranks them: the candidates it
  * compared by their similarity, the others after them, by their summary distance. */
std::vector<double>
databaseSimilarities (const Signature& query, const pcl::SignatureMatcher& matcher, const ModelDatabase& db)
{
  std::vector<double> row (db.labels.size (), -std::numeric_limits<double>::infinity ());
  for (const QueryHit& hit : db.signature_db.query (query, 0, matcher))
    row[hit.entry] = hit.compared ? hit.similarity : -1.0 - hit.summary_distance;
  return row;
}

/** Describes query \a q and compares it with every model by every method that runs. */
void
compareQuery (const std::string& path, const QueryPlan& plan, const ModelDatabase& db,
              const SingleViewRecognitionParameters& params, QueryRows& out)
{
  const std::size_t n = db.labels.size ();
  out.similarity.assign (plan.methods.size (), {});
  out.ms.assign (plan.methods.size (), 0.0);
  QueryDescription d;
  if (const Status s = describeQuery (path, plan, params, d); !s)
  {
    out.error = s.message.find (path) == std::string::npos ? path + ": " + s.message : s.message;
    return;
  }
  for (std::size_t m = 0; m < plan.methods.size (); ++m)
  {
    if (!plan.skipped[m].empty ())
      continue;
    const double t0 = threadMs ();
    std::vector<double>& row = out.similarity[m];
    row.resize (n);
    const RecognitionMethodKind kind = plan.methods[m].kind;
    if (kind == RecognitionMethodKind::kSignature && d.signature.views.single_view)
    {
      row = databaseSimilarities (d.signature, plan.matchers[m], db);
      out.ms[m] = d.ms[kindIndex (kind)] + msSince (t0);
      continue;
    }
    for (std::size_t j = 0; j < n; ++j)
      row[j] = kind == RecognitionMethodKind::kSignature ? plan.matchers[m].match (d.signature, db.signatures[j]).similarity
               : kind == RecognitionMethodKind::kEsf     ? histogramSimilarity (d.esf, db.esf[j])
                                                         : bestViewSimilarity (d.esf, db.views[j]);
    out.ms[m] = d.ms[kindIndex (kind)] + msSince (t0);
  }
}

/** The plan of the methods that run on \a db. */
QueryPlan
planQueries (const std::vector<RecognitionMethod>& methods, const ShapeCollection& models, const ModelDatabase& db,
             const MatchParameters& match)
{
  QueryPlan plan;
  plan.methods = methods;
  plan.skipped = skippedMethods (methods, models, db);
  plan.matchers.resize (methods.size ());
  for (std::size_t m = 0; m < methods.size (); ++m)
  {
    plan.matchers[m].setParameters (match);
    plan.matchers[m].setMethod (methods[m].match);
    if (plan.skipped[m].empty ())
      plan.needed[kindIndex (methods[m].kind)] = true;
  }
  return plan;
}

/** Scores method \a m over the queries' rows. */
Status
scoreMethod (std::size_t m, const QueryPlan& plan, const ModelDatabase& db, const std::vector<QueryRows>& rows,
             const std::vector<std::size_t>& model_of_query, MethodRecognition& r)
{
  r = MethodRecognition ();
  r.name = plan.methods[m].name;
  r.skipped = plan.skipped[m];
  if (!r.skipped.empty ())
    return Status::success ();
  std::vector<std::vector<double>> similarity (rows.size ());
  std::map<std::string, std::pair<double, std::size_t>> class_ms;
  for (std::size_t q = 0; q < rows.size (); ++q)
  {
    similarity[q] = rows[q].similarity[m];
    r.query_ms += rows[q].ms[m] / static_cast<double> (rows.size ());
    auto& c = class_ms[db.labels[model_of_query[q]]];
    c.first += rows[q].ms[m];
    ++c.second;
  }
  const std::size_t kind = kindIndex (plan.methods[m].kind);
  for (const auto& ms : db.ms)
    r.model_ms += ms[kind] / static_cast<double> (db.ms.size ());
  if (const Status s = scoreRecognition (similarity, model_of_query, db.labels, r.scores, r.per_class); !s)
    return s;
  r.similarity = std::move (similarity);
  for (const auto& c : r.per_class)
    r.class_query_ms.push_back (class_ms[c.label].first / static_cast<double> (class_ms[c.label].second));
  return Status::success ();
}

} // namespace

Status
evaluateSingleViewRecognition (const ShapeCollection& models, const ShapeCollection& queries,
                               const std::vector<RecognitionMethod>& methods, const SingleViewRecognitionParameters& params,
                               std::vector<MethodRecognition>& results, const RecognitionProgress& progress)
{
  results.clear ();
  std::vector<std::size_t> model_of_query;
  if (const Status s = modelsOfQueries (models.files, queries.files, model_of_query); !s)
    return s;
  if (params.signature.input.use_sensor_origin && params.flow.interior.viewpoint)
    return Status::error ("a viewpoint and the files' sensor origins exclude each other");
  ModelDatabase db;
  for (const auto& m : methods)
    db.needed[kindIndex (m.kind)] = true;
  if (const Status s = describeModels (models, params, db, progress); !s)
    return s;
  const QueryPlan plan = planQueries (methods, models, db, params.match);
  const std::size_t n = queries.files.size ();
  std::vector<QueryRows> rows (n);
  runParallelJobs (
      n, params.threads,
      [&] (std::size_t q) { compareQuery (queries.root + "/" + queries.files[q], plan, db, params, rows[q]); },
      [&] (std::size_t done, std::size_t) {
        if (progress)
          progress ("recognising queries", done, n);
      });
  for (const auto& r : rows)
    if (!r.error.empty ())
      return Status::error (r.error);
  results.resize (methods.size ());
  for (std::size_t m = 0; m < methods.size (); ++m)
    if (const Status s = scoreMethod (m, plan, db, rows, model_of_query, results[m]); !s)
      return s;
  return Status::success ();
}

} // namespace pcl_flowseg

/*
 * pcl_flowseg evaluation - single-view recognition: queries (scans of the models, say) against a
 * database of complete models, scored for category and instance by every method side by side.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include <pcl_flowseg/common/flow_parameters.h>
#include <pcl_flowseg/common/status.h>
#include <pcl_flowseg/evaluation/recognition_method.h>
#include <pcl_flowseg/evaluation/recognition_scores.h>
#include <pcl_flowseg/signature/match_parameters.h>
#include <pcl_flowseg/signature/signature_parameters.h>

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace pcl_flowseg {

/** \brief Shape files: a root folder and the files' paths relative to it (listShapeFiles). */
struct ShapeCollection
{
  std::string root;
  std::vector<std::string> files;
};

/** \brief How the models and the queries are described and compared. */
struct SingleViewRecognitionParameters
{
  /** Segmentation of models and queries. The models, complete shapes, are segmented without a
    * viewpoint; flow.interior.viewpoint, when set, is every query's. */
  FlowParameters flow;
  /** signature.input.mesh_points and seed sample the models that are meshes;
    * signature.input.use_sensor_origin: each query's viewpoint is its file's sensor origin. */
  SignatureParameters signature;
  MatchParameters match; ///< how signatures are compared (the method is each RecognitionMethod's)
  std::size_t views = 42; ///< views rendered per model for esf-views (viewSphereDirections)
  /** 0 = all cores: so many models, then queries, are described at once, each on one thread (the
    * segmentation's own threads are not used, flow.execution.threads is ignored). */
  unsigned threads = 0;
};

/** \brief One method's recognition over the queries. */
struct MethodRecognition
{
  std::string name;
  std::string skipped; ///< why the method was not evaluated, or "" (then the rest is filled in)
  RecognitionScores scores;
  std::vector<ClassRecognitionScores> per_class;
  /** Mean cost per query, in ms of CPU time of the one thread that does it: describing the query
    * and comparing it with every model (reading the file not included). */
  double query_ms = 0.0;
  std::vector<double> class_query_ms; ///< the same per class, in the order of per_class
  double model_ms = 0.0;              ///< mean CPU time to describe one model for the database
  /** Per query, its similarity to every model (higher = more similar), in the models' order. */
  std::vector<std::vector<double>> similarity;
};

/** \brief Told the stage ("describing models", "recognising queries"), jobs done and their number. */
using RecognitionProgress = std::function<void (const std::string& stage, std::size_t done, std::size_t total)>;

/** \brief Every query of \a queries against every model of \a models, query q's own model being
  * the one at its relative path without extension (modelsOfQueries); the class of a model is its
  * folder's name (shapeLabel). For each of \a methods, in their order, scoreRecognition's scores
  * and the times into \a results. A method that cannot run on these inputs is reported skipped:
  * esf-views when a model is not a mesh (a point sample cannot be rendered), contour when no model
  * is 2D. Fails, naming the file, when a query has no model or a shape cannot be read or described. */
Status
evaluateSingleViewRecognition (const ShapeCollection& models, const ShapeCollection& queries,
                               const std::vector<RecognitionMethod>& methods, const SingleViewRecognitionParameters& params,
                               std::vector<MethodRecognition>& results, const RecognitionProgress& progress = {});

} // namespace pcl_flowseg

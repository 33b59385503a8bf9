/*
 * pcl_flowseg evaluation - the figure of single-view recognition: scans, their parts, their best
 * matches.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include <pcl_flowseg/evaluation/single_view_figure.h>

#include <pcl_flowseg/evaluation/retrieval_figures.h>
#include <pcl_flowseg/io/shape_input.h>
#include <pcl_flowseg/segmentation/flow_pipeline.h>

#include <algorithm>
#include <numeric>
#include <set>

namespace pcl_flowseg {

namespace {

/** Points drawn per model: enough to see its shape. */
constexpr std::size_t kDrawnModelPoints = 3000;

/** The first query of each class, at most \a rows of them. */
std::vector<std::size_t>
firstOfEachClass (const ShapeCollection& queries, std::size_t rows)
{
  std::vector<std::size_t> chosen;
  std::set<std::string> seen;
  for (std::size_t q = 0; q < queries.files.size () && chosen.size () < rows; ++q)
    if (seen.insert (shapeLabel (queries.files[q])).second)
      chosen.push_back (q);
  return chosen;
}

/** The scan at \a path and each point's feature, segmented as seen from its viewpoint. */
Status
segmentedScan (const std::string& path, const SingleViewRecognitionParameters& params, std::vector<Eigen::Vector3d>& points,
               std::vector<std::uint32_t>& labels)
{
  std::optional<Eigen::Vector3d> origin;
  Status s = loadShapeSample (path, params.signature.input, points, &origin);
  FlowParameters flow = params.flow;
  if (params.signature.input.use_sensor_origin)
    flow.interior.viewpoint = origin;
  FlowResult result;
  if (s)
    s = runFlowSegmentation (points, flow, result);
  labels = result.point_labels;
  return s;
}

} // namespace

Status
writeSingleViewFigure (const std::string& path, const ShapeCollection& models, const ShapeCollection& queries,
                       const SingleViewRecognitionParameters& params, const MethodRecognition& result, std::size_t rows, int k)
{
  if (result.similarity.size () != queries.files.size ())
    return Status::error ("cannot write " + path + ": the method has no similarities of the queries");
  const std::vector<std::size_t> chosen = firstOfEachClass (queries, rows);
  std::vector<std::vector<Eigen::Vector3d>> scans (chosen.size ()), drawn (models.files.size ());
  std::vector<std::vector<std::uint32_t>> labels (chosen.size ());
  std::vector<std::string> scan_classes, model_classes;
  std::vector<std::vector<double>> similarity;
  ShapeInputOptions model_input = params.signature.input;
  model_input.use_sensor_origin = false;
  model_input.mesh_points = kDrawnModelPoints;
  for (std::size_t row = 0; row < chosen.size (); ++row)
  {
    const std::size_t q = chosen[row];
    if (const Status s = segmentedScan (queries.root + "/" + queries.files[q], params, scans[row], labels[row]); !s)
      return s;
    scan_classes.push_back (shapeLabel (queries.files[q]));
    similarity.push_back (result.similarity[q]);
    std::vector<std::size_t> order (models.files.size ());
    std::iota (order.begin (), order.end (), 0);
    std::stable_sort (order.begin (), order.end (),
                      [&] (std::size_t a, std::size_t b) { return result.similarity[q][a] > result.similarity[q][b]; });
    for (std::size_t r = 0; r < std::min<std::size_t> (static_cast<std::size_t> (k), order.size ()); ++r)
      if (drawn[order[r]].empty ())
        if (const Status s = loadShapeSample (models.root + "/" + models.files[order[r]], model_input, drawn[order[r]]); !s)
          return s;
  }
  for (const auto& f : models.files)
    model_classes.push_back (shapeLabel (f));
  return writeSingleViewMatchesPng (path, scans, labels, scan_classes, drawn, model_classes, similarity, k);
}

} // namespace pcl_flowseg

/*
 * pcl_flowseg - the signature of a shape file: read (or sample), segment, keep the significant features.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include <pcl_flowseg/signature/shape_signature.h>

#include <pcl_flowseg/common/parallel_jobs.h>
#include <pcl_flowseg/io/shape_input.h>
#include <pcl_flowseg/segmentation/flow_pipeline.h>
#include <pcl_flowseg/signature/view_description.h>

#include <pcl/console/print.h>

namespace pcl_flowseg {

Status
signatureOfShapeFile (const std::string& path, const ShapeInputOptions& input, const FlowParameters& params,
                      double significance, Signature& signature)
{
  std::vector<Eigen::Vector3d> points;
  std::optional<Eigen::Vector3d> origin;
  FlowResult result;
  Status s = input.use_sensor_origin && params.interior.viewpoint
                 ? Status::error ("a viewpoint and the file's sensor origin exclude each other")
                 : loadShapeSample (path, input, points, &origin);
  // Each file's own viewpoint: a collection of scans has as many as it has files.
  FlowParameters own = params;
  if (input.use_sensor_origin)
    own.interior.viewpoint = origin;
  if (s.ok && !own.interior.viewpoint && origin && looksLikeSingleView (points, *origin))
    PCL_WARN ("[pcl_flowseg] %s looks like a single view seen from its sensor origin (%g, %g, %g): single-view "
              "matching needs that viewpoint (flowseg apps: --use-sensor-origin or --viewpoint; Python: "
              "use_sensor_origin=True); without it the file is matched as a complete shape, which ranks single views "
              "poorly\n",
              path.c_str (), origin->x (), origin->y (), origin->z ());
  if (s.ok)
    s = runFlowSegmentation (points, own, result);
  if (s.ok)
    s = signatureFromSegmentation (result, significance, signature);
  if (!s.ok && s.message.find (path) == std::string::npos)
    s.message = path + ": " + s.message;
  return s;
}

void
signaturesOfShapeFiles (const std::vector<std::string>& paths, const ShapeInputOptions& input, const FlowParameters& params,
                        double significance, unsigned threads, std::vector<Signature>& signatures,
                        std::vector<Status>& statuses,
                        const std::function<void (std::size_t, const std::string&, const Status&)>& progress)
{
  FlowParameters per_job = params;
  per_job.execution.threads = threadsPerJob (paths.size (), threads);
  signatures.assign (paths.size (), Signature ());
  statuses.assign (paths.size (), Status::success ());
  runParallelJobs (
      paths.size (), threads,
      [&] (std::size_t i) { statuses[i] = signatureOfShapeFile (paths[i], input, per_job, significance, signatures[i]); },
      [&] (std::size_t done, std::size_t i) {
        if (progress)
          progress (done, paths[i], statuses[i]);
      });
}

} // namespace pcl_flowseg

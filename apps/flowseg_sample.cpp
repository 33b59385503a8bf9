/*
 * flowseg_sample: area-uniform point samples of a triangle mesh or a virtual range scan of it, with
 * optional noise and outliers, or the boundary of a silhouette image.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include "common/options.h"

#include <pcl_flowseg/common/flow_parameters.h>
#include <pcl_flowseg/io/mesh_io.h>
#include <pcl_flowseg/io/point_cloud_writer.h>
#include <pcl_flowseg/io/range_scan.h>
#include <pcl_flowseg/io/sample_outliers.h>
#include <pcl_flowseg/io/scan_protocol.h>
#include <pcl_flowseg/io/silhouette.h>

#include <iostream>
#include <optional>
#include <string>
#include <vector>

namespace {

struct Options
{
  std::string output;
  std::size_t points = 10000;
  double noise = 0.0;
  double outliers = 0.0;
  std::optional<Eigen::Vector3d> scan_from;
  bool scan_random = false;
  double scan_distance = 2.0;
  std::size_t scan_pixels = 0;
  double scan_fov = 0.0;
  pcl_flowseg::DepthNoiseModel noise_model = pcl_flowseg::DepthNoiseModel::kGrowsWithSquaredRange;
  std::uint32_t seed = 1;
  bool binary = false, quiet = false;
};

/** The boundary of the silhouette in an image; \a what describes it. */
pcl_flowseg::Status
silhouettePoints (const std::string& input, std::vector<Eigen::Vector3d>& pts, std::string& what)
{
  pcl_flowseg::GreyImage image;
  if (const pcl_flowseg::Status s = pcl_flowseg::loadGreyImage (input, image); !s)
    return s;
  pts = pcl_flowseg::silhouetteBoundary (image);
  if (pts.empty ())
    return pcl_flowseg::Status::error (input + ": the image holds no silhouette");
  what = "the silhouette boundary of a " + std::to_string (image.width) + "x" + std::to_string (image.height) + " image";
  return pcl_flowseg::Status::success ();
}

/** The scan options beyond --scan-from. */
void
declareScanOptions (flowseg_app::OptionParser& p, Options& o)
{
  using pcl_flowseg::DepthNoiseModel;
  p.flag ("--scan-random",
          "scan the mesh from a direction drawn uniformly on the sphere from --seed (which also draws the noise: "
          "another --noise keeps the rays), --scan-distance diagonals from the bounding-box centre (the library's "
          "protocolViewpoint)",
          o.scan_random);
  p.number ("--scan-distance", "D",
            "distance of the --scan-random viewpoint from the bounding-box centre, in bounding-box diagonals, more than 0.5",
            o.scan_distance, [] (double v) {
              return v > 0.5 && v <= 1e6 ? pcl_flowseg::Status::success () : pcl_flowseg::Status::error ("must lie in (0.5, 10^6]");
            });
  p.count ("--scan-pixels", "N",
           "scan with a camera of N x N pixels whose every pixel's ray returns its first hit (at most N^2 points; "
           "--points is ignored); 0: the image is chosen to give --points points",
           o.scan_pixels, 0, static_cast<long long> (pcl_flowseg::kMaxScanImagePixels));
  p.number ("--scan-fov", "DEG",
            "the scan's field of view in degrees, in (0, 180), horizontal and vertical alike, around the line to the "
            "bounding-box centre; 0: the image just covers the mesh's bounding sphere",
            o.scan_fov, [] (double v) {
              return v >= 0 && v < 180 ? pcl_flowseg::Status::success () : pcl_flowseg::Status::error ("must lie in [0, 180)");
            });
  p.choice ("--depth-noise-model", "M",
            "how a scan's depth noise (--noise) depends on the range: range (as --noise says) or constant (--noise "
            "along every ray)",
            o.noise_model, {{"range", DepthNoiseModel::kGrowsWithSquaredRange}, {"constant", DepthNoiseModel::kConstant}});
  p.action ("--single-view-protocol",
            "the single-view protocol: --scan-random --scan-distance 2 --scan-pixels 240 --scan-fov 50 "
            "--depth-noise-model constant, one view by a 240 x 240-pixel camera with a 50-degree field of view two "
            "diagonals from the centre in a random direction; options after it change those values; the depth noise "
            "is --noise (0.005 for the noisy scans)",
            [&o] () {
              o.scan_random = true;
              o.scan_distance = 2.0;
              o.scan_pixels = 240;
              o.scan_fov = 50.0;
              o.noise_model = DepthNoiseModel::kConstant;
            });
}

/** Why the scan options do not fit together, or "". */
std::string
scanOptionsConflict (const Options& o)
{
  if (o.scan_from && o.scan_random)
    return "--scan-from and --scan-random (or --single-view-protocol) exclude each other";
  if (o.scan_from && o.scan_distance != 2.0)
    return "--scan-distance applies to --scan-random only";
  if (!o.scan_from && !o.scan_random &&
      (o.scan_pixels != 0 || o.scan_fov != 0.0 || o.scan_distance != 2.0 ||
       o.noise_model != pcl_flowseg::DepthNoiseModel::kGrowsWithSquaredRange))
    return "--scan-pixels, --scan-fov, --scan-distance and --depth-noise-model need a scan: add --scan-from or --scan-random";
  return "";
}

/** What a scan with \a scan of \a mesh is, for the report. */
std::string
scanDescription (const pcl_flowseg::TriangleMesh& mesh, const pcl_flowseg::RangeScanOptions& scan, bool random)
{
  std::string what = "a scan of " + std::to_string (mesh.faces.size ()) + " faces";
  if (random)
    what += " from " + std::to_string (scan.viewpoint.x ()) + "," + std::to_string (scan.viewpoint.y ()) + "," +
            std::to_string (scan.viewpoint.z ());
  if (scan.image_pixels > 0)
    what += ", " + std::to_string (scan.image_pixels) + " x " + std::to_string (scan.image_pixels) + " pixels";
  if (scan.field_of_view > 0.0)
    what += ", field of view " + flowseg_app::defaultText (scan.field_of_view) + " degrees";
  const bool constant = scan.noise_model == pcl_flowseg::DepthNoiseModel::kConstant;
  return what + ", depth noise sigma " + std::to_string (scan.depth_noise * mesh.diagonal ()) +
         (constant ? " along each ray" : " at the centre's range");
}

/** Points sampled on a mesh's faces; \a what describes them, \a sensor is the viewpoint of a scan. */
pcl_flowseg::Status
meshPoints (const std::string& input, const Options& o, std::vector<Eigen::Vector3d>& pts, std::string& what,
            std::optional<Eigen::Vector3d>& sensor)
{
  pcl_flowseg::TriangleMesh mesh;
  if (const pcl_flowseg::Status s = pcl_flowseg::loadTriangleMesh (input, mesh); !s)
    return s;
  const double sigma = o.noise * mesh.diagonal ();
  if (!o.scan_from && !o.scan_random)
  {
    pts = pcl_flowseg::sampleMeshSurface (mesh, o.points, sigma, o.seed);
    what = std::to_string (mesh.faces.size ()) + " faces, noise sigma " + std::to_string (sigma);
    return pcl_flowseg::Status::success ();
  }
  pcl_flowseg::RangeScanOptions scan;
  scan.viewpoint = o.scan_from ? *o.scan_from : pcl_flowseg::protocolViewpoint (mesh, o.scan_distance, o.seed);
  scan.points = o.points;
  scan.depth_noise = o.noise;
  scan.noise_model = o.noise_model;
  scan.image_pixels = o.scan_pixels;
  scan.field_of_view = o.scan_fov;
  scan.seed = o.seed;
  what = scanDescription (mesh, scan, o.scan_random);
  sensor = scan.viewpoint;
  return pcl_flowseg::scanMesh (mesh, scan, pts);
}

} // namespace

int
main (int argc, char** argv)
{
  Options o;
  flowseg_app::OptionParser p ("flowseg_sample", "flowseg_sample INPUT -o OUTPUT.pcd [options]",
                               "Samples points area-uniformly on the faces of a triangle mesh (.off, .obj, .ply), or scans it\n"
                               "from a viewpoint (--scan-from, --scan-random, --single-view-protocol: the points a range\n"
                               "sensor there sees, the viewpoint written as the PCD VIEWPOINT), or takes the boundary of the\n"
                               "silhouette in a binary image (.png, .bmp, .pgm: the pixel-edge midpoints between the shape\n"
                               "and the background, in pixel units, z = 0; --points, --noise and the scan options do not\n"
                               "apply).");
  p.text ("-o, --output", "FILE", "output point cloud (.pcd), required", o.output);
  p.count ("-n, --points", "N", "number of points", o.points, 1, 100000000);
  const auto share = [] (double v) {
    return v >= 0 && v <= 1 ? pcl_flowseg::Status::success () : pcl_flowseg::Status::error ("must lie in [0, 1]");
  };
  p.number ("--noise", "F",
            "Gaussian noise, standard deviation as a share of the bounding-box\ndiagonal (0.005 = 0.5%); in a scan along "
            "the rays, at the range of\nthe centre, growing with the squared range (or the same along every\nray: "
            "--depth-noise-model constant)",
            o.noise, share);
  p.number ("--outliers", "F", "share of the points replaced by points uniform in their bounding box", o.outliers, share);
  p.point ("--scan-from", "scan the mesh from this viewpoint (mesh units, outside the mesh's\nbounding sphere)", o.scan_from);
  declareScanOptions (p, o);
  p.count ("--seed", "S", "random seed", o.seed, 0, 4294967295LL);
  p.flag ("--binary", "binary PCD (default ASCII)", o.binary);
  unsigned threads = 0;
  p.count ("-j, --threads", "N", "accepted as every app accepts it; sampling and scanning one mesh run on one thread",
           threads, 0, pcl_flowseg::kMaxThreads);
  p.flag ("-q, --quiet", "no summary on stderr", o.quiet);
  p.epilogue ("Exit status: 0 success, 1 unreadable input or unwritable output, 2 bad options.");
  std::vector<std::string> inputs;
  if (const int status = p.parse (argc, argv, inputs); status != flowseg_app::kContinue)
    return status;
  if (inputs.size () != 1 || o.output.empty ())
    return p.usageError (inputs.size () > 1 ? "more than one input" : "need an INPUT and --output FILE");
  if (const std::string conflict = scanOptionsConflict (o); !conflict.empty ())
    return p.usageError (conflict);
  std::vector<Eigen::Vector3d> pts;
  std::string what;
  std::optional<Eigen::Vector3d> sensor;
  const pcl_flowseg::Status read = pcl_flowseg::isSilhouetteFile (inputs[0]) ? silhouettePoints (inputs[0], pts, what)
                                                                            : meshPoints (inputs[0], o, pts, what, sensor);
  if (!read)
    return p.failure (read.message);
  if (o.outliers > 0.0)
    what += ", " + std::to_string (pcl_flowseg::replaceWithOutliers (pts, o.outliers, o.seed + 1)) + " points replaced by outliers";
  pcl::PointCloud<pcl::PointXYZ> cloud;
  if (sensor)
    cloud.sensor_origin_ = Eigen::Vector4f (static_cast<float> (sensor->x ()), static_cast<float> (sensor->y ()),
                                            static_cast<float> (sensor->z ()), 0.0f);
  for (const auto& q : pts)
    cloud.push_back (pcl::PointXYZ (static_cast<float> (q.x ()), static_cast<float> (q.y ()), static_cast<float> (q.z ())));
  if (const pcl_flowseg::Status s = pcl_flowseg::writePointCloud (o.output, cloud, o.binary); !s)
    return p.failure (s.message);
  if (!o.quiet)
    std::cerr << "wrote " << o.output << ": " << pts.size () << " points from " << what << "\n";
  return flowseg_app::kExitSuccess;
}

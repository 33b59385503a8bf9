/*
 * flowseg_sample: area-uniform point samples of a triangle mesh or a virtual range scan of it, with
 * optional noise and outliers, or the boundary of a silhouette image.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include "common/options.h"

#include <pcl_flowseg/io/mesh_io.h>
#include <pcl_flowseg/io/point_cloud_writer.h>
#include <pcl_flowseg/io/range_scan.h>
#include <pcl_flowseg/io/sample_outliers.h>
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

/** Points sampled on a mesh's faces; \a what describes them. */
pcl_flowseg::Status
meshPoints (const std::string& input, const Options& o, std::vector<Eigen::Vector3d>& pts, std::string& what)
{
  pcl_flowseg::TriangleMesh mesh;
  if (const pcl_flowseg::Status s = pcl_flowseg::loadTriangleMesh (input, mesh); !s)
    return s;
  const double sigma = o.noise * mesh.diagonal ();
  if (!o.scan_from)
  {
    pts = pcl_flowseg::sampleMeshSurface (mesh, o.points, sigma, o.seed);
    what = std::to_string (mesh.faces.size ()) + " faces, noise sigma " + std::to_string (sigma);
    return pcl_flowseg::Status::success ();
  }
  pcl_flowseg::RangeScanOptions scan;
  scan.viewpoint = *o.scan_from;
  scan.points = o.points;
  scan.depth_noise = o.noise;
  scan.seed = o.seed;
  what = "a scan of " + std::to_string (mesh.faces.size ()) + " faces, depth noise sigma " + std::to_string (sigma) +
         " at the centre's range";
  return pcl_flowseg::scanMesh (mesh, scan, pts);
}

} // namespace

int
main (int argc, char** argv)
{
  Options o;
  flowseg_app::OptionParser p ("flowseg_sample", "flowseg_sample INPUT -o OUTPUT.pcd [options]",
                               "Samples points area-uniformly on the faces of a triangle mesh (.off, .obj, .ply), or scans it\n"
                               "from a viewpoint (--scan-from: the points a range sensor there sees, the viewpoint written as\n"
                               "the PCD VIEWPOINT), or takes the boundary of the silhouette in a binary image (.png, .bmp,\n"
                               ".pgm: the pixel-edge midpoints between the shape and the background, in pixel units, z = 0;\n"
                               "--points, --noise and --scan-from do not apply).");
  p.text ("-o, --output", "FILE", "output point cloud (.pcd), required", o.output);
  p.count ("-n, --points", "N", "number of points", o.points, 1, 100000000);
  const auto share = [] (double v) {
    return v >= 0 && v <= 1 ? pcl_flowseg::Status::success () : pcl_flowseg::Status::error ("must lie in [0, 1]");
  };
  p.number ("--noise", "F",
            "Gaussian noise, standard deviation as a share of the bounding-box\ndiagonal (0.005 = 0.5%); in a scan along "
            "the rays, at the range of\nthe centre, growing with the squared range",
            o.noise, share);
  p.number ("--outliers", "F", "share of the points replaced by points uniform in their bounding box", o.outliers, share);
  p.point ("--scan-from", "scan the mesh from this viewpoint (mesh units, outside the mesh's\nbounding sphere)", o.scan_from);
  p.count ("--seed", "S", "random seed", o.seed, 0, 4294967295LL);
  p.flag ("--binary", "binary PCD (default ASCII)", o.binary);
  p.flag ("-q, --quiet", "no summary on stderr", o.quiet);
  p.epilogue ("Exit status: 0 success, 1 unreadable input or unwritable output, 2 bad options.");
  std::vector<std::string> inputs;
  if (const int status = p.parse (argc, argv, inputs); status != flowseg_app::kContinue)
    return status;
  if (inputs.size () != 1 || o.output.empty ())
    return p.usageError (inputs.size () > 1 ? "more than one input" : "need an INPUT and --output FILE");
  std::vector<Eigen::Vector3d> pts;
  std::string what;
  const pcl_flowseg::Status read = pcl_flowseg::isSilhouetteFile (inputs[0]) ? silhouettePoints (inputs[0], pts, what)
                                                                            : meshPoints (inputs[0], o, pts, what);
  if (!read)
    return p.failure (read.message);
  if (o.outliers > 0.0)
    what += ", " + std::to_string (pcl_flowseg::replaceWithOutliers (pts, o.outliers, o.seed + 1)) + " points replaced by outliers";
  pcl::PointCloud<pcl::PointXYZ> cloud;
  if (o.scan_from)
    cloud.sensor_origin_ = Eigen::Vector4f (static_cast<float> (o.scan_from->x ()), static_cast<float> (o.scan_from->y ()),
                                            static_cast<float> (o.scan_from->z ()), 0.0f);
  for (const auto& q : pts)
    cloud.push_back (pcl::PointXYZ (static_cast<float> (q.x ()), static_cast<float> (q.y ()), static_cast<float> (q.z ())));
  if (const pcl_flowseg::Status s = pcl_flowseg::writePointCloud (o.output, cloud, o.binary); !s)
    return p.failure (s.message);
  if (!o.quiet)
    std::cerr << "wrote " << o.output << ": " << pts.size () << " points from " << what << "\n";
  return flowseg_app::kExitSuccess;
}

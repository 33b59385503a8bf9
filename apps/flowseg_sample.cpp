/*
 * flowseg_sample: area-uniform point samples of a triangle mesh, with optional Gaussian noise, or the
 * boundary of a silhouette image.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include "common/options.h"

#include <pcl_flowseg/io/mesh_io.h>
#include <pcl_flowseg/io/point_cloud_writer.h>
#include <pcl_flowseg/io/silhouette.h>

#include <iostream>
#include <string>
#include <vector>

namespace {

struct Options
{
  std::string output;
  std::size_t points = 10000;
  double noise = 0.0;
  std::uint32_t seed = 1;
  bool binary = false;
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
  pts = pcl_flowseg::sampleMeshSurface (mesh, o.points, sigma, o.seed);
  what = std::to_string (mesh.faces.size ()) + " faces, noise sigma " + std::to_string (sigma);
  return pcl_flowseg::Status::success ();
}

} // namespace

int
main (int argc, char** argv)
{
  Options o;
  flowseg_app::OptionParser p ("flowseg_sample", "flowseg_sample INPUT -o OUTPUT.pcd [options]",
                               "Samples points area-uniformly on the faces of a triangle mesh (.off, .obj, .ply), or takes the\n"
                               "boundary of the silhouette in a binary image (.png, .bmp, .pgm: the pixel-edge midpoints between\n"
                               "the shape and the background, in pixel units, z = 0; --points, --noise and --seed do not apply).");
  p.text ("-o, --output", "FILE", "output point cloud (.pcd), required", o.output);
  p.count ("-n, --points", "N", "number of points", o.points, 1, 100000000);
  p.number ("--noise", "F", "Gaussian noise, standard deviation as a share of the bounding-box\ndiagonal (0.005 = 0.5%)", o.noise,
            [] (double v) {
              return v >= 0 && v <= 1 ? pcl_flowseg::Status::success () : pcl_flowseg::Status::error ("must lie in [0, 1]");
            });
  p.count ("--seed", "S", "random seed", o.seed, 0, 4294967295LL);
  p.flag ("--binary", "binary PCD (default ASCII)", o.binary);
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
  pcl::PointCloud<pcl::PointXYZ> cloud;
  for (const auto& q : pts)
    cloud.push_back (pcl::PointXYZ (static_cast<float> (q.x ()), static_cast<float> (q.y ()), static_cast<float> (q.z ())));
  if (const pcl_flowseg::Status s = pcl_flowseg::writePointCloud (o.output, cloud, o.binary); !s)
    return p.failure (s.message);
  std::cerr << "wrote " << o.output << ": " << pts.size () << " points from " << what << "\n";
  return flowseg_app::kExitSuccess;
}

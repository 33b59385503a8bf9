/*
 * flowseg_sample: area-uniform point samples of a triangle mesh, with optional Gaussian noise.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include "app_common.h"

#include <pcl_flowseg/io/mesh_io.h>
#include <pcl_flowseg/io/point_cloud_writer.h>
#include <pcl_flowseg/io/silhouette.h>

#include <cmath>
#include <cstdlib>
#include <iostream>
#include <string>

namespace {
void
printHelp ()
{
  std::cout << R"(Usage: flowseg_sample INPUT -o OUTPUT.pcd [options]

Samples points area-uniformly on the faces of a triangle mesh (.off, .obj, .ply), or takes the
boundary of the silhouette in a binary image (.png, .bmp, .pgm: the pixel-edge midpoints between
the shape and the background, in pixel units, z = 0; --points, --noise and --seed do not apply).

Options:
  -o, --output FILE   output point cloud (.pcd), required
  -n, --points N      number of points (default 10000)
      --noise F       Gaussian noise, standard deviation as a fraction of the bounding-box
                      diagonal (default 0; 0.005 = 0.5%)
      --seed S        random seed (default 1)
      --binary        binary PCD (default ASCII)
  -h, --help          this help
)";
}

int
usageError (const std::string& message)
{
  return flowseg_app::usageError ("flowseg_sample", message);
}
} // namespace

int
main (int argc, char** argv)
{
  std::string input, output;
  unsigned long count = 10000, seed = 1;
  double noise = 0.0;
  bool binary = false;
  for (int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    const char* next = i + 1 < argc ? argv[i + 1] : nullptr;
    char* end = nullptr;
    if (a == "-h" || a == "--help")
    {
      printHelp ();
      return 0;
    }
    else if ((a == "-o" || a == "--output") && next)
      output = argv[++i];
    else if ((a == "-n" || a == "--points") && next)
    {
      count = std::strtoul (next, &end, 10);
      if (*end || next[0] == '-' || count < 1 || count > 100000000)
        return usageError ("--points needs a whole number from 1 to 100000000, got '" + std::string (next) + "'");
      ++i;
    }
    else if (a == "--noise" && next)
    {
      noise = std::strtod (next, &end);
      if (*end || !std::isfinite (noise) || noise < 0 || noise > 1)
        return usageError ("--noise needs a number from 0 to 1, got '" + std::string (next) + "'");
      ++i;
    }
    else if (a == "--seed" && next)
    {
      seed = std::strtoul (next, &end, 10);
      if (*end || next[0] == '-')
        return usageError ("--seed needs a whole number >= 0");
      ++i;
    }
    else if (a == "--binary")
      binary = true;
    else if (!a.empty () && a[0] == '-')
      return usageError ("unknown or incomplete option '" + a + "'");
    else if (input.empty ())
      input = a;
    else
      return usageError ("more than one input");
  }
  if (input.empty () || output.empty ())
    return usageError ("need an INPUT and --output FILE");
  std::vector<Eigen::Vector3d> pts;
  std::string what;
  if (pcl_flowseg::isSilhouetteFile (input))
  {
    pcl_flowseg::GreyImage image;
    const auto loaded = pcl_flowseg::loadGreyImage (input, image);
    if (!loaded)
    {
      std::cerr << "flowseg_sample: " << loaded.message << "\n";
      return 1;
    }
    pts = pcl_flowseg::silhouetteBoundary (image);
    if (pts.empty ())
    {
      std::cerr << "flowseg_sample: " << input << ": the image holds no silhouette\n";
      return 1;
    }
    what = "the silhouette boundary of a " + std::to_string (image.width) + "x" + std::to_string (image.height) + " image";
  }
  else
  {
    pcl_flowseg::TriangleMesh mesh;
    const auto loaded = pcl_flowseg::loadTriangleMesh (input, mesh);
    if (!loaded)
    {
      std::cerr << "flowseg_sample: " << loaded.message << "\n";
      return 1;
    }
    const double sigma = noise * mesh.diagonal ();
    pts = pcl_flowseg::sampleMeshSurface (mesh, count, sigma, static_cast<std::uint32_t> (seed));
    what = std::to_string (mesh.faces.size ()) + " faces, noise sigma " + std::to_string (sigma);
  }
  pcl::PointCloud<pcl::PointXYZ> cloud;
  for (const auto& p : pts)
    cloud.push_back (pcl::PointXYZ (static_cast<float> (p.x ()), static_cast<float> (p.y ()), static_cast<float> (p.z ())));
  const auto st = pcl_flowseg::writePointCloud (output, cloud, binary);
  if (!st)
  {
    std::cerr << "flowseg_sample: " << st.message << "\n";
    return 1;
  }
  std::cerr << "wrote " << output << ": " << pts.size () << " points from " << what << "\n";
  return 0;
}

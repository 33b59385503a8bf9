/*
 * flowseg_make_samples: writes the procedural sample shapes (known parts) as PCD files.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include "common/flow_options.h"
#include "common/options.h"

#include <pcl_flowseg/common/parallel_jobs.h>
#include <pcl_flowseg/evaluation/shape_generator.h>
#include <pcl_flowseg/io/point_cloud_writer.h>

#include <cerrno>
#include <cstring>
#include <iostream>
#include <string>
#include <sys/stat.h>
#include <vector>

int
main (int argc, char** argv)
{
  std::string dir = "samples";
  std::size_t points2d = pcl_flowseg::kSamplePoints2D, points3d = pcl_flowseg::kSamplePoints3D;
  std::uint32_t seed = 1;
  bool quiet = false;
  unsigned threads = 0;
  flowseg_app::OptionParser p ("flowseg_make_samples", "flowseg_make_samples [options]",
                               "Writes point samples of the procedural shapes (unions of ellipses / ellipsoids with known\n"
                               "parts) as ASCII PCD files: dumbbell2d, star2d, hand2d, dumbbell3d, snowman3d, animal3d.");
  p.text ("-o, --output", "DIR", "folder to write into", dir);
  p.count ("--points2d", "N", "points per 2D shape", points2d, 3, 10000000);
  p.count ("--points3d", "N", "points per 3D shape", points3d, 4, 10000000);
  p.count ("--seed", "S", "random seed", seed, 0, 4294967295LL);
  flowseg_app::addThreadsOption (p, threads);
  p.flag ("-q, --quiet", "do not list the files written on stderr", quiet);
  std::vector<std::string> extra;
  if (const int status = p.parse (argc, argv, extra); status != flowseg_app::kContinue)
    return status;
  if (!extra.empty ())
    return p.usageError ("unexpected argument '" + extra[0] + "'");
  if (mkdir (dir.c_str (), 0755) != 0 && errno != EEXIST)
    return p.failure ("cannot create " + dir + ": " + std::strerror (errno));
  // Each shape on its own thread; the files and the messages are the same for every thread count.
  const auto& shapes = pcl_flowseg::sampleShapes ();
  std::vector<std::string> failures (shapes.size ()), written (shapes.size ());
  pcl_flowseg::runParallelJobs (shapes.size (), threads, [&] (std::size_t k) {
    const auto& shape = shapes[k];
    const std::size_t n = shape.dimension == 2 ? points2d : points3d;
    const auto points = pcl_flowseg::sampleBoundary (shape, n, seed);
    if (points.size () != n)
    {
      failures[k] = "could only place " + std::to_string (points.size ()) + " of " + std::to_string (n) + " points on " + shape.name;
      return;
    }
    pcl::PointCloud<pcl::PointXYZ> cloud;
    for (const auto& q : points)
      cloud.push_back (pcl::PointXYZ (static_cast<float> (q.x ()), static_cast<float> (q.y ()), static_cast<float> (q.z ())));
    const std::string path = dir + "/" + shape.name + ".pcd";
    if (const pcl_flowseg::Status s = pcl_flowseg::writePointCloud (path, cloud, false); !s)
      failures[k] = s.message;
    written[k] = "wrote " + path + " (" + std::to_string (n) + " points, " + std::to_string (shape.parts.size ()) + " parts)";
  });
  for (std::size_t k = 0; k < shapes.size (); ++k)
  {
    if (!failures[k].empty ())
      return p.failure (failures[k]);
    if (!quiet)
      std::cerr << written[k] << "\n";
  }
  return flowseg_app::kExitSuccess;
}

/*
 * flowseg_make_samples: writes the procedural sample shapes (known parts) as PCD files.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include <pcl_flowseg/io/point_cloud_writer.h>
#include <pcl_flowseg/evaluation/shape_generator.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <sys/stat.h>
#include <iostream>
#include <string>

namespace {
void
printHelp ()
{
  std::cout << R"(Usage: flowseg_make_samples [options]

Writes point samples of the procedural shapes (unions of ellipses / ellipsoids with known
parts) as ASCII PCD files: dumbbell2d, star2d, hand2d, dumbbell3d, snowman3d, animal3d.

Options:
  -o, --output DIR     folder to write into (default: samples)
      --points2d N     points per 2D shape (default 1500)
      --points3d N     points per 3D shape (default 4000)
      --seed S         random seed (default 1)
  -h, --help           this help
)";
}

bool
parseCount (const char* text, unsigned long& value)
{
  char* end = nullptr;
  value = std::strtoul (text, &end, 10);
  return *text && *end == '\0' && text[0] != '-';
}
} // namespace

int
main (int argc, char** argv)
{
  std::string dir = "samples";
  unsigned long n2 = 1500, n3 = 4000, seed = 1;
  for (int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    const bool has_value = i + 1 < argc;
    if (arg == "-h" || arg == "--help")
    {
      printHelp ();
      return 0;
    }
    else if ((arg == "-o" || arg == "--output") && has_value)
      dir = argv[++i];
    else if (arg == "--points2d" && has_value && parseCount (argv[i + 1], n2) && n2 >= 3 && n2 <= 10000000)
      ++i;
    else if (arg == "--points3d" && has_value && parseCount (argv[i + 1], n3) && n3 >= 4 && n3 <= 10000000)
      ++i;
    else if (arg == "--seed" && has_value && parseCount (argv[i + 1], seed))
      ++i;
    else
    {
      std::cerr << "flowseg_make_samples: bad or incomplete option '" << arg << "' (see --help)\n";
      return 2;
    }
  }
  if (mkdir (dir.c_str (), 0755) != 0 && errno != EEXIST)
  {
    std::cerr << "flowseg_make_samples: cannot create " << dir << ": " << std::strerror (errno) << "\n";
    return 1;
  }
  for (const auto& shape : pcl_flowseg::sampleShapes ())
  {
    const std::size_t n = shape.dimension == 2 ? n2 : n3;
    const auto points = pcl_flowseg::sampleBoundary (shape, n, static_cast<std::uint32_t> (seed));
    if (points.size () != n)
    {
      std::cerr << "flowseg_make_samples: could only place " << points.size () << " of " << n << " points on "
                << shape.name << "\n";
      return 1;
    }
    pcl::PointCloud<pcl::PointXYZ> cloud;
    for (const auto& p : points)
      cloud.push_back (pcl::PointXYZ (static_cast<float> (p.x ()), static_cast<float> (p.y ()), static_cast<float> (p.z ())));
    const std::string path = dir + "/" + shape.name + ".pcd";
    const auto st = pcl_flowseg::writePointCloud (path, cloud, false);
    if (!st)
    {
      std::cerr << "flowseg_make_samples: " << st.message << "\n";
      return 1;
    }
    std::cerr << "wrote " << path << " (" << n << " points, " << shape.parts.size () << " parts)\n";
  }
  return 0;
}

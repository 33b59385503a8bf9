/*
 * PCL's I/O and filters are loaded only when a run needs them: reading the formats the library
 * reads itself maps neither pcl_io nor the plugin; reading a PLY opens the plugin and works.
 * A program of its own: the main test program links pcl_io directly.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include <pcl_flowseg/io/point_io.h>

#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <string>
#include <unistd.h>

namespace {

/** Whether a library whose file name contains \a name is mapped into this process. */
bool
isMapped (const std::string& name)
{
  std::ifstream maps ("/proc/self/maps");
  std::string line;
  while (std::getline (maps, line))
    if (line.find (name) != std::string::npos)
      return true;
  return false;
}

const float kPoints[4][3] = {{0.f, 0.f, 0.f}, {1.f, 0.f, 0.f}, {0.f, 1.f, 0.f}, {0.f, 0.f, 1.5f}};

std::string
writeBinaryPcd ()
{
  const std::string path = "/tmp/flowseg_lazy_" + std::to_string (getpid ()) + ".pcd";
  std::ofstream out (path, std::ios::binary);
  out << "VERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\nWIDTH 4\nHEIGHT 1\n"
         "VIEWPOINT 0 0 0 1 0 0 0\nPOINTS 4\nDATA binary\n";
  out.write (reinterpret_cast<const char*> (kPoints), sizeof (kPoints));
  return path;
}

std::string
writeAsciiPly ()
{
  const std::string path = "/tmp/flowseg_lazy_" + std::to_string (getpid ()) + ".ply";
  std::ofstream out (path);
  out << "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\nend_header\n";
  for (const auto& p : kPoints)
    out << p[0] << ' ' << p[1] << ' ' << p[2] << '\n';
  return path;
}

/** Reads \a path (then removes it) and expects the four points back. */
void
expectThePointsFrom (const std::string& path)
{
  pcl::PointCloud<pcl::PointXYZ> cloud;
  const auto read = pcl_flowseg::loadPointCloud (path, cloud);
  std::remove (path.c_str ());
  ASSERT_TRUE (read.ok) << read.message;
  ASSERT_EQ (cloud.size (), 4u);
  for (std::size_t i = 0; i < 4; ++i)
  {
    EXPECT_EQ (cloud[i].x, kPoints[i][0]);
    EXPECT_EQ (cloud[i].y, kPoints[i][1]);
    EXPECT_EQ (cloud[i].z, kPoints[i][2]);
  }
}

} // namespace

TEST (LazyPcl, BinaryPcdLeavesPclIoUnloadedPlyLoadsThePlugin)
{
  ASSERT_FALSE (isMapped ("libpcl_io")) << "the library links pcl_io again: every process pays for VTK";
  expectThePointsFrom (writeBinaryPcd ());
  EXPECT_FALSE (isMapped ("libpcl_io"));
  EXPECT_FALSE (isMapped ("libpcl_flowseg_pcl"));

  expectThePointsFrom (writeAsciiPly ());
  EXPECT_TRUE (isMapped ("libpcl_flowseg_pcl.so"));
  EXPECT_TRUE (isMapped ("libpcl_io"));
}

// Fuzzes loadPointCloud: the first byte picks the file type, the rest is the file.
#include "fuzz_support.h"

#include <pcl_flowseg/io/point_io.h>

#include <pcl/console/print.h>

extern "C" int
LLVMFuzzerTestOneInput (const std::uint8_t* data, std::size_t size)
{
  static const char* const kTypes[] = {"pcd", "ply", "xyz", "off", "obj", "csv"};
  pcl::console::setVerbosityLevel (pcl::console::L_ALWAYS);
  if (size < 1)
    return 0;
  const std::string path = fuzzFile (data + 1, size - 1, kTypes[data[0] % 6]);
  pcl::PointCloud<pcl::PointXYZ> cloud;
  std::vector<Eigen::Vector3d> normals;
  const auto s = pcl_flowseg::loadPointCloud (path, cloud, normals);
  if (s.ok && (cloud.empty () || (!normals.empty () && normals.size () != cloud.size ())))
    __builtin_trap (); // success must mean a usable cloud
  return 0;
}

// Fuzzes loadTriangleMesh and mesh sampling: the first byte picks OFF, OBJ or PLY.
#include "fuzz_support.h"

#include <pcl_flowseg/io/mesh_io.h>

#include <pcl/console/print.h>

extern "C" int
LLVMFuzzerTestOneInput (const std::uint8_t* data, std::size_t size)
{
  static const char* const kTypes[] = {"off", "obj", "ply"};
  pcl::console::setVerbosityLevel (pcl::console::L_ALWAYS);
  if (size < 1)
    return 0;
  const std::string path = fuzzFile (data + 1, size - 1, kTypes[data[0] % 3]);
  pcl_flowseg::TriangleMesh mesh;
  if (pcl_flowseg::loadTriangleMesh (path, mesh).ok)
  {
    for (const auto& f : mesh.faces)
      for (int v : f)
        if (v < 0 || static_cast<std::size_t> (v) >= mesh.vertices.size ())
          __builtin_trap ();
    pcl_flowseg::sampleMeshSurface (mesh, 16, 0.0, 1);
  }
  return 0;
}

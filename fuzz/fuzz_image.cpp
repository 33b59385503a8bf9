// Fuzzes the silhouette readers (PNG, BMP, PGM) and the boundary extraction.
#include "fuzz_support.h"

#include <pcl_flowseg/io/silhouette.h>

extern "C" int
LLVMFuzzerTestOneInput (const std::uint8_t* data, std::size_t size)
{
  static const char* const kTypes[] = {"png", "bmp", "pgm"};
  if (size < 1)
    return 0;
  const std::string path = fuzzFile (data + 1, size - 1, kTypes[data[0] % 3]);
  pcl_flowseg::GreyImage image;
  if (pcl_flowseg::loadGreyImage (path, image).ok)
  {
    if (image.pixels.size () != static_cast<std::size_t> (image.width) * static_cast<std::size_t> (image.height))
      __builtin_trap ();
    pcl_flowseg::silhouetteBoundary (image);
  }
  return 0;
}

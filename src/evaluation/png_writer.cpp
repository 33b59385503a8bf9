/*
 * pcl_flowseg evaluation - 8-bit greyscale and RGB images written as PNG (libpng).
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include <pcl_flowseg/evaluation/png_writer.h>

#include <pcl_flowseg/io/atomic_file.h>

#include <png.h>

#include <cstdio>

namespace pcl_flowseg {

Status
writePng (const std::string& path, int width, int height, int channels, const std::vector<std::uint8_t>& pixels)
{
  if (width <= 0 || height <= 0 || (channels != 1 && channels != 3) ||
      pixels.size () != static_cast<std::size_t> (width) * static_cast<std::size_t> (height) * static_cast<std::size_t> (channels))
    return Status::error ("cannot write " + path + ": invalid image size");
  return writeFileAtomically (path, [&] (const std::string& tmp) {
    FILE* file = std::fopen (tmp.c_str (), "wb");
    if (!file)
      return Status::error ("cannot create file");
    png_structp png = png_create_write_struct (PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
    png_infop info = png ? png_create_info_struct (png) : nullptr;
    if (!png || !info || setjmp (png_jmpbuf (png)))
    {
      png_destroy_write_struct (&png, &info);
      std::fclose (file);
      return Status::error ("libpng failed");
    }
    png_init_io (png, file);
    png_set_IHDR (png, info, static_cast<png_uint_32> (width), static_cast<png_uint_32> (height), 8,
                  channels == 1 ? PNG_COLOR_TYPE_GRAY : PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT,
                  PNG_FILTER_TYPE_DEFAULT);
    png_write_info (png, info);
    const std::size_t stride = static_cast<std::size_t> (width) * static_cast<std::size_t> (channels);
    for (int y = 0; y < height; ++y)
      png_write_row (png, const_cast<png_bytep> (pixels.data () + static_cast<std::size_t> (y) * stride));
    png_write_end (png, nullptr);
    png_destroy_write_struct (&png, &info);
    return std::fclose (file) == 0 ? Status::success () : Status::error ("write failed");
  });
}

} // namespace pcl_flowseg

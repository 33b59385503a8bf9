/*
 * pcl_flowseg - binary silhouette images (PNG, BMP, PGM) as 2D boundary samples.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include <pcl_flowseg/io/silhouette.h>

#include "io/file_extension.h"

#include <png.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <climits>
#include <cstdlib>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <memory>
#include <sstream>

namespace pcl_flowseg {

namespace {

constexpr long long kMaxPixels = 1LL << 28; // refuse absurd sizes before allocating

std::uint8_t
luminance (int r, int g, int b)
{
  return static_cast<std::uint8_t> ((299 * r + 587 * g + 114 * b) / 1000);
}

Status
loadPng (const std::string& path, GreyImage& image)
{
  std::unique_ptr<FILE, int (*) (FILE*)> file (std::fopen (path.c_str (), "rb"), &std::fclose);
  if (!file)
    return Status::error (path + ": cannot open (" + std::strerror (errno) + ")");
  png_byte signature[8];
  if (std::fread (signature, 1, 8, file.get ()) != 8 || png_sig_cmp (signature, 0, 8) != 0)
    return Status::error (path + ": not a PNG file");
  png_structp png = png_create_read_struct (PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  png_infop info = png ? png_create_info_struct (png) : nullptr;
  if (!png || !info)
  {
    png_destroy_read_struct (&png, &info, nullptr);
    return Status::error (path + ": cannot initialise libpng");
  }
  std::vector<png_bytep> rows;
  std::vector<std::uint8_t> buffer;
  if (setjmp (png_jmpbuf (png)))
  {
    png_destroy_read_struct (&png, &info, nullptr);
    image = GreyImage ();
    return Status::error (path + ": corrupt PNG file");
  }
  png_init_io (png, file.get ());
  png_set_sig_bytes (png, 8);
  png_set_user_limits (png, 1 << 15, 1 << 15);
  png_read_info (png, info);
  const png_uint_32 w = png_get_image_width (png, info), h = png_get_image_height (png, info);
  const int colour = png_get_color_type (png, info), depth = png_get_bit_depth (png, info);
  if (static_cast<long long> (w) * h > kMaxPixels)
  {
    png_destroy_read_struct (&png, &info, nullptr);
    return Status::error (path + ": image too large");
  }
  if (depth == 16)
    png_set_strip_16 (png);
  if (colour == PNG_COLOR_TYPE_PALETTE)
    png_set_palette_to_rgb (png);
  if (colour == PNG_COLOR_TYPE_GRAY && depth < 8)
    png_set_expand_gray_1_2_4_to_8 (png);
  if (colour & PNG_COLOR_MASK_ALPHA || png_get_valid (png, info, PNG_INFO_tRNS))
  {
    png_color_16 white{0, 255, 255, 255, 255};
    png_set_background (png, &white, PNG_BACKGROUND_GAMMA_SCREEN, 0, 1.0); // transparent = white
  }
  if (colour == PNG_COLOR_TYPE_RGB || colour == PNG_COLOR_TYPE_RGB_ALPHA || colour == PNG_COLOR_TYPE_PALETTE)
    png_set_rgb_to_gray_fixed (png, 1, -1, -1);
  png_read_update_info (png, info);
  const std::size_t stride = png_get_rowbytes (png, info);
  const int channels = png_get_channels (png, info);
  buffer.resize (stride * h);
  rows.resize (h);
  for (png_uint_32 y = 0; y < h; ++y)
    rows[y] = buffer.data () + y * stride;
  png_read_image (png, rows.data ());
  png_destroy_read_struct (&png, &info, nullptr);
  image.width = static_cast<int> (w);
  image.height = static_cast<int> (h);
  image.pixels.resize (static_cast<std::size_t> (w) * h);
  for (png_uint_32 y = 0; y < h; ++y)
    for (png_uint_32 x = 0; x < w; ++x)
      image.pixels[y * w + x] = buffer[y * stride + x * static_cast<std::size_t> (channels)];
  return Status::success ();
}

std::uint32_t
le (const std::vector<std::uint8_t>& d, std::size_t at, int bytes)
{
  std::uint32_t v = 0;
  for (int k = bytes - 1; k >= 0; --k)
    v = (v << 8) | d[at + static_cast<std::size_t> (k)];
  return v;
}

Status
loadBmp (const std::string& path, GreyImage& image)
{
  std::ifstream in (path, std::ios::binary);
  if (!in)
    return Status::error (path + ": cannot open (" + std::strerror (errno) + ")");
  const std::vector<std::uint8_t> d ((std::istreambuf_iterator<char> (in)), std::istreambuf_iterator<char> ());
  if (d.size () < 54 || d[0] != 'B' || d[1] != 'M')
    return Status::error (path + ": not a BMP file");
  const std::uint32_t offset = le (d, 10, 4), header = le (d, 14, 4);
  const auto width = static_cast<std::int32_t> (le (d, 18, 4));
  const auto raw_height = static_cast<std::int32_t> (le (d, 22, 4));
  const int bpp = static_cast<int> (le (d, 28, 2));
  const std::uint32_t compression = le (d, 30, 4);
  if (header < 40 || width <= 0 || raw_height == 0 || raw_height == INT32_MIN)
    return Status::error (path + ": unsupported BMP header");
  const bool top_down = raw_height < 0;
  const int height = top_down ? -raw_height : raw_height;
  if (compression != 0 || (bpp != 1 && bpp != 4 && bpp != 8 && bpp != 24 && bpp != 32))
    return Status::error (path + ": unsupported BMP (compressed or " + std::to_string (bpp) + " bits per pixel)");
  if (static_cast<long long> (width) * height > kMaxPixels)
    return Status::error (path + ": image too large");
  const std::size_t stride = ((static_cast<std::size_t> (width) * static_cast<std::size_t> (bpp) + 31) / 32) * 4;
  if (offset > d.size () || d.size () - offset < stride * static_cast<std::size_t> (height))
    return Status::error (path + ": truncated BMP file");
  std::vector<std::uint8_t> palette;
  if (bpp <= 8)
  {
    const std::size_t colours = 1u << bpp, start = 14 + header;
    if (start + 4 * colours > offset)
      return Status::error (path + ": BMP palette missing");
    for (std::size_t k = 0; k < colours; ++k)
      palette.push_back (luminance (d[start + 4 * k + 2], d[start + 4 * k + 1], d[start + 4 * k]));
  }
  image.width = width;
  image.height = height;
  image.pixels.assign (static_cast<std::size_t> (width) * static_cast<std::size_t> (height), 0);
  for (int row = 0; row < height; ++row)
  {
    const std::size_t line = offset + static_cast<std::size_t> (top_down ? row : height - 1 - row) * stride;
    for (int x = 0; x < width; ++x)
    {
      std::uint8_t g;
      if (bpp <= 8)
      {
        const std::size_t bit = static_cast<std::size_t> (x) * static_cast<std::size_t> (bpp);
        const int shift = 8 - bpp - static_cast<int> (bit % 8);
        g = palette[(d[line + bit / 8] >> shift) & ((1u << bpp) - 1)];
      }
      else
      {
        const std::size_t at = line + static_cast<std::size_t> (x) * static_cast<std::size_t> (bpp / 8);
        g = luminance (d[at + 2], d[at + 1], d[at]);
      }
      image.pixels[static_cast<std::size_t> (row) * static_cast<std::size_t> (width) + static_cast<std::size_t> (x)] = g;
    }
  }
  return Status::success ();
}

Status
loadPgm (const std::string& path, GreyImage& image)
{
  std::ifstream in (path, std::ios::binary);
  if (!in)
    return Status::error (path + ": cannot open (" + std::strerror (errno) + ")");
  auto token = [&] () {
    std::string t;
    char c;
    while (in.get (c))
    {
      if (c == '#')
      {
        std::string rest;
        std::getline (in, rest);
        continue;
      }
      if (std::isspace (static_cast<unsigned char> (c)))
      {
        if (!t.empty ())
          break;
        continue;
      }
      t += c;
    }
    return t;
  };
  const std::string magic = token ();
  if (magic != "P2" && magic != "P5")
    return Status::error (path + ": not a PGM file (P2 or P5)");
  // Numbers are checked before any arithmetic on them (a width of 10^27 must not overflow).
  auto header_number = [&] (long long& out) {
    const std::string t = token ();
    char* end = nullptr;
    errno = 0;
    out = std::strtoll (t.c_str (), &end, 10);
    return !t.empty () && *end == '\0' && errno == 0 && out > 0 && out <= (1 << 20);
  };
  long long w = 0, h = 0, maxval = 0;
  if (!header_number (w) || !header_number (h) || !header_number (maxval) || maxval > 65535)
    return Status::error (path + ": invalid PGM header");
  if (w * h > kMaxPixels)
    return Status::error (path + ": image too large");
  image.width = static_cast<int> (w);
  image.height = static_cast<int> (h);
  image.pixels.assign (static_cast<std::size_t> (w * h), 0);
  for (auto& p : image.pixels)
  {
    long long v;
    if (magic == "P2")
    {
      const std::string t = token ();
      if (t.empty ())
        return Status::error (path + ": truncated PGM file");
      v = std::atoll (t.c_str ());
    }
    else
    {
      unsigned char b[2] = {0, 0};
      if (!in.read (reinterpret_cast<char*> (b), maxval > 255 ? 2 : 1))
        return Status::error (path + ": truncated PGM file");
      v = maxval > 255 ? (b[0] << 8 | b[1]) : b[0];
    }
    p = static_cast<std::uint8_t> (std::min (maxval, std::max (0LL, v)) * 255 / maxval);
  }
  return Status::success ();
}

} // namespace

bool
isSilhouetteFile (const std::string& path)
{
  const std::string ext = detail::lowerExtension (path);
  return ext == "png" || ext == "bmp" || ext == "pgm";
}

Status
loadGreyImage (const std::string& path, GreyImage& image)
{
  image = GreyImage ();
  const std::string ext = detail::lowerExtension (path);
  Status s = ext == "png" ? loadPng (path, image) : ext == "bmp" ? loadBmp (path, image) : ext == "pgm" ? loadPgm (path, image)
                                                                   : Status::error (path + ": not a .png, .bmp or .pgm image");
  if (!s.ok)
    image = GreyImage ();
  return s;
}

std::vector<Eigen::Vector3d>
silhouetteBoundary (const GreyImage& image, int threshold)
{
  std::vector<Eigen::Vector3d> out;
  const int w = image.width, h = image.height;
  if (w <= 0 || h <= 0)
    return out;
  auto dark = [&] (int x, int y) { return image.pixels[static_cast<std::size_t> (y) * static_cast<std::size_t> (w) + static_cast<std::size_t> (x)] < threshold; };
  // The shape is the class that covers less of the border.
  long long border = 0, border_dark = 0;
  for (int x = 0; x < w; ++x)
    for (int y : {0, h - 1})
    {
      ++border;
      border_dark += dark (x, y);
    }
  for (int y = 0; y < h; ++y)
    for (int x : {0, w - 1})
    {
      ++border;
      border_dark += dark (x, y);
    }
  const bool shape_is_dark = 2 * border_dark < border;
  auto inside = [&] (int x, int y) { return x >= 0 && y >= 0 && x < w && y < h && dark (x, y) == shape_is_dark; };
  // Pixel (x, y) covers [x, x+1] x [y, y+1]; y is flipped so that the shape stands upright.
  for (int y = -1; y < h; ++y)
    for (int x = -1; x < w; ++x)
    {
      const bool here = inside (x, y);
      if (here != inside (x + 1, y) && y >= 0)
        out.emplace_back (x + 1.0, -(y + 0.5), 0.0);
      if (here != inside (x, y + 1) && x >= 0)
        out.emplace_back (x + 0.5, -(y + 1.0), 0.0);
    }
  return out;
}

} // namespace pcl_flowseg

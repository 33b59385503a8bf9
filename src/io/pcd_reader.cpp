/*
 * pcl_flowseg - internal: reading ascii and binary PCD files ourselves.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include "io/pcd_reader.h"

#include "common/pcl_backend.h"
#include "io/pcd_header.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <limits>

namespace pcl_flowseg {
namespace detail {

namespace {

std::uint8_t
datatypeOf (char type, int size)
{
  switch (type)
  {
    case 'I': return size == 1 ? pcl::PCLPointField::INT8 : size == 2 ? pcl::PCLPointField::INT16
                   : size == 4 ? pcl::PCLPointField::INT32 : pcl::PCLPointField::INT64;
    case 'U': return size == 1 ? pcl::PCLPointField::UINT8 : size == 2 ? pcl::PCLPointField::UINT16
                   : size == 4 ? pcl::PCLPointField::UINT32 : pcl::PCLPointField::UINT64;
    default: return size == 4 ? pcl::PCLPointField::FLOAT32 : pcl::PCLPointField::FLOAT64;
  }
}

/** The blob's fields, offsets and sizes from a checked header. */
void
describeFields (const PcdHeader& h, pcl::PCLPointCloud2& blob)
{
  std::uint32_t offset = 0;
  for (std::size_t k = 0; k < h.fields.size (); ++k)
  {
    pcl::PCLPointField f;
    f.name = h.fields[k];
    f.offset = offset;
    const int size = std::atoi (h.sizes[k].c_str ());
    f.datatype = datatypeOf (h.types[k][0], size);
    f.count = h.counts.empty () ? 1 : static_cast<std::uint32_t> (std::atoi (h.counts[k].c_str ()));
    offset += f.count * static_cast<std::uint32_t> (size);
    blob.fields.push_back (f);
  }
  blob.width = static_cast<std::uint32_t> (h.width);
  blob.height = static_cast<std::uint32_t> (h.height);
  blob.point_step = offset;
  blob.row_step = offset * blob.width;
  blob.is_bigendian = false;
  blob.is_dense = false;
}

/** Parses one ascii value of \a type and \a size at \a text into \a out (little-endian bytes). */
bool
parseValue (const char* text, char type, int size, std::uint8_t* out)
{
  char* end = nullptr;
  errno = 0;
  if (type == 'F')
  {
    const double v = std::strtod (text, &end);
    if (end == text || *end != '\0')
      return false;
    if (size == 4)
    {
      const float f = static_cast<float> (v);
      std::memcpy (out, &f, 4);
    }
    else
      std::memcpy (out, &v, 8);
    return true;
  }
  if (type == 'I')
  {
    const long long v = std::strtoll (text, &end, 10);
    const long long high = size == 8 ? std::numeric_limits<long long>::max () : (1LL << (8 * size - 1)) - 1;
    if (end == text || *end != '\0' || errno == ERANGE || v > high || v < -high - 1)
      return false;
    std::memcpy (out, &v, static_cast<std::size_t> (size)); // little-endian: the low bytes first
    return true;
  }
  if (text[0] == '-')
    return false;
  const unsigned long long v = std::strtoull (text, &end, 10);
  const unsigned long long high = size == 8 ? std::numeric_limits<unsigned long long>::max () : (1ULL << (8 * size)) - 1;
  if (end == text || *end != '\0' || errno == ERANGE || v > high)
    return false;
  std::memcpy (out, &v, static_cast<std::size_t> (size));
  return true;
}

/** The ascii data: one point per non-empty line, one value per field element. */
Status
readAsciiData (const std::string& path, std::istream& in, const PcdHeader& h, pcl::PCLPointCloud2& blob)
{
  const std::size_t points = static_cast<std::size_t> (h.points);
  blob.data.assign (points * blob.point_step, 0);
  std::vector<int> sizes; // bytes per value of each field, decided once
  for (const std::string& size : h.sizes)
    sizes.push_back (std::atoi (size.c_str ()));
  std::size_t point = 0, line_number = 0;
  std::string line;
  const std::string at = path + ": data line ";
  while (std::getline (in, line))
  {
    ++line_number;
    char* cursor = line.data (); // tokens are cut in place; the string ends in a null character
    auto nextToken = [&cursor] () -> const char* {
      while (*cursor == ' ' || *cursor == '\t' || *cursor == '\r')
        ++cursor;
      if (!*cursor)
        return nullptr;
      const char* token = cursor;
      while (*cursor && *cursor != ' ' && *cursor != '\t' && *cursor != '\r')
        ++cursor;
      if (*cursor)
        *cursor++ = '\0';
      return token;
    };
    const char* token = nextToken ();
    if (!token)
      continue;
    if (point == points)
      return Status::error (at + std::to_string (line_number) + ": more points than the header's POINTS " + std::to_string (points));
    std::uint8_t* record = blob.data.data () + point * blob.point_step;
    for (std::size_t k = 0; k < blob.fields.size (); ++k)
    {
      const int size = sizes[k];
      for (std::uint32_t c = 0; c < blob.fields[k].count; ++c, token = nextToken ())
        if (!token || !parseValue (token, h.types[k][0], size, record + blob.fields[k].offset + c * static_cast<std::uint32_t> (size)))
          return Status::error (at + std::to_string (line_number) + ": " + (token ? "'" + std::string (token).substr (0, 40) + "' is not" : "missing") +
                                " a value of field '" + h.fields[k] + "' (" + h.types[k] + h.sizes[k] + ")");
    }
    if (token)
      return Status::error (at + std::to_string (line_number) + ": more values than the fields hold");
    ++point;
  }
  if (point != points)
    return Status::error (path + ": truncated PCD file (" + std::to_string (point) + " of " + std::to_string (points) + " points)");
  return Status::success ();
}

} // namespace

Status
readPcdFile (const std::string& path, pcl::PCLPointCloud2& blob, Eigen::Vector4f& origin, Eigen::Quaternionf& orientation)
{
  std::ifstream in (path, std::ios::binary);
  if (!in)
    return Status::error (path + ": cannot open (" + std::strerror (errno) + ")");
  PcdHeader h;
  if (const Status s = parsePcdHeader (path, in, h); !s)
    return s;
  const auto& v = h.viewpoint;
  origin = Eigen::Vector4f (static_cast<float> (v[0]), static_cast<float> (v[1]), static_cast<float> (v[2]), 0.0f);
  orientation = Eigen::Quaternionf (static_cast<float> (v[3]), static_cast<float> (v[4]), static_cast<float> (v[5]),
                                    static_cast<float> (v[6]));
  if (h.data == "binary_compressed") // its header passed the same check; PCL decompresses
  {
    in.close ();
    Status loaded;
    const PclBackend* pcl_io = pclBackend (loaded);
    if (!pcl_io)
      return loaded;
    return pcl_io->load_pcd (path, blob, origin, orientation) < 0 ? Status::error (path + ": not a readable PCD file")
                                                                   : Status::success ();
  }
  describeFields (h, blob);
  if (h.data == "ascii")
    return readAsciiData (path, in, h, blob);
  blob.data.resize (static_cast<std::size_t> (h.points) * blob.point_step);
  if (!in.read (reinterpret_cast<char*> (blob.data.data ()), static_cast<std::streamsize> (blob.data.size ())))
    return Status::error (path + ": truncated PCD file");
  return Status::success ();
}

} // namespace detail
} // namespace pcl_flowseg

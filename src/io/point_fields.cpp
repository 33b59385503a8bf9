/*
 * pcl_flowseg - internal: coordinates (and normals) out of a PCLPointCloud2, field by field.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include "io/point_fields.h"

#include <pcl/common/io.h>

#include <cstring>

namespace pcl_flowseg {
namespace detail {

Status
readPointFields (const pcl::PCLPointCloud2& blob, const std::string& path, pcl::PointCloud<pcl::PointXYZ>& cloud,
                std::vector<Eigen::Vector3d>* normals)
{
  // Coordinates are read field by field in whatever numeric type the file uses (PLY files often
  // store doubles, which pcl::fromPCLPointCloud2 would not convert into PointXYZ).
  const pcl::PCLPointField* axis[3] = {nullptr, nullptr, nullptr};
  const pcl::PCLPointField* normal[3] = {nullptr, nullptr, nullptr};
  for (const auto& f : blob.fields)
    for (int k = 0; k < 3; ++k)
    {
      if (f.name == std::string (1, "xyz"[k]))
        axis[k] = &f;
      if (f.name == std::string ("normal_") + "xyz"[k] || f.name == std::string ("n") + "xyz"[k])
        normal[k] = &f;
    }
  const bool has_normals = normals && normal[0] && normal[1] && normal[2];
  if (!axis[0] || !axis[1])
    return Status::error (path + ": has no x/y fields (not a point cloud)");
  const std::size_t n = static_cast<std::size_t> (blob.width) * blob.height;
  if (blob.point_step == 0 || blob.data.size () < n * blob.point_step)
    return Status::error (path + ": point data shorter than its header says");
  for (const auto* f : {axis[0], axis[1], axis[2], normal[0], normal[1], normal[2]})
  {
    // A size that does not fit the type (SIZE 2 with TYPE F, say) leaves no datatype at all.
    if (f && (f->datatype < pcl::PCLPointField::INT8 || f->datatype > pcl::PCLPointField::FLOAT64))
      return Status::error (path + ": field '" + f->name + "' is not a 1-8 byte integer or a float/double"
                            " (a SIZE that does not fit its TYPE?)");
    if (f && f->offset + pcl::getFieldSize (f->datatype) > blob.point_step)
      return Status::error (path + ": field '" + f->name + "' lies outside the point record");
  }
  auto read = [&] (const pcl::PCLPointField* f, const std::uint8_t* record) -> double {
    if (!f)
      return 0.0;
    const std::uint8_t* p = record + f->offset;
    switch (f->datatype)
    {
      case pcl::PCLPointField::INT8: { std::int8_t v; std::memcpy (&v, p, 1); return v; }
      case pcl::PCLPointField::UINT8: { std::uint8_t v; std::memcpy (&v, p, 1); return v; }
      case pcl::PCLPointField::INT16: { std::int16_t v; std::memcpy (&v, p, 2); return v; }
      case pcl::PCLPointField::UINT16: { std::uint16_t v; std::memcpy (&v, p, 2); return v; }
      case pcl::PCLPointField::INT32: { std::int32_t v; std::memcpy (&v, p, 4); return v; }
      case pcl::PCLPointField::UINT32: { std::uint32_t v; std::memcpy (&v, p, 4); return v; }
      case pcl::PCLPointField::FLOAT64: { double v; std::memcpy (&v, p, 8); return v; }
      default: { float v; std::memcpy (&v, p, 4); return v; } // FLOAT32: the others are refused above
    }
  };
  cloud.reserve (n);
  for (std::size_t i = 0; i < n; ++i)
  {
    const std::uint8_t* record = blob.data.data () + i * blob.point_step;
    cloud.push_back (pcl::PointXYZ (static_cast<float> (read (axis[0], record)), static_cast<float> (read (axis[1], record)),
                                    static_cast<float> (read (axis[2], record))));
    if (has_normals)
      normals->emplace_back (read (normal[0], record), read (normal[1], record), read (normal[2], record));
  }
  return Status::success ();
}

} // namespace detail
} // namespace pcl_flowseg

/*
 * pcl_flowseg - internal: coordinates (and normals) out of a PCLPointCloud2, field by field.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include "io/point_fields.h"

#include <pcl/common/io.h>

#include <cstring>

namespace pcl_flowseg {
namespace detail {

namespace {
/** Where a record's coordinates and normals are; fields absent are null. */
struct FieldLayout
{
  const pcl::PCLPointField* axis[3] = {nullptr, nullptr, nullptr};
  const pcl::PCLPointField* normal[3] = {nullptr, nullptr, nullptr};
  bool has_normals = false;
  std::size_t count = 0;
};

/** Finds the coordinate and (when \a want_normals) normal fields of \a blob and checks that the
  * data is as long as the header says and every field lies inside the point record. */
Status
locateFields (const pcl::PCLPointCloud2& blob, const std::string& path, bool want_normals, FieldLayout& layout)
{
  for (const auto& f : blob.fields)
    for (int k = 0; k < 3; ++k)
    {
      if (f.name == std::string (1, "xyz"[k]))
        layout.axis[k] = &f;
      if (f.name == std::string ("normal_") + "xyz"[k] || f.name == std::string ("n") + "xyz"[k])
        layout.normal[k] = &f;
    }
  layout.has_normals = want_normals && layout.normal[0] && layout.normal[1] && layout.normal[2];
  if (!layout.axis[0] || !layout.axis[1])
    return Status::error (path + ": has no x/y fields (not a point cloud)");
  layout.count = static_cast<std::size_t> (blob.width) * blob.height;
  if (blob.point_step == 0 || blob.data.size () < layout.count * blob.point_step)
    return Status::error (path + ": point data shorter than its header says");
  for (const auto* f : {layout.axis[0], layout.axis[1], layout.axis[2], layout.normal[0], layout.normal[1], layout.normal[2]})
  {
    // A size that does not fit the type (SIZE 2 with TYPE F, say) leaves no datatype at all.
    if (f && (f->datatype < pcl::PCLPointField::INT8 || f->datatype > pcl::PCLPointField::FLOAT64))
      return Status::error (path + ": field '" + f->name + "' is not a 1-8 byte integer or a float/double"
                            " (a SIZE that does not fit its TYPE?)");
    if (f && f->offset + pcl::getFieldSize (f->datatype) > blob.point_step)
      return Status::error (path + ": field '" + f->name + "' lies outside the point record");
  }
  return Status::success ();
}

/** The value of field \a f (0 when absent) in \a record, whatever its numeric type. */
double
fieldValue (const pcl::PCLPointField* f, const std::uint8_t* record)
{
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
}

float
fieldFloat (const pcl::PCLPointField* f, const std::uint8_t* record)
{
  return static_cast<float> (fieldValue (f, record));
}
} // namespace

Status
readPointFields (const pcl::PCLPointCloud2& blob, const std::string& path, pcl::PointCloud<pcl::PointXYZ>& cloud,
                std::vector<Eigen::Vector3d>* normals)
{
  // Coordinates are read field by field in whatever numeric type the file uses (PLY files often
  // store doubles, which pcl::fromPCLPointCloud2 would not convert into PointXYZ).
  FieldLayout at;
  if (const Status s = locateFields (blob, path, normals != nullptr, at); !s)
    return s;
  cloud.reserve (at.count);
  for (std::size_t i = 0; i < at.count; ++i)
  {
    const std::uint8_t* record = blob.data.data () + i * blob.point_step;
    cloud.push_back (pcl::PointXYZ (fieldFloat (at.axis[0], record), fieldFloat (at.axis[1], record), fieldFloat (at.axis[2], record)));
    if (at.has_normals)
      normals->emplace_back (fieldValue (at.normal[0], record), fieldValue (at.normal[1], record),
                             fieldValue (at.normal[2], record));
  }
  return Status::success ();
}

Status
readPointFields (const pcl::PCLPointCloud2& blob, const std::string& path, pcl::PointCloud<pcl::PointNormal>& cloud,
                bool& has_normals)
{
  FieldLayout at;
  if (const Status s = locateFields (blob, path, true, at); !s)
    return s;
  has_normals = at.has_normals;
  cloud.reserve (at.count);
  for (std::size_t i = 0; i < at.count; ++i)
  {
    const std::uint8_t* record = blob.data.data () + i * blob.point_step;
    pcl::PointNormal p;
    p.x = fieldFloat (at.axis[0], record);
    p.y = fieldFloat (at.axis[1], record);
    p.z = fieldFloat (at.axis[2], record);
    if (has_normals)
    {
      p.normal_x = fieldFloat (at.normal[0], record);
      p.normal_y = fieldFloat (at.normal[1], record);
      p.normal_z = fieldFloat (at.normal[2], record);
    }
    else
      p.normal_x = p.normal_y = p.normal_z = 0.0f;
    cloud.push_back (p);
  }
  return Status::success ();
}

} // namespace detail
} // namespace pcl_flowseg

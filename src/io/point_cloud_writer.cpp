/*
 * pcl_flowseg - writing point clouds and per-point labels as PCD files.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include <pcl_flowseg/io/point_cloud_writer.h>

#include <pcl_flowseg/io/atomic_file.h>

#include "common/pcl_backend.h"
#include "io/file_extension.h"
#include "io/output_buffer.h"

#include <cmath>

namespace pcl_flowseg {

namespace {

/** The header PCL's ASCII writer writes for PointXYZL. */
void
asciiLabelPcdHeader (OutputBuffer& out, std::uint32_t width, std::uint32_t height, const Eigen::Vector4f& origin,
                     const Eigen::Quaternionf& orientation)
{
  out.text ("# .PCD v0.7 - Point Cloud Data file format\nVERSION 0.7\n")
      .text ("FIELDS x y z label\nSIZE 4 4 4 4\nTYPE F F F U\nCOUNT 1 1 1 1\n")
      .text ("WIDTH ").integer (width).text ("\nHEIGHT ").integer (height).text ("\nVIEWPOINT ");
  for (int i = 0; i < 3; ++i)
    out.number (origin[i]).character (' ');
  out.number (orientation.w ()).character (' ').number (orientation.x ()).character (' ').number (orientation.y ())
      .character (' ').number (orientation.z ());
  out.text ("\nPOINTS ").integer (static_cast<std::int64_t> (width) * height).text ("\nDATA ascii\n");
}

/** A coordinate as PCL writes it: the shortest exact form, "nan" for any NaN. */
void
coordinate (OutputBuffer& out, float value)
{
  if (std::isnan (value))
    out.text ("nan");
  else
    out.number (value);
}

} // namespace

Status
writeLabelCloud (const std::string& path, const pcl::PointCloud<pcl::PointXYZL>& labels, bool binary)
{
  if (!binary) // PCL's ASCII writer formats through a stream, several times slower
    return writeTextFileAtomically (path, [&] (std::ostream& stream) {
      OutputBuffer out (stream);
      const bool organised = static_cast<std::size_t> (labels.width) * labels.height == labels.size ();
      asciiLabelPcdHeader (out, organised ? labels.width : static_cast<std::uint32_t> (labels.size ()), organised ? labels.height : 1,
                           labels.sensor_origin_, labels.sensor_orientation_);
      for (const pcl::PointXYZL& p : labels)
      {
        coordinate (out, p.x);
        coordinate (out.character (' '), p.y);
        coordinate (out.character (' '), p.z);
        out.character (' ').integer (p.label).character ('\n');
      }
    });
  Status loaded;
  const detail::PclBackend* pcl_io = detail::pclBackend (loaded);
  if (!pcl_io)
    return loaded;
  return writeFileAtomically (path, [&] (const std::string& tmp) {
    return pcl_io->write_pcd_xyzl_binary (tmp, labels) == 0 ? Status::success () : Status::error ("PCD writer failed");
  });
}

Status
writePointCloud (const std::string& path, const pcl::PointCloud<pcl::PointXYZ>& cloud, bool binary)
{
  if (detail::lowerExtension (path) != "pcd") // PCD content under another name would be misread later
    return Status::error ("cannot write " + path + ": point clouds are written as PCD, give the file a .pcd name");
  Status loaded;
  const detail::PclBackend* pcl_io = detail::pclBackend (loaded);
  if (!pcl_io)
    return loaded;
  return writeFileAtomically (path, [&] (const std::string& tmp) {
    return pcl_io->write_pcd_xyz (tmp, cloud, binary) == 0 ? Status::success () : Status::error ("PCD writer failed");
  });
}

} // namespace pcl_flowseg

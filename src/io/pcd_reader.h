/*
 * pcl_flowseg - internal: reading PCD files ourselves. PCL's reader kept crashing or asking for
 * terabytes on malformed files that a header check could not foresee (nine findings of the
 * point_file fuzz target), so ascii and binary PCD files are read here, strictly, and only
 * binary_compressed ones (after the same header check) by PCL.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include <pcl_flowseg/common/status.h>

#include <pcl/PCLPointCloud2.h>

#include <Eigen/Geometry>

#include <string>

namespace pcl_flowseg {
namespace detail {

/** \brief Reads the PCD file \a path into \a blob (fields, width, height, point_step, data) with its
  * VIEWPOINT as \a origin and \a orientation. The header must pass parsePcdHeader's checks; ascii data must
  * hold one point per line with one value per field element, each a number of the field's type
  * and range; binary data the bytes the header promises. Fails with the file's name (and the line,
  * for ascii data) otherwise. */
Status
readPcdFile (const std::string& path, pcl::PCLPointCloud2& blob, Eigen::Vector4f& origin, Eigen::Quaternionf& orientation);

} // namespace detail
} // namespace pcl_flowseg

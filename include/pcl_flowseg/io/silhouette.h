/*
 * pcl_flowseg - binary silhouette images (PNG, BMP, PGM) as 2D boundary samples.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include <pcl_flowseg/common/status.h>

#include <Eigen/Core>

#include <cstdint>
#include <string>
#include <vector>

namespace pcl_flowseg {

/** \brief An 8-bit greyscale image, rows from the top. */
struct GreyImage
{
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> pixels; ///< width * height values
};

/** \brief Reads a PNG (any colour type, through libpng), BMP (uncompressed 1, 4, 8, 24 or 32 bits
  * per pixel) or PGM (P2/P5) image as greyscale. Fails with a message on a missing, truncated or
  * unsupported file. */
Status
loadGreyImage (const std::string& path, GreyImage& image);

/** \brief The boundary of the silhouette in \a image: pixels darker than \a threshold form one
  * class, the others the other; the shape is the class that covers less of the image border (so
  * black-on-white and white-on-black both work). Returns the midpoints of the pixel edges between
  * shape and background, in pixel units with y pointing up (z = 0); the image border counts as
  * background. Empty when the image holds no shape. */
std::vector<Eigen::Vector3d>
silhouetteBoundary (const GreyImage& image, int threshold = 128);

/** \brief True for the image types loadGreyImage reads (.png, .bmp, .pgm). */
bool
isSilhouetteFile (const std::string& path);

} // namespace pcl_flowseg

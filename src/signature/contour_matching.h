/*
 * pcl_flowseg - matching two 2D contours by dynamic programming (internal header).
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include <pcl_flowseg/signature/shape_description.h>

#include <cstddef>
#include <vector>

namespace pcl_flowseg {

/** \brief The sector a direction in \a sector falls into in the mirror image (theta becomes
  * pi - theta): 0 and 5, 1 and 4, 2 and 3, 6 and 11, 7 and 10, 8 and 9 trade places. */
constexpr std::size_t
mirroredSector (std::size_t sector)
{
  return (kContourAngleBins / 2 - 1 + kContourAngleBins - sector) % kContourAngleBins;
}

/** \brief The contour of the mirror image: the sequence reversed (the outline still runs
  * counter-clockwise) and each direction theta from the tangent becomes pi - theta. */
std::vector<ContourHistogram>
mirroredContour (const std::vector<ContourHistogram>& contour);

/** \brief Dissimilarity of two contour descriptions: the least cost of an order-keeping matching of
  * the two point sequences (any start on the second, either direction, which is mirroring), each
  * matched pair costing the Hellinger distance of its histograms, each skipped point a fixed
  * penalty; over the number of points. 0 unless both have kContourPoints histograms (3D shapes
  * have none). */
double
contourDistance (const ShapeDescription& a, const ShapeDescription& b);

} // namespace pcl_flowseg

/*
 * pcl_flowseg - internal: how far apart two views of shapes are.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include <pcl_flowseg/signature/view_description.h>

namespace pcl_flowseg {
namespace internal {

/** \brief L1 distance between two views' histograms (0 to 4): cheap, roll-invariant, for picking
  * the views worth aligning. */
double
viewHistogramDistance (const ViewDescription& a, const ViewDescription& b);

/** \brief How far the points of view \a a lie from those of \a b once aligned: the best of every
  * roll about the line of sight (and its mirror image) is refined by iterative closest points with
  * rotation, translation and scale; the result is the mean distance from each point of \a a to the
  * nearest of \a b plus the other way, in view-frame units (RMS radii). 0 for equal views. */
double
viewDistance (const ViewDescription& a, const ViewDescription& b);

/** \brief How far a single view \a scan lies from a complete shape seen from many directions: the
  * scan is aligned (as viewDistance does) with each of the kAlignedViews views whose histograms are
  * nearest its own, then refined against the shape's whole surface (its shape_points); the result
  * is the smallest mean distance from the scan's points to the surface plus from the view's points
  * to the scan's, in view-frame units. Infinite when \a shape has no views. */
double
singleViewDistance (const ViewDescription& scan, const ViewSet& shape);

/** \brief Views of a complete shape aligned with a scan (singleViewDistance). */
constexpr std::size_t kAlignedViews = 5;

} // namespace internal
} // namespace pcl_flowseg

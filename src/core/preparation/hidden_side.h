/*
 * pcl_flowseg - internal: the hidden side of a single-view scan, guessed by mirroring.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include <Eigen/Core>

#include <vector>

namespace pcl_flowseg {
namespace core {

/** Neighbours in the sensor's image that decide whether a sample lies on the rim of what it sees. */
constexpr int kRimNeighbours = 24;
/** A sample lies on the rim when its image neighbours leave a gap wider than this angle (radians)
  * around it (the silhouette), */
constexpr double kRimGapAngle = 2.6179938779914944; // 150 degrees
/** ... or when a neighbour lies deeper by more than this many footprints (a sample's size at its
  * range) */
constexpr double kRimDepthJump = 8.0;
/** ... and the step to it is this many times steeper than the median step to the others (an
  * occlusion edge; a surface seen at a grazing angle is steep everywhere). */
constexpr double kRimSteepness = 4.0;
/** Rim samples considered for the depth a sample is mirrored about, nearest in the image first, */
constexpr int kRimCandidates = 16;
/** ... up to this many times the nearest one's image distance (plus one footprint): a farther rim
  * belongs to another part. */
constexpr double kRimReach = 1.5;
/** Passes of averaging the rim depths over image neighbours (not across occlusion edges): the
  * mirrored side comes out as smooth as the seen one. */
constexpr int kRimSmoothingPasses = 120;
/** Samples less than this many footprints before their rim are not mirrored (they lie on it). */
constexpr double kMinMirrorDepth = 0.5;

/** \brief Points on the side of a single view that the sensor at \a viewpoint cannot see: each
  * sample mirrored along its ray about the depth of the rim near it (silhouette or occlusion edge)
  * that lies deeper than it, as if every part reached as far behind its rim as before it. The rim
  * depths are averaged over neighbouring samples first. Samples on or behind their rim add
  * nothing. 3D scans; empty when the samples do not all lie in front of the sensor. */
std::vector<Eigen::Vector3d>
mirroredHiddenSide (const std::vector<Eigen::Vector3d>& samples, const Eigen::Vector3d& viewpoint);

/** \brief \a mirrored without the points equal to one of \a samples or to an earlier point of
  * \a mirrored, in their order: the triangulation's vertices must be distinct. */
std::vector<Eigen::Vector3d>
withoutCopies (const std::vector<Eigen::Vector3d>& samples, const std::vector<Eigen::Vector3d>& mirrored);

} // namespace core
} // namespace pcl_flowseg

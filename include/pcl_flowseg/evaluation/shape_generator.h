/*
 * pcl_flowseg - procedural shapes with known parts, for samples, tests and benchmarks.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include <Eigen/Core>

#include <cstdint>
#include <string>
#include <vector>

namespace pcl_flowseg {

/** \brief An ellipsoid (3D) or ellipse (2D: z of centre and radii ignored) part of a shape. */
struct EllipsoidPart
{
  std::string name;                                  ///< the part a person would name
  Eigen::Vector3d centre = Eigen::Vector3d::Zero ();
  Eigen::Vector3d radii = Eigen::Vector3d::Ones ();  ///< semi-axes along the rotated x, y, z
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity (); ///< columns: the part's axes
};

/** \brief A shape made as the union of ellipsoids (3D) or ellipses (2D). Its boundary is a
  * closed surface (curve) and its parts are known, which makes it a ground truth for tests. */
struct BlobShape
{
  std::string name;
  int dimension = 3;
  std::vector<EllipsoidPart> parts;

  /** Smallest normalised radius of \a p over the parts: < 1 inside, 1 on the boundary. */
  double level (const Eigen::Vector3d& p) const;
  /** True when \a p lies strictly inside at least one part. */
  bool contains (const Eigen::Vector3d& p) const;
  /** Index of the part whose normalised distance to \a p is smallest (the part \a p belongs to). */
  int nearestPart (const Eigen::Vector3d& p) const;
};

/** \brief \a count points spread uniformly (by area / arc length) over the boundary of the union,
  * reproducible for a given \a seed. Each ellipsoid is sampled area-uniformly by rejection and
  * points inside another part are discarded. */
std::vector<Eigen::Vector3d>
sampleBoundary (const BlobShape& shape, std::size_t count, std::uint32_t seed);

/** \brief Points of the shipped samples (the .pcd files in samples/, made by flowseg_make_samples), per shape. */
constexpr std::size_t kSamplePoints2D = 1500;
constexpr std::size_t kSamplePoints3D = 4000;

/** \brief The shipped sample shapes. 2D: "dumbbell2d" (two discs and a neck), "star2d" (five
  * arms around a disc), "hand2d" (palm, four fingers, thumb). 3D: "dumbbell3d" (two spheres and
  * a neck), "snowman3d" (three spheres), "animal3d" (body, head, neck, four legs, tail). */
std::vector<BlobShape>
sampleShapes ();

/** \brief One of sampleShapes() by name; empty shape (no parts) when unknown. */
BlobShape
sampleShape (const std::string& name);

} // namespace pcl_flowseg

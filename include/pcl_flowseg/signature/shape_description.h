/*
 * pcl_flowseg - a shape described by its interior features and its interior triangulation, for
 * retrieval beyond the paper's weighted points: the features as parts with attributes, and three
 * distributions measured inside the shape (thickness, inner distances, solid distances).
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include <pcl_flowseg/common/status.h>

#include <array>
#include <cstddef>
#include <vector>

namespace pcl_flowseg {

/** \brief Bins of each interior distribution. */
constexpr std::size_t kDistributionBins = 32;
/** \brief Smallest share of the interior volume an interior feature needs to be described as a part:
  * small enough to keep fingers and ears of a 10,000-point sample, large enough to leave out the
  * slivers that noise and sampling make. */
constexpr double kPartShare = 0.005;
/** \brief Most parts described (the largest); a bearing or a spring can have hundreds of features. */
constexpr std::size_t kMaxParts = 16;
/** \brief Interior cells drawn (volume-weighted) for the distributions: the same for every shape, so
  * that histograms of different shapes have the same sampling noise. */
constexpr std::size_t kInteriorSamples = 2048;
/** \brief Drawn cells from which inner distances (and solid distances) to all drawn cells are
  * measured: 64 x 2048 distances per shape. They are spread over the shape (farthest points) and
  * weighted by the share of drawn cells nearest to each. */
constexpr std::size_t kDistanceSources = 64;
/** \brief Range of the thickness distribution: natural log of a cell's circumradius over the unit. */
constexpr double kThicknessLogLow = -5.0, kThicknessLogHigh = 0.0;
/** \brief Range of the inner-distance distribution: natural log of the distance over the unit. */
constexpr double kInnerLogLow = -3.0, kInnerLogHigh = 3.0;
/** \brief Range of the solid-distance distribution: distance over the mean such distance. */
constexpr double kSolidHigh = 3.0;
/** \brief Rows of the inner-distance profiles: the sources, ordered from the most central to the
  * most remote, cut into this many equal shares of their weight. */
constexpr std::size_t kProfileRows = 16;
/** \brief Points along the outline of a 2D shape at which its inner-distance shape context is
  * taken (equal steps of arc length). */
constexpr std::size_t kContourPoints = 64;
/** \brief Bins of each contour histogram: log inner distance (over the mean, from 1/8 to 2) times
  * direction from the outline's tangent (30 degree sectors). */
constexpr std::size_t kContourDistanceBins = 5, kContourAngleBins = 12;
constexpr std::size_t kContourBins = kContourDistanceBins * kContourAngleBins;
/** \brief Bins of each inner-distance context: log of the inner distance over the shape's mean
  * inner distance, in [kContextLogLow, kContextLogHigh]. */
constexpr std::size_t kContextBins = 16;
constexpr double kContextLogLow = -3.0, kContextLogHigh = 1.5;

/** \brief One interior feature described for part matching. Lengths are in the unit of its
  * signature (interior volume^(1/d)), so they do not change with scale. */
struct PartDescription
{
  double weight = 0.0;         ///< volume share among the described parts (they sum to 1)
  double thickness = 0.0;      ///< radius of the part's largest empty ball (its maximum's circumradius)
  double extent = 0.0;         ///< root of the largest principal variance of the part's cells
  double middle_ratio = 0.0;   ///< root of the middle over the largest principal variance, in [0, 1]
  double smallest_ratio = 0.0; ///< root of the smallest over the largest (0 in 2D), in [0, 1]
  /** Mean inner distance from the shape's sources (ShapeDescription::inner_contexts) to the
    * centroid of the part's maximum cell: where in the shape the part lies (a torso little, a
    * hand much), and unlike a straight distance from the centre it stays when a limb bends. */
  double remoteness = 0.0;
};

/** \brief A volume-weighted histogram that sums to 1 (values outside the range go to the end bins). */
using Distribution = std::array<double, kDistributionBins>;

/** \brief Inner distances seen from the centre out to the extremities: row r is the distribution of
  * the inner distances from the sources in the r-th share of their weight, the sources ordered by
  * their mean log inner distance. A tip of a limb sees long distances, the middle of a body short
  * ones, so the rows describe how the shape's parts are arranged, and bending a limb moves little. */
using InnerProfiles = std::array<Distribution, kProfileRows>;

/** \brief Thickness seen from the centre out to the extremities: entry r is the mean log
  * circumradius over the unit of the drawn cells in the r-th share of remoteness (their mean inner
  * distance from the sources): a torso's thickness first, then arms', then fingers'. */
using ThicknessProfile = std::array<double, kProfileRows>;

/** \brief What one point of a 2D outline sees of the rest of it (inner-distance shape context):
  * the outline's length share by ring of log inner distance and sector of direction, row-major by
  * ring; sums to 1. Floats: a shape has kContourPoints of them. */
using ContourHistogram = std::array<float, kContourBins>;

/** \brief What one source of inner distances sees of the shape (an inner-distance context): the
  * share of the drawn interior cells by log inner distance from it over the shape's mean inner
  * distance (kContextBins bins, summing to 1), and how thick the shape is at the source. Floats: a
  * shape has up to kDistanceSources of them. */
struct InnerContext
{
  float thickness = 0.0f;                          ///< log circumradius of the source cell over the unit
  std::array<float, kContextBins> distances{};     ///< inner-distance histogram, sums to 1
};

/** \brief What describeShape measures; all of it invariant to translation, rotation, mirroring and
  * uniform scale. Empty (no parts, zero distributions) when not computed. */
struct ShapeDescription
{
  /** The interior features of at least kPartShare of the interior volume, the kMaxParts largest,
    * by decreasing weight (the largest feature alone when none reaches the share). */
  std::vector<PartDescription> parts;
  /** Circumradii of interior cells (a local thickness: the radius of the empty ball around the
    * cell), log over the unit, in [kThicknessLogLow, kThicknessLogHigh]. */
  Distribution thickness{};
  /** Inner distances between interior cells (shortest paths from centroid to centroid along the
    * edges of interior cells: they change little when a limb bends), log over the unit, in
    * [kInnerLogLow, kInnerLogHigh]. */
  Distribution inner_distance{};
  /** Straight distances between interior cells over their mean, in [0, kSolidHigh]. */
  Distribution solid_distance{};
  /** Inner distances by the remoteness of their source (log over the unit, in [kInnerLogLow,
    * kInnerLogHigh]); the same pairs as inner_distance. */
  InnerProfiles inner_profiles{};
  /** Thickness by remoteness: means of log circumradius over the unit, each in [kThicknessLogLow,
    * kThicknessLogHigh]. */
  ThicknessProfile thickness_profile{};
  /** 2D only (empty in 3D or without a closed outline): the inner-distance shape context at
    * kContourPoints points along the outline, counter-clockwise from an arbitrary start. Inner
    * distances run through the interior, so a bent limb changes them little. */
  std::vector<ContourHistogram> contour;
  /** The inner-distance context of each source (kDistanceSources, fewer on a shape of fewer
    * interior cells), in the sources' farthest-point order. Compared as a set: each source of one
    * shape is matched to one of the other's at least total cost. */
  std::vector<InnerContext> inner_contexts;

  bool empty () const { return parts.empty (); }
};

/** \brief Why \a description is not one describeShape could have made (a message), or success: an
  * empty description, or 1 to kMaxParts parts with weights in (0, 1] ordered by decreasing weight
  * and summing to 1, lengths finite and > 0 (remoteness >= 0), ratios in [0, 1], and distributions
  * (also each row of the inner-distance profiles) of entries in [0, 1] summing to 1, and a
  * thickness profile within the thickness range; a contour of 0 or kContourPoints histograms, each
  * of entries in [0, 1] summing to 1; 1 to kDistanceSources inner contexts with histograms likewise
  * and thicknesses within the thickness range (none without parts). */
Status
checkShapeDescription (const ShapeDescription& description);

} // namespace pcl_flowseg

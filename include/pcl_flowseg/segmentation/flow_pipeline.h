/*
 * pcl_flowseg - shape segmentation by flow discretization (Dey, Giesen, Goswami).
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include <pcl_flowseg/segmentation/flow_result.h>
#include <pcl_flowseg/common/status.h>

#include <functional>
#include <string>
#include <vector>

namespace pcl_flowseg {

/** \brief Default merge threshold rho (see FlowParameters::rho). Chosen with
  * kDefaultSamplingTolerance on the Princeton Segmentation Benchmark (README, "Segmentation
  * quality"): the middle of the range of rho and tolerance over which the error is lowest. */
constexpr double kDefaultRho = 1.05;

/** \brief Default additive merge tolerance, in local sample spacings (see
  * FlowParameters::sampling_tolerance). */
constexpr double kDefaultSamplingTolerance = 0.5;

/** \brief Default thickness ratio above which thin parts take back their stumps (see
  * FlowParameters::stump_ratio). */
constexpr double kDefaultStumpRatio = 2.0;

/** \brief Default merge threshold for compact segments (see FlowParameters::compact_rho). */
constexpr double kDefaultCompactRho = 1.2;

/** \brief Default size, in balls of the saddle's radius, below which a segment counts as compact
  * (see FlowParameters::compact_size). */
constexpr double kDefaultCompactSize = 2.5;

/** \brief How the dimension of the flow is chosen. */
enum class DimensionMode
{
  Automatic = 0, ///< 2D when all points lie on one plane, 3D otherwise
  Planar = 2,    ///< 2D: points are projected onto their plane
  Spatial = 3    ///< 3D: fails on coplanar input
};

/** \brief Whether the interior/exterior separation works on a smoothed copy of noisy samples. */
enum class Denoising
{
  Automatic = 0, ///< when the median surface variation of the sample shows noise (default)
  Off = 1,       ///< never: use the sample as it is
  Always = 2     ///< always smooth (at least one pass)
};

/** \brief Parameters of the flow segmentation. */
struct FlowParameters
{
  /** Merge threshold rho (dimensionless, > 0). Two stable manifolds that share a facet t are
    * merged when the circumradii of both their maximum cells are below rho times the
    * circumradius of t (paper, section 4, discrete rule; radii, not squared radii), plus
    * sampling_tolerance local sample spacings. Values below 1 merge nothing. Default kDefaultRho. */
  double rho = kDefaultRho;
  DimensionMode dimension = DimensionMode::Automatic;
  /** Separate the shape's interior from its exterior (surface/curve reconstruction). Default on;
    * off gives the paper's raw segmentation of the whole convex hull. */
  bool separate_interior = true;
  /** Which features are reported. Default: the interior ones. */
  FeatureSide features = FeatureSide::Interior;
  /** Denoising for the interior/exterior separation (the segmentation itself always uses the
    * sample as given). Default Automatic. */
  Denoising denoising = Denoising::Automatic;
  /** Optional outward normals, one per input point (empty: none). Oriented normals make the
    * interior/exterior decision near the surface more reliable, notably with noise. */
  std::vector<Eigen::Vector3d> normals;
  /** Optional sensor position of a single-view scan: the cells the rays from it to the points
    * cross are free space, hence outside. */
  bool use_viewpoint = false;
  Eigen::Vector3d viewpoint = Eigen::Vector3d::Zero ();
  /** Memory the run may use, in bytes; 0 (default) = the memory the system reports available.
    * Inputs whose estimated need (estimateSegmentationMemory) exceeds it are refused up front. */
  std::size_t memory_limit = 0;
  /** Relative flatness below which Automatic chooses 2D: the spread of the points normal to
    * their best-fit plane divided by the bounding-box diagonal. Default 1e-9. */
  double planar_tolerance = 1e-9;
  /** Worker threads for the triangulation (CGAL with TBB) and the per-cell stages (OpenMP);
    * 0 (default) = all hardware threads, 1 = sequential. The result does not depend on it: cells
    * are put in a canonical order after the triangulation. */
  unsigned threads = 0;
  /** Additive tolerance of the merge rule, in units of the local sample spacing (dimensionless,
    * finite, >= 0). Two stable manifolds sharing a facet t merge when the circumradii of both
    * their maxima are below rho R(t) + sampling_tolerance s(t), where s(t) is the mean distance
    * from t's vertices to their nearest other sample. Why: heights computed from a sample differ
    * from those of the sampled surface by up to about the sample spacing, so in parts as thin as
    * the spacing (walls, plates, fins) maxima and saddles are indistinguishable and the ratio rule
    * alone cuts them into hundreds of pieces; in parts much thicker than the spacing the term is
    * negligible. 0 gives the paper's rule exactly. Ignored when rho < 1 (no merging).
    * Default kDefaultSamplingTolerance (0.5, about the largest distance from a point of a
    * uniformly sampled surface to its nearest sample, in nearest-neighbour distances). */
  double sampling_tolerance = kDefaultSamplingTolerance;
  /** Thin parts take back their stumps (dimensionless ratio of circumradii; 0 = off, else >= 1).
    * The flow cuts a thin part (finger, leg, ear) off a thick one where the thin part is narrowest;
    * the stretch from there to the junction widens towards the thick part and flows into it (the
    * "stump" the paper notes on fingers). After merging, where a segment borders one whose highest
    * maximum is more than stump_ratio times thicker (circumradius), the cells of the thick segment
    * connected to the thin one through cells no larger than the thin segment's highest maximum
    * join the thin segment. Segments are then no longer unions of stable manifolds (maxima stay).
    * 0 gives the paper's segments. Default kDefaultStumpRatio (2: the thick part's largest ball at
    * least twice as wide as the thin part's). */
  double stump_ratio = kDefaultStumpRatio;
  /** Merge threshold for compact segments (dimensionless, finite, > 0; effective only when above
    * rho). After the rule at rho, two segments whose saddle t passes the same rule with
    * compact_rho in place of rho merge when the smaller of the two holds no more volume (area in
    * 2D) than compact_size balls (discs) of radius R(t); saddles are taken from the shallowest.
    * Why: a shallow bump that is no bigger than a couple of balls of its neck (a bulge of a
    * body, a knuckle, a boss on a machined part) is not a part people name, whereas a protrusion
    * that runs far beyond a neck of the same depth (a plier handle, a finger) is. Height ratios
    * alone cannot tell them apart (both near 1.1 on the PSB's fish and pliers). Default
    * kDefaultCompactRho. */
  double compact_rho = kDefaultCompactRho;
  /** Largest compact segment, in balls (2D: discs) of the saddle's radius (dimensionless,
    * finite, >= 0; 0 = no compact merging, the paper's rule with sampling_tolerance and
    * stump_ratio 0). Default kDefaultCompactSize. */
  double compact_size = kDefaultCompactSize;
};

/** \brief Progress report: a stage name and the fraction of the whole run done (0..1). */
using ProgressCallback = std::function<void (const std::string& stage, double fraction)>;

/** \brief Estimated peak memory, in bytes, of segmenting \a points points in \a dimension (2 or 3;
  * 0 = unknown, assume 3), with interior/exterior separation and possibly denoising: about 3 KiB
  * per point in 3D (measured peak on horse.off, 48k points: see README) and 1 KiB in 2D. */
std::size_t
estimateSegmentationMemory (std::size_t points, int dimension);

/** \brief Memory the system reports available (Linux MemAvailable), in bytes; 0 when unknown. */
std::size_t
availableMemory ();

/** \brief Runs the whole flow segmentation on raw coordinates.
  *
  * \param[in] points input coordinates (z ignored for 2D input given with z = const); may
  *            contain NaN/Inf (skipped and counted) and duplicates (labelled like the first
  *            copy and counted).
  * \param[in] params parameters; rejected when absurd (rho not finite or <= 0).
  * \param[out] result everything computed; left empty on failure.
  * \param[in] progress optional progress callback.
  * \return ok, or a message saying why the input cannot be segmented (too few points,
  *         all points collinear, coplanar in 3D mode, ...). Never throws for bad input.
  */
Status
runFlowSegmentation (const std::vector<Eigen::Vector3d>& points,
                     const FlowParameters& params,
                     FlowResult& result,
                     const ProgressCallback& progress = ProgressCallback ());

/** \brief Re-runs only the merging stage of an existing result with another rho (the other
  * merge parameters at their defaults). Cheap compared to runFlowSegmentation: the
  * triangulation and flow are kept. */
Status
remergeFlowSegmentation (double rho, FlowResult& result);

/** \brief Re-runs only the merging stage with the merge parameters of \a params (rho,
  * sampling_tolerance, stump_ratio, compact_rho, compact_size; the others are ignored). */
Status
remergeFlowSegmentation (const FlowParameters& params, FlowResult& result);

} // namespace pcl_flowseg

/*
 * pcl_flowseg - shape segmentation by flow discretization (Dey, Giesen, Goswami).
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include <pcl_flowseg/flow_result.h>
#include <pcl_flowseg/status.h>

#include <functional>
#include <string>
#include <vector>

namespace pcl_flowseg {

/** \brief Default merge threshold rho (see FlowParameters::rho). */
constexpr double kDefaultRho = 1.3;

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
    * circumradius of t (paper, section 4, discrete rule; radii, not squared radii).
    * Values below 1 merge nothing. Default kDefaultRho. */
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

/** \brief Re-runs only the merging stage of an existing result with another rho.
  * Cheap compared to runFlowSegmentation: the triangulation and flow are kept. */
Status
remergeFlowSegmentation (double rho, FlowResult& result);

} // namespace pcl_flowseg

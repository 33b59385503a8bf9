/*
 * pcl_flowseg - the parameters of a flow segmentation, in groups, each default given once here.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include <pcl_flowseg/common/status.h>

#include <Eigen/Core>

#include <cstddef>
#include <optional>

namespace pcl_flowseg {

/** \brief How the dimension of the flow is chosen. */
enum class DimensionMode
{
  Automatic = 0, ///< 2D when all points lie on one plane, 3D otherwise
  Planar = 2,    ///< 2D: points are projected onto their best-fit plane
  Spatial = 3    ///< 3D: fails on coplanar input
};

/** \brief Whether the interior/exterior separation works on a smoothed copy of a noisy sample. */
enum class Denoising
{
  Automatic = 0, ///< when the sample shows noise (see docs/parameters.md)
  Off = 1,       ///< never: the sample as it is
  Always = 2     ///< always (at least one smoothing pass)
};

/** \brief Whether outliers are removed before the triangulation. */
enum class OutlierRemoval
{
  Automatic = 0, ///< when the sample shows isolated or detached points (NoiseEstimate::isolated_share, ::detached_share)
  Off = 1,       ///< never: every point is a vertex
  Always = 2     ///< always
};

/** \brief Whether a 3D sample is smoothed before the triangulation. */
enum class Smoothing
{
  Automatic = 0, ///< when the sample is rough (NoiseEstimate::roughness above kRoughSample)
  Off = 1,       ///< never: the vertices are the points
  Always = 2     ///< always, exactly PreparationParameters::smoothing_passes passes
};

/** \brief Roughness (NoiseEstimate::roughness) above which automatic smoothing acts: between the
  * clean samples of the development meshes and those with 0.25% noise (docs/method.md). */
constexpr double kRoughSample = 0.1;
/** \brief Roughness at which automatic smoothing stops: that of the roughest clean samples. */
constexpr double kSmoothedRoughness = 0.08;
/** \brief Most smoothing passes before the triangulation. */
constexpr unsigned kMaxSmoothingPasses = 8;

/** \brief Which segments are reported as features. */
enum class FeatureSide
{
  Interior = 0, ///< the shape's features
  Exterior = 1, ///< pockets and concavities outside the shape
  Both = 2      ///< every segment
};

/** \brief From input points to the triangulated vertices. */
struct PreparationParameters
{
  /** 2D or 3D flow. */
  DimensionMode dimension = DimensionMode::Automatic;
  /** Automatic mode chooses 2D when the spread of the points normal to their best-fit plane is at
    * most this share of the bounding-box diagonal (dimensionless, >= 0). */
  double planar_tolerance = 1e-9;
  /** Outliers: points PCL's StatisticalOutlierRemoval finds far from their neighbours, then points
    * still detached from the surface (2D: curve) their neighbours sample, are left out (labelled
    * kNoSegment, counted in FlowResult::outlier_points). Automatic: only when the sample shows
    * isolated or detached points. */
  OutlierRemoval outliers = OutlierRemoval::Automatic;
  /** Smoothing of a 3D sample before the triangulation (FlowResult::vertices are then the smoothed
    * positions): each pass moves every vertex along the normal of its 16 nearest neighbours by
    * their offsets, weighted down where they lie more than the estimated noise (NoiseEstimate::sigma)
    * off it, so that the two sides of a thin wall stay apart. Automatic: when the sample is rough,
    * passes until it is as smooth as a clean sample. 2D samples are never smoothed. */
  Smoothing smoothing = Smoothing::Automatic;
  /** Passes of smoothing: the most (Automatic) or exactly this many (Always); 1 to
    * kMaxSmoothingPasses. */
  unsigned smoothing_passes = 6;
};

/** \brief How stable manifolds merge into segments. All values are dimensionless; with
  * sampling_tolerance, stump_ratio, compact_size and min_part_share 0 the result is the paper's
  * segmentation. */
struct MergeParameters
{
  /** The paper's threshold (finite, > 0): two stable manifolds sharing a facet t merge when the
    * circumradii of both their maxima are below rho R(t) + sampling_tolerance s(t). Below 1
    * nothing merges. */
  double rho = 1.05;
  /** Additive slack of the rule, in local sample spacings s(t) (finite, >= 0): heights measured
    * on a sample carry an error of about the spacing. Ignored when rho < 1. */
  double sampling_tolerance = 0.5;
  /** Thin parts take back their stumps from parts more than this many times thicker
    * (circumradius ratio; 0 = off, else >= 1). */
  double stump_ratio = 2.0;
  /** Threshold of the compact pass (finite, > 0; acts only above rho): segments whose saddle
    * passes the rule at this threshold merge when the smaller is compact (see compact_size). */
  double compact_rho = 1.2;
  /** Largest compact segment, in balls (2D: discs) of its saddle's radius (finite, >= 0; 0 = no
    * compact pass). */
  double compact_size = 2.5;
  /** Smallest part, as a share of the volume (2D: area) of all segments on its side (interior,
    * exterior) in [0, 1): a smaller segment joins the neighbour on its side it shares its widest
    * saddle with, so the reported features are parts, not slivers. 0 keeps every segment. */
  double min_part_share = 0.0003;
  /** The smallest part on a single view whose hidden side was guessed
    * (FlowResult::hidden_side_vertices > 0), in [0, 1), in place of min_part_share: the guessed
    * side's thin rims add slivers that are no parts of the object. */
  double single_view_min_part_share = 0.003;

  /** \brief Switches off what goes beyond the paper's rule (sampling tolerance, compact pass,
    * stumps, small parts), keeping rho. */
  void
  usePaperRule ()
  {
    sampling_tolerance = stump_ratio = compact_size = min_part_share = single_view_min_part_share = 0.0;
  }

  /** \brief The paper's rule alone at \a rho. */
  static MergeParameters
  paperRule (double rho)
  {
    MergeParameters m;
    m.rho = rho;
    m.usePaperRule ();
    return m;
  }
};

/** \brief The separation of the shape's interior from its exterior (surface reconstruction). */
struct InteriorParameters
{
  /** Separate interior and exterior; off gives the paper's raw segmentation of the whole convex
    * hull, every segment reported. */
  bool separate = true;
  /** Smoothing of noisy samples before the separation (the flow always uses the sample as is). */
  Denoising denoising = Denoising::Automatic;
  /** Sensor position of a single-view scan, input frame: the cells the rays from it to the
    * points cross are free space, hence outside. None by default. */
  std::optional<Eigen::Vector3d> viewpoint;
  /** 3D: where the boundary between inside and outside cells is not a manifold (an edge on more
    * than two boundary facets, a vertex where its facets meet in more than one fan), the cells
    * around that vertex are relabelled until it is one: the smallest group of cells changes side.
    * Not applied with a viewpoint (a single view's boundary is open where it was not seen). */
  bool manifold_repair = true;
  /** 3D, with a viewpoint: the side of the single view the sensor cannot see is guessed before the
    * triangulation, each seen sample mirrored along its ray about the depth of the nearest rim
    * (silhouette or occlusion edge) behind it, so that parts get a volume and their own features
    * instead of one shell. The added vertices label no point (FlowResult::hidden_side_vertices). */
  bool hidden_side = true;
  /** 3D, without a viewpoint, in sample spacings (the median distance to the nearest sample): the
    * space a ball of this radius reaches from beyond the convex hull, between samples at least
    * twice as far apart, is evidence of the outside (a cup's cavity, the space under a table),
    * however the surfaces of a noisy thin wall are labelled. 0 = off; narrower openings pass
    * through the gaps of a random sample, so it must be at least kMinExteriorOpening. */
  double exterior_opening = 4.0;
};

/** \brief Smallest InteriorParameters::exterior_opening other than 0, in sample spacings (a whole
  * number: messages print it as one). */
constexpr double kMinExteriorOpening = 3.0;

/** \brief Most worker threads a run may be given (ExecutionParameters::threads). */
constexpr unsigned kMaxThreads = 1024;

/** \brief Where and how much the run may compute. The result does not depend on it. */
struct ExecutionParameters
{
  /** Worker threads for the triangulation, the per-cell stages and the inner-distance searches
    * of the shape description (signatures): 0 = all hardware threads, 1 = sequential; at most
    * kMaxThreads. */
  unsigned threads = 0;
  /** Memory the run may use, in bytes; 0 = what the system reports available. Inputs whose
    * estimated need exceeds it are refused before any work. */
  std::size_t memory_limit = 0;
};

/** \brief Everything that decides a flow segmentation. FlowResult::parameters records it. */
struct FlowParameters
{
  PreparationParameters preparation;
  MergeParameters merge;
  InteriorParameters interior;
  /** Which segments are reported as features (FlowResult::features, per-point labels). */
  FeatureSide features = FeatureSide::Interior;
  ExecutionParameters execution;
};

/** \brief Why \a merge cannot be used (a message naming the parameter), or success. */
Status
checkMergeParameters (const MergeParameters& merge);

/** \brief Why \a params cannot be used, or success: every group checked, enumerations included. */
Status
checkParameters (const FlowParameters& params);

} // namespace pcl_flowseg

/*
 * pcl_flowseg - shape segmentation by flow discretization (Dey, Giesen, Goswami).
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include <pcl_flowseg/common/flow_parameters.h>

#include <Eigen/Core>

#include <array>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace pcl_flowseg {

/** \brief Label of a point that has no segment (non-finite input coordinates). */
constexpr std::uint32_t kNoSegment = std::numeric_limits<std::uint32_t>::max();

/** \brief Marks a missing neighbour (the convex hull side of a cell). */
constexpr int kInfiniteCell = -1;

/** \brief One Delaunay cell (triangle in 2D, tetrahedron in 3D) and its place in the flow.
  *
  * Vertices are indices into the prepared point list (FlowResult::point_to_vertex maps
  * input points to them). In 2D only the first three entries of \a vertices and
  * \a neighbors are used; the fourth is -1. neighbors[i] is the cell across the facet
  * opposite vertices[i], or kInfiniteCell on the convex hull.
  */
struct FlowCell
{
  std::array<int, 4> vertices{{-1, -1, -1, -1}};
  std::array<int, 4> neighbors{{kInfiniteCell, kInfiniteCell, kInfiniteCell, kInfiniteCell}};
  /** Bit i set: the cell flows across the facet opposite vertices[i] (paper's relation <). */
  std::uint8_t flow_mask = 0;
  /** Index of the facet (0..d) the strengthened flow keeps, or -1 for a maximum. */
  std::int8_t successor_facet = -1;
  /** Interior/exterior label: 1 inside the shape, 0 outside, -1 not computed. */
  std::int8_t inside = -1; // beside the other bytes: a FlowCell is 88 bytes, not 96
  /** Squared circumradius (the height of the cell's Voronoi vertex). */
  double squared_radius = 0.0;
  /** Area (2D) or volume (3D). */
  double volume = 0.0;
  /** Centroid of the cell, in the frame of the input cloud. */
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero ();
  /** Stable manifold (before merging) the cell belongs to: index into FlowResult::manifolds. */
  int manifold = -1;
  /** Segment (after merging) the cell belongs to: index into FlowResult::segments. */
  int segment = -1;
};

/** \brief A maximum of the distance function: a cell that contains its own circumcentre. */
struct FlowMaximum
{
  int cell = -1;                                   ///< cell holding the maximum
  Eigen::Vector3d location = Eigen::Vector3d::Zero (); ///< the circumcentre (input frame)
  double height = 0.0;                             ///< squared circumradius
};

/** \brief A facet shared by two cells of different segments whose circumradius is the highest
  * among all facets those two segments share: the discrete saddle between them. */
struct SaddleFacet
{
  int segment_a = -1;            ///< smaller segment (or manifold) index of the pair
  int segment_b = -1;            ///< larger segment (or manifold) index of the pair
  int cell = -1;                 ///< a cell on one side of the facet
  int facet = -1;                ///< facet of \a cell (index of the opposite vertex)
  std::array<int, 3> vertices{{-1, -1, -1}}; ///< facet vertices (third is -1 in 2D)
  double squared_radius = 0.0;   ///< squared circumradius of the facet (its height)
  Eigen::Vector3d location = Eigen::Vector3d::Zero (); ///< centre of the facet's smallest circumsphere
};

/** \brief A set of cells: a stable manifold of one maximum, or a segment after merging. */
struct FlowSegment
{
  /** True for the cells whose flow leaves the convex hull (the maximum at infinity). */
  bool flows_to_infinity = false;
  /** 1: a feature of the shape's interior, 0: of the exterior, -1: not separated. */
  std::int8_t interior = -1;
  /** Highest maximum of the segment (for the infinity segment: cell -1, height +inf). */
  FlowMaximum maximum;
  /** Indices into FlowResult::maxima of all maxima merged into this segment. */
  std::vector<int> maxima;
  double volume = 0.0;                         ///< area (2D) or volume (3D)
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero (); ///< volume-weighted centroid
  std::size_t cell_count = 0;                  ///< number of Delaunay cells
  std::size_t point_count = 0;                 ///< number of input points labelled with it
};

/** \brief Wall-clock time of each stage of FlowSegmentation, in milliseconds. */
struct StageTimings
{
  double preparation_ms = 0.0; ///< finite filter, duplicates, dimension detection
  double noise_ms = 0.0;       ///< the noise estimate
  double delaunay_ms = 0.0;    ///< CGAL triangulation and its conversion to cells in canonical order
  double flow_ms = 0.0;        ///< flow relation (exact predicates), circumradii, volumes, centroids;
                               ///< the flow relation runs just before manifolds_ms, on its thread
  double manifolds_ms = 0.0;   ///< strengthened flow, maxima, stable manifolds and their adjacency
  double interior_ms = 0.0;    ///< interior/exterior separation (surface reconstruction); with
                               ///< more than one thread it runs at the same time as the flow
                               ///< relation and manifolds_ms
  double merge_ms = 0.0;       ///< rho-merging and segment statistics
  double labels_ms = 0.0;      ///< per-point labels
  double total_ms = 0.0;
};

/** \brief The sample's noise, estimated before the triangulation. */
struct NoiseEstimate
{
  /** Median over the vertices used of the standard deviation of their nearest neighbours (a fixed
    * number of them) along the neighbourhood's PCA normal (2D: the curve's normal), in the input's
    * unit: about the noise's standard deviation on a noisy sample, near 0 on a clean dense one
    * (curvature adds a little). */
  double sigma = 0.0;
  /** sigma as a share of the bounding-box diagonal of the vertices (dimensionless). */
  double share = 0.0;
  /** Vertices whose neighbourhoods the estimate measured: all, or an evenly spaced
    * kNoiseEstimatePoints when there are more (their neighbours taken among all vertices, or among
    * an evenly spaced subset of them on very large samples). */
  std::size_t points_used = 0;
  /** Share of those vertices whose distance to one of their nearest neighbours (the same rank for
    * every vertex) is more than kIsolatedDistance times the median such distance: isolated points,
    * outliers. */
  double isolated_share = 0.0;
  /** Share of those vertices that lie off the PCA plane (2D: line) of their nearest other vertices
    * (the neighbourhood of sigma) by more than about a sample spacing plus a few of those
    * neighbours' standard deviations along its normal: points detached from the surface, outliers
    * near it included. */
  double detached_share = 0.0;
  /** Median over the vertices used of the standard deviation of their kRoughnessNeighbours nearest
    * neighbours along the neighbourhood's PCA normal, in sample spacings (the median of the
    * neighbour distances isolated_share compares): too few neighbours to reach across a thin wall,
    * so unlike sigma it stays near 0 on every clean sample and tells noise (dimensionless). */
  double roughness = 0.0;
};

/** \brief Neighbours of the roughness measure (NoiseEstimate::roughness). */
constexpr std::size_t kRoughnessNeighbours = 8;

/** \brief Most vertices whose neighbourhoods the noise estimate measures: enough for a stable
  * median and a fine-grained isolated share, few enough to cost little next to the triangulation. */
constexpr std::size_t kNoiseEstimatePoints = 4000;
/** \brief A vertex is isolated when the distance to one of its nearest neighbours (the same rank
  * for every vertex) is this many times the median such distance (surface samples, noisy or
  * scanned at grazing angles, rarely are). */
constexpr double kIsolatedDistance = 8.0;
/** \brief Share of isolated vertices above which automatic outlier removal acts. */
constexpr double kIsolatedShare = 0.001;
/** \brief Share of detached vertices (NoiseEstimate::detached_share) above which automatic outlier
  * removal acts. */
constexpr double kDetachedShare = 0.004;
/** \brief Fewest isolated (or detached) vertices on which automatic outlier removal acts: in a small
  * sample one or two are more likely a gap in the sampling than outliers. */
constexpr std::size_t kIsolatedMinimum = 3;

/** \brief What the interior/exterior separation found. */
struct InteriorReport
{
  bool computed = false;
  double inside_volume = 0.0;       ///< total volume (area) of the cells labelled inside
  std::size_t inside_cells = 0;
  std::size_t boundary_facets = 0;  ///< facets between inside and outside (the surface/curve)
  /** Boundary edges (3D) or vertices (2D) not shared by exactly two boundary facets. */
  std::size_t nonmanifold_edges = 0;
  /** Boundary vertices whose boundary facets do not form a single disk (3D) or which lie on
    * more than two boundary edges (2D). */
  std::size_t nonmanifold_vertices = 0;
  /** Sample points on no boundary facet (inside the shape, or in a spurious pocket). */
  std::size_t vertices_off_boundary = 0;
  bool closed = false;   ///< every boundary edge (3D) / vertex (2D) bounds an even number of facets
  /** Cells labelled outside as tiny pockets cut off from the rest of the interior (single views
    * with a guessed hidden side only). */
  std::size_t island_cells = 0;
  /** Cells relabelled to make the boundary a manifold (InteriorParameters::manifold_repair). */
  std::size_t repaired_cells = 0;
  bool manifold = false; ///< closed, and no non-manifold edge or vertex
  std::size_t ray_cells = 0; ///< cells marked outside by sensor rays (viewpoint given)
  /** Cells marked outside as reached from beyond the convex hull through openings wider than
    * InteriorParameters::exterior_opening (3D without a viewpoint). */
  std::size_t opening_cells = 0;
  /** Median over the samples of the surface variation of their nearest neighbours (smallest
    * PCA eigenvalue over the sum; in 2D the same for the curve): small for clean dense samples,
    * large for noisy ones. Computed only when the raw labelling left many samples off its boundary
    * (or denoising is Always); -1 otherwise. */
  double surface_variation = -1.0;
  /** Smoothing passes applied before separating interior and exterior (0: the sample as given). */
  int smoothing_passes = 0;
};

/** \brief Everything FlowSegmentation computes, with no CGAL type in it. */
struct FlowResult
{
  int dimension = 0;                 ///< 2 or 3: the dimension the flow was computed in
  std::size_t input_points = 0;      ///< points handed in (after setIndices)
  std::size_t non_finite_points = 0; ///< points skipped for NaN/Inf coordinates
  std::size_t duplicate_points = 0;  ///< points equal to an earlier point (labelled like it)
  std::size_t outlier_points = 0;    ///< points left out as outliers (label kNoSegment)
  unsigned smoothing_passes = 0;     ///< smoothing passes applied to the vertices before the triangulation
  /** Vertices added behind a single view (the side the sensor cannot see), the last ones of
    * \a vertices; they label no input point. */
  std::size_t hidden_side_vertices = 0;

  /** Coordinates of the unique finite points (the triangulation's vertices), input frame, in a
    * spatial order (along a Z-order curve), not in input order: use point_to_vertex. The last
    * hidden_side_vertices of them were guessed behind a single view. */
  std::vector<Eigen::Vector3d> vertices;
  /** For each input point, its vertex in \a vertices, or -1 when it was not finite. */
  std::vector<int> point_to_vertex;

  std::vector<FlowCell> cells;        ///< all finite Delaunay cells
  std::vector<FlowMaximum> maxima;    ///< all maxima, ordered by decreasing height
  /** Stable manifolds before merging; the last one flows to infinity when any cell does. */
  std::vector<FlowSegment> manifolds;
  /** Segments after rho-merging: interior ones by decreasing volume, then exterior ones, the one at
    * infinity last. With interior/exterior separation every cell belongs to a segment of its own
    * side: a cell whose flow leaves its side joins the neighbouring segment of its side it touches
    * through its highest facet. */
  std::vector<FlowSegment> segments;
  /** Saddles between adjacent stable manifolds (segment_a/b index \a manifolds). */
  std::vector<SaddleFacet> manifold_adjacency;
  /** Saddles between adjacent segments after merging (segment_a/b index \a segments). */
  std::vector<SaddleFacet> segment_adjacency;

  /** The parameters the result was computed with (after remergeFlowSegmentation: its merge group). */
  FlowParameters parameters;

  /** The sample's estimated noise. */
  NoiseEstimate noise;
  /** Interior/exterior separation summary (computed = false when it was switched off). */
  InteriorReport interior;
  /** Segments reported as features, in order: indices into \a segments. Without interior/exterior
    * separation, every segment. */
  std::vector<int> features;

  /** Feature of each input point: index into \a features (so into the PointIndices returned by
    * FlowSegmentation::segment), or kNoSegment for non-finite points and points with no incident
    * cell on the reported side. */
  std::vector<std::uint32_t> point_labels;

  /** Cells that could not be ordered by the flow (only on degenerate input; they become
    * their own maxima). Zero in exact arithmetic; reported to make any such case visible. */
  std::size_t cycle_breaks = 0;

  StageTimings timings;
  std::vector<std::string> warnings; ///< human-readable notes about the input

  /** Points with finite coordinates that touch no reported feature (label kNoSegment). */
  std::size_t unlabelledPoints () const;
  /** For each segment its index in \a features, or -1 when it is not reported. */
  std::vector<int> featureOfSegment () const;
};

} // namespace pcl_flowseg

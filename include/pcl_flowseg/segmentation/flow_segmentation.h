/*
 * pcl_flowseg - shape segmentation by flow discretization (Dey, Giesen, Goswami).
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include <pcl_flowseg/segmentation/flow_pipeline.h>
#include <pcl_flowseg/segmentation/flow_result.h>

#include <pcl/PointIndices.h>
#include <pcl/pcl_base.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <string>
#include <vector>

namespace pcl {

/** \brief Segments a point sample of a closed curve (2D) or surface (3D) into the stable
  * manifolds of the maxima of its distance function (Dey, Giesen, Goswami 2003), merged by the
  * rho rule.
  *
  * The flow is computed on the Delaunay triangulation of the points (CGAL, exact predicates),
  * exactly in 2D and with the paper's strengthened flow relation in 3D. Segments are sets of
  * Delaunay cells; each input point is labelled with the segment owning most of the volume of
  * its incident cells.
  *
  * The cells are labelled inside or outside the sampled shape by a surface (curve) reconstruction;
  * by default the interior segments are reported: the shape's features. The exterior segments
  * (pockets, concavities) or all segments are available with setFeatureSide().
  *
  * Usage:
  * \code
  * pcl::FlowSegmentation<pcl::PointXYZ> seg;
  * seg.setInputCloud (cloud);
  * seg.setRho (1.3);
  * std::vector<pcl::PointIndices> segments;
  * if (!seg.segment (segments)) std::cerr << seg.getLastError () << "\n";
  * \endcode
  */
template <typename PointT>
class FlowSegmentation : public PCLBase<PointT>
{
  using BasePCLBase = PCLBase<PointT>;
  using BasePCLBase::deinitCompute;
  using BasePCLBase::indices_;
  using BasePCLBase::initCompute;
  using BasePCLBase::input_;

public:
  using Ptr = shared_ptr<FlowSegmentation<PointT>>;
  using ConstPtr = shared_ptr<const FlowSegmentation<PointT>>;
  using PointCloudConstPtr = typename PointCloud<PointT>::ConstPtr;

  FlowSegmentation () = default;

  /** \brief Merge threshold rho (dimensionless, finite, > 0; default pcl_flowseg::kDefaultRho).
    * Two stable manifolds sharing a facet t merge when both their maximum cells have a
    * circumradius below rho times the circumradius of t plus the sampling tolerance (see
    * setSamplingTolerance). Below 1 nothing merges; larger values merge more (never giving more
    * segments). */
  inline void setRho (double rho) { params_.rho = rho; }
  inline double getRho () const { return params_.rho; }

  /** \brief Additive tolerance of the merge rule, in local sample spacings (finite, >= 0;
    * default pcl_flowseg::kDefaultSamplingTolerance = 0.5). Two stable manifolds sharing a facet
    * t merge when both their maxima have a circumradius below rho R(t) + tolerance s(t), s(t)
    * being the mean nearest-neighbour distance of t's vertices: heights measured on a sample
    * carry an error of about the sample spacing, which in parts as thin as the spacing (walls,
    * plates) is as large as the differences the ratio rho tests. 0 gives the paper's rule
    * exactly; ignored when rho < 1. */
  inline void setSamplingTolerance (double tolerance) { params_.sampling_tolerance = tolerance; }
  inline double getSamplingTolerance () const { return params_.sampling_tolerance; }

  /** \brief Thin parts take back their stumps (ratio of circumradii: 0 = off, else >= 1; default
    * pcl_flowseg::kDefaultStumpRatio = 2). The flow cuts a finger or leg off the body where it is
    * narrowest, leaving the stretch from there to the body (the stump) with the body. Where a
    * segment borders one whose highest maximum is more than this ratio thicker, the thick
    * segment's cells connected to the thin one through cells no larger than the thin one's
    * highest maximum join the thin one. 0 gives the paper's segments. */
  inline void setStumpRatio (double ratio) { params_.stump_ratio = ratio; }
  inline double getStumpRatio () const { return params_.stump_ratio; }

  /** \brief Merge threshold for compact segments (dimensionless, finite, > 0; default
    * pcl_flowseg::kDefaultCompactRho = 1.2; acts only when above rho). After merging at rho, two
    * segments whose saddle passes the rule at this threshold merge when the smaller holds no
    * more than setCompactSize balls of the saddle's radius: a shallow bulge no bigger than its
    * neck is not a part, a protrusion that runs far beyond a neck of the same depth (a handle,
    * a finger) is. */
  inline void setCompactRho (double rho) { params_.compact_rho = rho; }
  inline double getCompactRho () const { return params_.compact_rho; }

  /** \brief Largest compact segment, in balls (2D: discs) of the saddle's radius (finite, >= 0;
    * default pcl_flowseg::kDefaultCompactSize = 2.5; 0 = off). With sampling tolerance, stump
    * ratio and compact size 0 the segments are the paper's. */
  inline void setCompactSize (double size) { params_.compact_size = size; }
  inline double getCompactSize () const { return params_.compact_size; }

  /** \brief 0 = automatic (default: 2D when all points lie on one plane), 2 or 3 to force. */
  inline void
  setDimension (int dimension)
  {
    params_.dimension = dimension == 2 ? pcl_flowseg::DimensionMode::Planar
                        : dimension == 3 ? pcl_flowseg::DimensionMode::Spatial
                                         : pcl_flowseg::DimensionMode::Automatic;
    dimension_ok_ = dimension == 0 || dimension == 2 || dimension == 3;
  }
  inline int getDimension () const { return static_cast<int> (params_.dimension); }

  /** \brief Flatness (spread normal to the best-fit plane / bounding-box diagonal) below which
    * automatic mode chooses 2D. Default 1e-9. */
  inline void setPlanarTolerance (double tolerance) { params_.planar_tolerance = tolerance; }
  inline double getPlanarTolerance () const { return params_.planar_tolerance; }

  /** \brief Worker threads for the triangulation and the per-cell stages: 0 (default) = all
    * hardware threads, 1 = sequential. The result is the same for every value. */
  inline void setNumberOfThreads (unsigned int threads) { params_.threads = threads; }
  inline unsigned int getNumberOfThreads () const { return params_.threads; }

  /** \brief Separate interior and exterior (default true). False gives the paper's raw
    * segmentation of the whole convex hull, every segment reported. */
  inline void setSeparateInterior (bool separate) { params_.separate_interior = separate; }
  inline bool getSeparateInterior () const { return params_.separate_interior; }

  /** \brief Which segments segment() reports: Interior (default), Exterior or Both. */
  inline void setFeatureSide (pcl_flowseg::FeatureSide side) { params_.features = side; }
  inline pcl_flowseg::FeatureSide getFeatureSide () const { return params_.features; }

  /** \brief Denoising before interior/exterior separation: Automatic (default), Off, Always. */
  inline void setDenoising (pcl_flowseg::Denoising mode) { params_.denoising = mode; }
  inline pcl_flowseg::Denoising getDenoising () const { return params_.denoising; }

  /** \brief Use the points' normals (point types with normal_x/y/z; they must point outwards)
    * as evidence for interior/exterior. Default false. Ignored for types without normals. */
  inline void setUseNormals (bool use) { use_normals_ = use; }
  inline bool getUseNormals () const { return use_normals_; }

  /** \brief Treat the input cloud's sensor_origin_ as the viewpoint of a single-view scan: the
    * space the rays from it to the points cross is outside. Default false. */
  inline void setUseSensorOrigin (bool use) { use_sensor_origin_ = use; }
  inline bool getUseSensorOrigin () const { return use_sensor_origin_; }

  /** \brief Called with a stage name and the fraction done; empty by default. */
  inline void setProgressCallback (const pcl_flowseg::ProgressCallback& cb) { progress_ = cb; }

  /** \brief Segments the input (honouring setIndices).
    * \param[out] segments one PointIndices per reported feature, in the order of
    *             getResult().features (by decreasing volume; interior features first when both
    *             sides are reported; the segment at infinity last), holding indices into the input
    *             cloud. A point belongs to the feature holding most of the volume of its incident
    *             cells on the reported side.
    * \return false on bad input or parameters; getLastError() says why, segments is empty. */
  bool segment (std::vector<PointIndices>& segments);

  /** \brief Re-runs only the merging with another rho (keeps triangulation and flow; the
    * sampling tolerance, stump ratio, compact rho and compact size are the ones set).
    * \return false when segment() has not succeeded before or rho or the tolerance is invalid. */
  bool remerge (double rho, std::vector<PointIndices>& segments);

  /** \brief One PointXYZL per point of the input cloud, in input order: label = index into the
    * segments returned by segment(); points outside the indices, with non-finite coordinates or
    * touching no reported feature get pcl_flowseg::kNoSegment. */
  void getLabelCloud (PointCloud<PointXYZL>& labels) const;

  /** \brief Everything computed by the last successful segment(): cells, maxima, stable
    * manifolds, segments, adjacency (saddles), per-point labels. */
  inline const pcl_flowseg::FlowResult& getResult () const { return result_; }
  /** \brief Stage timings of the last run, in milliseconds. */
  inline const pcl_flowseg::StageTimings& getTimings () const { return result_.timings; }
  /** \brief Why the last segment() or remerge() failed (empty after success). */
  inline const std::string& getLastError () const { return last_error_; }

protected:
  void extractIndices (std::vector<PointIndices>& segments) const;
  void copyNormals (std::vector<Eigen::Vector3d>& normals) const;

  pcl_flowseg::FlowParameters params_;
  bool dimension_ok_ = true;
  bool use_normals_ = false;
  bool use_sensor_origin_ = false;
  pcl_flowseg::ProgressCallback progress_;
  pcl_flowseg::FlowResult result_;
  std::vector<index_t> used_indices_; ///< cloud index of each point handed to the core
  std::string last_error_;
};

} // namespace pcl

#ifdef PCL_NO_PRECOMPILE
#include <pcl_flowseg/segmentation/impl/flow_segmentation.hpp>
#endif

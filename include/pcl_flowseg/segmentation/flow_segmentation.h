/*
 * pcl_flowseg - pcl::FlowSegmentation: the shape's features of a point cloud, as PointIndices.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include <pcl_flowseg/common/flow_parameters.h>
#include <pcl_flowseg/segmentation/flow_pipeline.h>
#include <pcl_flowseg/common/flow_result.h>

#include <pcl/PointIndices.h>
#include <pcl/pcl_base.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <string>
#include <vector>

namespace pcl {

/** \brief Segments a point sample of a closed curve (2D) or surface (3D) into the stable
  * manifolds of the maxima of its distance function (Dey, Giesen, Goswami 2003), merged by the
  * rho rule; by default the interior segments are reported: the shape's features.
  *
  * The parameters are a pcl_flowseg::FlowParameters (setParameters; docs/parameters.md lists
  * them all); setRho, setDimension, setFeatureSide and setNumberOfThreads change one field each.
  * Bad values are reported by segment(), not by the setters.
  *
  * \code
  * pcl::FlowSegmentation<pcl::PointXYZ> seg;
  * seg.setInputCloud (cloud);
  * seg.setRho (1.3);
  * std::vector<pcl::PointIndices> features;
  * if (!seg.segment (features)) std::cerr << seg.getLastError () << "\n";
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

  /** \brief All parameters at once (pcl_flowseg::FlowParameters; its defaults are the class's). */
  inline void setParameters (const pcl_flowseg::FlowParameters& params) { params_ = params; }
  inline const pcl_flowseg::FlowParameters& getParameters () const { return params_; }

  /** \brief pcl_flowseg::MergeParameters::rho, the paper's merge threshold (default 1.05). */
  inline void setRho (double rho) { params_.merge.rho = rho; }
  inline double getRho () const { return params_.merge.rho; }
  /** \brief pcl_flowseg::PreparationParameters::dimension as a number: 0 = automatic (default), 2 or 3. */
  inline void setDimension (int dimension) { params_.preparation.dimension = static_cast<pcl_flowseg::DimensionMode> (dimension); }
  inline int getDimension () const { return static_cast<int> (params_.preparation.dimension); }
  /** \brief pcl_flowseg::FlowParameters::features: which segments are reported (default Interior). */
  inline void setFeatureSide (pcl_flowseg::FeatureSide side) { params_.features = side; }
  inline pcl_flowseg::FeatureSide getFeatureSide () const { return params_.features; }
  /** \brief pcl_flowseg::ExecutionParameters::threads: 0 = all cores (default), 1 = sequential. */
  inline void setNumberOfThreads (unsigned int threads) { params_.execution.threads = threads; }
  inline unsigned int getNumberOfThreads () const { return params_.execution.threads; }

  /** \brief Use the points' normals (types with normal_x/y/z, pointing outwards) as evidence for
    * interior/exterior. Default false; ignored for point types without normals. */
  inline void setUseNormals (bool use) { use_normals_ = use; }
  inline bool getUseNormals () const { return use_normals_; }
  /** \brief Take the viewpoint of a single-view scan (pcl_flowseg::InteriorParameters::viewpoint)
    * from the input cloud's sensor_origin_. Default false. */
  inline void setUseSensorOrigin (bool use) { use_sensor_origin_ = use; }
  inline bool getUseSensorOrigin () const { return use_sensor_origin_; }

  /** \brief Called with a stage name and the share done; none by default. */
  inline void setProgressCallback (const pcl_flowseg::ProgressCallback& cb) { progress_ = cb; }

  /** \brief Segments the input (honouring setIndices).
    * \param[out] segments one PointIndices per reported feature, in the order of
    *             getResult().features, holding indices into the input cloud. A point belongs to
    *             the feature holding most of the volume of its incident cells on the reported side.
    * \return false on bad input or parameters; getLastError() says why, segments is empty. */
  bool segment (std::vector<PointIndices>& segments);

  /** \brief Merges again with \a merge, keeping the triangulation, flow and interior of the last
    * segment(); \a merge becomes the class's merge group.
    * \return false when segment() has not succeeded before or \a merge is invalid. */
  bool remerge (const pcl_flowseg::MergeParameters& merge, std::vector<PointIndices>& segments);
  /** \brief remerge with the current merge group, rho replaced by \a rho. */
  bool remerge (double rho, std::vector<PointIndices>& segments);

  /** \brief One PointXYZL per point of the input cloud, in input order: label = index into the
    * segments returned by segment(); points outside the indices, with non-finite coordinates or
    * touching no reported feature get pcl_flowseg::kNoSegment. */
  void getLabelCloud (PointCloud<PointXYZL>& labels) const;

  /** \brief Everything the last successful segment() or remerge() computed, with the parameters. */
  inline const pcl_flowseg::FlowResult& getResult () const { return result_; }
  /** \brief Stage timings of the last run, in milliseconds. */
  inline const pcl_flowseg::StageTimings& getTimings () const { return result_.timings; }
  /** \brief Why the last segment() or remerge() failed (empty after success). */
  inline const std::string& getLastError () const { return last_error_; }

protected:
  void extractIndices (std::vector<PointIndices>& segments) const;
  void copyNormals (std::vector<Eigen::Vector3d>& normals) const;

  pcl_flowseg::FlowParameters params_;
  bool use_normals_ = false;
  bool use_sensor_origin_ = false;
  pcl_flowseg::ProgressCallback progress_;
  pcl_flowseg::FlowResult result_;
  std::vector<index_t> used_indices_; ///< cloud index of each point handed to the pipeline
  std::string last_error_;
};

} // namespace pcl

#ifdef PCL_NO_PRECOMPILE
#include <pcl_flowseg/segmentation/impl/flow_segmentation.hpp>
#endif

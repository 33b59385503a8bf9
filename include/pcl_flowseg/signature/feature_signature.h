/*
 * pcl_flowseg - pcl::FeatureSignature: a shape's significant features as weighted points.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include <pcl_flowseg/segmentation/flow_segmentation.h>
#include <pcl_flowseg/signature/signature.h>

namespace pcl {

/** \brief Segments a point sample (FlowSegmentation, interior features) and keeps the significant
  * features as a normalised pcl_flowseg::Signature (volume share as weight, volume-weighted
  * centroid as position; invariant to translation, rotation, mirroring and uniform scale), with the
  * shape's description (parts and interior distributions) that the default match method compares.
  *
  * \code
  * pcl::FeatureSignature<pcl::PointXYZ> sig;
  * sig.setInputCloud (cloud);
  * pcl_flowseg::Signature s;
  * if (!sig.compute (s)) std::cerr << sig.getLastError () << "\n";
  * \endcode
  */
template <typename PointT>
class FeatureSignature : public PCLBase<PointT>
{
  using BasePCLBase = PCLBase<PointT>;
  using BasePCLBase::indices_;
  using BasePCLBase::input_;

public:
  using Ptr = shared_ptr<FeatureSignature<PointT>>;
  using ConstPtr = shared_ptr<const FeatureSignature<PointT>>;

  FeatureSignature () = default;

  /** \brief A feature is significant when its volume exceeds this fraction of the interior volume
    * (default pcl_flowseg::kDefaultSignificance). */
  inline void setSignificance (double fraction) { significance_ = fraction; }
  inline double getSignificance () const { return significance_; }

  /** \brief The segmentation used (its setters: rho, dimension, denoising, normals, ...). */
  inline FlowSegmentation<PointT>& getSegmentation () { return segmentation_; }
  inline const FlowSegmentation<PointT>& getSegmentation () const { return segmentation_; }

  /** \brief Computes the signature of the input (honouring setIndices).
    * \return false on bad input; getLastError() says why. */
  bool compute (pcl_flowseg::Signature& signature);

  inline const std::string& getLastError () const { return last_error_; }

protected:
  double significance_ = pcl_flowseg::kDefaultSignificance;
  FlowSegmentation<PointT> segmentation_;
  std::string last_error_;
};

} // namespace pcl

#ifdef PCL_NO_PRECOMPILE
#include <pcl_flowseg/signature/impl/feature_signature.hpp>
#endif

/*
 * pcl_flowseg - template implementation of pcl::FeatureSignature.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include <pcl_flowseg/signature/feature_signature.h>

namespace pcl {

template <typename PointT> bool
FeatureSignature<PointT>::compute (pcl_flowseg::Signature& signature)
{
  last_error_.clear ();
  segmentation_.setInputCloud (input_);
  segmentation_.setIndices (indices_);
  pcl_flowseg::FlowParameters params = segmentation_.getParameters ();
  params.interior.separate = true;
  segmentation_.setParameters (params);
  std::vector<PointIndices> features;
  if (!segmentation_.segment (features))
  {
    last_error_ = segmentation_.getLastError ();
    return false;
  }
  const pcl_flowseg::Status s = pcl_flowseg::signatureFromSegmentation (segmentation_.getResult (), significance_, signature);
  if (!s.ok)
    last_error_ = s.message;
  return s.ok;
}

} // namespace pcl

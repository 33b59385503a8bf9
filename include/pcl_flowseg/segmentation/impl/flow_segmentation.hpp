/*
 * pcl_flowseg - template implementation of pcl::FlowSegmentation.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include <pcl_flowseg/segmentation/flow_segmentation.h>

#include <pcl/console/print.h>
#include <pcl/type_traits.h>

namespace pcl {

template <typename PointT> bool
FlowSegmentation<PointT>::segment (std::vector<PointIndices>& segments)
{
  segments.clear ();
  result_ = pcl_flowseg::FlowResult ();
  used_indices_.clear ();
  last_error_.clear ();
  if (!input_)
    last_error_ = "no input cloud given (setInputCloud)";
  else if (!initCompute ())
    last_error_ = "invalid input cloud or indices";
  if (!last_error_.empty ())
  {
    PCL_ERROR ("[pcl::FlowSegmentation::segment] %s\n", last_error_.c_str ());
    return false;
  }

  std::vector<Eigen::Vector3d> points, normals;
  points.reserve (indices_->size ());
  used_indices_.reserve (indices_->size ());
  for (const auto idx : *indices_)
  {
    const PointT& p = (*input_)[idx];
    points.emplace_back (p.x, p.y, p.z);
    used_indices_.push_back (idx);
  }
  if (use_normals_)
    copyNormals (normals);
  pcl_flowseg::FlowParameters params = params_;
  if (use_sensor_origin_)
    params.interior.viewpoint = input_->sensor_origin_.template head<3> ().template cast<double> ();
  const pcl_flowseg::Status status = pcl_flowseg::runFlowSegmentation (points, normals, params, result_, progress_);
  deinitCompute ();
  if (!status.ok)
  {
    last_error_ = status.message;
    PCL_ERROR ("[pcl::FlowSegmentation::segment] %s\n", last_error_.c_str ());
    return false;
  }
  for (const std::string& w : result_.warnings)
    PCL_WARN ("[pcl::FlowSegmentation::segment] %s\n", w.c_str ());
  extractIndices (segments);
  return true;
}

template <typename PointT> bool
FlowSegmentation<PointT>::remerge (const pcl_flowseg::MergeParameters& merge, std::vector<PointIndices>& segments)
{
  segments.clear ();
  const pcl_flowseg::Status status = pcl_flowseg::remergeFlowSegmentation (merge, result_);
  if (!status.ok)
  {
    last_error_ = status.message;
    PCL_ERROR ("[pcl::FlowSegmentation::remerge] %s\n", last_error_.c_str ());
    return false;
  }
  last_error_.clear ();
  params_.merge = merge;
  extractIndices (segments);
  return true;
}

template <typename PointT> bool
FlowSegmentation<PointT>::remerge (double rho, std::vector<PointIndices>& segments)
{
  pcl_flowseg::MergeParameters merge = params_.merge;
  merge.rho = rho;
  return remerge (merge, segments);
}

template <typename PointT> void
FlowSegmentation<PointT>::extractIndices (std::vector<PointIndices>& segments) const
{
  segments.assign (result_.features.size (), PointIndices ());
  for (auto& s : segments)
    s.header = input_->header;
  for (std::size_t k = 0; k < segments.size (); ++k)
    segments[k].indices.reserve (result_.segments[static_cast<std::size_t> (result_.features[k])].point_count);
  for (std::size_t i = 0; i < result_.point_labels.size (); ++i)
  {
    const std::uint32_t label = result_.point_labels[i];
    if (label != pcl_flowseg::kNoSegment)
      segments[label].indices.push_back (used_indices_[i]);
  }
}

template <typename PointT> void
FlowSegmentation<PointT>::copyNormals (std::vector<Eigen::Vector3d>& normals) const
{
  normals.clear ();
  if constexpr (pcl::traits::has_normal_v<PointT>)
  {
    normals.reserve (indices_->size ());
    for (const auto idx : *indices_)
    {
      const PointT& p = (*input_)[idx];
      normals.emplace_back (p.normal_x, p.normal_y, p.normal_z);
    }
  }
}

template <typename PointT> void
FlowSegmentation<PointT>::getLabelCloud (PointCloud<PointXYZL>& labels) const
{
  labels.clear ();
  if (!input_)
    return;
  labels.header = input_->header;
  labels.resize (input_->size ());
  for (std::size_t i = 0; i < input_->size (); ++i)
  {
    const PointT& p = (*input_)[i];
    PointXYZL& q = labels[i];
    q.x = p.x;
    q.y = p.y;
    q.z = p.z;
    q.label = pcl_flowseg::kNoSegment;
  }
  for (std::size_t i = 0; i < result_.point_labels.size (); ++i)
    labels[static_cast<std::size_t> (used_indices_[i])].label = result_.point_labels[i];
  labels.width = input_->width;
  labels.height = input_->height;
  labels.is_dense = input_->is_dense;
}

} // namespace pcl


/*
 * pcl_flowseg - explicit instantiations of pcl::FlowSegmentation.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include <pcl_flowseg/segmentation/flow_segmentation.h>
#include <pcl_flowseg/segmentation/impl/flow_segmentation.hpp>

template class pcl::FlowSegmentation<pcl::PointXYZ>;
template class pcl::FlowSegmentation<pcl::PointXYZI>;
template class pcl::FlowSegmentation<pcl::PointXYZRGB>;
template class pcl::FlowSegmentation<pcl::PointXYZRGBA>;
template class pcl::FlowSegmentation<pcl::PointNormal>;
template class pcl::FlowSegmentation<pcl::PointXYZRGBNormal>;

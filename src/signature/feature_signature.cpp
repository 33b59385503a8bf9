/*
 * pcl_flowseg - explicit instantiations of pcl::FeatureSignature.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include <pcl_flowseg/signature/feature_signature.h>
#include <pcl_flowseg/signature/impl/feature_signature.hpp>

template class pcl::FeatureSignature<pcl::PointXYZ>;
template class pcl::FeatureSignature<pcl::PointXYZI>;
template class pcl::FeatureSignature<pcl::PointXYZRGB>;
template class pcl::FeatureSignature<pcl::PointXYZRGBA>;
template class pcl::FeatureSignature<pcl::PointNormal>;
template class pcl::FeatureSignature<pcl::PointXYZRGBNormal>;

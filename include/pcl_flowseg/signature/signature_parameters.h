/*
 * pcl_flowseg - how shape files become signatures: the sampling of meshes and the share of the
 * volume that makes a feature significant, with the table that describes them.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include <pcl_flowseg/common/feature_significance.h>
#include <pcl_flowseg/common/parameter_table.h>
#include <pcl_flowseg/io/shape_input.h>

namespace pcl_flowseg {

/** \brief What turns a shape file into a signature, besides the segmentation's FlowParameters. */
struct SignatureParameters
{
  /** Features above this share of the interior volume are significant (checkSignificance). */
  double significance = kDefaultSignificance;
  /** How files are read: meshes sampled, the sensor origin used. */
  ShapeInputOptions input;
};

/** \brief Why \a params cannot be used, or success. */
Status
checkSignatureParameters (const SignatureParameters& params);

/** \brief The parameters of SignatureParameters, described once (see flowParameterTable). */
const ParameterTable<SignatureParameters>&
signatureParameterTable ();

} // namespace pcl_flowseg

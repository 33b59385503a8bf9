/*
 * pcl_flowseg evaluation - the methods single-view recognition compares: this module's signatures,
 * PCL's ESF of a complete sample, PCL's ESF of rendered views.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include <pcl_flowseg/common/status.h>
#include <pcl_flowseg/signature/match_method.h>

#include <string>
#include <vector>

namespace pcl_flowseg {

/** \brief What a recognition method describes a model by. */
enum class RecognitionMethodKind
{
  kSignature, ///< this module's signature of a sample of the model, compared by a MatchMethod
  kEsf,       ///< PCL's ESF of a sample of the model (the whole surface)
  kEsfViews   ///< PCL's ESF of each view the protocol camera takes of the model; the nearest view counts
};

/** \brief A method of single-view recognition. */
struct RecognitionMethod
{
  std::string name; ///< a MatchMethod's name (flowseg, parts, ...), esf or esf-views
  RecognitionMethodKind kind = RecognitionMethodKind::kSignature;
  MatchMethod match = MatchMethod::Combined; ///< kSignature: how signatures are compared
};

/** \brief The methods of a comma-separated \a list: any matchMethodName, esf and esf-views, in
  * the list's order. Fails on an unknown, repeated or empty name, listing the names. */
Status
parseRecognitionMethods (const std::string& list, std::vector<RecognitionMethod>& methods);

} // namespace pcl_flowseg

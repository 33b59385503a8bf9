/*
 * pcl_flowseg - internal: the rho rule (paper, section 4), with the sampling tolerance.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include <pcl_flowseg/common/flow_parameters.h>
#include <pcl_flowseg/common/flow_result.h>

#include <cstdint>
#include <vector>

namespace pcl_flowseg {
namespace core {

/** \brief Side of each stable manifold: that of its maximum's cell (1 inside, 0 outside; the one at
  * infinity is outside), or -1 for all when the interior was not separated. */
std::vector<std::int8_t>
manifoldSides (const FlowResult& result);

/** \brief Joins in \a parent (union-find over result.manifolds) every pair of finite manifolds of
  * one side whose highest shared facet t passes the rule
  *   R(max A) < rho R(t) + tolerance s(t)  and  R(max B) < rho R(t) + tolerance s(t)
  * (circumradii; s: saddleSpacing). Without tolerance the rule is evaluated in squared radii, as the
  * paper states it; rho < 1 merges nothing.
  * \return the saddles that fail the rule at rho but pass it at compact_rho, when the compact pass
  *         is on (compact_size > 0 and compact_rho > rho >= 1): the candidates of mergeCompactGroups. */
std::vector<const SaddleFacet*>
joinMergeableManifolds (const MergeParameters& params, const FlowResult& result, const std::vector<std::int8_t>& side,
                        std::vector<int>& parent);

} // namespace core
} // namespace pcl_flowseg

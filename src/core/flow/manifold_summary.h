/*
 * pcl_flowseg - internal: the stable manifolds as FlowSegments, with their maxima and saddles.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include "core/flow/stable_manifolds.h"

#include <pcl_flowseg/common/flow_result.h>

namespace pcl_flowseg {
namespace core {

/** \brief Fills result.maxima (by decreasing height, with their circumcentres), result.manifolds
  * (statistics; the one at infinity last, height +inf) and result.manifold_adjacency from the
  * cells' manifold labels set by computeStableManifolds. */
void
describeManifolds (const StableManifolds& sm, FlowResult& result);

} // namespace core
} // namespace pcl_flowseg

/*
 * pcl_flowseg - a database queried with a single-view scan: candidates by their views' histograms,
 * compared by aligning the scan with them.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include <pcl_flowseg/signature/signature_database.h>

#include "view_distance.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace pcl_flowseg {

std::vector<QueryHit>
SignatureDatabase::querySingleViewLocked (const Signature& signature, std::size_t k, const pcl::SignatureMatcher& matcher,
                                          std::size_t candidates) const
{
  if (signature.views.views.size () != 1)
    return {}; // not a scan's view set (checkViewSet refuses it): nothing to align
  // Every stored 3D shape with views by the histogram distance of its nearest view: the nearest
  // are the candidates, aligned with the scan in full.
  std::vector<QueryHit> hits;
  for (std::size_t i = 0; i < entries_.size (); ++i)
  {
    const ViewSet& views = entries_[i].signature.views;
    if (views.views.empty ())
      continue;
    QueryHit hit;
    hit.entry = i;
    hit.summary_distance = std::numeric_limits<double>::infinity ();
    for (const ViewDescription& view : views.views)
      hit.summary_distance = std::min (hit.summary_distance, internal::viewHistogramDistance (signature.views.views[0], view));
    hit.similarity = hit.distance = hit.paper_score = std::numeric_limits<double>::quiet_NaN ();
    hits.push_back (hit);
  }
  const std::size_t compared = candidates == 0 ? hits.size () : std::min (candidates, hits.size ());
  std::stable_sort (hits.begin (), hits.end (),
                    [] (const QueryHit& a, const QueryHit& b) { return a.summary_distance < b.summary_distance; });
  for (std::size_t r = 0; r < hits.size (); ++r)
    hits[r].compared = r < compared;
  compareCandidates (signature, matcher, compared, hits);
  if (k > 0 && hits.size () > k)
    hits.resize (k);
  return hits;
}

} // namespace pcl_flowseg

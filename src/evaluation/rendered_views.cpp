/*
 * pcl_flowseg evaluation - a model as the ESF descriptors of the protocol camera's views of it.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include <pcl_flowseg/evaluation/rendered_views.h>

#include <pcl_flowseg/evaluation/shape_distributions.h>
#include <pcl_flowseg/io/range_scan.h>
#include <pcl_flowseg/io/scan_protocol.h>

#include <algorithm>
#include <limits>
#include <sstream>

namespace pcl_flowseg {

Status
renderProtocolViews (const TriangleMesh& mesh, const std::vector<Eigen::Vector3d>& directions,
                     std::vector<std::vector<Eigen::Vector3d>>& views)
{
  views.assign (directions.size (), {});
  for (std::size_t k = 0; k < directions.size (); ++k)
  {
    const Status s = scanMesh (mesh, singleViewProtocolScanAlong (mesh, directions[k]), views[k]);
    if (!s || views[k].empty ())
    {
      std::ostringstream d;
      d << directions[k].x () << "," << directions[k].y () << "," << directions[k].z ();
      views.clear ();
      return Status::error ("the view from direction " + d.str () + ": " + (s ? "no point seen" : s.message));
    }
  }
  return Status::success ();
}

Status
esfOfProtocolViews (const TriangleMesh& mesh, const std::vector<Eigen::Vector3d>& directions,
                    std::vector<std::vector<double>>& descriptors)
{
  descriptors.assign (directions.size (), {});
  for (std::size_t k = 0; k < directions.size (); ++k)
  {
    // One view at a time: 42 views of 240 x 240 pixels would hold millions of points at once.
    std::vector<std::vector<Eigen::Vector3d>> one;
    Status s = renderProtocolViews (mesh, {directions[k]}, one);
    if (s)
      s = esfDescriptor (one.front (), descriptors[k]);
    if (!s)
    {
      descriptors.clear ();
      return s;
    }
  }
  return Status::success ();
}

double
bestViewSimilarity (const std::vector<double>& query, const std::vector<std::vector<double>>& views)
{
  if (views.empty ())
    return 0.0;
  double best = -std::numeric_limits<double>::infinity ();
  for (const auto& v : views)
    best = std::max (best, histogramSimilarity (query, v));
  return best;
}

} // namespace pcl_flowseg

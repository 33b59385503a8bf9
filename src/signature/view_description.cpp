/*
 * pcl_flowseg - a shape as a depth camera sees it: the view frame's axes, and the checks of views.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include <pcl_flowseg/signature/view_description.h>

#include <Eigen/Geometry>

#include <cmath>

namespace pcl_flowseg {

namespace {

/** As many unit normals as points, or why not. */
Status
checkNormals (const std::vector<Eigen::Vector3f>& points, const std::vector<Eigen::Vector3f>& normals)
{
  if (normals.size () != points.size ())
    return Status::error (std::to_string (points.size ()) + " points but " + std::to_string (normals.size ()) + " normals");
  for (const auto& n : normals)
    if (!n.allFinite () || std::abs (n.norm () - 1.0f) > 1e-2f)
      return Status::error ("a normal is not a unit vector");
  return Status::success ();
}

} // namespace

Eigen::Matrix3d
viewFrameAxes (const Eigen::Vector3d& sight)
{
  const Eigen::Vector3d helper = std::abs (sight.x ()) < 0.9 ? Eigen::Vector3d::UnitX () : Eigen::Vector3d::UnitY ();
  Eigen::Matrix3d axes;
  axes.col (0) = helper.cross (sight).normalized ();
  axes.col (1) = sight.cross (axes.col (0));
  axes.col (2) = sight;
  return axes;
}

Eigen::Matrix3d
viewAxes (const ViewDescription& view)
{
  return viewFrameAxes (-view.direction.cast<double> ().normalized ()) *
         Eigen::AngleAxisd (view.roll, Eigen::Vector3d::UnitZ ()).toRotationMatrix ();
}

Status
checkViewSet (const ViewSet& set)
{
  if (set.single_view && set.views.size () != 1)
    return Status::error ("a single-view set needs exactly one view, it has " + std::to_string (set.views.size ()));
  for (const ViewDescription& v : set.views)
  {
    if (!v.direction.allFinite () || std::abs (v.direction.norm () - 1.0f) > 1e-3f)
      return Status::error ("a view direction is not a unit vector");
    if (!v.centre.allFinite () || !std::isfinite (v.scale) || !(v.scale > 0.0f) || !(std::abs (v.roll) <= 4.0f))
      return Status::error ("a view's centre or roll is not finite or its scale not > 0");
    if (v.points.size () > kViewPoints || v.points.size () < 2)
      return Status::error ("a view has " + std::to_string (v.points.size ()) + " points (2 to " +
                            std::to_string (kViewPoints) + ")");
    for (const auto& p : v.points)
      if (!p.allFinite () || p.norm () > 1e3f)
        return Status::error ("a view point is not finite or lies absurdly far");
    if (const Status n = checkNormals (v.points, v.normals); !n)
      return n;
    for (float b : v.histogram)
      if (!std::isfinite (b) || b < 0.0f || b > 1.0f + 1e-4f)
        return Status::error ("a view histogram bin is outside [0, 1]");
  }
  if (set.shape_points.size () > kShapePoints)
    return Status::error ("a view set has more than " + std::to_string (kShapePoints) + " shape points");
  for (const auto& p : set.shape_points)
    if (!p.allFinite ())
      return Status::error ("a shape point is not finite");
  return checkNormals (set.shape_points, set.shape_normals);
}

} // namespace pcl_flowseg

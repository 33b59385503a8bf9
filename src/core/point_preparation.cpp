/*
 * pcl_flowseg - internal: finite filter, duplicate merging and dimension detection.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include "point_preparation.h"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <sstream>

namespace pcl_flowseg {
namespace core {

namespace {
bool
lexLess (const Eigen::Vector3d& a, const Eigen::Vector3d& b)
{
  if (a.x () != b.x ()) return a.x () < b.x ();
  if (a.y () != b.y ()) return a.y () < b.y ();
  return a.z () < b.z ();
}
} // namespace

bool
preparePoints (const std::vector<Eigen::Vector3d>& points, const FlowParameters& params,
               PreparedPoints& out, std::vector<std::string>& warnings, std::string& error)
{
  out = PreparedPoints ();
  out.point_to_vertex.assign (points.size (), -1);

  std::vector<int> finite;
  finite.reserve (points.size ());
  for (std::size_t i = 0; i < points.size (); ++i)
  {
    if (points[i].allFinite ())
      finite.push_back (static_cast<int> (i));
    else
      ++out.non_finite;
  }
  if (out.non_finite > 0)
    warnings.push_back (std::to_string (out.non_finite) + " point(s) with NaN/Inf coordinates skipped (label kNoSegment)");
  if (finite.empty ())
  {
    error = points.empty () ? "the input cloud is empty" : "the input cloud has no finite point";
    return false;
  }

  // Duplicates: sort by coordinates, every copy maps to the first copy in input order.
  std::vector<int> sorted = finite;
  std::stable_sort (sorted.begin (), sorted.end (), [&] (int a, int b) {
    return lexLess (points[static_cast<std::size_t> (a)], points[static_cast<std::size_t> (b)]);
  });
  std::vector<int> representative (points.size (), -1);
  for (std::size_t k = 0; k < sorted.size ();)
  {
    std::size_t e = k + 1;
    while (e < sorted.size () && points[static_cast<std::size_t> (sorted[e])] == points[static_cast<std::size_t> (sorted[k])])
      ++e;
    for (std::size_t j = k; j < e; ++j)
      representative[static_cast<std::size_t> (sorted[j])] = sorted[k]; // stable: the first copy
    k = e;
  }
  for (int i : finite)
  {
    const int rep = representative[static_cast<std::size_t> (i)];
    if (rep == i)
    {
      out.point_to_vertex[static_cast<std::size_t> (i)] = static_cast<int> (out.vertices.size ());
      out.vertices.push_back (points[static_cast<std::size_t> (i)]);
    }
    else
    {
      out.point_to_vertex[static_cast<std::size_t> (i)] = out.point_to_vertex[static_cast<std::size_t> (rep)];
      ++out.duplicates;
    }
  }
  if (out.duplicates > 0)
    warnings.push_back (std::to_string (out.duplicates) + " duplicate point(s) share the vertex (and label) of their first copy");

  // Best-fit plane: spread of the points along the normal, relative to the bounding box.
  Eigen::Vector3d lo = out.vertices.front (), hi = out.vertices.front ();
  Eigen::Vector3d mean = Eigen::Vector3d::Zero ();
  for (const auto& v : out.vertices)
  {
    lo = lo.cwiseMin (v);
    hi = hi.cwiseMax (v);
    mean += v;
  }
  mean /= static_cast<double> (out.vertices.size ());
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero ();
  for (const auto& v : out.vertices)
    cov += (v - mean) * (v - mean).transpose ();
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver (cov);
  const Eigen::Vector3d normal = solver.eigenvectors ().col (0);
  const Eigen::Vector3d axis_u = solver.eigenvectors ().col (2);
  const Eigen::Vector3d axis_v = solver.eigenvectors ().col (1);
  double thickness = 0.0;
  for (const auto& v : out.vertices)
    thickness = std::max (thickness, std::abs ((v - mean).dot (normal)));
  const double diagonal = (hi - lo).norm ();
  int constant_axis = -1;
  for (int a = 2; a >= 0; --a)
    if (lo[a] == hi[a])
      constant_axis = a;
  out.thickness = constant_axis >= 0 ? 0.0 : thickness;
  const bool flat = constant_axis >= 0 || thickness <= params.planar_tolerance * diagonal;

  switch (params.dimension)
  {
    case DimensionMode::Automatic: out.dimension = flat ? 2 : 3; break;
    case DimensionMode::Planar: out.dimension = 2; break;
    case DimensionMode::Spatial: out.dimension = 3; break;
  }
  if (out.dimension == 2 && !flat)
  {
    std::ostringstream s;
    s << "2D mode on points that are not planar (spread " << thickness << " normal to the best-fit plane, diagonal "
      << diagonal << "): points are projected onto that plane";
    warnings.push_back (s.str ());
  }
  if (out.dimension == 2)
  {
    out.planar.reserve (out.vertices.size ());
    for (const auto& v : out.vertices)
    {
      if (constant_axis >= 0)
      {
        // Drop the constant axis exactly (no rounding from a change of basis).
        const int a = constant_axis == 0 ? 1 : 0;
        const int b = constant_axis == 2 ? 1 : 2;
        out.planar.emplace_back (v[a], v[b]);
      }
      else
        out.planar.emplace_back ((v - mean).dot (axis_u), (v - mean).dot (axis_v));
    }
    if (constant_axis < 0)
    {
      // Keep the 3D vertices consistent with the plane the flow is computed in.
      for (std::size_t k = 0; k < out.vertices.size (); ++k)
        out.vertices[k] = mean + out.planar[k].x () * axis_u + out.planar[k].y () * axis_v;
    }
  }
  return true;
}

} // namespace core
} // namespace pcl_flowseg

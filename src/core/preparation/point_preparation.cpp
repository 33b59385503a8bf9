/*
 * pcl_flowseg - internal: finite filter, duplicate merging and dimension detection.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include "core/preparation/point_preparation.h"

#include "core/support/huge_pages.h"
#include "core/support/parallel.h"

#include <tbb/parallel_sort.h>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
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
/** Interleaves the low 21 bits of x, y and z (a Morton code). */
std::uint64_t
mortonCode (std::uint32_t x, std::uint32_t y, std::uint32_t z)
{
  auto spread = [] (std::uint64_t v) {
    v &= 0x1fffff;
    v = (v | v << 32) & 0x1f00000000ffffULL;
    v = (v | v << 16) & 0x1f0000ff0000ffULL;
    v = (v | v << 8) & 0x100f00f00f00f00fULL;
    v = (v | v << 4) & 0x10c30c30c30c30c3ULL;
    v = (v | v << 2) & 0x1249249249249249ULL;
    return v;
  };
  return spread (x) | spread (y) << 1 | spread (z) << 2;
}

/** The finite points of the input, in input order; non-finite ones are counted. */
std::vector<int>
finitePoints (const std::vector<Eigen::Vector3d>& points, PreparedPoints& out)
{
  std::vector<int> finite;
  reserveOnHugePages (finite, points.size ());
  for (std::size_t i = 0; i < points.size (); ++i)
  {
    if (points[i].allFinite ())
      finite.push_back (static_cast<int> (i));
    else
      ++out.non_finite;
  }
  return finite;
}

/** The Z-order (Morton) code of each finite point in the bounding box of them all, with its input index. */
std::vector<std::pair<std::uint64_t, int>>
mortonKeys (const std::vector<Eigen::Vector3d>& points, const std::vector<int>& finite)
{
  Eigen::Vector3d lo = points[static_cast<std::size_t> (finite.front ())], hi = lo;
  for (int i : finite)
  {
    lo = lo.cwiseMin (points[static_cast<std::size_t> (i)]);
    hi = hi.cwiseMax (points[static_cast<std::size_t> (i)]);
  }
  const Eigen::Vector3d extent = (hi - lo).cwiseMax (Eigen::Vector3d::Constant (std::numeric_limits<double>::min ()));
  std::vector<std::pair<std::uint64_t, int>> keyed;
  assignOnHugePages (keyed, finite.size ());
  parallelFor (finite.size (), [&] (std::size_t k) {
    const Eigen::Vector3d& p = points[static_cast<std::size_t> (finite[k])];
    std::uint32_t q[3];
    for (int a = 0; a < 3; ++a)
      q[a] = static_cast<std::uint32_t> (std::min (2097151.0, std::floor ((p[a] - lo[a]) / extent[a] * 2097151.0)));
    keyed[k] = {mortonCode (q[0], q[1], q[2]), finite[k]};
  });
  return keyed;
}

/** One vertex per distinct finite point, numbered along a Z-order curve through their bounding
  * box (ties by coordinates): cells numbered by their vertices (canonical order) are then close in
  * memory when close in space, and the numbering does not depend on the input's order. Copies of a
  * point map to its vertex; one sort (copies last by input index) finds both. */
void
mergeDuplicatesInSpatialOrder (const std::vector<Eigen::Vector3d>& points, const std::vector<int>& finite, PreparedPoints& out)
{
  std::vector<std::pair<std::uint64_t, int>> keyed = mortonKeys (points, finite);
  tbb::parallel_sort (keyed.begin (), keyed.end (), [&] (const auto& a, const auto& b) {
    if (a.first != b.first)
      return a.first < b.first;
    const Eigen::Vector3d& pa = points[static_cast<std::size_t> (a.second)];
    const Eigen::Vector3d& pb = points[static_cast<std::size_t> (b.second)];
    return pa != pb ? lexLess (pa, pb) : a.second < b.second;
  });
  reserveOnHugePages (out.vertices, keyed.size ());
  for (std::size_t k = 0; k < keyed.size (); ++k)
  {
    const std::size_t i = static_cast<std::size_t> (keyed[k].second);
    if (k > 0 && points[i] == points[static_cast<std::size_t> (keyed[k - 1].second)])
      ++out.duplicates;
    else
      out.vertices.push_back (points[i]);
    out.point_to_vertex[i] = static_cast<int> (out.vertices.size ()) - 1;
  }
}

/** The best-fit plane of the vertices and how flat they are. */
struct PlaneFit
{
  Eigen::Vector3d mean, normal, axis_u, axis_v;
  double thickness = 0.0; ///< largest distance from the plane
  double diagonal = 0.0;  ///< of the bounding box
  int constant_axis = -1; ///< an axis along which every vertex has the same coordinate, or -1
};

PlaneFit
fitPlane (const std::vector<Eigen::Vector3d>& vertices)
{
  PlaneFit fit;
  Eigen::Vector3d lo = vertices.front (), hi = vertices.front ();
  fit.mean = Eigen::Vector3d::Zero ();
  for (const auto& v : vertices)
  {
    lo = lo.cwiseMin (v);
    hi = hi.cwiseMax (v);
    fit.mean += v;
  }
  fit.mean /= static_cast<double> (vertices.size ());
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero ();
  for (const auto& v : vertices)
    cov += (v - fit.mean) * (v - fit.mean).transpose ();
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver (cov);
  fit.normal = solver.eigenvectors ().col (0);
  fit.axis_u = solver.eigenvectors ().col (2);
  fit.axis_v = solver.eigenvectors ().col (1);
  for (const auto& v : vertices)
    fit.thickness = std::max (fit.thickness, std::abs ((v - fit.mean).dot (fit.normal)));
  fit.diagonal = (hi - lo).norm ();
  for (int a = 2; a >= 0; --a)
    if (lo[a] == hi[a])
      fit.constant_axis = a;
  return fit;
}

/** Plane coordinates of the vertices: the constant axis dropped exactly when there is one (no
  * rounding from a change of basis), else the best-fit plane's basis, the 3D vertices then moved
  * onto that plane so that both describe the same geometry. */
void
projectToPlane (const PlaneFit& fit, PreparedPoints& out)
{
  out.planar.reserve (out.vertices.size ());
  for (const auto& v : out.vertices)
  {
    if (fit.constant_axis >= 0)
    {
      const int a = fit.constant_axis == 0 ? 1 : 0;
      const int b = fit.constant_axis == 2 ? 1 : 2;
      out.planar.emplace_back (v[a], v[b]);
    }
    else
      out.planar.emplace_back ((v - fit.mean).dot (fit.axis_u), (v - fit.mean).dot (fit.axis_v));
  }
  if (fit.constant_axis < 0)
    for (std::size_t k = 0; k < out.vertices.size (); ++k)
      out.vertices[k] = fit.mean + out.planar[k].x () * fit.axis_u + out.planar[k].y () * fit.axis_v;
}

/** The dimension of the flow: forced, or 2 when the vertices are flat. */
int
chooseDimension (const PreparationParameters& params, const PlaneFit& fit, std::vector<std::string>& warnings)
{
  const bool flat = fit.constant_axis >= 0 || fit.thickness <= params.planar_tolerance * fit.diagonal;
  const int dimension = params.dimension == DimensionMode::Planar ? 2 : params.dimension == DimensionMode::Spatial ? 3 : (flat ? 2 : 3);
  if (dimension == 2 && !flat)
  {
    std::ostringstream s;
    s << "2D mode on points that are not planar (spread " << fit.thickness << " normal to the best-fit plane, diagonal "
      << fit.diagonal << "): points are projected onto that plane";
    warnings.push_back (s.str ());
  }
  return dimension;
}
} // namespace

Status
preparePoints (const std::vector<Eigen::Vector3d>& points, const PreparationParameters& params,
               PreparedPoints& out, std::vector<std::string>& warnings)
{
  out = PreparedPoints ();
  assignOnHugePages (out.point_to_vertex, points.size (), -1);
  const std::vector<int> finite = finitePoints (points, out);
  if (out.non_finite > 0)
    warnings.push_back (std::to_string (out.non_finite) + " point(s) with NaN/Inf coordinates skipped (label kNoSegment)");
  if (finite.empty ())
    return Status::error (points.empty () ? "the input cloud is empty" : "the input cloud has no finite point");
  mergeDuplicatesInSpatialOrder (points, finite, out);
  if (out.duplicates > 0)
    warnings.push_back (std::to_string (out.duplicates) + " duplicate point(s) share the vertex (and label) of their first copy");
  const PlaneFit fit = fitPlane (out.vertices);
  out.thickness = fit.constant_axis >= 0 ? 0.0 : fit.thickness;
  out.dimension = chooseDimension (params, fit, warnings);
  if (out.dimension == 2)
    projectToPlane (fit, out);
  return Status::success ();
}

} // namespace core
} // namespace pcl_flowseg

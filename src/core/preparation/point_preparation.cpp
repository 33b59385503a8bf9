/*
 * pcl_flowseg - internal: finite filter, duplicate merging and dimension detection.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include "core/preparation/point_preparation.h"

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

/** Renumbers the vertices along a Z-order curve through their bounding box (ties by coordinates):
  * cells numbered by their vertices (canonical order) are then close in memory when close in
  * space, whatever the order of the input, and the numbering does not depend on that order. */
void
putInSpatialOrder (PreparedPoints& out)
{
  const std::size_t n = out.vertices.size ();
  Eigen::Vector3d lo = out.vertices.front (), hi = out.vertices.front ();
  for (const auto& v : out.vertices)
  {
    lo = lo.cwiseMin (v);
    hi = hi.cwiseMax (v);
  }
  const Eigen::Vector3d extent = (hi - lo).cwiseMax (Eigen::Vector3d::Constant (std::numeric_limits<double>::min ()));
  std::vector<std::pair<std::uint64_t, int>> keyed (n);
  parallelFor (n, [&] (std::size_t k) {
    std::uint32_t q[3];
    for (int a = 0; a < 3; ++a)
      q[a] = static_cast<std::uint32_t> (std::min (2097151.0, std::floor ((out.vertices[k][a] - lo[a]) / extent[a] * 2097151.0)));
    keyed[k] = {mortonCode (q[0], q[1], q[2]), static_cast<int> (k)};
  });
  tbb::parallel_sort (keyed.begin (), keyed.end (), [&] (const auto& a, const auto& b) {
    if (a.first != b.first)
      return a.first < b.first;
    return lexLess (out.vertices[static_cast<std::size_t> (a.second)], out.vertices[static_cast<std::size_t> (b.second)]);
  });
  std::vector<int> new_index (n);
  std::vector<Eigen::Vector3d> ordered (n);
  for (std::size_t k = 0; k < n; ++k)
  {
    new_index[static_cast<std::size_t> (keyed[k].second)] = static_cast<int> (k);
    ordered[k] = out.vertices[static_cast<std::size_t> (keyed[k].second)];
  }
  out.vertices.swap (ordered);
  for (int& v : out.point_to_vertex)
    if (v >= 0)
      v = new_index[static_cast<std::size_t> (v)];
}

/** The finite points of the input, in input order; non-finite ones are counted. */
std::vector<int>
finitePoints (const std::vector<Eigen::Vector3d>& points, PreparedPoints& out)
{
  std::vector<int> finite;
  finite.reserve (points.size ());
  for (std::size_t i = 0; i < points.size (); ++i)
  {
    if (points[i].allFinite ())
      finite.push_back (static_cast<int> (i));
    else
      ++out.non_finite;
  }
  return finite;
}

/** One vertex per distinct finite point, in first-seen order: every copy maps to the first copy
  * in input order (found by sorting by coordinates). */
void
mergeDuplicates (const std::vector<Eigen::Vector3d>& points, const std::vector<int>& finite, PreparedPoints& out)
{
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
  out.point_to_vertex.assign (points.size (), -1);
  const std::vector<int> finite = finitePoints (points, out);
  if (out.non_finite > 0)
    warnings.push_back (std::to_string (out.non_finite) + " point(s) with NaN/Inf coordinates skipped (label kNoSegment)");
  if (finite.empty ())
    return Status::error (points.empty () ? "the input cloud is empty" : "the input cloud has no finite point");
  mergeDuplicates (points, finite, out);
  if (out.duplicates > 0)
    warnings.push_back (std::to_string (out.duplicates) + " duplicate point(s) share the vertex (and label) of their first copy");
  putInSpatialOrder (out);
  const PlaneFit fit = fitPlane (out.vertices);
  out.thickness = fit.constant_axis >= 0 ? 0.0 : fit.thickness;
  out.dimension = chooseDimension (params, fit, warnings);
  if (out.dimension == 2)
    projectToPlane (fit, out);
  return Status::success ();
}

} // namespace core
} // namespace pcl_flowseg

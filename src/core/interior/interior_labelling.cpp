/*
 * pcl_flowseg - internal: interior/exterior labelling of Delaunay cells.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include "core/interior/interior_labelling.h"

#include "core/geometry/cell_geometry.h"
#include "core/support/cell_heap.h"
#include "core/delaunay/delaunay_cells.h"
#include "core/interior/denoising.h"
#include "core/support/huge_pages.h"
#include "core/support/parallel.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <numeric>
#include <unordered_map>
#include <unordered_set>

namespace pcl_flowseg {
namespace core {

namespace {

constexpr double kCrustWeight = 0.5;

std::uint64_t
pairKey (int a, int b)
{
  if (a > b)
    std::swap (a, b);
  return (static_cast<std::uint64_t> (static_cast<std::uint32_t> (a)) << 32) | static_cast<std::uint32_t> (b);
}

/** NN-crust (Dey & Kumar): every sample joined to its nearest neighbour, and to its nearest
  * neighbour among the samples on the other side of that first edge. Both are Delaunay edges. */
std::unordered_set<std::uint64_t>
nnCrust (const std::vector<Eigen::Vector3d>& vertices, const std::vector<FlowCell>& cells)
{
  std::vector<std::vector<int>> adjacent (vertices.size ());
  for (const FlowCell& c : cells)
    for (int i = 0; i < 3; ++i)
    {
      const int a = c.vertices[(i + 1) % 3], b = c.vertices[(i + 2) % 3];
      if (c.neighbors[i] < 0 || a < b) // each interior edge once from one side; hull edges once
      {
        adjacent[static_cast<std::size_t> (a)].push_back (b);
        adjacent[static_cast<std::size_t> (b)].push_back (a);
      }
    }
  std::unordered_set<std::uint64_t> crust;
  for (std::size_t p = 0; p < adjacent.size (); ++p)
  {
    const Eigen::Vector3d& x = vertices[p];
    int nearest = -1;
    double best = std::numeric_limits<double>::infinity ();
    for (int q : adjacent[p])
    {
      const double d = (vertices[static_cast<std::size_t> (q)] - x).squaredNorm ();
      if (d < best || (d == best && q < nearest))
      {
        best = d;
        nearest = q;
      }
    }
    if (nearest < 0)
      continue;
    crust.insert (pairKey (static_cast<int> (p), nearest));
    const Eigen::Vector3d dir = vertices[static_cast<std::size_t> (nearest)] - x;
    int half = -1;
    best = std::numeric_limits<double>::infinity ();
    for (int q : adjacent[p])
    {
      const Eigen::Vector3d e = vertices[static_cast<std::size_t> (q)] - x;
      if (e.dot (dir) >= 0)
        continue;
      const double d = e.squaredNorm ();
      if (d < best || (d == best && q < half))
      {
        best = d;
        half = q;
      }
    }
    if (half >= 0)
      crust.insert (pairKey (static_cast<int> (p), half));
  }
  return crust;
}

/** Walks from the sample \a vertex towards \a target through the triangulation and marks every cell
  * the segment crosses; returns the number of cells marked. */
std::size_t
markRay (const std::vector<Eigen::Vector3d>& vertices, const std::vector<FlowCell>& cells, int d,
         const VertexIncidence& inc, int vertex, const Eigen::Vector3d& target, std::vector<std::uint8_t>& free_space)
{
  const int f = d + 1;
  const Eigen::Vector3d origin = vertices[static_cast<std::size_t> (vertex)];
  const Eigen::Vector3d dir = target - origin;
  if (dir.squaredNorm () == 0.0)
    return 0;
  // A point just off the sample along the ray locates the first cell.
  auto contains = [&] (const FlowCell& c, const Eigen::Vector3d& p) {
    for (int i = 0; i < f; ++i)
    {
      const Eigen::Vector3d n = outwardFacetNormal (vertices, c, i, d);
      const Eigen::Vector3d& on = vertices[static_cast<std::size_t> (c.vertices[(i + 1) % f])];
      if ((p - on).dot (n) > 0)
        return false;
    }
    return true;
  };
  int cell = -1;
  double scale = 0.0;
  for (std::size_t k = inc.first[static_cast<std::size_t> (vertex)]; k < inc.first[static_cast<std::size_t> (vertex) + 1]; ++k)
    scale = std::max (scale, std::sqrt (cells[static_cast<std::size_t> (inc.cells[k])].squared_radius));
  const Eigen::Vector3d probe = origin + dir.normalized () * (1e-6 * scale);
  for (std::size_t k = inc.first[static_cast<std::size_t> (vertex)]; k < inc.first[static_cast<std::size_t> (vertex) + 1] && cell < 0; ++k)
    if (contains (cells[static_cast<std::size_t> (inc.cells[k])], probe))
      cell = inc.cells[k];
  std::size_t marked = 0;
  double t = 0.0;
  for (std::size_t steps = 0; cell >= 0 && steps < cells.size (); ++steps)
  {
    const FlowCell& c = cells[static_cast<std::size_t> (cell)];
    // The cell at the sample itself is skipped: at grazing angles it may lie behind the surface.
    if (steps > 0 && !free_space[static_cast<std::size_t> (cell)])
    {
      free_space[static_cast<std::size_t> (cell)] = 1;
      ++marked;
    }
    // Exit facet: the smallest parameter beyond t at which the ray leaves through a facet plane.
    int exit = -1;
    double t_exit = std::numeric_limits<double>::infinity ();
    for (int i = 0; i < f; ++i)
    {
      const Eigen::Vector3d n = outwardFacetNormal (vertices, c, i, d);
      const double speed = dir.dot (n);
      if (speed <= 0)
        continue;
      const Eigen::Vector3d& on = vertices[static_cast<std::size_t> (c.vertices[(i + 1) % f])];
      const double ti = (on - origin).dot (n) / speed;
      if (ti > t && ti < t_exit)
      {
        t_exit = ti;
        exit = i;
      }
    }
    if (exit < 0 || t_exit >= 1.0)
      break; // the target lies in this cell
    t = t_exit;
    cell = c.neighbors[exit];
  }
  return marked;
}

/** The greedy labelling of \a cells (see labelInterior); returns the number of cells sensor rays
  * marked as free space. */
std::size_t
labelCells (const std::vector<Eigen::Vector3d>& vertices, std::vector<FlowCell>& cells, int d,
            const InteriorParameters& params, const std::vector<Eigen::Vector3d>& vertex_normals)
{
  const int f = d + 1;
  const std::size_t n = cells.size ();
  std::size_t ray_cells = 0;
  std::vector<Eigen::Vector3d> centre;
  assignOnHugePages (centre, n, Eigen::Vector3d (Eigen::Vector3d::Zero ()));
  parallelFor (n, [&] (std::size_t c) { centre[c] = cellCircumcentre (vertices, cells[c], d); });
  const std::unordered_set<std::uint64_t> crust = d == 2 ? nnCrust (vertices, cells) : std::unordered_set<std::uint64_t> ();

  // Agreement across facet i of cell c: > 0 same side, < 0 opposite sides, |value| = confidence.
  // The cosine of the angle between the two spheres, measured at a facet vertex (on both) as the
  // angle between the directions to the two centres: unlike the law of cosines this stays accurate
  // for the huge spheres of flat cells, whose centres are far away but in a well-defined direction.
  auto measureAgreement = [&] (std::size_t c, int i) {
    const FlowCell& cell = cells[c];
    const int nb = cell.neighbors[i];
    const Eigen::Vector3d& on = vertices[static_cast<std::size_t> (cell.vertices[(i + 1) % f])];
    const Eigen::Vector3d to_a = (centre[c] - on).normalized ();
    double s;
    if (nb < 0)
      s = to_a.dot (outwardFacetNormal (vertices, cell, i, d));
    else
      s = to_a.dot ((centre[static_cast<std::size_t> (nb)] - on).normalized ());
    if (!std::isfinite (s))
      s = 0.0;
    s = std::max (-1.0, std::min (1.0, s));
    if (d == 2)
    {
      const bool on_crust = crust.count (pairKey (cell.vertices[(i + 1) % 3], cell.vertices[(i + 2) % 3])) > 0;
      s = on_crust ? std::min (s, -kCrustWeight) : std::max (s, kCrustWeight);
    }
    return s;
  };
  // Every value the greedy pass below may ask for, computed up front in parallel (the pass itself
  // is sequential).
  std::vector<std::array<double, 4>> facet_agreement;
  assignOnHugePages (facet_agreement, n);
  parallelFor (n, [&] (std::size_t c) {
    for (int i = 0; i < f; ++i)
      facet_agreement[c][static_cast<std::size_t> (i)] = measureAgreement (c, i);
  });
  auto agreement = [&] (std::size_t c, int i) { return facet_agreement[c][static_cast<std::size_t> (i)]; };

  std::vector<double> in_score, out_score, margin;
  assignOnHugePages (in_score, n, 0.0);
  assignOnHugePages (out_score, n, 0.0);
  assignOnHugePages (margin, n, 0.0);
  std::vector<std::int8_t> label (n, -1);
  // The undecided cells that have heard evidence, most certain (largest margin) first.
  CellHeap queue (margin);
  // Evidence adds up: a cell hears every labelled neighbour, so one confident but wrong facet
  // (a flat cell's sphere) is outvoted (keeping only the strongest, a whole tube section of
  // knot.off came out inside out).
  auto evidence = [&] (std::size_t c, bool outside, double weight) {
    (outside ? out_score[c] : in_score[c]) += weight;
    margin[c] = std::abs (in_score[c] - out_score[c]);
    queue.update (static_cast<int> (c));
  };

  // The outside beyond the convex hull.
  for (std::size_t c = 0; c < n; ++c)
    for (int i = 0; i < f; ++i)
      if (cells[c].neighbors[i] < 0)
      {
        const double s = agreement (c, i);
        evidence (c, s >= 0, std::abs (s));
      }

  // Oriented normals: a cell whose circumcentre lies along the normals of its vertices is outside.
  if (!vertex_normals.empty ())
    for (std::size_t c = 0; c < n; ++c)
    {
      double u = 0.0;
      int count = 0;
      for (int i = 0; i < f; ++i)
      {
        const std::size_t v = static_cast<std::size_t> (cells[c].vertices[i]);
        const Eigen::Vector3d to_centre = centre[c] - vertices[v];
        const double len = to_centre.norm ();
        if (len > 0 && vertex_normals[v].allFinite () && vertex_normals[v].squaredNorm () > 0)
        {
          u += to_centre.dot (vertex_normals[v].normalized ()) / len;
          ++count;
        }
      }
      if (count > 0)
        evidence (c, u > 0, std::abs (u) / count);
    }

  // Sensor rays: everything between the sensor and a sample is free space.
  if (params.viewpoint)
  {
    const VertexIncidence inc = vertexIncidence (cells, vertices.size (), d);
    std::vector<std::uint8_t> free_space (n, 0);
    for (std::size_t v = 0; v < vertices.size (); ++v)
      ray_cells += markRay (vertices, cells, d, inc, static_cast<int> (v), *params.viewpoint, free_space);
    for (std::size_t c = 0; c < n; ++c)
      if (free_space[c])
        evidence (c, true, 1.0); // as strong as the strongest geometric evidence
  }

  while (!queue.empty ())
  {
    const std::size_t c = static_cast<std::size_t> (queue.pop ());
    label[c] = out_score[c] >= in_score[c] ? 0 : 1;
    for (int i = 0; i < f; ++i)
    {
      const int nb = cells[c].neighbors[i];
      if (nb < 0 || label[static_cast<std::size_t> (nb)] >= 0)
        continue;
      const double s = agreement (c, i);
      const bool nb_outside = (label[c] == 0) == (s >= 0);
      evidence (static_cast<std::size_t> (nb), nb_outside, std::abs (s));
    }
  }
  for (std::size_t c = 0; c < n; ++c)
    cells[c].inside = label[c] < 0 ? 0 : label[c];
  return ray_cells;
}

} // namespace

void
labelInterior (FlowResult& r, const InteriorParameters& params, const std::vector<Eigen::Vector3d>& vertex_normals)
{
  const int d = r.dimension;
  r.interior = InteriorReport ();
  r.interior.computed = true;
  // First on the sample as given: right for clean samples, and cheap.
  if (params.denoising != Denoising::Always)
  {
    r.interior.ray_cells = labelCells (r.vertices, r.cells, d, params, vertex_normals);
    measureBoundary (r);
  }
  if (params.denoising == Denoising::Off)
    return;

  // Noise shows twice: in a raw labelling that leaves many samples off the boundary it finds, and
  // in the local PCA fits (undersampled sharp parts show only the first). The first is free, so
  // the nearest-neighbour search for the second runs only when the first is seen.
  const double off_boundary = static_cast<double> (r.interior.vertices_off_boundary) / std::max<std::size_t> (1, r.vertices.size ());
  if (params.denoising == Denoising::Automatic && off_boundary <= kOffBoundaryShare)
    return;
  const Neighbourhoods hoods = nearestNeighbourhoods (r.vertices);
  double variation = medianVariation (r.vertices, hoods, d);
  r.interior.surface_variation = variation;
  if (params.denoising == Denoising::Automatic && variation <= kNoiseVariation)
    return;

  // Noisy sample: decide in/out on a smoothed copy of the points (the greedy labelling needs a
  // thin sample), then give every cell the label of the smoothed cell holding its centroid.
  std::vector<Eigen::Vector3d> points = r.vertices;
  for (int it = 0; it < kMaxSmoothingPasses; ++it)
  {
    points = smoothPoints (points, hoods, d);
    ++r.interior.smoothing_passes;
    variation = medianVariation (points, hoods, d);
    if (variation <= kNoiseVariation)
      break;
  }
  std::vector<FlowCell> smooth_cells;
  if (const Status s = triangulateWorking (points, d, smooth_cells); !s)
  {
    r.warnings.push_back ("denoising skipped: " + s.message);
    r.interior.smoothing_passes = 0;
    if (params.denoising == Denoising::Always)
    {
      r.interior.ray_cells = labelCells (r.vertices, r.cells, d, params, vertex_normals);
      measureBoundary (r);
    }
    return;
  }
  r.interior.ray_cells = labelCells (points, smooth_cells, d, params, vertex_normals);
  // Each walk starts at a smoothed cell of the cell's first vertex: the sample moved little.
  std::vector<int> cell_of_vertex (points.size (), 0);
  for (std::size_t k = 0; k < smooth_cells.size (); ++k)
    for (int i = 0; i <= d; ++i)
      cell_of_vertex[static_cast<std::size_t> (smooth_cells[k].vertices[i])] = static_cast<int> (k);
  for (FlowCell& c : r.cells)
  {
    const int hint = cell_of_vertex[static_cast<std::size_t> (c.vertices[0])];
    const int found = locateCell (points, smooth_cells, d, c.centroid, hint);
    c.inside = found >= 0 ? smooth_cells[static_cast<std::size_t> (found)].inside : 0;
  }
  const double surface_variation = r.interior.surface_variation;
  const int passes = r.interior.smoothing_passes;
  const std::size_t rays = r.interior.ray_cells;
  measureBoundary (r);
  r.interior.surface_variation = surface_variation;
  r.interior.smoothing_passes = passes;
  r.interior.ray_cells = rays;
}

void
measureBoundary (FlowResult& r)
{
  InteriorReport& rep = r.interior;
  const int d = r.dimension, f = d + 1;
  rep.inside_volume = 0.0;
  rep.inside_cells = 0;
  rep.boundary_facets = 0;
  std::vector<std::array<int, 3>> facets;
  for (const FlowCell& c : r.cells)
  {
    if (c.inside != 1)
      continue;
    rep.inside_volume += c.volume;
    ++rep.inside_cells;
    for (int i = 0; i < f; ++i)
    {
      const int nb = c.neighbors[i];
      if (nb >= 0 && r.cells[static_cast<std::size_t> (nb)].inside == 1)
        continue;
      std::array<int, 3> t{{c.vertices[(i + 1) % f], c.vertices[(i + 2) % f], d == 3 ? c.vertices[(i + 3) % f] : -1}};
      facets.push_back (t);
    }
  }
  rep.boundary_facets = facets.size ();

  std::vector<std::uint8_t> on_boundary (r.vertices.size (), 0);
  rep.nonmanifold_edges = 0;
  rep.nonmanifold_vertices = 0;
  bool odd = false;
  if (d == 2)
  {
    // The boundary is a set of edges; every vertex on it must have exactly two.
    std::vector<int> degree (r.vertices.size (), 0);
    for (const auto& e : facets)
      for (int k = 0; k < 2; ++k)
        ++degree[static_cast<std::size_t> (e[k])];
    for (std::size_t v = 0; v < degree.size (); ++v)
    {
      on_boundary[v] = degree[v] > 0;
      odd |= degree[v] % 2 == 1;
      rep.nonmanifold_vertices += degree[v] > 2;
    }
    rep.nonmanifold_edges = 0;
  }
  else
  {
    // Per vertex, from the boundary triangles around it: every edge to a neighbour w must lie on
    // exactly two triangles (counted where v < w), and the triangles must form one fan (one
    // component when linked through shared edges). Vertices are independent: parallel.
    std::vector<std::size_t> first (r.vertices.size () + 1, 0);
    for (const auto& t : facets)
      for (int k = 0; k < 3; ++k)
        ++first[static_cast<std::size_t> (t[k]) + 1];
    for (std::size_t v = 0; v < r.vertices.size (); ++v)
      first[v + 1] += first[v];
    std::vector<int> around (first.back ());
    std::vector<std::size_t> fill (first.begin (), first.end () - 1);
    for (std::size_t k = 0; k < facets.size (); ++k)
      for (int j = 0; j < 3; ++j)
        around[fill[static_cast<std::size_t> (facets[k][j])]++] = static_cast<int> (k);
    std::vector<std::uint32_t> bad_edges (r.vertices.size (), 0);
    std::vector<std::uint8_t> odd_edge (r.vertices.size (), 0), bad_vertex (r.vertices.size (), 0);
    parallelFor (r.vertices.size (), [&] (std::size_t v) {
      const std::size_t m = first[v + 1] - first[v];
      if (m == 0)
        return;
      on_boundary[v] = 1;
      thread_local std::vector<std::pair<int, int>> ends; // (other vertex, local triangle)
      thread_local std::vector<int> parent;
      ends.clear ();
      parent.resize (m);
      std::iota (parent.begin (), parent.end (), 0);
      for (std::size_t k = 0; k < m; ++k)
        for (int j : facets[static_cast<std::size_t> (around[first[v] + k])])
          if (j != static_cast<int> (v))
            ends.emplace_back (j, static_cast<int> (k));
      std::sort (ends.begin (), ends.end ());
      auto find = [&] (int x) {
        while (parent[static_cast<std::size_t> (x)] != x)
          x = parent[static_cast<std::size_t> (x)] = parent[static_cast<std::size_t> (parent[static_cast<std::size_t> (x)])];
        return x;
      };
      for (std::size_t i = 0; i < ends.size ();)
      {
        std::size_t j = i + 1;
        for (; j < ends.size () && ends[j].first == ends[i].first; ++j)
          parent[static_cast<std::size_t> (find (ends[j].second))] = find (ends[i].second);
        const std::size_t count = j - i;
        if (static_cast<int> (v) < ends[i].first)
        {
          odd_edge[v] |= count % 2 == 1;
          bad_edges[v] += count != 2;
        }
        i = j;
      }
      int components = 0;
      for (std::size_t k = 0; k < m; ++k)
        components += find (static_cast<int> (k)) == static_cast<int> (k);
      bad_vertex[v] = components > 1;
    });
    for (std::size_t v = 0; v < r.vertices.size (); ++v)
    {
      odd |= odd_edge[v] != 0;
      rep.nonmanifold_edges += bad_edges[v];
      rep.nonmanifold_vertices += bad_vertex[v];
    }
  }
  rep.vertices_off_boundary = 0;
  for (std::uint8_t b : on_boundary)
    rep.vertices_off_boundary += b ? 0 : 1;
  rep.closed = !odd && rep.boundary_facets > 0;
  rep.manifold = rep.closed && rep.nonmanifold_edges == 0 && rep.nonmanifold_vertices == 0;
}

} // namespace core
} // namespace pcl_flowseg

/*
 * pcl_flowseg - internal: is the interior/exterior boundary a closed manifold?
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include "core/interior/boundary_measure.h"

#include "core/support/bucket_rows.h"
#include "core/support/parallel.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <numeric>
#include <utility>

namespace pcl_flowseg {
namespace core {

namespace {
using Facets = std::vector<std::array<int, 3>>;

/** What the boundary checks find. */
struct BoundaryCheck
{
  std::vector<std::uint8_t> on_boundary; ///< per vertex
  bool odd = false;                      ///< some edge (3D) or vertex (2D) bounds an odd number of facets
  std::size_t nonmanifold_edges = 0;
  std::size_t nonmanifold_vertices = 0;
  std::vector<int> nonmanifold; ///< 3D: the vertices on a non-manifold edge or with a non-manifold fan, ascending
};

/** The facets of inside cells that face an outside cell or the hull (found on all workers, listed
  * in cell order); inside volume and cells (summed in cell order). */
Facets
insideFacets (const FlowResult& r, InteriorReport& rep)
{
  const int d = r.dimension, f = d + 1;
  rep.inside_volume = 0.0;
  rep.inside_cells = 0;
  for (const FlowCell& c : r.cells)
    if (c.inside == 1)
    {
      rep.inside_volume += c.volume;
      ++rep.inside_cells;
    }
  return gatherListInOrder<std::array<int, 3>> (r.cells.size (), [&] (std::size_t begin, std::size_t end, Facets& facets) {
    for (std::size_t k = begin; k < end; ++k)
    {
      const FlowCell& c = r.cells[k];
      if (c.inside != 1)
        continue;
      for (int i = 0; i < f; ++i)
      {
        const int nb = c.neighbors[i];
        if (nb >= 0 && r.cells[static_cast<std::size_t> (nb)].inside == 1)
          continue;
        facets.push_back ({{c.vertices[(i + 1) % f], c.vertices[(i + 2) % f], d == 3 ? c.vertices[(i + 3) % f] : -1}});
      }
    }
  });
}

/** 2D: the boundary is a set of edges; every vertex on it must have exactly two. */
BoundaryCheck
checkCurve (const Facets& edges, std::size_t vertex_count)
{
  BoundaryCheck check;
  check.on_boundary.assign (vertex_count, 0);
  std::vector<int> degree (vertex_count, 0);
  for (const auto& e : edges)
    for (int k = 0; k < 2; ++k)
      ++degree[static_cast<std::size_t> (e[k])];
  for (std::size_t v = 0; v < vertex_count; ++v)
  {
    check.on_boundary[v] = degree[v] > 0;
    check.odd |= degree[v] % 2 == 1;
    check.nonmanifold_vertices += degree[v] > 2;
  }
  return check;
}

/** The triangles around each vertex, as compressed rows: triangles of v are items[first[v]..first[v+1]). */
using Around = BucketRows;

Around
trianglesAround (const Facets& triangles, std::size_t vertex_count)
{
  return bucketInOrder (triangles.size (), vertex_count, [&] (std::size_t k, const auto& add) {
    for (int j = 0; j < 3; ++j)
      add (static_cast<std::size_t> (triangles[k][static_cast<std::size_t> (j)]));
  });
}

/** The fan of vertex \a v: its edges to each neighbour w (counted where v < w; \a on_bad_edge for
  * any w) must lie on exactly two triangles, and the triangles must form one component when linked
  * through shared edges. */
void
checkFan (std::size_t v, const Facets& triangles, const Around& a, std::uint8_t& odd_edge, std::uint32_t& bad_edges,
          std::uint8_t& bad_vertex, std::uint8_t& on_bad_edge)
{
  const std::size_t m = a.first[v + 1] - a.first[v];
  thread_local std::vector<std::pair<int, int>> ends; // (other vertex, local triangle)
  thread_local std::vector<int> parent;
  ends.clear ();
  parent.resize (m);
  std::iota (parent.begin (), parent.end (), 0);
  for (std::size_t k = 0; k < m; ++k)
    for (int j : triangles[static_cast<std::size_t> (a.items[a.first[v] + k])])
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
    on_bad_edge |= j - i != 2;
    if (static_cast<int> (v) < ends[i].first)
    {
      odd_edge |= (j - i) % 2 == 1;
      bad_edges += j - i != 2;
    }
    i = j;
  }
  int components = 0;
  for (std::size_t k = 0; k < m; ++k)
    components += find (static_cast<int> (k)) == static_cast<int> (k);
  bad_vertex = components > 1;
}

/** 3D: every vertex's fan checked on its own (vertices are independent: in parallel). */
BoundaryCheck
checkSurface (const Facets& triangles, std::size_t vertex_count)
{
  BoundaryCheck check;
  check.on_boundary.assign (vertex_count, 0);
  const Around a = trianglesAround (triangles, vertex_count);
  std::vector<std::uint32_t> bad_edges (vertex_count, 0);
  std::vector<std::uint8_t> odd_edge (vertex_count, 0), bad_vertex (vertex_count, 0), on_bad_edge (vertex_count, 0);
  parallelFor (vertex_count, [&] (std::size_t v) {
    if (a.first[v + 1] == a.first[v])
      return;
    check.on_boundary[v] = 1;
    checkFan (v, triangles, a, odd_edge[v], bad_edges[v], bad_vertex[v], on_bad_edge[v]);
  });
  for (std::size_t v = 0; v < vertex_count; ++v)
  {
    check.odd |= odd_edge[v] != 0;
    check.nonmanifold_edges += bad_edges[v];
    check.nonmanifold_vertices += bad_vertex[v];
    if (on_bad_edge[v] != 0 || bad_vertex[v] != 0)
      check.nonmanifold.push_back (static_cast<int> (v));
  }
  return check;
}
} // namespace

std::vector<int>
measureBoundary (FlowResult& r)
{
  InteriorReport& rep = r.interior;
  const Facets facets = insideFacets (r, rep);
  rep.boundary_facets = facets.size ();
  const BoundaryCheck check = r.dimension == 2 ? checkCurve (facets, r.vertices.size ()) : checkSurface (facets, r.vertices.size ());
  rep.nonmanifold_edges = check.nonmanifold_edges;
  rep.nonmanifold_vertices = check.nonmanifold_vertices;
  rep.vertices_off_boundary = 0;
  for (std::uint8_t b : check.on_boundary)
    rep.vertices_off_boundary += b ? 0 : 1;
  rep.closed = !check.odd && rep.boundary_facets > 0;
  rep.manifold = rep.closed && rep.nonmanifold_edges == 0 && rep.nonmanifold_vertices == 0;
  return check.nonmanifold;
}

} // namespace core
} // namespace pcl_flowseg

/*
 * pcl_flowseg - directions spread evenly over the sphere: an icosahedron, subdivided.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include <pcl_flowseg/signature/view_sphere.h>

#include <array>
#include <cmath>
#include <map>
#include <utility>

namespace pcl_flowseg {

namespace {

using Triangle = std::array<std::size_t, 3>;

/** The regular icosahedron: its 12 vertices (0, +-1, +-phi) and cyclic permutations, on the unit
  * sphere, and its 20 faces. */
void
icosahedron (std::vector<Eigen::Vector3d>& vertices, std::vector<Triangle>& faces)
{
  const double phi = 0.5 * (1.0 + std::sqrt (5.0));
  vertices = {{-1, phi, 0}, {1, phi, 0},  {-1, -phi, 0}, {1, -phi, 0}, {0, -1, phi}, {0, 1, phi},
              {0, -1, -phi}, {0, 1, -phi}, {phi, 0, -1},  {phi, 0, 1},  {-phi, 0, -1}, {-phi, 0, 1}};
  for (auto& v : vertices)
    v.normalize ();
  faces = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
           {11, 10, 2}, {10, 7, 6}, {7, 1, 8},   {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
           {3, 8, 9},  {4, 9, 5},  {2, 4, 11},  {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
}

/** Splits every triangle into four; each edge's midpoint, pushed onto the sphere, becomes a
  * vertex once. */
void
subdivide (std::vector<Eigen::Vector3d>& vertices, std::vector<Triangle>& faces)
{
  std::map<std::pair<std::size_t, std::size_t>, std::size_t> midpoint_of;
  const auto midpoint = [&] (std::size_t a, std::size_t b) {
    const auto key = std::make_pair (std::min (a, b), std::max (a, b));
    const auto found = midpoint_of.find (key);
    if (found != midpoint_of.end ())
      return found->second;
    vertices.push_back ((vertices[a] + vertices[b]).normalized ());
    midpoint_of[key] = vertices.size () - 1;
    return vertices.size () - 1;
  };
  std::vector<Triangle> finer;
  finer.reserve (4 * faces.size ());
  for (const Triangle& f : faces)
  {
    const std::size_t ab = midpoint (f[0], f[1]), bc = midpoint (f[1], f[2]), ca = midpoint (f[2], f[0]);
    finer.push_back ({f[0], ab, ca});
    finer.push_back ({f[1], bc, ab});
    finer.push_back ({f[2], ca, bc});
    finer.push_back ({ab, bc, ca});
  }
  faces = std::move (finer);
}

} // namespace

Status
viewSphereDirections (std::size_t count, std::vector<Eigen::Vector3d>& directions)
{
  directions.clear ();
  std::vector<Triangle> faces;
  icosahedron (directions, faces);
  // 10 4^k + 2 vertices after k subdivisions; more than 10^6 directions is no view sphere.
  while (directions.size () < count && directions.size () < 1000000)
    subdivide (directions, faces);
  if (directions.size () != count)
  {
    directions.clear ();
    return Status::error ("a view sphere has 12, 42, 162, 642, ... (10 4^k + 2) directions, not " + std::to_string (count));
  }
  return Status::success ();
}

} // namespace pcl_flowseg

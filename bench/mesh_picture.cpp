/*
 * Pictures of segmented meshes without a display: a small z-buffer rasteriser writing PNG.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include "mesh_picture.h"

#include <pcl_flowseg/evaluation/png_writer.h>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>

namespace flowseg_bench {

namespace {
/** A colour per label, by rank of first appearance, from a palette of well separated hues. */
std::array<double, 3>
colour (int rank)
{
  static const double palette[][3] = {{0.90, 0.30, 0.25}, {0.25, 0.55, 0.90}, {0.35, 0.75, 0.35}, {0.95, 0.75, 0.20},
                                      {0.65, 0.40, 0.80}, {0.20, 0.80, 0.80}, {0.95, 0.50, 0.70}, {0.60, 0.45, 0.30},
                                      {0.55, 0.85, 0.20}, {0.30, 0.30, 0.70}, {0.95, 0.60, 0.40}, {0.40, 0.65, 0.55}};
  const auto& c = palette[rank % 12];
  return {c[0], c[1], c[2]};
}
} // namespace

pcl_flowseg::Status
renderSegmentedMesh (const pcl_flowseg::TriangleMesh& mesh, const std::vector<int>& face_labels, const std::string& path, int size)
{
  if (mesh.vertices.empty () || face_labels.size () != mesh.faces.size ())
    return pcl_flowseg::Status::error ("nothing to draw");
  // Frame: principal axes; x = longest, y = middle, view along the shortest.
  Eigen::Vector3d mean = Eigen::Vector3d::Zero ();
  for (const auto& v : mesh.vertices)
    mean += v;
  mean /= static_cast<double> (mesh.vertices.size ());
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero ();
  for (const auto& v : mesh.vertices)
    cov += (v - mean) * (v - mean).transpose ();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es (cov);
  Eigen::Matrix3d frame;
  frame.row (0) = es.eigenvectors ().col (2).transpose ();
  frame.row (1) = es.eigenvectors ().col (1).transpose ();
  frame.row (2) = frame.row (0).cross (frame.row (1));
  // A slight turn so that the third dimension shows.
  frame = Eigen::AngleAxisd (0.35, Eigen::Vector3d::UnitX ()).toRotationMatrix () *
          Eigen::AngleAxisd (0.25, Eigen::Vector3d::UnitY ()).toRotationMatrix () * frame;
  std::vector<Eigen::Vector3d> p (mesh.vertices.size ());
  Eigen::Vector3d lo = Eigen::Vector3d::Constant (std::numeric_limits<double>::infinity ()), hi = -lo;
  for (std::size_t i = 0; i < p.size (); ++i)
  {
    p[i] = frame * (mesh.vertices[i] - mean);
    lo = lo.cwiseMin (p[i]);
    hi = hi.cwiseMax (p[i]);
  }
  const double scale = 0.92 * size / std::max (hi.x () - lo.x (), hi.y () - lo.y ());
  const Eigen::Vector2d centre (0.5 * (lo.x () + hi.x ()), 0.5 * (lo.y () + hi.y ()));
  auto toPixel = [&] (const Eigen::Vector3d& q) {
    return Eigen::Vector3d ((q.x () - centre.x ()) * scale + 0.5 * size, (centre.y () - q.y ()) * scale + 0.5 * size, q.z ());
  };
  std::map<int, int> rank;
  std::vector<std::uint8_t> pixels (static_cast<std::size_t> (3 * size * size), 255);
  std::vector<double> depth (static_cast<std::size_t> (size * size), -std::numeric_limits<double>::infinity ());
  const Eigen::Vector3d light = Eigen::Vector3d (-0.3, 0.4, 1.0).normalized ();
  for (std::size_t f = 0; f < mesh.faces.size (); ++f)
  {
    const auto& t = mesh.faces[f];
    const Eigen::Vector3d a = toPixel (p[static_cast<std::size_t> (t[0])]), b = toPixel (p[static_cast<std::size_t> (t[1])]),
                          c = toPixel (p[static_cast<std::size_t> (t[2])]);
    const Eigen::Vector3d n = (p[static_cast<std::size_t> (t[1])] - p[static_cast<std::size_t> (t[0])])
                                  .cross (p[static_cast<std::size_t> (t[2])] - p[static_cast<std::size_t> (t[0])]);
    const double shade = n.norm () > 0 ? 0.35 + 0.65 * std::abs (n.normalized ().dot (light)) : 0.35;
    std::array<double, 3> base = {0.6, 0.6, 0.6};
    if (face_labels[f] >= 0)
    {
      const auto it = rank.emplace (face_labels[f], static_cast<int> (rank.size ())).first;
      base = colour (it->second);
    }
    const double area = (b.x () - a.x ()) * (c.y () - a.y ()) - (c.x () - a.x ()) * (b.y () - a.y ());
    if (area == 0.0)
      continue;
    const int x0 = std::max (0, static_cast<int> (std::floor (std::min ({a.x (), b.x (), c.x ()}))));
    const int x1 = std::min (size - 1, static_cast<int> (std::ceil (std::max ({a.x (), b.x (), c.x ()}))));
    const int y0 = std::max (0, static_cast<int> (std::floor (std::min ({a.y (), b.y (), c.y ()}))));
    const int y1 = std::min (size - 1, static_cast<int> (std::ceil (std::max ({a.y (), b.y (), c.y ()}))));
    for (int y = y0; y <= y1; ++y)
      for (int x = x0; x <= x1; ++x)
      {
        const double px = x + 0.5, py = y + 0.5;
        const double w0 = ((b.x () - px) * (c.y () - py) - (c.x () - px) * (b.y () - py)) / area;
        const double w1 = ((c.x () - px) * (a.y () - py) - (a.x () - px) * (c.y () - py)) / area;
        const double w2 = 1.0 - w0 - w1;
        if (w0 < 0 || w1 < 0 || w2 < 0)
          continue;
        const double z = w0 * a.z () + w1 * b.z () + w2 * c.z ();
        const std::size_t at = static_cast<std::size_t> (y * size + x);
        if (z <= depth[at])
          continue;
        depth[at] = z;
        for (int k = 0; k < 3; ++k)
          pixels[3 * at + static_cast<std::size_t> (k)] = static_cast<std::uint8_t> (std::lround (255.0 * base[static_cast<std::size_t> (k)] * shade));
      }
  }
  return pcl_flowseg::writePng (path, size, size, 3, pixels);
}

} // namespace flowseg_bench

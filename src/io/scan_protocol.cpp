/*
 * pcl_flowseg - the single-view protocol: a camera of fixed image and field of view, at a fixed
 * number of diagonals from the mesh in a random direction, with constant depth noise.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include <pcl_flowseg/io/scan_protocol.h>

#include <algorithm>
#include <cmath>
#include <random>

namespace pcl_flowseg {

namespace {
constexpr std::size_t kProtocolImagePixels = 240;
constexpr double kProtocolFieldOfView = 50.0;      // degrees
constexpr double kProtocolDistanceDiagonals = 2.0; // from the bounding-box centre

/** A number in (0, 1) from one 32-bit output: the centre of its 2^-32 interval. */
double
unitInterval (std::uint32_t word)
{
  return (static_cast<double> (word) + 0.5) / 4294967296.0;
}
} // namespace

Eigen::Vector3d
protocolViewpoint (const TriangleMesh& mesh, double distance_in_diagonals, std::uint32_t seed)
{
  std::mt19937 rng (seed);
  const double u = unitInterval (static_cast<std::uint32_t> (rng ()));
  const double v = unitInterval (static_cast<std::uint32_t> (rng ()));
  const double z = 1.0 - 2.0 * u, r = std::sqrt (std::max (0.0, 1.0 - z * z)), phi = 2.0 * M_PI * v;
  return protocolViewpointAlong (mesh, Eigen::Vector3d (r * std::cos (phi), r * std::sin (phi), z), distance_in_diagonals);
}

Eigen::Vector3d
protocolViewpointAlong (const TriangleMesh& mesh, const Eigen::Vector3d& direction, double distance_in_diagonals)
{
  Eigen::Vector3d lo = Eigen::Vector3d::Zero (), hi = lo;
  if (!mesh.vertices.empty ())
  {
    lo = hi = mesh.vertices.front ();
    for (const auto& p : mesh.vertices)
    {
      lo = lo.cwiseMin (p);
      hi = hi.cwiseMax (p);
    }
  }
  return 0.5 * (lo + hi) + distance_in_diagonals * mesh.diagonal () * direction;
}

namespace {
/** The protocol's camera at \a viewpoint. */
RangeScanOptions
protocolCamera (const Eigen::Vector3d& viewpoint, double depth_noise, std::uint32_t seed)
{
  RangeScanOptions o;
  o.viewpoint = viewpoint;
  o.image_pixels = kProtocolImagePixels;
  o.field_of_view = kProtocolFieldOfView;
  o.depth_noise = depth_noise;
  o.noise_model = DepthNoiseModel::kConstant;
  o.seed = seed;
  return o;
}
} // namespace

RangeScanOptions
singleViewProtocolScan (const TriangleMesh& mesh, double depth_noise, std::uint32_t seed)
{
  return protocolCamera (protocolViewpoint (mesh, kProtocolDistanceDiagonals, seed), depth_noise, seed);
}

RangeScanOptions
singleViewProtocolScanAlong (const TriangleMesh& mesh, const Eigen::Vector3d& direction, double depth_noise, std::uint32_t seed)
{
  return protocolCamera (protocolViewpointAlong (mesh, direction, kProtocolDistanceDiagonals), depth_noise, seed);
}

} // namespace pcl_flowseg

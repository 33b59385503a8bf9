/*
 * pcl_flowseg - procedural shapes with known parts, for samples, tests and benchmarks.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include <pcl_flowseg/evaluation/shape_generator.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

namespace pcl_flowseg {

namespace {

/** Squared normalised radius of \a p in the frame of \a part: < 1 inside. */
double
normalisedSquared (const EllipsoidPart& part, const Eigen::Vector3d& p, int dimension)
{
  const Eigen::Vector3d local = part.rotation.transpose () * (p - part.centre);
  double s = 0.0;
  for (int k = 0; k < dimension; ++k)
    s += (local[k] / part.radii[k]) * (local[k] / part.radii[k]);
  return s;
}

/** Surface area (3D, Knud Thomsen's approximation) or perimeter (2D, Ramanujan). */
double
boundaryMeasure (const EllipsoidPart& part, int dimension)
{
  const double a = part.radii.x (), b = part.radii.y (), c = part.radii.z ();
  if (dimension == 2)
  {
    const double h = (a - b) * (a - b) / ((a + b) * (a + b));
    return M_PI * (a + b) * (1 + 3 * h / (10 + std::sqrt (4 - 3 * h)));
  }
  const double p = 1.6075;
  return 4 * M_PI * std::pow ((std::pow (a * b, p) + std::pow (a * c, p) + std::pow (b * c, p)) / 3.0, 1.0 / p);
}

EllipsoidPart
part (const std::string& name, Eigen::Vector3d centre, Eigen::Vector3d radii,
      const Eigen::Matrix3d& rotation = Eigen::Matrix3d::Identity ())
{
  EllipsoidPart e;
  e.name = name;
  e.centre = centre;
  e.radii = radii;
  e.rotation = rotation;
  return e;
}

Eigen::Matrix3d
rotationZ (double degrees)
{
  return Eigen::AngleAxisd (degrees * M_PI / 180.0, Eigen::Vector3d::UnitZ ()).toRotationMatrix ();
}

Eigen::Matrix3d
rotationY (double degrees)
{
  return Eigen::AngleAxisd (degrees * M_PI / 180.0, Eigen::Vector3d::UnitY ()).toRotationMatrix ();
}

} // namespace

double
BlobShape::level (const Eigen::Vector3d& p) const
{
  double best = std::numeric_limits<double>::infinity ();
  for (const auto& e : parts)
    best = std::min (best, std::sqrt (normalisedSquared (e, p, dimension)));
  return best;
}

bool
BlobShape::contains (const Eigen::Vector3d& p) const
{
  for (const auto& e : parts)
    if (normalisedSquared (e, p, dimension) < 1.0)
      return true;
  return false;
}

int
BlobShape::nearestPart (const Eigen::Vector3d& p) const
{
  int best = -1;
  double best_value = std::numeric_limits<double>::infinity ();
  for (std::size_t k = 0; k < parts.size (); ++k)
  {
    const double v = std::sqrt (normalisedSquared (parts[k], p, dimension));
    if (v < best_value)
    {
      best_value = v;
      best = static_cast<int> (k);
    }
  }
  return best;
}

std::vector<Eigen::Vector3d>
sampleBoundary (const BlobShape& shape, std::size_t count, std::uint32_t seed)
{
  std::vector<Eigen::Vector3d> out;
  if (shape.parts.empty () || count == 0)
    return out;
  const int d = shape.dimension;
  std::mt19937 rng (seed);
  std::normal_distribution<double> gauss (0.0, 1.0);
  std::uniform_real_distribution<double> uniform (0.0, 1.0);
  std::vector<double> measure;
  for (const auto& e : shape.parts)
    measure.push_back (boundaryMeasure (e, d));
  std::discrete_distribution<std::size_t> pick (measure.begin (), measure.end ());

  out.reserve (count);
  std::size_t attempts = 0;
  const std::size_t max_attempts = 1000 * count + 100000;
  while (out.size () < count && attempts++ < max_attempts)
  {
    const std::size_t k = pick (rng);
    const EllipsoidPart& e = shape.parts[k];
    // Uniform direction, then rejection by the local area (length) stretch of the ellipsoid map.
    Eigen::Vector3d u (gauss (rng), gauss (rng), d == 3 ? gauss (rng) : 0.0);
    const double n = u.norm ();
    if (n == 0.0)
      continue;
    u /= n;
    const double a = e.radii.x (), b = e.radii.y (), c = e.radii.z ();
    double stretch, max_stretch;
    if (d == 2)
    {
      stretch = std::hypot (a * u.y (), b * u.x ());
      max_stretch = std::max (a, b);
    }
    else
    {
      stretch = std::sqrt (std::pow (b * c * u.x (), 2) + std::pow (a * c * u.y (), 2) + std::pow (a * b * u.z (), 2));
      max_stretch = std::max ({b * c, a * c, a * b});
    }
    if (uniform (rng) * max_stretch > stretch)
      continue;
    Eigen::Vector3d local (a * u.x (), b * u.y (), d == 3 ? c * u.z () : 0.0);
    Eigen::Vector3d p = e.centre + e.rotation * local;
    if (d == 2)
      p.z () = 0.0;
    bool hidden = false;
    for (std::size_t j = 0; j < shape.parts.size () && !hidden; ++j)
      hidden = j != k && normalisedSquared (shape.parts[j], p, d) < 1.0;
    if (!hidden)
      out.push_back (p);
  }
  return out;
}

std::vector<BlobShape>
sampleShapes ()
{
  std::vector<BlobShape> shapes;
  using V = Eigen::Vector3d;
  {
    BlobShape s{"dumbbell2d", 2, {}};
    s.parts = {part ("left bulb", V (-2, 0, 0), V (1, 1, 1)), part ("right bulb", V (2, 0, 0), V (1, 1, 1)),
               part ("neck", V (0, 0, 0), V (2.0, 0.3, 1))};
    shapes.push_back (s);
  }
  {
    BlobShape s{"star2d", 2, {}};
    s.parts = {part ("centre", V (0, 0, 0), V (0.6, 0.6, 1))};
    for (int k = 0; k < 5; ++k)
    {
      const double angle = 90.0 + 72.0 * k;
      const double rad = angle * M_PI / 180.0;
      s.parts.push_back (part ("arm " + std::to_string (k + 1), V (1.1 * std::cos (rad), 1.1 * std::sin (rad), 0),
                               V (1.0, 0.25, 1), rotationZ (angle)));
    }
    shapes.push_back (s);
  }
  {
    BlobShape s{"hand2d", 2, {}};
    s.parts = {part ("palm", V (0, 0, 0), V (0.9, 1.05, 1))};
    const double xs[4] = {-0.6, -0.2, 0.2, 0.6};
    const double tilt[4] = {8, 3, -3, -8};
    const double len[4] = {0.55, 0.68, 0.64, 0.5};
    for (int k = 0; k < 4; ++k)
      s.parts.push_back (part ("finger " + std::to_string (k + 1), V (xs[k], 1.0 + len[k], 0), V (0.15, len[k], 1),
                               rotationZ (tilt[k])));
    s.parts.push_back (part ("thumb", V (-1.05, -0.05, 0), V (0.55, 0.17, 1), rotationZ (35)));
    shapes.push_back (s);
  }
  {
    BlobShape s{"dumbbell3d", 3, {}};
    s.parts = {part ("left bulb", V (-2, 0, 0), V (1, 1, 1)), part ("right bulb", V (2, 0, 0), V (1, 1, 1)),
               part ("neck", V (0, 0, 0), V (2.0, 0.3, 0.3))};
    shapes.push_back (s);
  }
  {
    BlobShape s{"snowman3d", 3, {}};
    s.parts = {part ("bottom", V (0, 0, 0), V (1, 1, 1)), part ("middle", V (0, 0, 1.45), V (0.7, 0.7, 0.7)),
               part ("head", V (0, 0, 2.45), V (0.45, 0.45, 0.45))};
    shapes.push_back (s);
  }
  {
    BlobShape s{"animal3d", 3, {}};
    s.parts = {part ("body", V (0, 0, 1.4), V (1.6, 0.7, 0.6)),
               part ("neck", V (1.45, 0, 1.85), V (0.55, 0.2, 0.2), rotationY (-45)),
               part ("head", V (1.95, 0, 2.3), V (0.5, 0.3, 0.3)),
               part ("tail", V (-1.9, 0, 1.7), V (0.6, 0.08, 0.08), rotationY (30))};
    const double lx[2] = {1.0, -1.0}, ly[2] = {0.4, -0.4};
    for (int i = 0; i < 2; ++i)
      for (int j = 0; j < 2; ++j)
        s.parts.push_back (part (std::string (i == 0 ? "front" : "hind") + (j == 0 ? " left" : " right") + " leg",
                                 V (lx[i], ly[j], 0.7), V (0.17, 0.17, 0.75)));
    shapes.push_back (s);
  }
  return shapes;
}

BlobShape
sampleShape (const std::string& name)
{
  for (auto& s : sampleShapes ())
    if (s.name == name)
      return s;
  return BlobShape{name, 3, {}};
}

} // namespace pcl_flowseg

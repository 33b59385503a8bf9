/*
 * pcl_flowseg - a virtual range scanner: a depth buffer of the mesh seen from a viewpoint, one ray
 * per pixel, the hits moved along their rays by depth noise.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include <pcl_flowseg/io/range_scan.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numeric>
#include <random>

namespace pcl_flowseg {

namespace {
constexpr std::size_t kMaxScanPoints = 100000000;
constexpr long kMaxImageSide = 40000;

/** The bounding-box centre and the radius of the ball around it that holds every vertex. */
struct BoundingSphere
{
  Eigen::Vector3d centre = Eigen::Vector3d::Zero ();
  double radius = 0.0;
};

BoundingSphere
boundingSphere (const TriangleMesh& mesh)
{
  BoundingSphere s;
  if (mesh.vertices.empty ())
    return s;
  Eigen::Vector3d lo = mesh.vertices.front (), hi = lo;
  for (const auto& v : mesh.vertices)
  {
    lo = lo.cwiseMin (v);
    hi = hi.cwiseMax (v);
  }
  s.centre = 0.5 * (lo + hi);
  for (const auto& v : mesh.vertices)
    s.radius = std::max (s.radius, (v - s.centre).norm ());
  return s;
}

/** Half the side of the image on the plane at depth 1 of a camera with this field of view
  * (degrees); 0 when the angle is so small that it vanishes. */
double
halfWidth (double field_of_view)
{
  return std::tan (field_of_view * M_PI / 360.0);
}

/** A pinhole camera at the viewpoint aimed at the sphere's centre; its image is the square
  * [-half, half]^2 on the plane at depth 1, which spans the field of view or, without one, just
  * covers the sphere. */
struct Camera
{
  Eigen::Vector3d eye, forward, right, up;
  double half = 0.0;

  Camera (const Eigen::Vector3d& viewpoint, const BoundingSphere& sphere, double field_of_view)
    : eye (viewpoint), forward ((sphere.centre - viewpoint).normalized ())
  {
    const Eigen::Vector3d helper = std::abs (forward.z ()) < 0.9 ? Eigen::Vector3d::UnitZ () : Eigen::Vector3d::UnitX ();
    right = forward.cross (helper).normalized ();
    up = right.cross (forward);
    const double distance = (sphere.centre - viewpoint).norm ();
    half = field_of_view > 0.0 ? halfWidth (field_of_view) : std::tan (std::asin (sphere.radius / distance));
  }

  /** The image coordinates of \a p (in front of the camera). */
  Eigen::Vector2d
  project (const Eigen::Vector3d& p) const
  {
    const Eigen::Vector3d q = p - eye;
    const double z = q.dot (forward);
    return Eigen::Vector2d (q.dot (right) / z, q.dot (up) / z);
  }

  /** The ray through image point (x, y), with unit depth component. */
  Eigen::Vector3d
  ray (double x, double y) const
  {
    return forward + x * right + y * up;
  }
};

/** Per pixel of a side x side image: the ray parameter of the nearest hit (infinity: none) and
  * the face hit. */
struct DepthImage
{
  long side = 0;
  std::vector<double> depth;
  std::vector<int> face;
};

/** Pixel coordinate (centres at integers) of image coordinate \a x. */
double
toPixel (const Camera& camera, long side, double x)
{
  return (x + camera.half) / (2.0 * camera.half) * static_cast<double> (side) - 0.5;
}

double
fromPixel (const Camera& camera, long side, double pixel)
{
  return (pixel + 0.5) / static_cast<double> (side) * 2.0 * camera.half - camera.half;
}

/** A whole pixel coordinate \a v as an integer, held within [-1, side] first so that faces far
  * outside a narrow image convert safely (every value outside the image stays outside). */
long
toWhole (double v, long side)
{
  return static_cast<long> (std::clamp (v, -1.0, static_cast<double> (side)));
}

/** Writes the face's hits into the pixels whose centres it covers, where it is nearer. */
void
rasteriseFace (const TriangleMesh& mesh, int face_index, const Camera& camera, DepthImage& image)
{
  const std::array<int, 3>& face = mesh.faces[static_cast<std::size_t> (face_index)];
  const Eigen::Vector3d& a = mesh.vertices[static_cast<std::size_t> (face[0])];
  const Eigen::Vector3d normal = (mesh.vertices[static_cast<std::size_t> (face[1])] - a)
                                     .cross (mesh.vertices[static_cast<std::size_t> (face[2])] - a);
  std::array<Eigen::Vector2d, 3> px;
  for (int k = 0; k < 3; ++k)
  {
    const Eigen::Vector2d xy = camera.project (mesh.vertices[static_cast<std::size_t> (face[k])]);
    px[k] = Eigen::Vector2d (toPixel (camera, image.side, xy.x ()), toPixel (camera, image.side, xy.y ()));
  }
  const double area = (px[1] - px[0]).x () * (px[2] - px[0]).y () - (px[1] - px[0]).y () * (px[2] - px[0]).x ();
  if (area == 0.0 || !std::isfinite (area) || normal.squaredNorm () == 0.0)
    return; // edge-on or degenerate: seen from the side, it hides nothing; or far off a narrow image
  const long side = image.side;
  const long x0 = std::max (0L, toWhole (std::ceil (std::min ({px[0].x (), px[1].x (), px[2].x ()})), side));
  const long x1 = std::min (side - 1, toWhole (std::floor (std::max ({px[0].x (), px[1].x (), px[2].x ()})), side));
  const long y0 = std::max (0L, toWhole (std::ceil (std::min ({px[0].y (), px[1].y (), px[2].y ()})), side));
  const long y1 = std::min (side - 1, toWhole (std::floor (std::max ({px[0].y (), px[1].y (), px[2].y ()})), side));
  const double plane = normal.dot (a - camera.eye);
  for (long y = y0; y <= y1; ++y)
    for (long x = x0; x <= x1; ++x)
    {
      const Eigen::Vector2d p (static_cast<double> (x), static_cast<double> (y));
      bool inside = true;
      for (int k = 0; k < 3 && inside; ++k)
      {
        const Eigen::Vector2d e = px[(k + 1) % 3] - px[k], q = p - px[k];
        inside = (e.x () * q.y () - e.y () * q.x ()) * area >= 0.0;
      }
      if (!inside)
        continue;
      const Eigen::Vector3d dir = camera.ray (fromPixel (camera, image.side, p.x ()), fromPixel (camera, image.side, p.y ()));
      const double along = normal.dot (dir);
      if (along == 0.0)
        continue;
      const std::size_t pixel = static_cast<std::size_t> (y * image.side + x);
      if (plane / along < image.depth[pixel])
      {
        image.depth[pixel] = plane / along;
        image.face[pixel] = face_index;
      }
    }
}

DepthImage
renderDepth (const TriangleMesh& mesh, const Camera& camera, long side)
{
  DepthImage image;
  image.side = side;
  image.depth.assign (static_cast<std::size_t> (side * side), std::numeric_limits<double>::infinity ());
  image.face.assign (image.depth.size (), -1);
  for (std::size_t f = 0; f < mesh.faces.size (); ++f)
    rasteriseFace (mesh, static_cast<int> (f), camera, image);
  return image;
}

std::size_t
countHits (const DepthImage& image)
{
  return static_cast<std::size_t> (std::count_if (image.depth.begin (), image.depth.end (), [] (double d) { return std::isfinite (d); }));
}

/** A depth image with at least \a wanted hits, its side grown from a first guess by the share
  * of the image the mesh covers; an image of the largest side when even that has fewer. */
DepthImage
renderEnoughHits (const TriangleMesh& mesh, const Camera& camera, std::size_t wanted)
{
  long side = std::max (8L, static_cast<long> (std::ceil (std::sqrt (static_cast<double> (wanted)))));
  DepthImage image = renderDepth (mesh, camera, side);
  for (int attempt = 0; attempt < 4; ++attempt)
  {
    const std::size_t hits = countHits (image);
    if (hits >= wanted || hits == 0 || side == kMaxImageSide)
      break;
    const double grow = std::sqrt (1.05 * static_cast<double> (wanted) / static_cast<double> (hits));
    side = std::min (kMaxImageSide, static_cast<long> (std::ceil (static_cast<double> (side) * std::max (grow, 1.01))));
    image = renderDepth (mesh, camera, side);
  }
  return image;
}
} // namespace

Status
checkRangeScanOptions (const TriangleMesh& mesh, const RangeScanOptions& options)
{
  if (!options.viewpoint.allFinite ())
    return Status::error ("the scan viewpoint has non-finite coordinates");
  if (options.image_pixels == 0 && (options.points < 4 || options.points > kMaxScanPoints))
    return Status::error ("a scan needs between 4 and 10^8 points, got " + std::to_string (options.points));
  if (options.image_pixels > kMaxScanImagePixels)
    return Status::error ("the scan image must be at most " + std::to_string (kMaxScanImagePixels) +
                          " pixels on a side (0: chosen from the points wanted), got " + std::to_string (options.image_pixels));
  if (!(options.field_of_view == 0.0 ||
        (options.field_of_view > 0.0 && options.field_of_view < 180.0 && halfWidth (options.field_of_view) > 0.0)))
    return Status::error ("the scan's field of view must be an angle in degrees in (0, 180) (0: the image just covers the "
                          "bounding sphere), got " + std::to_string (options.field_of_view));
  if (!(options.depth_noise >= 0.0 && options.depth_noise <= 1.0))
    return Status::error ("the depth noise must be a share of the diagonal in [0, 1], got " + std::to_string (options.depth_noise));
  if (options.noise_model != DepthNoiseModel::kGrowsWithSquaredRange && options.noise_model != DepthNoiseModel::kConstant)
    return Status::error ("unknown depth noise model " + std::to_string (static_cast<int> (options.noise_model)));
  if (mesh.faces.empty ())
    return Status::error ("the mesh has no faces to scan");
  const BoundingSphere sphere = boundingSphere (mesh);
  if ((options.viewpoint - sphere.centre).norm () <= sphere.radius * (1.0 + 1e-9))
    return Status::error ("the scan viewpoint must lie outside the mesh's bounding sphere (centre " +
                          std::to_string (sphere.centre.x ()) + "," + std::to_string (sphere.centre.y ()) + "," +
                          std::to_string (sphere.centre.z ()) + ", radius " + std::to_string (sphere.radius) + ")");
  return Status::success ();
}

Status
scanMesh (const TriangleMesh& mesh, const RangeScanOptions& options, std::vector<Eigen::Vector3d>& points)
{
  std::vector<int> faces;
  return scanMesh (mesh, options, points, faces);
}

Status
scanMesh (const TriangleMesh& mesh, const RangeScanOptions& options, std::vector<Eigen::Vector3d>& points,
          std::vector<int>& face_of_point)
{
  points.clear ();
  face_of_point.clear ();
  if (const Status s = checkRangeScanOptions (mesh, options); !s)
    return s;
  const BoundingSphere sphere = boundingSphere (mesh);
  const Camera camera (options.viewpoint, sphere, options.field_of_view);
  const DepthImage image = options.image_pixels > 0 ? renderDepth (mesh, camera, static_cast<long> (options.image_pixels))
                                                    : renderEnoughHits (mesh, camera, options.points);
  std::vector<std::size_t> hits;
  for (std::size_t k = 0; k < image.depth.size (); ++k)
    if (std::isfinite (image.depth[k]))
      hits.push_back (k);
  if (hits.empty ())
    return Status::error ("the mesh shows no face to the sensor at the scan viewpoint");
  std::mt19937_64 rng (options.seed);
  if (options.image_pixels == 0 && hits.size () > options.points) // keep a random subset, in image order
  {
    std::shuffle (hits.begin (), hits.end (), rng);
    hits.resize (options.points);
    std::sort (hits.begin (), hits.end ());
  }
  const double centre_range = (sphere.centre - options.viewpoint).norm ();
  const double sigma = options.depth_noise * mesh.diagonal ();
  const bool constant = options.noise_model == DepthNoiseModel::kConstant;
  std::normal_distribution<double> gauss (0.0, 1.0);
  points.reserve (hits.size ());
  for (std::size_t k : hits)
  {
    const long x = static_cast<long> (k) % image.side, y = static_cast<long> (k) / image.side;
    const Eigen::Vector3d dir = camera.ray (fromPixel (camera, image.side, static_cast<double> (x)),
                                            fromPixel (camera, image.side, static_cast<double> (y)));
    const double range = image.depth[k] * dir.norm (), scale = constant ? 1.0 : range / centre_range;
    const double noisy = range + (sigma > 0.0 ? sigma * scale * scale * gauss (rng) : 0.0);
    points.push_back (options.viewpoint + noisy * dir.normalized ());
    face_of_point.push_back (image.face[k]);
  }
  return Status::success ();
}

} // namespace pcl_flowseg

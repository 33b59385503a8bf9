/*
 * pcl_flowseg - a 2D segmentation as an SVG drawing.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include <pcl_flowseg/io/segmentation_svg.h>

#include <pcl_flowseg/common/interior_boundary.h>
#include <pcl_flowseg/io/atomic_file.h>
#include <pcl_flowseg/io/segment_colours.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <ostream>
#include <sstream>

namespace pcl_flowseg {

namespace {

/** The drawing's frame: an orthonormal basis of the points' plane (the z = const plane when it is
  * one), scaled so that the longer side spans 760 pixels inside a 20-pixel margin, y up. */
class Canvas
{
public:
  explicit Canvas (const FlowResult& r) : origin_ (r.vertices.front ())
  {
    if (!r.cells.empty ())
    {
      const FlowCell& c = r.cells.front ();
      const Eigen::Vector3d& a = r.vertices[static_cast<std::size_t> (c.vertices[0])];
      const Eigen::Vector3d n = (r.vertices[static_cast<std::size_t> (c.vertices[1])] - a)
                                    .cross (r.vertices[static_cast<std::size_t> (c.vertices[2])] - a)
                                    .normalized ();
      if (std::abs (n.z ()) < 0.999)
      {
        u_ = n.cross (Eigen::Vector3d::UnitZ ()).normalized ();
        v_ = n.cross (u_).normalized ();
      }
    }
    for (const auto& x : r.vertices)
    {
      plane_.push_back (toPlane (x));
      lo_ = lo_.cwiseMin (plane_.back ());
      hi_ = hi_.cwiseMax (plane_.back ());
    }
    scale_ = 760.0 / std::max ({hi_.x () - lo_.x (), hi_.y () - lo_.y (), 1e-300});
  }

  int width () const { return static_cast<int> (40 + (hi_.x () - lo_.x ()) * scale_); }
  int height () const { return static_cast<int> (40 + (hi_.y () - lo_.y ()) * scale_); }
  std::size_t vertices () const { return plane_.size (); }
  /** "x,y" of vertex \a i. */
  std::string
  at (int i) const
  {
    return pixels (plane_[static_cast<std::size_t> (i)]);
  }
  /** Pixel x, y of the point \a x of the plane, as attributes named \a name_x and \a name_y. */
  std::string
  attributes (const Eigen::Vector3d& x, const char* name_x, const char* name_y) const
  {
    const Eigen::Vector2d p = toPlane (x);
    return attributes (p, name_x, name_y);
  }
  std::string
  attributes (int i, const char* name_x, const char* name_y) const
  {
    return attributes (plane_[static_cast<std::size_t> (i)], name_x, name_y);
  }

private:
  Eigen::Vector2d toPlane (const Eigen::Vector3d& x) const { return Eigen::Vector2d ((x - origin_).dot (u_), (x - origin_).dot (v_)); }
  double px (const Eigen::Vector2d& p) const { return 20 + (p.x () - lo_.x ()) * scale_; }
  double py (const Eigen::Vector2d& p) const { return 20 + (hi_.y () - p.y ()) * scale_; }
  std::string
  pixels (const Eigen::Vector2d& p) const
  {
    std::ostringstream s;
    s << std::fixed << std::setprecision (2) << px (p) << "," << py (p);
    return s.str ();
  }
  std::string
  attributes (const Eigen::Vector2d& p, const char* name_x, const char* name_y) const
  {
    std::ostringstream s;
    s << std::fixed << std::setprecision (2) << name_x << "=\"" << px (p) << "\" " << name_y << "=\"" << py (p) << "\"";
    return s.str ();
  }

  Eigen::Vector3d origin_;
  Eigen::Vector3d u_ = Eigen::Vector3d::UnitX (), v_ = Eigen::Vector3d::UnitY ();
  std::vector<Eigen::Vector2d> plane_;
  Eigen::Vector2d lo_ = Eigen::Vector2d::Constant (1e300), hi_ = Eigen::Vector2d::Constant (-1e300);
  double scale_ = 1.0;
};

/** The triangles, filled in their feature's colour (light grey when not reported). */
void
drawCells (std::ostream& out, const FlowResult& r, const Canvas& canvas)
{
  const std::vector<int> feature_of_segment = r.featureOfSegment ();
  out << "<g stroke-width=\"0.4\">\n";
  for (const FlowCell& c : r.cells)
  {
    const int f = feature_of_segment[static_cast<std::size_t> (c.segment)];
    const auto col = f < 0 ? std::array<std::uint8_t, 3>{{235, 235, 235}}
                           : segmentColour (static_cast<std::uint32_t> (f), r.segments[static_cast<std::size_t> (c.segment)].flows_to_infinity);
    const std::string rgb = "rgb(" + std::to_string (col[0]) + "," + std::to_string (col[1]) + "," + std::to_string (col[2]) + ")";
    out << "<polygon points=\"" << canvas.at (c.vertices[0]) << " " << canvas.at (c.vertices[1]) << " " << canvas.at (c.vertices[2])
        << "\" fill=\"" << rgb << "\" stroke=\"" << rgb << "\"/>\n";
  }
  out << "</g>\n";
}

void
drawEdge (std::ostream& out, const Canvas& canvas, int a, int b)
{
  out << "<line " << canvas.attributes (a, "x1", "y1") << " " << canvas.attributes (b, "x2", "y2") << "/>\n";
}

/** The edges between stable manifolds (black) and the reconstructed curve (blue). */
void
drawBoundaries (std::ostream& out, const FlowResult& r, const Canvas& canvas)
{
  out << "<g stroke=\"black\" stroke-width=\"0.6\">\n";
  for (const FlowCell& c : r.cells)
    for (int i = 0; i < 3; ++i)
    {
      const int nb = c.neighbors[i];
      if (nb < 0 || r.cells[static_cast<std::size_t> (nb)].manifold == c.manifold || &c > &r.cells[static_cast<std::size_t> (nb)])
        continue;
      drawEdge (out, canvas, c.vertices[(i + 1) % 3], c.vertices[(i + 2) % 3]);
    }
  out << "</g>\n<g stroke=\"#1f4fd0\" stroke-width=\"1.6\">\n";
  for (const auto& e : boundaryFacets (r))
    drawEdge (out, canvas, e[0], e[1]);
  out << "</g>\n";
}

/** The samples (black) and the maxima of the reported features (red). */
void
drawPoints (std::ostream& out, const FlowResult& r, const Canvas& canvas)
{
  out << "<g fill=\"black\">\n";
  for (std::size_t i = 0; i < canvas.vertices (); ++i)
    out << "<circle " << canvas.attributes (static_cast<int> (i), "cx", "cy") << " r=\"1\"/>\n";
  out << "</g>\n<g fill=\"#d02020\">\n";
  for (int k : r.features)
    for (int m : r.segments[static_cast<std::size_t> (k)].maxima)
      out << "<circle " << canvas.attributes (r.maxima[static_cast<std::size_t> (m)].location, "cx", "cy") << " r=\"2.5\"/>\n";
  out << "</g>\n";
}

} // namespace

Status
writeSegmentationSvg (const std::string& path, const FlowResult& r)
{
  if (r.dimension != 2)
    return Status::error ("cannot write " + path + ": SVG output is for 2D results");
  const Canvas canvas (r);
  return writeTextFileAtomically (path, [&] (std::ostream& out) {
    const int w = canvas.width (), h = canvas.height ();
    out << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << w << "\" height=\"" << h << "\" viewBox=\"0 0 " << w << " " << h
        << "\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
    drawCells (out, r, canvas);
    drawBoundaries (out, r, canvas);
    drawPoints (out, r, canvas);
    out << "</svg>\n";
  });
}

} // namespace pcl_flowseg

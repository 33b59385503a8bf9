/*
 * flowseg_view: shows a shape's features with PCL's visualiser: points coloured by feature,
 * feature centroids as spheres sized by weight, optionally the reconstructed surface as a wireframe.
 * --screenshot FILE.png renders off-screen (works under xvfb-run) and exits.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include "common/flow_options.h"
#include "common/options.h"

#include <pcl_flowseg/common/feature_significance.h>
#include <pcl_flowseg/common/interior_boundary.h>
#include <pcl_flowseg/io/segment_colours.h>
#include <pcl_flowseg/io/shape_input.h>
#include <pcl_flowseg/segmentation/flow_segmentation.h>

#include <pcl/PolygonMesh.h>
#include <pcl/common/io.h>
#include <pcl/console/print.h>
#include <pcl/visualization/pcl_visualizer.h>

#include <vtkLogger.h>
#include <vtkObject.h>

#include <Eigen/Eigenvalues>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <string>
#include <utility>
#include <vector>

namespace {

using flowseg_app::OptionParser;
using Visualizer = pcl::visualization::PCLVisualizer;

struct Options
{
  pcl_flowseg::FlowParameters params;
  flowseg_app::SignatureOptions signature;
  std::string screenshot, size = "900x700";
  double point_size = 3;
  bool surface = false, quiet = false;
  std::optional<Eigen::Vector3d> view;
  int width = 900, height = 700;
};

OptionParser
makeParser (Options& o)
{
  OptionParser p ("flowseg_view", "flowseg_view INPUT [options]",
                  "Shows the features of a shape: points coloured by feature, feature centroids as spheres whose\n"
                  "size follows the feature's volume share, and optionally the reconstructed surface as a wireframe.\n"
                  "INPUT: any file flowseg_segment reads, a mesh (sampled) or a silhouette image.");
  o.signature.input.mesh_points = 20000; // a picture wants more points than a signature
  flowseg_app::addSegmentationOptions (p, o.params);
  flowseg_app::addViewpointOptions (p, o.params.interior.viewpoint, o.signature.input.use_sensor_origin);
  flowseg_app::addSignatureOptions (p, o.signature);
  p.flag ("--surface", "draw the reconstructed surface as a wireframe", o.surface);
  p.number ("--point-size", "P", "rendered point size in pixels, 1 to 50", o.point_size, [] (double v) {
    return v >= 1 && v <= 50 ? pcl_flowseg::Status::success () : pcl_flowseg::Status::error ("must lie in [1, 50]");
  });
  p.text ("--size", "WxH", "window / screenshot size, 64 to 8192 pixels a side", o.size);
  p.point ("--view", "camera direction from the shape's centre (default: along the shape's\nthinnest principal axis, longest axis up; 2D: from above)", o.view);
  p.text ("--screenshot", "FILE", "render off-screen to FILE (.png) and exit (use xvfb-run without a display)", o.screenshot);
  flowseg_app::addThreadsOption (p, o.params.execution.threads);
  p.flag ("-q, --quiet", "no summary on stderr", o.quiet);
  p.epilogue ("Exit status: 0 success, 1 unreadable or unsegmentable input, 2 bad options.");
  return p;
}

int
checkOptions (const OptionParser& p, const std::vector<std::string>& inputs, Options& o)
{
  if (inputs.size () != 1)
    return p.usageError (inputs.empty () ? "no input file given" : "more than one input");
  if (std::sscanf (o.size.c_str (), "%dx%d", &o.width, &o.height) != 2 || o.width < 64 || o.height < 64 || o.width > 8192 ||
      o.height > 8192)
    return p.usageError ("--size needs WxH with sides from 64 to 8192, got '" + o.size + "'");
  if (o.view && !(o.view->norm () > 0))
    return p.usageError ("--view needs a direction, not 0,0,0");
  if (!o.screenshot.empty () && (o.screenshot.size () < 4 || o.screenshot.substr (o.screenshot.size () - 4) != ".png"))
    return p.usageError ("--screenshot needs a .png file name");
  return flowseg_app::checkViewpointOptions (p, o.params, o.signature.input.use_sensor_origin);
}

/** Every input point in the colour of its feature; points of no feature grey. */
pcl::PointCloud<pcl::PointXYZRGB>::Ptr
colouredPoints (const pcl::PointCloud<pcl::PointXYZ>& cloud, const pcl_flowseg::FlowResult& r)
{
  pcl::PointCloud<pcl::PointXYZRGB>::Ptr coloured (new pcl::PointCloud<pcl::PointXYZRGB>);
  for (std::size_t i = 0; i < cloud.size (); ++i)
  {
    const std::uint32_t label = i < r.point_labels.size () ? r.point_labels[i] : pcl_flowseg::kNoSegment;
    const auto c = pcl_flowseg::segmentColour (label);
    pcl::PointXYZRGB q;
    q.x = cloud[i].x;
    q.y = cloud[i].y;
    q.z = cloud[i].z;
    q.r = c[0];
    q.g = c[1];
    q.b = c[2];
    coloured->push_back (q);
  }
  return coloured;
}

/** A sphere at the centroid of every significant feature, sized by its volume share; how many. */
std::size_t
addFeatureSpheres (Visualizer& viewer, const pcl_flowseg::FlowResult& r, double significance, double diagonal)
{
  double total = 0.0;
  for (int k : r.features)
    total += r.segments[static_cast<std::size_t> (k)].volume;
  std::vector<char> significant (r.segments.size (), 0);
  for (int k : pcl_flowseg::significantSegments (r, r.features, significance))
    significant[static_cast<std::size_t> (k)] = 1;
  std::size_t spheres = 0;
  for (std::size_t f = 0; f < r.features.size (); ++f)
  {
    const auto& s = r.segments[static_cast<std::size_t> (r.features[f])];
    if (!significant[static_cast<std::size_t> (r.features[f])])
      continue;
    const auto c = pcl_flowseg::segmentColour (static_cast<std::uint32_t> (f));
    const double radius = 0.02 * diagonal + 0.08 * diagonal * std::cbrt (s.volume / total);
    const std::string id = "feature" + std::to_string (f);
    const Eigen::Vector3f centre = s.centroid.cast<float> ();
    viewer.addSphere (pcl::PointXYZ (centre.x (), centre.y (), centre.z ()), radius, c[0] / 255.0 * 0.7, c[1] / 255.0 * 0.7,
                      c[2] / 255.0 * 0.7, id);
    viewer.setShapeRenderingProperties (pcl::visualization::PCL_VISUALIZER_OPACITY, 0.55, id);
    ++spheres;
  }
  return spheres;
}

/** The reconstructed surface (3D) as a grey wireframe. */
void
addSurface (Visualizer& viewer, const pcl_flowseg::FlowResult& r)
{
  pcl::PolygonMesh mesh;
  pcl::PointCloud<pcl::PointXYZ> vertices;
  for (const auto& v : r.vertices)
    vertices.push_back (pcl::PointXYZ (static_cast<float> (v.x ()), static_cast<float> (v.y ()), static_cast<float> (v.z ())));
  pcl::toPCLPointCloud2 (vertices, mesh.cloud);
  for (const auto& t : pcl_flowseg::boundaryFacets (r))
  {
    pcl::Vertices poly;
    for (int k = 0; k < 3; ++k)
      poly.vertices.push_back (static_cast<std::uint32_t> (t[static_cast<std::size_t> (k)]));
    mesh.polygons.push_back (poly);
  }
  viewer.addPolylineFromPolygonMesh (mesh, "surface");
  viewer.setShapeRenderingProperties (pcl::visualization::PCL_VISUALIZER_COLOR, 0.55, 0.55, 0.55, "surface");
}

/** The bounding box of the points: lowest and highest corner. */
std::pair<Eigen::Vector3d, Eigen::Vector3d>
boundingBox (const std::vector<Eigen::Vector3d>& pts)
{
  Eigen::Vector3d lo = pts.front (), hi = pts.front ();
  for (const auto& p : pts)
  {
    lo = lo.cwiseMin (p);
    hi = hi.cwiseMax (p);
  }
  return {lo, hi};
}

/** Camera: by default along the shape's thinnest principal axis (it shows the most), tilted a
  * little, with the longest axis up; 2D from above; \a view sets the direction. */
void
placeCamera (Visualizer& viewer, const std::vector<Eigen::Vector3d>& pts, int dimension, std::optional<Eigen::Vector3d> view)
{
  const auto [lo, hi] = boundingBox (pts);
  const Eigen::Vector3d centre = 0.5 * (lo + hi);
  Eigen::Vector3d up = dimension == 2 ? Eigen::Vector3d (0, 1, 0) : Eigen::Vector3d (0, 0, 1);
  if (!view && dimension == 2)
    view = Eigen::Vector3d (0, 0, 1);
  else if (!view)
  {
    Eigen::Matrix3d cov = Eigen::Matrix3d::Zero ();
    for (const auto& p : pts)
      cov += (p - centre) * (p - centre).transpose ();
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es (cov);
    up = es.eigenvectors ().col (2);
    if (up.z () < 0)
      up = -up;
    view = es.eigenvectors ().col (0) + 0.35 * es.eigenvectors ().col (1);
  }
  else if (dimension == 3 && std::abs (view->normalized ().dot (up)) > 0.99)
    up = Eigen::Vector3d (0, 1, 0);
  const Eigen::Vector3d eye = centre + view->normalized () * 2.0 * (hi - lo).norm ();
  viewer.setCameraPosition (eye.x (), eye.y (), eye.z (), centre.x (), centre.y (), centre.z (), up.x (), up.y (), up.z ());
}

} // namespace

int
main (int argc, char** argv)
{
  Options o;
  const OptionParser parser = makeParser (o);
  std::vector<std::string> inputs;
  if (const int status = parser.parse (argc, argv, inputs); status != flowseg_app::kContinue)
    return status;
  if (const int status = checkOptions (parser, inputs, o); status != flowseg_app::kContinue)
    return status;
  pcl::console::setVerbosityLevel (pcl::console::L_ERROR);
  if (o.quiet) // VTK's warnings too (deprecations, under xvfb); its errors still show
  {
    vtkObject::GlobalWarningDisplayOff ();
    vtkLogger::SetStderrVerbosity (vtkLogger::VERBOSITY_ERROR);
  }

  std::vector<Eigen::Vector3d> pts;
  std::optional<Eigen::Vector3d> origin;
  if (const pcl_flowseg::Status s = pcl_flowseg::loadShapeSample (inputs[0], o.signature.input, pts, &origin); !s)
    return parser.failure (s.message);
  if (o.signature.input.use_sensor_origin)
    o.params.interior.viewpoint = origin;
  pcl::PointCloud<pcl::PointXYZ>::Ptr cloud (new pcl::PointCloud<pcl::PointXYZ>);
  for (const auto& p : pts)
    cloud->push_back (pcl::PointXYZ (static_cast<float> (p.x ()), static_cast<float> (p.y ()), static_cast<float> (p.z ())));
  pcl::FlowSegmentation<pcl::PointXYZ> seg;
  seg.setInputCloud (cloud);
  seg.setParameters (o.params);
  std::vector<pcl::PointIndices> features;
  if (!seg.segment (features))
    return parser.failure (inputs[0] + ": " + seg.getLastError ());
  const auto& r = seg.getResult ();

  const bool offscreen = !o.screenshot.empty ();
  Visualizer viewer ("flowseg_view", true);
  if (offscreen)
    viewer.getRenderWindow ()->SetOffScreenRendering (1);
  viewer.setSize (o.width, o.height);
  viewer.setBackgroundColor (1.0, 1.0, 1.0);
  viewer.addPointCloud<pcl::PointXYZRGB> (colouredPoints (*cloud, r), "points");
  viewer.setPointCloudRenderingProperties (pcl::visualization::PCL_VISUALIZER_POINT_SIZE, o.point_size, "points");
  const auto [lo, hi] = boundingBox (pts);
  const std::size_t spheres = addFeatureSpheres (viewer, r, o.signature.significance, (hi - lo).norm ());
  if (o.surface && r.interior.computed && r.dimension == 3)
    addSurface (viewer, r);
  placeCamera (viewer, pts, r.dimension, o.view);
  if (!o.quiet)
    std::cerr << r.dimension << "D: " << cloud->size () << " points, " << r.features.size () << " features, " << spheres
              << " shown as spheres (volume share above " << o.signature.significance << ")\n";
  if (!offscreen)
  {
    viewer.spin ();
    return flowseg_app::kExitSuccess;
  }
  viewer.spinOnce (1, true);
  viewer.saveScreenshot (o.screenshot);
  if (!std::ifstream (o.screenshot).good ())
    return parser.failure ("could not write " + o.screenshot + " (is there an X display? try xvfb-run)");
  if (!o.quiet)
    std::cerr << "wrote " << o.screenshot << "\n";
  return flowseg_app::kExitSuccess;
}

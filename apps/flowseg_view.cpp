/*
 * flowseg_view: shows a shape's features with PCL's visualiser: points coloured by feature,
 * feature centroids as spheres sized by weight, optionally the reconstructed surface as a wireframe.
 * --screenshot FILE.png renders off-screen (works under xvfb-run) and exits.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include "app_common.h"

#include <pcl_flowseg/common/feature_significance.h>
#include <pcl_flowseg/common/interior_boundary.h>
#include <pcl_flowseg/segmentation/flow_segmentation.h>
#include <pcl_flowseg/io/segment_colours.h>
#include <pcl_flowseg/io/shape_input.h>

#include <pcl/PolygonMesh.h>
#include <pcl/common/io.h>
#include <pcl/console/print.h>
#include <pcl/visualization/pcl_visualizer.h>

#include <Eigen/Eigenvalues>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <string>

namespace {

void
printHelp ()
{
  std::cout << R"(Usage: flowseg_view INPUT [options]

Shows the features of a shape: points coloured by feature, feature centroids as spheres whose
size follows the feature's volume share, and optionally the reconstructed surface as a wireframe.
INPUT: any file flowseg_segment reads, a mesh (sampled) or a silhouette image.

Options:
  -r, --rho R            merge threshold (default )" << pcl_flowseg::MergeParameters ().rho << R"()
      --paper-rule       the paper's merging rule alone (no tolerance, compact pass or stumps)
  -f, --features SIDE    interior | exterior | both (default interior)
      --significance F   centroid spheres for features above this volume share (default )" << pcl_flowseg::kDefaultSignificance << R"()
      --surface          draw the reconstructed surface as a wireframe
      --mesh-points N    points sampled on a mesh (default 20000)
      --point-size P     rendered point size in pixels (default 3)
      --size WxH         window / screenshot size (default 900x700)
      --view X,Y,Z       camera direction from the shape's centre (default: along the shape's
                         thinnest principal axis, longest axis up; 2D: from above)
      --screenshot FILE  render off-screen to FILE (.png) and exit (use xvfb-run without a display)
  -h, --help             this help
Exit status: 0 success, 1 unreadable or unsegmentable input, 2 bad options.
)";
}

int
usageError (const std::string& message)
{
  return flowseg_app::usageError ("flowseg_view", message);
}

} // namespace

int
main (int argc, char** argv)
{
  std::string input, screenshot;
  double rho = pcl_flowseg::MergeParameters ().rho, significance = pcl_flowseg::kDefaultSignificance, point_size = 3;
  bool paper_rule = false;
  pcl_flowseg::FeatureSide side = pcl_flowseg::FeatureSide::Interior;
  bool surface = false, has_view = false;
  int width = 900, height = 700;
  Eigen::Vector3d view (1, -1, 0.7);
  pcl_flowseg::ShapeInputOptions in;
  in.mesh_points = 20000;
  for (int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    const bool more = i + 1 < argc;
    double v;
    if (a == "-h" || a == "--help")
    {
      printHelp ();
      return 0;
    }
    else if ((a == "-r" || a == "--rho") && more && flowseg_app::parseNumber (argv[i + 1], v) && v > 0)
      rho = v, ++i;
    else if (a == "--paper-rule")
      paper_rule = true;
    else if ((a == "-f" || a == "--features") && more)
    {
      const std::string s = argv[++i];
      if (s == "interior") side = pcl_flowseg::FeatureSide::Interior;
      else if (s == "exterior") side = pcl_flowseg::FeatureSide::Exterior;
      else if (s == "both") side = pcl_flowseg::FeatureSide::Both;
      else return usageError ("--features must be interior, exterior or both");
    }
    else if (a == "--significance" && more && flowseg_app::parseNumber (argv[i + 1], v) && v >= 0 && v < 1)
      significance = v, ++i;
    else if (a == "--surface")
      surface = true;
    else if (a == "--mesh-points" && more && flowseg_app::parseNumber (argv[i + 1], v) && v >= 4 && v <= 1e8)
      in.mesh_points = static_cast<std::size_t> (v), ++i;
    else if (a == "--point-size" && more && flowseg_app::parseNumber (argv[i + 1], v) && v >= 1 && v <= 50)
      point_size = v, ++i;
    else if (a == "--size" && more && std::sscanf (argv[i + 1], "%dx%d", &width, &height) == 2 && width >= 64 &&
             height >= 64 && width <= 8192 && height <= 8192)
      ++i;
    else if (a == "--view" && more && std::sscanf (argv[i + 1], "%lf,%lf,%lf", &view.x (), &view.y (), &view.z ()) == 3 &&
             view.allFinite () && view.norm () > 0)
      has_view = true, ++i;
    else if (a == "--screenshot" && more)
      screenshot = argv[++i];
    else if (!a.empty () && a[0] == '-')
      return usageError ("bad, incomplete or unknown option '" + a + "'");
    else if (input.empty ())
      input = a;
    else
      return usageError ("more than one input");
  }
  if (input.empty ())
    return usageError ("no input file given");
  if (!screenshot.empty () && (screenshot.size () < 4 || screenshot.substr (screenshot.size () - 4) != ".png"))
    return usageError ("--screenshot needs a .png file name");
  pcl::console::setVerbosityLevel (pcl::console::L_ERROR);

  std::vector<Eigen::Vector3d> pts;
  auto st = pcl_flowseg::loadShapeSample (input, in, pts);
  if (!st)
  {
    std::cerr << "flowseg_view: " << st.message << "\n";
    return 1;
  }
  pcl::PointCloud<pcl::PointXYZ>::Ptr cloud (new pcl::PointCloud<pcl::PointXYZ>);
  for (const auto& p : pts)
    cloud->push_back (pcl::PointXYZ (static_cast<float> (p.x ()), static_cast<float> (p.y ()), static_cast<float> (p.z ())));
  pcl::FlowSegmentation<pcl::PointXYZ> seg;
  seg.setInputCloud (cloud);
  seg.setRho (rho);
  if (paper_rule)
  {
    seg.setSamplingTolerance (0.0);
    seg.setCompactSize (0.0);
    seg.setStumpRatio (0.0);
  }
  seg.setFeatureSide (side);
  std::vector<pcl::PointIndices> features;
  if (!seg.segment (features))
  {
    std::cerr << "flowseg_view: " << input << ": " << seg.getLastError () << "\n";
    return 1;
  }
  const auto& r = seg.getResult ();

  // Points coloured by feature; points of no feature grey.
  pcl::PointCloud<pcl::PointXYZRGB>::Ptr coloured (new pcl::PointCloud<pcl::PointXYZRGB>);
  for (std::size_t i = 0; i < cloud->size (); ++i)
  {
    const std::uint32_t label = i < r.point_labels.size () ? r.point_labels[i] : pcl_flowseg::kNoSegment;
    const auto c = pcl_flowseg::segmentColour (label);
    pcl::PointXYZRGB q;
    q.x = (*cloud)[i].x;
    q.y = (*cloud)[i].y;
    q.z = (*cloud)[i].z;
    q.r = c[0];
    q.g = c[1];
    q.b = c[2];
    coloured->push_back (q);
  }
  const bool offscreen = !screenshot.empty ();
  pcl::visualization::PCLVisualizer viewer ("flowseg_view", true);
  if (offscreen)
    viewer.getRenderWindow ()->SetOffScreenRendering (1);
  viewer.setSize (width, height);
  viewer.setBackgroundColor (1.0, 1.0, 1.0);
  viewer.addPointCloud<pcl::PointXYZRGB> (coloured, "points");
  viewer.setPointCloudRenderingProperties (pcl::visualization::PCL_VISUALIZER_POINT_SIZE, point_size, "points");

  double total = 0.0;
  for (int k : r.features)
    total += r.segments[static_cast<std::size_t> (k)].volume;
  Eigen::Vector3d lo = pts.front (), hi = pts.front ();
  for (const auto& p : pts)
  {
    lo = lo.cwiseMin (p);
    hi = hi.cwiseMax (p);
  }
  const double diag = (hi - lo).norm ();
  std::size_t spheres = 0;
  std::vector<char> significant (r.segments.size (), 0);
  for (int k : pcl_flowseg::significantSegments (r, r.features, significance))
    significant[static_cast<std::size_t> (k)] = 1;
  for (std::size_t f = 0; f < r.features.size (); ++f)
  {
    const auto& s = r.segments[static_cast<std::size_t> (r.features[f])];
    if (!significant[static_cast<std::size_t> (r.features[f])])
      continue;
    const auto c = pcl_flowseg::segmentColour (static_cast<std::uint32_t> (f));
    const double radius = 0.02 * diag + 0.08 * diag * std::cbrt (s.volume / total);
    const std::string id = "feature" + std::to_string (f);
    viewer.addSphere (pcl::PointXYZ (static_cast<float> (s.centroid.x ()), static_cast<float> (s.centroid.y ()), static_cast<float> (s.centroid.z ())),
                      radius, c[0] / 255.0 * 0.7, c[1] / 255.0 * 0.7, c[2] / 255.0 * 0.7, id);
    viewer.setShapeRenderingProperties (pcl::visualization::PCL_VISUALIZER_OPACITY, 0.55, id);
    ++spheres;
  }
  if (surface && r.interior.computed && r.dimension == 3)
  {
    pcl::PolygonMesh mesh;
    pcl::PointCloud<pcl::PointXYZ> vertices;
    for (const auto& v : r.vertices)
      vertices.push_back (pcl::PointXYZ (static_cast<float> (v.x ()), static_cast<float> (v.y ()), static_cast<float> (v.z ())));
    pcl::toPCLPointCloud2 (vertices, mesh.cloud);
    for (const auto& t : pcl_flowseg::boundaryFacets (r))
    {
      pcl::Vertices poly;
      poly.vertices = {static_cast<std::uint32_t> (t[0]), static_cast<std::uint32_t> (t[1]), static_cast<std::uint32_t> (t[2])};
      mesh.polygons.push_back (poly);
    }
    viewer.addPolylineFromPolygonMesh (mesh, "surface");
    viewer.setShapeRenderingProperties (pcl::visualization::PCL_VISUALIZER_COLOR, 0.55, 0.55, 0.55, "surface");
  }

  // Camera: by default along the shape's thinnest principal axis (it shows the most), tilted a
  // little, with the longest axis up; 2D from above; --view sets the direction.
  const Eigen::Vector3d centre = 0.5 * (lo + hi);
  Eigen::Vector3d up = r.dimension == 2 ? Eigen::Vector3d (0, 1, 0) : Eigen::Vector3d (0, 0, 1);
  if (!has_view)
  {
    if (r.dimension == 2)
      view = Eigen::Vector3d (0, 0, 1);
    else
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
  }
  else if (r.dimension == 3 && std::abs (view.normalized ().dot (up)) > 0.99)
    up = Eigen::Vector3d (0, 1, 0);
  const Eigen::Vector3d eye = centre + view.normalized () * 2.0 * diag;
  viewer.setCameraPosition (eye.x (), eye.y (), eye.z (), centre.x (), centre.y (), centre.z (), up.x (), up.y (), up.z ());
  std::cerr << r.dimension << "D: " << cloud->size () << " points, " << r.features.size () << " features, " << spheres
            << " shown as spheres (volume share above " << significance << ")\n";
  if (offscreen)
  {
    viewer.spinOnce (1, true);
    viewer.saveScreenshot (screenshot);
    std::ifstream check (screenshot);
    if (!check.good ())
    {
      std::cerr << "flowseg_view: could not write " << screenshot << " (is there an X display? try xvfb-run)\n";
      return 1;
    }
    std::cerr << "wrote " << screenshot << "\n";
    return 0;
  }
  viewer.spin ();
  return 0;
}

/*
 * Reading point files and writing results: formats, errors, files that appear whole or not at all.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include "test_support.h"

#include <pcl_flowseg/signature/signature_database.h>

#include <pcl_flowseg/segmentation/flow_segmentation.h>
#include <pcl_flowseg/io/point_io.h>
#include <pcl_flowseg/io/point_cloud_writer.h>
#include <pcl_flowseg/io/segmentation_json.h>
#include <pcl_flowseg/io/segmentation_ply.h>
#include <pcl_flowseg/io/segmentation_svg.h>
#include <pcl_flowseg/io/mesh_io.h>
#include <pcl_flowseg/io/shape_input.h>
#include <pcl_flowseg/io/silhouette.h>

#include <pcl_flowseg/io/atomic_file.h>
#include <pcl_flowseg/io/json_text.h>

#include <pcl/io/pcd_io.h>
#include <pcl/io/ply_io.h>

#include <gtest/gtest.h>

#include <cstdio>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <optional>
#include <sstream>
#include <unistd.h>

using namespace pcl_flowseg;

namespace {

class TempDir
{
public:
  TempDir ()
  {
    char tmpl[] = "/tmp/flowseg_io_XXXXXX";
    path_ = ::mkdtemp (tmpl);
  }
  ~TempDir () { std::system (("rm -rf '" + path_ + "'").c_str ()); }
  std::string file (const std::string& name) const { return path_ + "/" + name; }
  std::string write (const std::string& name, const std::string& text) const
  {
    std::ofstream (file (name), std::ios::binary) << text;
    return file (name);
  }

private:
  std::string path_;
};

bool
exists (const std::string& path)
{
  return std::ifstream (path).good ();
}

std::string
slurp (const std::string& path)
{
  std::ostringstream s;
  s << std::ifstream (path).rdbuf ();
  return s.str ();
}

} // namespace

TEST (PointIO, TextFormats)
{
  TempDir dir;
  pcl::PointCloud<pcl::PointXYZ> cloud;
  ASSERT_TRUE (loadPointCloud (dir.write ("a.xyz", "# comment\n1 2 3\n4 5 6  # trailing\n\n7,8,9\n"), cloud).ok);
  ASSERT_EQ (cloud.size (), 3u);
  EXPECT_EQ (cloud[2].x, 7.0f);
  EXPECT_EQ (cloud[2].z, 9.0f);
  ASSERT_TRUE (loadPointCloud (dir.write ("b.txt", "1 2\n3 4\n5 6\n"), cloud).ok);
  ASSERT_EQ (cloud.size (), 3u);
  EXPECT_EQ (cloud[1].z, 0.0f);
  EXPECT_EQ (cloud.width, 3u);

  Status bad = loadPointCloud (dir.write ("c.xyz", "1 2 3\n4 five 6\n"), cloud);
  EXPECT_FALSE (bad.ok);
  EXPECT_NE (bad.message.find (":2:"), std::string::npos) << bad.message;
  EXPECT_TRUE (cloud.empty ());
  bad = loadPointCloud (dir.write ("d.xyz", "1 2 3\n4 5\n"), cloud);
  EXPECT_NE (bad.message.find ("columns"), std::string::npos) << bad.message;
  bad = loadPointCloud (dir.write ("e.xyz", "1\n"), cloud);
  EXPECT_NE (bad.message.find ("at least 2"), std::string::npos) << bad.message;
  bad = loadPointCloud (dir.write ("f.xyz", "# nothing\n"), cloud);
  EXPECT_NE (bad.message.find ("no points"), std::string::npos) << bad.message;
  ASSERT_TRUE (loadPointCloud (dir.write ("g.xyz", "nan 0 0\n1 1 1\n"), cloud).ok);
  EXPECT_FALSE (cloud.is_dense);
}

TEST (PointIO, MeshVertices)
{
  TempDir dir;
  pcl::PointCloud<pcl::PointXYZ> cloud;
  const std::string off = "OFF\n# tetrahedron\n4 4 6\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 1 2\n3 0 1 3\n3 0 2 3\n3 1 2 3\n";
  ASSERT_TRUE (loadPointCloud (dir.write ("t.off", off), cloud).ok);
  ASSERT_EQ (cloud.size (), 4u);
  EXPECT_EQ (cloud[3].z, 1.0f);
  const std::string obj = "# obj\nv 0 0 0\nvn 0 0 1\nv 1 0 0\nv 0 1 0\nvt 0 0\nf 1 2 3\n";
  ASSERT_TRUE (loadPointCloud (dir.write ("t.obj", obj), cloud).ok);
  EXPECT_EQ (cloud.size (), 3u);
  EXPECT_FALSE (loadPointCloud (dir.write ("short.off", "OFF\n4 4 6\n0 0 0\n1 0 0\n"), cloud).ok);
  EXPECT_FALSE (loadPointCloud (dir.write ("bad.off", "PLY\n4 4 6\n"), cloud).ok);
  EXPECT_FALSE (loadPointCloud (dir.write ("neg.off", "OFF\n-4 4 6\n"), cloud).ok);
}

TEST (PointIO, PcdAndPlyRoundTrip)
{
  TempDir dir;
  pcl::PointCloud<pcl::PointXYZ> cloud, back;
  for (int i = 0; i < 10; ++i)
    cloud.push_back (pcl::PointXYZ (static_cast<float> (i), static_cast<float> (i * i), 0.5f));
  for (bool binary : {false, true})
  {
    const std::string path = dir.file (binary ? "b.pcd" : "a.pcd");
    ASSERT_TRUE (writePointCloud (path, cloud, binary).ok);
    ASSERT_TRUE (loadPointCloud (path, back).ok);
    ASSERT_EQ (back.size (), cloud.size ());
    EXPECT_EQ (back[9].y, 81.0f);
  }
  const std::string ply = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
                          "end_header\n0 0 0\n1 0 0\n0 1 2\n";
  ASSERT_TRUE (loadPointCloud (dir.write ("a.ply", ply), back).ok) << loadPointCloud (dir.file ("a.ply"), back).message;
  ASSERT_EQ (back.size (), 3u);
  EXPECT_EQ (back[2].z, 2.0f);
}

TEST (PointIO, PlyWithDoubleCoordinates)
{
  TempDir dir;
  std::string ply = "ply\nformat binary_little_endian 1.0\nelement vertex 2\nproperty double x\nproperty double y\n"
                    "property double z\nproperty double nx\nend_header\n";
  const double values[8] = {1.5, -2.25, 3.0, 0.0, 4.0, 5.0, 6.5, 1.0};
  ply.append (reinterpret_cast<const char*> (values), sizeof (values));
  pcl::PointCloud<pcl::PointXYZ> cloud;
  ASSERT_TRUE (loadPointCloud (dir.write ("d.ply", ply), cloud).ok);
  ASSERT_EQ (cloud.size (), 2u);
  EXPECT_EQ (cloud[0].y, -2.25f);
  EXPECT_EQ (cloud[1].z, 6.5f);
}

TEST (PointIO, SharedCloudsLoadAndSegment)
{
  const std::string dir = flowseg_test::sharedDataPath ("clouds/pcl/bunny.pcd");
  if (dir.empty ())
    GTEST_SKIP () << "../shared/data not present";
  const std::string base = dir.substr (0, dir.size () - std::string ("pcl/bunny.pcd").size ());
  for (const char* name : {"pcl/bunny.pcd", "pcl/milk.pcd", "cgal/kitten.xyz", "cgal/hippo1.ply"})
  {
    pcl::PointCloud<pcl::PointXYZ>::Ptr cloud (new pcl::PointCloud<pcl::PointXYZ>);
    const Status s = loadPointCloud (base + name, *cloud);
    ASSERT_TRUE (s.ok) << s.message;
    pcl::FlowSegmentation<pcl::PointXYZ> seg;
    seg.setInputCloud (cloud);
    std::vector<pcl::PointIndices> segments;
    ASSERT_TRUE (seg.segment (segments)) << name << ": " << seg.getLastError ();
    EXPECT_EQ (seg.getResult ().dimension, 3) << name;
    EXPECT_GT (seg.getResult ().vertices.size (), 0.99 * cloud->size ()) << name << ": coordinates lost in reading";
    ASSERT_FALSE (segments.empty ()) << name;
    for (const pcl::PointIndices& segment : segments)
      for (int index : segment.indices)
        EXPECT_LT (static_cast<std::size_t> (index), cloud->size ()) << name;
  }
}

TEST (PointIO, AbsurdPointCountsAreRefused)
{
  TempDir dir;
  pcl::PointCloud<pcl::PointXYZ> cloud;
  const std::string header = "VERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\nWIDTH 1500000000\nHEIGHT 1\n"
                             "POINTS 1500000000\nDATA ascii\n0 0 0\n";
  const Status s = loadPointCloud (dir.write ("huge.pcd", header), cloud);
  EXPECT_FALSE (s.ok);
  EXPECT_NE (s.message.find ("memory"), std::string::npos) << s.message;
  const Status off = loadPointCloud (dir.write ("huge.off", "OFF\n900000000 0 0\n0 0 0\n"), cloud);
  EXPECT_FALSE (off.ok);
  EXPECT_NE (off.message.find ("ends after 1"), std::string::npos) << off.message;
}

TEST (PointIO, ClearErrors)
{
  TempDir dir;
  pcl::PointCloud<pcl::PointXYZ> cloud;
  Status s = loadPointCloud (dir.file ("missing.pcd"), cloud);
  EXPECT_FALSE (s.ok);
  EXPECT_NE (s.message.find ("cannot open"), std::string::npos) << s.message;
  s = loadPointCloud (dir.write ("x.stl", "solid"), cloud);
  EXPECT_NE (s.message.find ("unknown file type"), std::string::npos) << s.message;
  s = loadPointCloud (dir.write ("junk.pcd", "this is not a pcd file\n\x01\x02"), cloud);
  EXPECT_FALSE (s.ok);
  EXPECT_NE (s.message.find ("PCD"), std::string::npos) << s.message;
  s = loadPointCloud (dir.write ("junk.ply", "garbage"), cloud);
  EXPECT_FALSE (s.ok);
}

TEST (ResultWriter, WritesAreAtomic)
{
  TempDir dir;
  const std::string target = dir.file ("out.txt");
  const Status failed = writeFileAtomically (target, [] (const std::string& tmp) {
    std::ofstream (tmp) << "half";
    return Status::error ("simulated failure");
  });
  EXPECT_FALSE (failed.ok);
  EXPECT_FALSE (exists (target));
  EXPECT_FALSE (exists (target + ".tmp." + std::to_string (::getpid ())));
  const Status thrown = writeFileAtomically (target, [] (const std::string& tmp) -> Status {
    std::ofstream (tmp) << "half";
    throw std::runtime_error ("boom");
  });
  EXPECT_FALSE (thrown.ok);
  EXPECT_FALSE (exists (target));
  EXPECT_FALSE (writePointCloud (dir.file ("no/such/dir/x.pcd"), pcl::PointCloud<pcl::PointXYZ> (), false).ok);
  pcl::PointCloud<pcl::PointXYZ> one;
  one.push_back (pcl::PointXYZ (1.0f, 2.0f, 3.0f));
  EXPECT_FALSE (writePointCloud (dir.file ("x.xyz"), one, false).ok); // PCD content, another format's name
  EXPECT_FALSE (exists (dir.file ("x.xyz")));
  EXPECT_TRUE (writePointCloud (dir.file ("x.PCD"), one, false).ok);
}

TEST (ResultWriter, SegmentationOutputsAreWellFormed)
{
  TempDir dir;
  pcl::PointCloud<pcl::PointXYZ>::Ptr cloud (new pcl::PointCloud<pcl::PointXYZ>);
  for (const auto& p : flowseg_test::shapeSample ("hand2d", 400))
    cloud->push_back (pcl::PointXYZ (static_cast<float> (p.x ()), static_cast<float> (p.y ()), 0.0f));
  cloud->push_back (pcl::PointXYZ (std::nanf (""), 0.0f, 0.0f));
  pcl::FlowSegmentation<pcl::PointXYZ> seg;
  seg.setInputCloud (cloud);
  pcl_flowseg::FlowParameters raw;
  raw.interior.separate = false;
  seg.setParameters (raw);
  std::vector<pcl::PointIndices> segments;
  ASSERT_TRUE (seg.segment (segments));
  pcl::PointCloud<pcl::PointXYZL> labels;
  seg.getLabelCloud (labels);

  ASSERT_TRUE (writeLabelCloud (dir.file ("l.pcd"), labels, true).ok);
  pcl::PointCloud<pcl::PointXYZL> back;
  ASSERT_EQ (pcl::io::loadPCDFile (dir.file ("l.pcd"), back), 0);
  ASSERT_EQ (back.size (), labels.size ());
  EXPECT_EQ (back[5].label, labels[5].label);
  EXPECT_EQ (back.back ().label, kNoSegment);

  RunInfo info;
  info.input = "hand \"2d\".pcd";
  ASSERT_TRUE (writeSegmentationJson (dir.file ("r.json"), seg.getResult (), info).ok);
  const std::string json = slurp (dir.file ("r.json"));
  EXPECT_NE (json.find ("\"segment_count\": " + std::to_string (segments.size ())), std::string::npos);
  EXPECT_NE (json.find ("\"timings_ms\""), std::string::npos);
  EXPECT_NE (json.find ("hand \\\"2d\\\".pcd"), std::string::npos);
  EXPECT_NE (json.find ("\"non_finite_points\": 1"), std::string::npos);
  // The parameters come from the result itself, every group of them.
  std::ostringstream rho;
  rho << std::setprecision (10) << seg.getResult ().parameters.merge.rho;
  EXPECT_NE (json.find ("\"rho\": " + rho.str () + ",\n"), std::string::npos);
  EXPECT_NE (json.find ("\"parameters\": {\"preparation\": {\"dimension\": \"auto\""), std::string::npos);
  EXPECT_NE (json.find ("\"merge\": {\"rho\": " + rho.str () + ", \"sampling_tolerance\""), std::string::npos);
  EXPECT_NE (json.find ("\"interior\": {\"separate_interior\": false, \"denoising\": \"auto\", \"viewpoint\": null, \"manifold_repair\": true, \"hidden_side\": true, \"exterior_opening\": 4}"), std::string::npos);
  EXPECT_EQ (std::count (json.begin (), json.end (), '{'), std::count (json.begin (), json.end (), '}'));
  EXPECT_EQ (json.find ("nan"), std::string::npos);
  EXPECT_EQ (json.find (": inf"), std::string::npos);
  EXPECT_EQ (json.find (": -nan"), std::string::npos);

  ASSERT_TRUE (writeSegmentationPly (dir.file ("s.ply"), seg.getResult (), labels).ok);
  const std::string ply = slurp (dir.file ("s.ply"));
  EXPECT_NE (ply.find ("element vertex 400\n"), std::string::npos); // the NaN point is not drawn
  EXPECT_NE (ply.find ("element face " + std::to_string (seg.getResult ().cells.size ())), std::string::npos);
  EXPECT_EQ (ply.find ("nan"), std::string::npos);
}

TEST (ResultWriter, AsciiLabelsAreExactAndBinaryPlyHoldsTheSameValues)
{
  TempDir dir;
  pcl::PointCloud<pcl::PointXYZ>::Ptr cloud (new pcl::PointCloud<pcl::PointXYZ>);
  for (const auto& p : flowseg_test::shapeSample ("animal3d", 1500))
    cloud->push_back (pcl::PointXYZ (static_cast<float> (p.x () * 1.0001), static_cast<float> (p.y ()), static_cast<float> (p.z ())));
  cloud->push_back (pcl::PointXYZ (std::nanf (""), 0.0f, 0.0f));
  pcl::FlowSegmentation<pcl::PointXYZ> seg;
  seg.setInputCloud (cloud);
  std::vector<pcl::PointIndices> segments;
  ASSERT_TRUE (seg.segment (segments));
  pcl::PointCloud<pcl::PointXYZL> labels;
  seg.getLabelCloud (labels);

  // ASCII labels: every coordinate reads back to the same float, every label to the same number.
  ASSERT_TRUE (writeLabelCloud (dir.file ("l.pcd"), labels, false).ok);
  pcl::PointCloud<pcl::PointXYZL> back;
  ASSERT_EQ (pcl::io::loadPCDFile (dir.file ("l.pcd"), back), 0);
  ASSERT_EQ (back.size (), labels.size ());
  for (std::size_t i = 0; i + 1 < labels.size (); ++i)
  {
    ASSERT_EQ (back[i].x, labels[i].x) << i;
    ASSERT_EQ (back[i].y, labels[i].y) << i;
    ASSERT_EQ (back[i].z, labels[i].z) << i;
    ASSERT_EQ (back[i].label, labels[i].label) << i;
  }
  EXPECT_TRUE (std::isnan (back.back ().x));
  EXPECT_EQ (back.back ().label, kNoSegment);

  // Binary and ASCII PLY files hold the same vertices (PCL's reader), the binary one in fewer bytes.
  ASSERT_TRUE (writeSegmentationPly (dir.file ("a.ply"), seg.getResult (), labels, false).ok);
  ASSERT_TRUE (writeSegmentationPly (dir.file ("b.ply"), seg.getResult (), labels, true).ok);
  ASSERT_TRUE (writeSurfacePly (dir.file ("as.ply"), seg.getResult (), false).ok);
  ASSERT_TRUE (writeSurfacePly (dir.file ("bs.ply"), seg.getResult (), true).ok);
  for (const auto& [ascii, binary] : {std::pair<std::string, std::string> ("a.ply", "b.ply"), {"as.ply", "bs.ply"}})
  {
    pcl::PointCloud<pcl::PointXYZ> a, b;
    ASSERT_EQ (pcl::io::loadPLYFile (dir.file (ascii), a), 0) << ascii;
    ASSERT_EQ (pcl::io::loadPLYFile (dir.file (binary), b), 0) << binary;
    ASSERT_EQ (a.size (), b.size ());
    ASSERT_GT (a.size (), 1000u);
    for (std::size_t i = 0; i < a.size (); ++i)
      ASSERT_TRUE (a[i].x == b[i].x && a[i].y == b[i].y && a[i].z == b[i].z) << binary << " " << i;
    EXPECT_LT (slurp (dir.file (binary)).size (), slurp (dir.file (ascii)).size ());
    EXPECT_NE (slurp (dir.file (binary)).find ("format binary_little_endian 1.0\n"), std::string::npos);
  }
  pcl::PolygonMesh mesh;
  ASSERT_EQ (pcl::io::loadPLYFile (dir.file ("bs.ply"), mesh), 0);
  EXPECT_EQ (mesh.polygons.size (), seg.getResult ().interior.boundary_facets);
}

TEST (PointIO, PcdFilesAreReadByOurOwnStrictReader)
{
  // The input that made PCL's reader ask for 100 TB after 25 minutes of fuzzing: a valid header
  // whose binary data are arbitrary bytes. Read by our reader, it is 4 points (one not finite).
  pcl::PointCloud<pcl::PointXYZ> cloud;
  const std::string found = std::string (PCL_FLOWSEG_SOURCE_DIR) + "/test/data/fuzz_regressions/point_pcd_binary_data_e306c3c0.pcd";
  ASSERT_TRUE (loadPointCloud (found, cloud).ok);
  EXPECT_EQ (cloud.size (), 4u);

  TempDir dir;
  const std::string head = "VERSION 0.7\nFIELDS x y z rgb\nSIZE 4 4 4 1\nTYPE F F F U\nCOUNT 1 1 1 1\nWIDTH 2\nHEIGHT 1\n"
                           "VIEWPOINT 1 2 3 1 0 0 0\nPOINTS 2\nDATA ascii\n";
  auto load = [&] (const std::string& body) {
    std::ofstream (dir.file ("a.pcd")) << head << body;
    return loadPointCloud (dir.file ("a.pcd"), cloud);
  };
  ASSERT_TRUE (load ("1 2 3 4\n\n  5e-1 nan -7 255  \r\n").ok);
  ASSERT_EQ (cloud.size (), 2u);
  EXPECT_EQ (cloud[1].x, 0.5f);
  EXPECT_TRUE (std::isnan (cloud[1].y));
  EXPECT_EQ (cloud.sensor_origin_.head<3> (), Eigen::Vector3f (1, 2, 3));
  const std::pair<std::string, std::string> refused[] = {
      {"1 2 3 4\n5 6 7\n", "a.pcd: data line 2: missing a value of field 'rgb'"},
      {"1 2 3 4\n5 6 7 8 9\n", "data line 2: more values than the fields hold"},
      {"1 2 3 256\n5 6 7 8\n", "data line 1: '256' is not a value of field 'rgb' (U1)"},
      {"1 2 3 -1\n5 6 7 8\n", "'-1' is not a value"},
      {"1 2 x3 4\n5 6 7 8\n", "'x3' is not a value of field 'z' (F4)"},
      {"1 2 3 4\n", "truncated PCD file (1 of 2 points)"},
      {"1 2 3 4\n5 6 7 8\n9 9 9 9\n", "data line 3: more points than the header's POINTS 2"}};
  for (const auto& [body, message] : refused)
  {
    const Status s = load (body);
    EXPECT_FALSE (s.ok) << body;
    EXPECT_NE (s.message.find (message), std::string::npos) << s.message;
  }
}

TEST (FuzzRegressions, InputsTheFuzzersFoundAreRefusedCleanly)
{
  // Each file once crashed a reader (found by scripts/fuzz.sh); now each is refused with a message.
  const std::string dir = std::string (PCL_FLOWSEG_SOURCE_DIR) + "/test/data/fuzz_regressions/";
  std::size_t checked = 0;
  for (const char* name : {"mesh_ply_header_27fc9764.ply", "pgm_huge_width_dcafbfbf.pgm", "mesh_ply_negative_count.ply",
                           "point_pcd_size_type.pcd", "point_pcd_float_size2_c82b59f5.pcd",
                           "mesh_ply_vertex_list_c916fd58.ply", "point_pcd_height0_ed412c7f.pcd",
                           "point_pcd_points_twice_c9647db9.pcd", "point_pcd_huge_height_437fadd9.pcd",
                           "point_pcd_control_bytes_header.pcd", "point_pcd_no_points_line.pcd",
                           "point_pcd_non_ascii_comment.pcd", "point_pcd_version_twice.pcd"})
  {
    const std::string path = dir + name;
    std::vector<Eigen::Vector3d> pts;
    const Status s = loadShapeSample (path, ShapeInputOptions (), pts);
    EXPECT_FALSE (s.ok) << name;
    EXPECT_FALSE (s.message.empty ()) << name;
    TriangleMesh mesh;
    GreyImage image;
    EXPECT_FALSE (loadTriangleMesh (path, mesh).ok && loadGreyImage (path, image).ok);
    ++checked;
  }
  EXPECT_EQ (checked, 13u);
  // The causes, named: a negative element count is refused before PCL allocates for it, and a
  // PCD float field of 2 bytes before PCL's reader (which crashed on one) or ours sees it.
  std::vector<Eigen::Vector3d> pts;
  const Status ply = loadShapeSample (dir + "mesh_ply_negative_count.ply", ShapeInputOptions (), pts);
  EXPECT_NE (ply.message.find ("count that is not a whole number"), std::string::npos) << ply.message;
  pcl::PointCloud<pcl::PointXYZ> cloud;
  const Status pcd = loadPointCloud (dir + "point_pcd_size_type.pcd", cloud);
  EXPECT_NE (pcd.message.find ("invalid SIZE/TYPE 2/F"), std::string::npos) << pcd.message;
  for (const char* name : {"point_pcd_float_size2_c82b59f5.pcd", "point_pcd_control_bytes_header.pcd",
                           "point_pcd_non_ascii_comment.pcd"})
  {
    const Status garbled = loadPointCloud (dir + name, cloud); // PCL misread their headers
    EXPECT_NE (garbled.message.find ("control characters in the PCD header"), std::string::npos) << garbled.message;
  }
  // PCL's PLY reader stops on an assertion for a list in the vertex element, its PCD reader
  // misreads a file of no points: both are refused first.
  TempDir tmp;
  std::ofstream (tmp.file ("list.ply")) << "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                                           "property list uchar int vertex_indices\nend_header\n0 0 1 0\n1 0 1 1\n0 1 1 2\n";
  const Status list = loadShapeSample (tmp.file ("list.ply"), ShapeInputOptions (), pts);
  EXPECT_NE (list.message.find ("a list property of the vertex element"), std::string::npos) << list.message;
  std::ofstream (tmp.file ("height0.pcd")) << "VERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\nWIDTH 4\n"
                                              "HEIGHT 0\nPOINTS 0\nDATA ascii\n"; // as the fuzzer's, without its bad VIEWPOINT
  const Status none = loadPointCloud (tmp.file ("height0.pcd"), cloud);
  EXPECT_NE (none.message.find ("holds no points"), std::string::npos) << none.message;
  std::ofstream (tmp.file ("twice.pcd")) << "VERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\nWIDTH 4\n"
                                             "HEIGHT 1\nPOINTS  0\nPOINTS 4\nDATA ascii\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n";
  const Status twice = loadPointCloud (tmp.file ("twice.pcd"), cloud); // the fuzzer's file also has control bytes
  EXPECT_NE (twice.message.find (":9: 'POINTS' appears twice"), std::string::npos) << twice.message;
  const Status lost = loadPointCloud (dir + "point_pcd_no_points_line.pcd", cloud); // POINTS ran into VIEWPOINT
  EXPECT_NE (lost.message.find (":9: VIEWPOINT needs 7 numbers"), std::string::npos) << lost.message;
  std::ofstream (tmp.file ("nopoints.pcd")) << "VERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\nWIDTH 4\n"
                                               "HEIGHT 1\nDATA ascii\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n";
  const Status missing = loadPointCloud (tmp.file ("nopoints.pcd"), cloud);
  EXPECT_NE (missing.message.find ("WIDTH or POINTS missing"), std::string::npos) << missing.message;
  const Status version = loadPointCloud (dir + "point_pcd_version_twice.pcd", cloud);
  EXPECT_NE (version.message.find (":2: VERSION must be one of"), std::string::npos) << version.message;
  const Status tall = loadPointCloud (dir + "point_pcd_huge_height_437fadd9.pcd", cloud);
  EXPECT_NE (tall.message.find (":8: invalid HEIGHT"), std::string::npos) << tall.message;
  // A database with an absurd weight (a query on it once died with SIGSEGV) is refused at its line.
  SignatureDatabase db;
  const Status loaded = db.load (dir + "database_absurd_weight.db");
  EXPECT_FALSE (loaded.ok);
  EXPECT_NE (loaded.message.find (":4: the weight"), std::string::npos) << loaded.message;
  const Status huge = db.load (dir + "database_huge_count_24256e5a.db");
  EXPECT_NE (huge.message.find (":2: 44204242 shapes cannot fit"), std::string::npos) << huge.message;
}

TEST (PointIO, PointNormalCloudCarriesNormalsAndViewpoint)
{
  TempDir dir;
  std::ofstream (dir.file ("n.xyz")) << "0 0 0 0 0 1\n1 0 0 0 0 1\n0 1 0 0 0 -1\n";
  pcl::PointCloud<pcl::PointNormal> cloud;
  bool has_normals = false;
  ASSERT_TRUE (loadPointCloud (dir.file ("n.xyz"), cloud, has_normals));
  EXPECT_TRUE (has_normals);
  ASSERT_EQ (cloud.size (), 3u);
  EXPECT_EQ (cloud[2].normal_z, -1.0f);
  EXPECT_EQ (cloud[1].x, 1.0f);
  pcl::PointCloud<pcl::PointXYZ> plain;
  plain.push_back (pcl::PointXYZ (1, 2, 3));
  plain.sensor_origin_ = Eigen::Vector4f (4, 5, 6, 0);
  ASSERT_EQ (pcl::io::savePCDFileASCII (dir.file ("v.pcd"), plain), 0);
  ASSERT_TRUE (loadPointCloud (dir.file ("v.pcd"), cloud, has_normals));
  EXPECT_FALSE (has_normals);
  EXPECT_EQ (cloud[0].normal_x, 0.0f);
  EXPECT_EQ (cloud.sensor_origin_, Eigen::Vector4f (4, 5, 6, 0));
  EXPECT_FALSE (loadPointCloud (dir.file ("none.pcd"), cloud, has_normals));
  EXPECT_TRUE (cloud.empty ());
}

TEST (PointIO, PointNormalReadOfPcdAndPlyMatchesThePointsAndNormalsRead)
{
  // PCD and PLY go straight into PointNormal; the result must be what the PointXYZ reader with its
  // normals gives, in every numeric type, with zero normals when a file has only some of them.
  TempDir dir;
  std::string ply = "ply\nformat binary_little_endian 1.0\nelement vertex 2\nproperty double x\nproperty double y\n"
                    "property double z\nproperty float nx\nproperty float ny\nproperty float nz\nend_header\n";
  const double xyz[2][3] = {{1.5, -2.25, 3.0}, {0.1, 4.0, 1e-3}};
  const float normal[2][3] = {{0.0f, 0.6f, 0.8f}, {1.0f, 0.0f, 0.0f}};
  for (int i = 0; i < 2; ++i)
  {
    ply.append (reinterpret_cast<const char*> (xyz[i]), sizeof (xyz[i]));
    ply.append (reinterpret_cast<const char*> (normal[i]), sizeof (normal[i]));
  }
  const std::string partial = "# .PCD v0.7\nVERSION 0.7\nFIELDS x y z normal_x\nSIZE 4 4 4 4\nTYPE F F F F\nCOUNT 1 1 1 1\n"
                              "WIDTH 2\nHEIGHT 1\nVIEWPOINT 0 0 0 1 0 0 0\nPOINTS 2\nDATA ascii\n1 2 3 0.5\nnan 0 0 1\n";
  for (const std::string& path : {dir.write ("n.ply", ply), dir.write ("p.pcd", partial)})
  {
    pcl::PointCloud<pcl::PointXYZ> points;
    std::vector<Eigen::Vector3d> normals;
    ASSERT_TRUE (loadPointCloud (path, points, normals)) << path;
    pcl::PointCloud<pcl::PointNormal> cloud;
    bool has_normals = false;
    ASSERT_TRUE (loadPointCloud (path, cloud, has_normals)) << path;
    EXPECT_EQ (has_normals, !normals.empty ()) << path;
    ASSERT_EQ (cloud.size (), points.size ()) << path;
    EXPECT_EQ (cloud.is_dense, points.is_dense) << path;
    EXPECT_EQ (cloud.width, points.width) << path;
    for (std::size_t i = 0; i < cloud.size (); ++i)
    {
      EXPECT_EQ (Eigen::Vector3f (cloud[i].x, cloud[i].y, cloud[i].z).hasNaN (), !std::isfinite (points[i].x)) << path;
      if (std::isfinite (points[i].x))
        EXPECT_EQ (cloud[i].getVector3fMap (), points[i].getVector3fMap ()) << path << " " << i;
      const Eigen::Vector3f expected = has_normals ? Eigen::Vector3f (normals[i].cast<float> ()) : Eigen::Vector3f::Zero ();
      EXPECT_EQ (cloud[i].getNormalVector3fMap (), expected) << path << " " << i;
    }
  }
  pcl::PointCloud<pcl::PointNormal> cloud;
  bool has_normals = false;
  ASSERT_TRUE (loadPointCloud (dir.file ("n.ply"), cloud, has_normals));
  EXPECT_TRUE (has_normals);
  EXPECT_EQ (cloud[0].y, -2.25f);
  EXPECT_EQ (cloud[0].normal_z, 0.8f);
  ASSERT_TRUE (loadPointCloud (dir.file ("p.pcd"), cloud, has_normals));
  EXPECT_FALSE (has_normals); // only normal_x: no normals
  EXPECT_FALSE (cloud.is_dense);
}

TEST (PointIO, ShapeInputOptionsAreChecked)
{
  ShapeInputOptions o;
  EXPECT_TRUE (checkShapeInputOptions (o));
  o.mesh_points = 3;
  EXPECT_FALSE (checkShapeInputOptions (o));
  o.mesh_points = 100000001;
  EXPECT_FALSE (checkShapeInputOptions (o));
}

TEST (PointIO, ShapeSamplesGiveTheSensorOriginOfTheFilesThatCarryOne)
{
  TempDir dir;
  pcl::PointCloud<pcl::PointXYZ> scan;
  for (int i = 0; i < 4; ++i)
    scan.push_back (pcl::PointXYZ (i == 1, i == 2, i == 3));
  scan.sensor_origin_ = Eigen::Vector4f (4, 5, 6, 0);
  ASSERT_TRUE (writePointCloud (dir.file ("scan.pcd"), scan, false));
  ShapeInputOptions o;
  std::vector<Eigen::Vector3d> pts;
  std::optional<Eigen::Vector3d> origin;
  ASSERT_TRUE (loadShapeSample (dir.file ("scan.pcd"), o, pts, &origin));
  EXPECT_EQ (pts.size (), 4u);
  ASSERT_TRUE (origin.has_value ());
  EXPECT_EQ (*origin, Eigen::Vector3d (4, 5, 6));
  o.use_sensor_origin = true; // the same: a PCD file carries one
  origin.reset ();
  ASSERT_TRUE (loadShapeSample (dir.file ("scan.pcd"), o, pts, &origin));
  EXPECT_EQ (origin, Eigen::Vector3d (4, 5, 6));
  EXPECT_TRUE (carriesSensorOrigin ("a/B.PCD"));

  // Text, PLY and meshes carry none: none is given, and asking for one fails, naming the file.
  const std::string xyz = dir.write ("scan.xyz", "0 0 0\n1 0 0\n0 1 0\n0 0 1\n");
  const std::string off = dir.write ("tet.off", "OFF\n4 4 6\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n");
  for (const std::string& path : {xyz, off})
  {
    EXPECT_FALSE (carriesSensorOrigin (path));
    o.use_sensor_origin = false;
    origin = Eigen::Vector3d (1, 1, 1);
    ASSERT_TRUE (loadShapeSample (path, o, pts, &origin)) << path;
    EXPECT_FALSE (pts.empty ());
    EXPECT_FALSE (origin.has_value ()) << path;
    o.use_sensor_origin = true;
    const Status refused = loadShapeSample (path, o, pts, &origin);
    EXPECT_FALSE (refused.ok) << path;
    EXPECT_NE (refused.message.find (path + ": the file carries no sensor origin"), std::string::npos) << refused.message;
    EXPECT_TRUE (pts.empty ());
    EXPECT_FALSE (origin.has_value ());
  }
  EXPECT_FALSE (carriesSensorOrigin ("scan.ply"));
}

TEST (ResultWriter, JsonTextIsEscapedAndTextFilesAreAtomic)
{
  EXPECT_EQ (jsonString ("a\"b\\c\nd\te\x01"), "\"a\\\"b\\\\c\\nd\\te\\u0001\"");
  EXPECT_EQ (jsonNumber (std::nan ("")), "null");
  EXPECT_EQ (jsonNumber (1.0 / 0.0), "null");
  EXPECT_EQ (jsonNumber (0.125), "0.125");
  TempDir dir;
  ASSERT_TRUE (writeTextFileAtomically (dir.file ("t.txt"), [] (std::ostream& out) { out << "whole"; }));
  EXPECT_EQ (slurp (dir.file ("t.txt")), "whole");
  EXPECT_FALSE (writeTextFileAtomically (dir.file ("no/such/t.txt"), [] (std::ostream& out) { out << "x"; }));
  const Status thrown = writeTextFileAtomically (dir.file ("u.txt"), [] (std::ostream& out) {
    out << "half";
    throw std::runtime_error ("boom");
  });
  EXPECT_FALSE (thrown);
  EXPECT_FALSE (std::ifstream (dir.file ("u.txt")).good ());
}

/*
 * Silhouette images: readers, polarity, boundary samples, and their segmentation.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include "test_support.h"

#include <pcl_flowseg/evaluation/png_writer.h>
#include <pcl_flowseg/evaluation/retrieval_figures.h>
#include <pcl_flowseg/evaluation/shape_distributions.h>
#include <pcl_flowseg/io/shape_input.h>
#include <pcl_flowseg/io/silhouette.h>

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <unistd.h>

using namespace pcl_flowseg;

namespace {
std::string
tempPath (const std::string& name)
{
  return "/tmp/flowseg_sil_" + std::to_string (::getpid ()) + "_" + name;
}

/** A 64 x 48 image of a disc of radius 15 (value \a shape) on \a background. */
std::vector<std::uint8_t>
disc (std::uint8_t shape, std::uint8_t background)
{
  std::vector<std::uint8_t> px (64 * 48, background);
  for (int y = 0; y < 48; ++y)
    for (int x = 0; x < 64; ++x)
      if (std::hypot (x + 0.5 - 30, y + 0.5 - 24) < 15)
        px[static_cast<std::size_t> (y * 64 + x)] = shape;
  return px;
}

void
expectDiscBoundary (const std::vector<Eigen::Vector3d>& pts)
{
  ASSERT_GT (pts.size (), 80u);
  for (const auto& p : pts)
  {
    EXPECT_NEAR (std::hypot (p.x () - 30, -p.y () - 24), 15.0, 1.0);
    EXPECT_EQ (p.z (), 0.0);
  }
}
} // namespace

TEST (Silhouette, PngEitherPolarity)
{
  for (bool dark_shape : {true, false})
  {
    const std::string p = tempPath (dark_shape ? "dark.png" : "light.png");
    ASSERT_TRUE (writePng (p, 64, 48, 1, disc (dark_shape ? 0 : 255, dark_shape ? 255 : 0)).ok);
    GreyImage img;
    ASSERT_TRUE (loadGreyImage (p, img).ok);
    EXPECT_EQ (img.width, 64);
    EXPECT_EQ (img.height, 48);
    expectDiscBoundary (silhouetteBoundary (img));
    std::remove (p.c_str ());
  }
}

TEST (Silhouette, PgmAndBmp)
{
  const auto px = disc (0, 255);
  const std::string pgm = tempPath ("d.pgm");
  {
    std::ofstream out (pgm, std::ios::binary);
    out << "P5\n# a disc\n64 48\n255\n";
    out.write (reinterpret_cast<const char*> (px.data ()), static_cast<std::streamsize> (px.size ()));
  }
  GreyImage img;
  ASSERT_TRUE (loadGreyImage (pgm, img).ok);
  expectDiscBoundary (silhouetteBoundary (img));

  // 24-bit bottom-up BMP, rows padded to 4 bytes.
  const std::string bmp = tempPath ("d.bmp");
  {
    const int w = 64, h = 48, stride = (w * 3 + 3) / 4 * 4;
    std::vector<std::uint8_t> f (54 + static_cast<std::size_t> (stride * h), 0);
    auto put = [&] (std::size_t at, std::uint32_t v, int n) {
      for (int k = 0; k < n; ++k)
        f[at + static_cast<std::size_t> (k)] = static_cast<std::uint8_t> (v >> (8 * k));
    };
    f[0] = 'B';
    f[1] = 'M';
    put (2, static_cast<std::uint32_t> (f.size ()), 4);
    put (10, 54, 4);
    put (14, 40, 4);
    put (18, w, 4);
    put (22, h, 4);
    put (26, 1, 2);
    put (28, 24, 2);
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x)
        for (int c = 0; c < 3; ++c)
          f[54 + static_cast<std::size_t> ((h - 1 - y) * stride + x * 3 + c)] = px[static_cast<std::size_t> (y * w + x)];
    std::ofstream (bmp, std::ios::binary).write (reinterpret_cast<const char*> (f.data ()), static_cast<std::streamsize> (f.size ()));
  }
  ASSERT_TRUE (loadGreyImage (bmp, img).ok);
  expectDiscBoundary (silhouetteBoundary (img));

  // Through the shape input: a 2D sample that segments into one interior feature.
  std::vector<Eigen::Vector3d> pts;
  ASSERT_TRUE (loadShapeSample (bmp, ShapeInputOptions (), pts).ok);
  FlowParameters params;
  FlowResult r;
  ASSERT_TRUE (runFlowSegmentation (pts, params, r).ok);
  EXPECT_EQ (r.dimension, 2);
  EXPECT_NEAR (r.interior.inside_volume, M_PI * 15 * 15, 0.05 * M_PI * 15 * 15);
  std::remove (pgm.c_str ());
  std::remove (bmp.c_str ());
}

TEST (Silhouette, BadFiles)
{
  GreyImage img;
  const std::string p = tempPath ("bad.png");
  std::ofstream (p) << "not an image";
  EXPECT_NE (loadGreyImage (p, img).message.find ("not a PNG"), std::string::npos);
  const std::string b = tempPath ("bad.bmp");
  std::ofstream (b) << "BM too short";
  EXPECT_FALSE (loadGreyImage (b, img).ok);
  const std::string g = tempPath ("bad.pgm");
  std::ofstream (g) << "P5\n10 10\n255\nabc";
  EXPECT_NE (loadGreyImage (g, img).message.find ("truncated"), std::string::npos);
  EXPECT_FALSE (loadGreyImage (tempPath ("missing.png"), img).ok);
  // A blank image holds no silhouette.
  EXPECT_TRUE (silhouetteBoundary (GreyImage{4, 4, std::vector<std::uint8_t> (16, 255)}).empty ());
  for (const auto& f : {p, b, g})
    std::remove (f.c_str ());
}

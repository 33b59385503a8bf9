/*
 * pcl_flowseg - retrieval evaluation over a labelled collection, and the D2 shape distribution.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include <pcl_flowseg/evaluation/retrieval.h>

#include <pcl_flowseg/io/atomic_file.h>

#include <pcl/features/esf.h>

#include <png.h>

#include <cstdio>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <map>
#include <numeric>
#include <random>

namespace pcl_flowseg {

RetrievalScores
scoreRetrieval (const std::vector<std::vector<double>>& similarity, const std::vector<std::string>& labels)
{
  RetrievalScores s;
  const std::size_t n = labels.size ();
  std::map<std::string, std::size_t> class_size;
  for (const auto& l : labels)
    ++class_size[l];
  std::vector<std::size_t> order;
  for (std::size_t q = 0; q < n; ++q)
  {
    const std::size_t c = class_size[labels[q]];
    if (c < 2)
      continue;
    order.clear ();
    for (std::size_t j = 0; j < n; ++j)
      if (j != q)
        order.push_back (j);
    std::stable_sort (order.begin (), order.end (), [&] (std::size_t a, std::size_t b) { return similarity[q][a] > similarity[q][b]; });
    const std::size_t relevant = c - 1;
    std::size_t first = 0, second = 0, eye = 1; // the bull's eye counts the query itself
    double dcg = 0.0, ideal = 0.0;
    for (std::size_t r = 0; r < order.size (); ++r)
    {
      const bool hit = labels[order[r]] == labels[q];
      const double discount = r == 0 ? 1.0 : 1.0 / std::log2 (static_cast<double> (r + 1));
      if (hit)
        dcg += discount;
      if (r < relevant)
        ideal += discount;
      first += hit && r < relevant;
      second += hit && r < 2 * relevant;
      eye += hit && r + 1 < 2 * c;
    }
    s.nearest_neighbour += labels[order[0]] == labels[q];
    s.first_tier += static_cast<double> (first) / relevant;
    s.second_tier += static_cast<double> (second) / relevant;
    s.dcg += dcg / ideal;
    s.bulls_eye += static_cast<double> (eye) / c;
    ++s.queries;
  }
  if (s.queries)
  {
    const double q = static_cast<double> (s.queries);
    s.nearest_neighbour /= q;
    s.first_tier /= q;
    s.second_tier /= q;
    s.dcg /= q;
    s.bulls_eye /= q;
  }
  return s;
}

std::vector<double>
d2Distribution (const std::vector<Eigen::Vector3d>& points, std::size_t pairs, int bins, std::uint32_t seed)
{
  std::vector<double> h (static_cast<std::size_t> (std::max (1, bins)), 0.0);
  if (points.size () < 2 || pairs == 0)
    return h;
  std::mt19937 rng (seed);
  std::uniform_int_distribution<std::size_t> pick (0, points.size () - 1);
  std::vector<double> d (pairs);
  double mean = 0.0;
  for (auto& v : d)
  {
    v = (points[pick (rng)] - points[pick (rng)]).norm ();
    mean += v;
  }
  mean /= static_cast<double> (pairs);
  if (!(mean > 0.0))
    return h;
  for (double v : d)
  {
    const int b = static_cast<int> (v / mean / 3.0 * bins);
    h[static_cast<std::size_t> (std::min (std::max (b, 0), bins - 1))] += 1.0 / static_cast<double> (pairs);
  }
  return h;
}

std::vector<double>
esfDescriptor (const std::vector<Eigen::Vector3d>& points)
{
  pcl::PointCloud<pcl::PointXYZ>::Ptr cloud (new pcl::PointCloud<pcl::PointXYZ>);
  // ESF voxelises the cloud: scale it to a fixed size first (its histograms are scale invariant
  // in intent, its voxel grid is not).
  Eigen::Vector3d lo = points.empty () ? Eigen::Vector3d::Zero () : points.front (), hi = lo;
  for (const auto& p : points)
  {
    lo = lo.cwiseMin (p);
    hi = hi.cwiseMax (p);
  }
  const double diag = (hi - lo).norm ();
  for (const auto& p : points)
  {
    const Eigen::Vector3d q = diag > 0 ? Eigen::Vector3d ((p - lo) / diag) : Eigen::Vector3d::Zero ();
    cloud->push_back (pcl::PointXYZ (static_cast<float> (q.x ()), static_cast<float> (q.y ()), static_cast<float> (q.z ())));
  }
  pcl::ESFEstimation<pcl::PointXYZ, pcl::ESFSignature640> esf;
  esf.setInputCloud (cloud);
  pcl::PointCloud<pcl::ESFSignature640> out;
  esf.compute (out);
  std::vector<double> h;
  if (out.size () != 1)
    return h;
  double sum = 0.0;
  for (float v : out[0].histogram)
  {
    h.push_back (v);
    sum += v;
  }
  if (sum > 0)
    for (auto& v : h)
      v /= sum;
  return h;
}

double
histogramSimilarity (const std::vector<double>& a, const std::vector<double>& b)
{
  double l1 = 0.0;
  for (std::size_t k = 0; k < std::min (a.size (), b.size ()); ++k)
    l1 += std::abs (a[k] - b[k]);
  return 1.0 - 0.5 * l1;
}

Status
writeSimilarityCsv (const std::string& path, const std::vector<std::string>& names, const std::vector<std::vector<double>>& similarity)
{
  auto quote = [] (const std::string& s) {
    std::string q = "\"";
    for (char c : s)
      q += c == '"' ? std::string ("\"\"") : std::string (1, c);
    return q + "\"";
  };
  return writeFileAtomically (path, [&] (const std::string& tmp) {
    std::ofstream out (tmp);
    if (!out)
      return Status::error ("cannot create file");
    out << "shape";
    for (const auto& n : names)
      out << "," << quote (n);
    out << "\n" << std::setprecision (8);
    for (std::size_t i = 0; i < names.size (); ++i)
    {
      out << quote (names[i]);
      for (std::size_t j = 0; j < names.size (); ++j)
        out << "," << similarity[i][j];
      out << "\n";
    }
    out.flush ();
    return out.good () ? Status::success () : Status::error ("write failed");
  });
}

Status
writePng (const std::string& path, int width, int height, int channels, const std::vector<std::uint8_t>& pixels)
{
  if (width <= 0 || height <= 0 || (channels != 1 && channels != 3) ||
      pixels.size () != static_cast<std::size_t> (width) * static_cast<std::size_t> (height) * static_cast<std::size_t> (channels))
    return Status::error ("cannot write " + path + ": invalid image size");
  return writeFileAtomically (path, [&] (const std::string& tmp) {
    FILE* file = std::fopen (tmp.c_str (), "wb");
    if (!file)
      return Status::error ("cannot create file");
    png_structp png = png_create_write_struct (PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
    png_infop info = png ? png_create_info_struct (png) : nullptr;
    if (!png || !info || setjmp (png_jmpbuf (png)))
    {
      png_destroy_write_struct (&png, &info);
      std::fclose (file);
      return Status::error ("libpng failed");
    }
    png_init_io (png, file);
    png_set_IHDR (png, info, static_cast<png_uint_32> (width), static_cast<png_uint_32> (height), 8,
                  channels == 1 ? PNG_COLOR_TYPE_GRAY : PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT,
                  PNG_FILTER_TYPE_DEFAULT);
    png_write_info (png, info);
    const std::size_t stride = static_cast<std::size_t> (width) * static_cast<std::size_t> (channels);
    for (int y = 0; y < height; ++y)
      png_write_row (png, const_cast<png_bytep> (pixels.data () + static_cast<std::size_t> (y) * stride));
    png_write_end (png, nullptr);
    png_destroy_write_struct (&png, &info);
    return std::fclose (file) == 0 ? Status::success () : Status::error ("write failed");
  });
}

namespace {
/** Draws \a points into the square cell at (x0, y0) of an RGB image \a width pixels wide. */
void
drawShape (std::vector<std::uint8_t>& img, int width, int x0, int y0, int cell, const std::vector<Eigen::Vector3d>& points)
{
  if (points.empty ())
    return;
  Eigen::Vector3d mean = Eigen::Vector3d::Zero ();
  for (const auto& p : points)
    mean += p;
  mean /= static_cast<double> (points.size ());
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero ();
  for (const auto& p : points)
    cov += (p - mean) * (p - mean).transpose ();
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es (cov);
  Eigen::Vector3d u = es.eigenvectors ().col (2), v = es.eigenvectors ().col (1);
  // Planar shapes keep their orientation: project on x and y when z is constant.
  bool planar = true;
  for (const auto& p : points)
    planar &= p.z () == points.front ().z ();
  if (planar)
  {
    u = Eigen::Vector3d::UnitX ();
    v = Eigen::Vector3d::UnitY ();
  }
  double lo_u = 1e300, hi_u = -1e300, lo_v = 1e300, hi_v = -1e300;
  for (const auto& p : points)
  {
    lo_u = std::min (lo_u, (p - mean).dot (u));
    hi_u = std::max (hi_u, (p - mean).dot (u));
    lo_v = std::min (lo_v, (p - mean).dot (v));
    hi_v = std::max (hi_v, (p - mean).dot (v));
  }
  const double span = std::max (hi_u - lo_u, hi_v - lo_v);
  if (!(span > 0))
    return;
  const double scale = (cell - 12) / span;
  for (const auto& p : points)
  {
    const int x = x0 + 6 + static_cast<int> (((p - mean).dot (u) - lo_u) * scale + 0.5 * (cell - 12 - (hi_u - lo_u) * scale));
    const int y = y0 + cell - 7 - static_cast<int> (((p - mean).dot (v) - lo_v) * scale + 0.5 * (cell - 12 - (hi_v - lo_v) * scale));
    if (x < x0 || y < y0 || x >= x0 + cell || y >= y0 + cell)
      continue;
    for (int c = 0; c < 3; ++c)
      img[3 * (static_cast<std::size_t> (y) * static_cast<std::size_t> (width) + static_cast<std::size_t> (x)) + static_cast<std::size_t> (c)] = 40;
  }
}

void
frame (std::vector<std::uint8_t>& img, int width, int x0, int y0, int cell, std::uint8_t r, std::uint8_t g, std::uint8_t b)
{
  for (int t = 0; t < 3; ++t)
    for (int i = 0; i < cell; ++i)
      for (const auto& xy : {std::make_pair (x0 + i, y0 + t), std::make_pair (x0 + i, y0 + cell - 1 - t), std::make_pair (x0 + t, y0 + i),
                             std::make_pair (x0 + cell - 1 - t, y0 + i)})
      {
        const std::size_t at = 3 * (static_cast<std::size_t> (xy.second) * static_cast<std::size_t> (width) + static_cast<std::size_t> (xy.first));
        img[at] = r;
        img[at + 1] = g;
        img[at + 2] = b;
      }
}
} // namespace

Status
writeTopMatchesPng (const std::string& path, const std::vector<std::vector<Eigen::Vector3d>>& shapes,
                    const std::vector<std::string>& labels, const std::vector<std::vector<double>>& similarity,
                    const std::vector<std::size_t>& queries, int k, int cell)
{
  if (queries.empty () || k < 1 || cell < 16 || shapes.size () != similarity.size () || labels.size () != shapes.size ())
    return Status::error ("cannot write " + path + ": nothing to draw");
  const int width = (k + 1) * cell, height = static_cast<int> (queries.size ()) * cell;
  std::vector<std::uint8_t> img (3 * static_cast<std::size_t> (width) * static_cast<std::size_t> (height), 255);
  for (std::size_t row = 0; row < queries.size (); ++row)
  {
    const std::size_t q = queries[row];
    const int y0 = static_cast<int> (row) * cell;
    drawShape (img, width, 0, y0, cell, shapes[q]);
    frame (img, width, 0, y0, cell, 40, 90, 220);
    std::vector<std::size_t> order;
    for (std::size_t j = 0; j < shapes.size (); ++j)
      if (j != q)
        order.push_back (j);
    std::stable_sort (order.begin (), order.end (), [&] (std::size_t a, std::size_t b) { return similarity[q][a] > similarity[q][b]; });
    for (int r = 0; r < k && r < static_cast<int> (order.size ()); ++r)
    {
      const std::size_t j = order[static_cast<std::size_t> (r)];
      drawShape (img, width, (r + 1) * cell, y0, cell, shapes[j]);
      if (labels[j] == labels[q])
        frame (img, width, (r + 1) * cell, y0, cell, 40, 170, 60);
      else
        frame (img, width, (r + 1) * cell, y0, cell, 220, 50, 40);
    }
  }
  return writePng (path, width, height, 3, img);
}

Status
writeSimilarityPng (const std::string& path, const std::vector<std::vector<double>>& similarity, int best, int cell)
{
  const int n = static_cast<int> (similarity.size ());
  if (n == 0 || cell < 1 || best < 1)
    return Status::error ("cannot write " + path + ": empty matrix");
  const int size = n * cell;
  std::vector<std::uint8_t> img (static_cast<std::size_t> (size) * static_cast<std::size_t> (size), 255);
  std::vector<int> order (static_cast<std::size_t> (n));
  for (int i = 0; i < n; ++i)
  {
    std::iota (order.begin (), order.end (), 0);
    std::stable_sort (order.begin (), order.end (), [&] (int a, int b) { return similarity[static_cast<std::size_t> (i)][static_cast<std::size_t> (a)] > similarity[static_cast<std::size_t> (i)][static_cast<std::size_t> (b)]; });
    for (int r = 0; r < std::min (best, n); ++r)
    {
      const auto grey = static_cast<std::uint8_t> (200 * r / std::max (1, best));
      const int j = order[static_cast<std::size_t> (r)];
      for (int y = i * cell; y < (i + 1) * cell; ++y)
        for (int x = j * cell; x < (j + 1) * cell; ++x)
          img[static_cast<std::size_t> (y) * static_cast<std::size_t> (size) + static_cast<std::size_t> (x)] = grey;
    }
  }
  return writePng (path, size, size, 1, img);
}

} // namespace pcl_flowseg

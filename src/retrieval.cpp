/*
 * pcl_flowseg - retrieval evaluation over a labelled collection, and the D2 shape distribution.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include <pcl_flowseg/retrieval.h>

#include "atomic_file.h"

#include <pcl/features/esf.h>

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

namespace {

std::uint32_t
crc32 (const std::uint8_t* data, std::size_t n, std::uint32_t crc = 0)
{
  static std::uint32_t table[256];
  static bool ready = false;
  if (!ready)
  {
    for (std::uint32_t i = 0; i < 256; ++i)
    {
      std::uint32_t c = i;
      for (int k = 0; k < 8; ++k)
        c = c & 1 ? 0xEDB88320u ^ (c >> 1) : c >> 1;
      table[i] = c;
    }
    ready = true;
  }
  crc = ~crc;
  for (std::size_t i = 0; i < n; ++i)
    crc = table[(crc ^ data[i]) & 0xFF] ^ (crc >> 8);
  return ~crc;
}

void
put32 (std::vector<std::uint8_t>& v, std::uint32_t x)
{
  for (int s = 24; s >= 0; s -= 8)
    v.push_back (static_cast<std::uint8_t> (x >> s));
}

void
chunk (std::vector<std::uint8_t>& png, const char* type, const std::vector<std::uint8_t>& data)
{
  put32 (png, static_cast<std::uint32_t> (data.size ()));
  std::vector<std::uint8_t> body (type, type + 4);
  body.insert (body.end (), data.begin (), data.end ());
  png.insert (png.end (), body.begin (), body.end ());
  put32 (png, crc32 (body.data (), body.size ()));
}

} // namespace

Status
writePng (const std::string& path, int width, int height, int channels, const std::vector<std::uint8_t>& pixels)
{
  if (width <= 0 || height <= 0 || (channels != 1 && channels != 3) ||
      pixels.size () != static_cast<std::size_t> (width) * static_cast<std::size_t> (height) * static_cast<std::size_t> (channels))
    return Status::error ("cannot write " + path + ": invalid image size");
  // Raw scan lines (filter byte 0), then a zlib stream of stored deflate blocks.
  std::vector<std::uint8_t> raw;
  const std::size_t row = static_cast<std::size_t> (width) * static_cast<std::size_t> (channels);
  for (int y = 0; y < height; ++y)
  {
    raw.push_back (0);
    raw.insert (raw.end (), pixels.begin () + static_cast<long> (y * row), pixels.begin () + static_cast<long> ((y + 1) * row));
  }
  std::vector<std::uint8_t> z = {0x78, 0x01};
  for (std::size_t pos = 0; pos < raw.size () || raw.empty ();)
  {
    const std::size_t len = std::min<std::size_t> (65535, raw.size () - pos);
    z.push_back (pos + len >= raw.size () ? 1 : 0);
    z.push_back (static_cast<std::uint8_t> (len & 0xFF));
    z.push_back (static_cast<std::uint8_t> (len >> 8));
    z.push_back (static_cast<std::uint8_t> (~len & 0xFF));
    z.push_back (static_cast<std::uint8_t> ((~len >> 8) & 0xFF));
    z.insert (z.end (), raw.begin () + static_cast<long> (pos), raw.begin () + static_cast<long> (pos + len));
    pos += len;
    if (raw.empty ())
      break;
  }
  std::uint32_t s1 = 1, s2 = 0; // Adler-32
  for (std::uint8_t b : raw)
  {
    s1 = (s1 + b) % 65521;
    s2 = (s2 + s1) % 65521;
  }
  put32 (z, (s2 << 16) | s1);

  std::vector<std::uint8_t> png = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
  std::vector<std::uint8_t> ihdr;
  put32 (ihdr, static_cast<std::uint32_t> (width));
  put32 (ihdr, static_cast<std::uint32_t> (height));
  ihdr.push_back (8);
  ihdr.push_back (channels == 1 ? 0 : 2);
  ihdr.push_back (0);
  ihdr.push_back (0);
  ihdr.push_back (0);
  chunk (png, "IHDR", ihdr);
  chunk (png, "IDAT", z);
  chunk (png, "IEND", {});
  return writeFileAtomically (path, [&] (const std::string& tmp) {
    std::ofstream out (tmp, std::ios::binary);
    out.write (reinterpret_cast<const char*> (png.data ()), static_cast<std::streamsize> (png.size ()));
    out.flush ();
    return out.good () ? Status::success () : Status::error ("write failed");
  });
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

/*
 * pcl_flowseg evaluation - the paper's figures: similarity matrices (CSV, PNG) and the best matches of queries (PNG).
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include <pcl_flowseg/evaluation/retrieval_figures.h>

#include <pcl_flowseg/evaluation/png_writer.h>
#include <pcl_flowseg/io/atomic_file.h>
#include <pcl_flowseg/io/segment_colours.h>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <array>
#include <iomanip>
#include <numeric>
#include <ostream>

namespace pcl_flowseg {

Status
writeSimilarityCsv (const std::string& path, const std::vector<std::string>& names, const std::vector<std::vector<double>>& similarity)
{
  auto quote = [] (const std::string& s) {
    std::string q = "\"";
    for (char c : s)
      q += c == '"' ? std::string ("\"\"") : std::string (1, c);
    return q + "\"";
  };
  return writeTextFileAtomically (path, [&] (std::ostream& out) {
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
  });
}

namespace {
/** Draws \a points into the square cell at (x0, y0) of an RGB image \a width pixels wide, dark
  * grey, or each in its feature's colour when \a labels (one per point) are given. */
void
drawShape (std::vector<std::uint8_t>& img, int width, int x0, int y0, int cell, const std::vector<Eigen::Vector3d>& points,
           const std::vector<std::uint32_t>* labels = nullptr)
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
  for (std::size_t i = 0; i < points.size (); ++i)
  {
    const Eigen::Vector3d& p = points[i];
    const int x = x0 + 6 + static_cast<int> (((p - mean).dot (u) - lo_u) * scale + 0.5 * (cell - 12 - (hi_u - lo_u) * scale));
    const int y = y0 + cell - 7 - static_cast<int> (((p - mean).dot (v) - lo_v) * scale + 0.5 * (cell - 12 - (hi_v - lo_v) * scale));
    if (x < x0 || y < y0 || x >= x0 + cell || y >= y0 + cell)
      continue;
    const std::array<std::uint8_t, 3> colour =
        labels && i < labels->size () ? segmentColour ((*labels)[i]) : std::array<std::uint8_t, 3>{{40, 40, 40}};
    for (int c = 0; c < 3; ++c)
      img[3 * (static_cast<std::size_t> (y) * static_cast<std::size_t> (width) + static_cast<std::size_t> (x)) + static_cast<std::size_t> (c)] =
          colour[static_cast<std::size_t> (c)];
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
writeSingleViewMatchesPng (const std::string& path, const std::vector<std::vector<Eigen::Vector3d>>& scans,
                           const std::vector<std::vector<std::uint32_t>>& scan_labels, const std::vector<std::string>& scan_classes,
                           const std::vector<std::vector<Eigen::Vector3d>>& models, const std::vector<std::string>& model_classes,
                           const std::vector<std::vector<double>>& similarity, int k, int cell)
{
  if (scans.empty () || k < 1 || cell < 16 || scan_labels.size () != scans.size () || scan_classes.size () != scans.size () ||
      similarity.size () != scans.size () || model_classes.size () != models.size ())
    return Status::error ("cannot write " + path + ": nothing to draw");
  const int width = (k + 1) * cell, height = static_cast<int> (scans.size ()) * cell;
  std::vector<std::uint8_t> img (3 * static_cast<std::size_t> (width) * static_cast<std::size_t> (height), 255);
  for (std::size_t row = 0; row < scans.size (); ++row)
  {
    const int y0 = static_cast<int> (row) * cell;
    drawShape (img, width, 0, y0, cell, scans[row], &scan_labels[row]);
    frame (img, width, 0, y0, cell, 40, 90, 220);
    if (similarity[row].size () != models.size ())
      return Status::error ("cannot write " + path + ": a similarity row does not match the models");
    std::vector<std::size_t> order (models.size ());
    std::iota (order.begin (), order.end (), 0);
    std::stable_sort (order.begin (), order.end (),
                      [&] (std::size_t a, std::size_t b) { return similarity[row][a] > similarity[row][b]; });
    for (int r = 0; r < k && r < static_cast<int> (order.size ()); ++r)
    {
      const std::size_t j = order[static_cast<std::size_t> (r)];
      drawShape (img, width, (r + 1) * cell, y0, cell, models[j]);
      const bool same = model_classes[j] == scan_classes[row];
      frame (img, width, (r + 1) * cell, y0, cell, same ? 40 : 220, same ? 170 : 50, same ? 60 : 40);
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

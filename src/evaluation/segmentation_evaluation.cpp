/*
 * pcl_flowseg - measuring segmentations against reference ones (Princeton Segmentation Benchmark).
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include <pcl_flowseg/evaluation/segmentation_evaluation.h>

#include <flann/flann.hpp>

#include <Eigen/Geometry>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <limits>
#include <map>
#include <unordered_map>

namespace pcl_flowseg {

namespace {

/** Parses \a line as one integer with optional surrounding white space. */
bool
parseInteger (const std::string& line, int& value)
{
  const char* begin = line.c_str ();
  char* end = nullptr;
  errno = 0;
  const long v = std::strtol (begin, &end, 10);
  if (end == begin || errno == ERANGE || v < std::numeric_limits<int>::min () || v > std::numeric_limits<int>::max ())
    return false;
  for (; *end; ++end)
    if (!std::isspace (static_cast<unsigned char> (*end)))
      return false;
  value = static_cast<int> (v);
  return true;
}

bool
isBlank (const std::string& line)
{
  return line.find_first_not_of (" \t\r") == std::string::npos;
}

/** Sum of the squared weights of the segments of a labelling (keys: labels or label pairs). */
template <typename Key, typename LabelOf>
double
sumOfSquaredSegmentWeights (const std::vector<double>& weights, LabelOf label_of)
{
  std::unordered_map<Key, double> segment_weight;
  for (std::size_t i = 0; i < weights.size (); ++i)
    segment_weight[label_of (i)] += weights[i];
  double sum = 0.0;
  for (const auto& entry : segment_weight)
    sum += entry.second * entry.second;
  return sum;
}

} // namespace

Status
readFaceSegmentation (const std::string& path, std::size_t face_count, std::vector<int>& labels)
{
  labels.clear ();
  std::ifstream in (path);
  if (!in)
    return Status::error ("cannot open segmentation " + path + ": " + std::strerror (errno));
  std::vector<int> read;
  read.reserve (face_count);
  std::string line;
  std::size_t number = 0;
  while (std::getline (in, line))
  {
    ++number;
    if (isBlank (line))
      continue;
    int value = 0;
    if (!parseInteger (line, value))
      return Status::error (path + ":" + std::to_string (number) + ": not an integer segment id: \"" + line + "\"");
    read.push_back (value);
  }
  if (in.bad ())
    return Status::error ("cannot read segmentation " + path);
  if (read.size () != face_count)
    return Status::error (path + ": " + std::to_string (read.size ()) + " segment ids for a mesh of " +
                          std::to_string (face_count) + " faces");
  labels = std::move (read);
  return Status::success ();
}

std::vector<double>
faceAreas (const TriangleMesh& mesh)
{
  std::vector<double> areas;
  areas.reserve (mesh.faces.size ());
  for (const auto& f : mesh.faces)
  {
    const Eigen::Vector3d& p = mesh.vertices[static_cast<std::size_t> (f[0])];
    const Eigen::Vector3d& q = mesh.vertices[static_cast<std::size_t> (f[1])];
    const Eigen::Vector3d& r = mesh.vertices[static_cast<std::size_t> (f[2])];
    areas.push_back (0.5 * (q - p).cross (r - p).norm ());
  }
  return areas;
}

Status
randIndexError (const std::vector<double>& weights, const std::vector<int>& a, const std::vector<int>& b, double& error)
{
  error = 0.0;
  if (a.size () != weights.size () || b.size () != weights.size ())
    return Status::error ("Rand index: " + std::to_string (weights.size ()) + " weights for " + std::to_string (a.size ()) +
                          " and " + std::to_string (b.size ()) + " labels");
  double total = 0.0, self_pairs = 0.0;
  for (double w : weights)
  {
    total += w;
    self_pairs += w * w;
  }
  const double all_pairs = total * total - self_pairs; // twice the weight of the pairs i < j
  if (!(all_pairs > 0.0))
    return Status::success ();
  const double in_a = sumOfSquaredSegmentWeights<int> (weights, [&] (std::size_t i) { return a[i]; });
  const double in_b = sumOfSquaredSegmentWeights<int> (weights, [&] (std::size_t i) { return b[i]; });
  const double in_both = sumOfSquaredSegmentWeights<std::uint64_t> (weights, [&] (std::size_t i) {
    return (static_cast<std::uint64_t> (static_cast<std::uint32_t> (a[i])) << 32) | static_cast<std::uint32_t> (b[i]);
  });
  // The self pairs (w_i^2) are in each of the three sums and cancel: in_a + in_b - 2 in_both is
  // twice the weight of the pairs of distinct elements on which a and b disagree.
  error = std::min (1.0, std::max (0.0, (in_a + in_b - 2.0 * in_both) / all_pairs));
  return Status::success ();
}

Status
transferPointLabelsToFaces (const TriangleMesh& mesh, const std::vector<Eigen::Vector3d>& points,
                            const std::vector<std::uint32_t>& point_labels, std::vector<int>& face_labels,
                            const std::vector<std::uint32_t>& unlabelled)
{
  constexpr int kNeighbours = 4;
  face_labels.assign (mesh.faces.size (), -1);
  if (points.size () != point_labels.size ())
    return Status::error ("label transfer: " + std::to_string (point_labels.size ()) + " labels for " +
                          std::to_string (points.size ()) + " points");

  std::vector<float> coordinates;
  std::vector<int> voter_labels;
  for (std::size_t i = 0; i < points.size (); ++i)
  {
    const std::uint32_t label = point_labels[i];
    if (label == kNoSegment || !points[i].allFinite () ||
        std::find (unlabelled.begin (), unlabelled.end (), label) != unlabelled.end ())
      continue;
    for (int k = 0; k < 3; ++k)
      coordinates.push_back (static_cast<float> (points[i][k]));
    voter_labels.push_back (static_cast<int> (label));
  }
  if (voter_labels.empty () || mesh.faces.empty ())
    return Status::success ();

  flann::Index<flann::L2_Simple<float>> index (flann::Matrix<float> (coordinates.data (), voter_labels.size (), 3),
                                               flann::KDTreeSingleIndexParams (10));
  index.buildIndex ();

  // Four query places per face: the centroid and the points halfway to the corners.
  const std::size_t places = 4 * mesh.faces.size ();
  std::vector<float> queries;
  queries.reserve (3 * places);
  for (const auto& f : mesh.faces)
  {
    const Eigen::Vector3d corners[3] = {mesh.vertices[static_cast<std::size_t> (f[0])],
                                        mesh.vertices[static_cast<std::size_t> (f[1])],
                                        mesh.vertices[static_cast<std::size_t> (f[2])]};
    const Eigen::Vector3d centroid = (corners[0] + corners[1] + corners[2]) / 3.0;
    const Eigen::Vector3d place[4] = {centroid, 0.5 * (centroid + corners[0]), 0.5 * (centroid + corners[1]),
                                      0.5 * (centroid + corners[2])};
    for (const auto& p : place)
      for (int k = 0; k < 3; ++k)
        queries.push_back (static_cast<float> (p[k]));
  }
  const int k = std::min<int> (kNeighbours, static_cast<int> (voter_labels.size ()));
  std::vector<int> ids (places * static_cast<std::size_t> (k));
  std::vector<float> distances (ids.size ());
  flann::Matrix<int> id_matrix (ids.data (), places, static_cast<std::size_t> (k));
  flann::Matrix<float> distance_matrix (distances.data (), places, static_cast<std::size_t> (k));
  index.knnSearch (flann::Matrix<float> (queries.data (), places, 3), id_matrix, distance_matrix, k,
                   flann::SearchParams (flann::FLANN_CHECKS_UNLIMITED));

  const std::size_t votes_per_face = 4 * static_cast<std::size_t> (k);
  std::map<int, int> votes; // ordered: ties go to the smaller label
  for (std::size_t f = 0; f < mesh.faces.size (); ++f)
  {
    votes.clear ();
    for (std::size_t v = 0; v < votes_per_face; ++v)
    {
      const int id = ids[f * votes_per_face + v];
      if (id >= 0)
        ++votes[voter_labels[static_cast<std::size_t> (id)]];
    }
    int best_count = 0;
    for (const auto& entry : votes)
      if (entry.second > best_count)
      {
        best_count = entry.second;
        face_labels[f] = entry.first;
      }
  }
  return Status::success ();
}

} // namespace pcl_flowseg

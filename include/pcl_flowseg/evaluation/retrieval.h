/*
 * pcl_flowseg - retrieval evaluation over a labelled collection, and the D2 shape distribution.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include <pcl_flowseg/common/status.h>

#include <Eigen/Core>

#include <cstdint>
#include <string>
#include <vector>

namespace pcl_flowseg {

/** \brief Retrieval scores of a similarity matrix over labelled shapes (Princeton Shape Benchmark
  * conventions; every shape is a query, the query itself excluded from its ranking). */
struct RetrievalScores
{
  double nearest_neighbour = 0.0; ///< share of queries whose best match has their class
  double first_tier = 0.0;        ///< mean share of the class (C-1) found in the top C-1
  double second_tier = 0.0;       ///< mean share of the class found in the top 2(C-1)
  double dcg = 0.0;               ///< mean discounted cumulative gain, normalised by the ideal
  double bulls_eye = 0.0;         ///< MPEG-7: same-class shapes among the top 2C (query included) / C
  std::size_t queries = 0;        ///< queries with at least one other shape of their class
};

/** \brief Scores \a similarity (higher = more similar; row = query) against \a labels. */
RetrievalScores
scoreRetrieval (const std::vector<std::vector<double>>& similarity, const std::vector<std::string>& labels);

/** \brief Osada's D2 shape distribution adapted to point samples: the histogram of distances
  * between \a pairs random pairs of points, distances divided by their mean (scale invariance),
  * \a bins bins over [0, 3). Reproducible for \a seed. */
std::vector<double>
d2Distribution (const std::vector<Eigen::Vector3d>& points, std::size_t pairs = 100000, int bins = 64, std::uint32_t seed = 1);

/** \brief PCL's Ensemble of Shape Functions descriptor (pcl::ESFEstimation, 640 bins; contains a
  * D2 part) of a point sample; empty when PCL cannot compute it. */
std::vector<double>
esfDescriptor (const std::vector<Eigen::Vector3d>& points);

/** \brief Similarity of two histograms: 1 - L1 distance / 2 (1 for equal distributions). */
double
histogramSimilarity (const std::vector<double>& a, const std::vector<double>& b);

/** \brief Writes the similarity matrix as CSV: the header row and the first column name the shapes
  * in one order. Atomic. */
Status
writeSimilarityCsv (const std::string& path, const std::vector<std::string>& names,
                    const std::vector<std::vector<double>>& similarity);

/** \brief The paper's Figure 11: an image whose row i shows the \a best most similar shapes of
  * shape i (black = best match, lighter by rank, white = not among them), \a cell pixels per
  * shape, written as an 8-bit greyscale PNG. Atomic. */
Status
writeSimilarityPng (const std::string& path, const std::vector<std::vector<double>>& similarity, int best = 5, int cell = 4);

/** \brief The paper's Figure 10: one row per query in \a queries, showing the query and its \a k
  * most similar other shapes as point drawings (2D as they are, 3D projected onto their two main
  * PCA axes), \a cell pixels each; frames: blue for the query, green for a match of the same class,
  * red otherwise. RGB PNG. Atomic. */
Status
writeTopMatchesPng (const std::string& path, const std::vector<std::vector<Eigen::Vector3d>>& shapes,
                    const std::vector<std::string>& labels, const std::vector<std::vector<double>>& similarity,
                    const std::vector<std::size_t>& queries, int k = 5, int cell = 96);

/** \brief Writes an 8-bit greyscale (channels = 1) or RGB (channels = 3) image as PNG (libpng).
  * Atomic. */
Status
writePng (const std::string& path, int width, int height, int channels, const std::vector<std::uint8_t>& pixels);

} // namespace pcl_flowseg

/*
 * pcl_flowseg evaluation - the paper's figures: similarity matrices (CSV, PNG) and the best matches of queries (PNG).
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include <pcl_flowseg/common/status.h>

#include <Eigen/Core>

#include <cstdint>
#include <string>
#include <vector>

namespace pcl_flowseg {

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

/** \brief Single-view recognition's figure: one row per scan, drawn with its points coloured by
  * their feature (\a scan_labels, segmentColour; kNoSegment grey) in a blue frame, then its \a k
  * most similar models by \a similarity (scan x model), green frames for the scan's class, red
  * otherwise. RGB PNG. Atomic. */
Status
writeSingleViewMatchesPng (const std::string& path, const std::vector<std::vector<Eigen::Vector3d>>& scans,
                           const std::vector<std::vector<std::uint32_t>>& scan_labels, const std::vector<std::string>& scan_classes,
                           const std::vector<std::vector<Eigen::Vector3d>>& models, const std::vector<std::string>& model_classes,
                           const std::vector<std::vector<double>>& similarity, int k = 5, int cell = 128);

} // namespace pcl_flowseg

/*
 * pcl_flowseg evaluation - retrieval scores of a similarity matrix over labelled shapes (Princeton Shape Benchmark conventions).
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include <pcl_flowseg/common/status.h>

#include <functional>
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

/** \brief Scores \a similarity (higher = more similar; row = query) against \a labels into
  * \a scores; fails when the matrix is not square with one row per label, or holds NaN. */
Status
scoreRetrieval (const std::vector<std::vector<double>>& similarity, const std::vector<std::string>& labels,
                RetrievalScores& scores);

/** \brief The n x n matrix of \a similarity (i, j) for every pair, rows computed in parallel on
  * \a threads threads (0 = all cores); \a progress (optional) is told how many rows are done. */
std::vector<std::vector<double>>
similarityMatrix (std::size_t n, const std::function<double (std::size_t, std::size_t)>& similarity, unsigned threads,
                  const std::function<void (std::size_t rows_done)>& progress = {});

/** \brief As similarityMatrix, for a \a similarity that is exactly symmetric: each pair is compared
  * once (i <= j, n (n + 1) / 2 calls) and its value written to both (i, j) and (j, i). */
std::vector<std::vector<double>>
symmetricSimilarityMatrix (std::size_t n, const std::function<double (std::size_t, std::size_t)>& similarity, unsigned threads,
                           const std::function<void (std::size_t rows_done)>& progress = {});

} // namespace pcl_flowseg

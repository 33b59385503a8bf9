/*
 * pcl_flowseg evaluation - the files of a retrieval evaluation: figures per method, scores as JSON.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include <pcl_flowseg/common/status.h>
#include <pcl_flowseg/evaluation/retrieval_scores.h>

#include <Eigen/Core>

#include <string>
#include <vector>

namespace pcl_flowseg {

/** \brief One method's results over a collection. */
struct MethodEvaluation
{
  std::string name;                  ///< flowseg, d2, esf, ...
  RetrievalScores scores;
  double describe_ms_per_shape = 0.0; ///< time to describe a shape (signature, histogram)
  double compare_ms_per_pair = 0.0;   ///< CPU time of one comparison
};

/** \brief Writes \a dir/similarity_METHOD.csv, \a dir/similarity_METHOD.png (row i: the 5 best
  * matches of shape i) and \a dir/top5_METHOD.png (the first shape of up to eight classes, in the
  * order of \a labels, and its five best matches; \a drawings: a few thousand points per shape). */
Status
writeRetrievalFigures (const std::string& dir, const std::string& method, const std::vector<std::string>& names,
                       const std::vector<std::string>& labels, const std::vector<std::vector<double>>& similarity,
                       const std::vector<std::vector<Eigen::Vector3d>>& drawings);

/** \brief Writes the scores of every method as JSON: the collection's root and size, and per method
  * nearest neighbour, first and second tier, DCG, (when \a planar) bull's eye, queries and times.
  * Atomic. */
Status
writeRetrievalScoresJson (const std::string& path, const std::string& root, std::size_t shapes, bool planar,
                          const std::vector<MethodEvaluation>& methods);

} // namespace pcl_flowseg

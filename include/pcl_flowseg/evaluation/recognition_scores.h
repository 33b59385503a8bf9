/*
 * pcl_flowseg evaluation - recognition scores of queries (single views, say) against a database of
 * labelled models, each query naming its own model: category and instance recognition.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include <pcl_flowseg/common/status.h>

#include <string>
#include <vector>

namespace pcl_flowseg {

/** \brief How well queries recognise the category and the instance of their model. */
struct RecognitionScores
{
  /** Category, the query's own model left out of its ranking: share of queries whose best match
    * has their class. */
  double nearest_neighbour = 0.0;
  /** Category: mean share of the C-1 other models of the query's class (C models in the database)
    * found in the top C-1 of its ranking. */
  double first_tier = 0.0;
  /** Instance, the own model kept in: share of queries whose best match is their own model. */
  double instance_top1 = 0.0;
  std::size_t queries = 0;          ///< queries scored for the instance
  std::size_t category_queries = 0; ///< of them, those with another model of their class
};

/** \brief The scores of one class's queries (class = label of their model). */
struct ClassRecognitionScores
{
  std::string label;
  RecognitionScores scores;
};

/** \brief Scores \a similarity (row q: query q against every model; higher = more similar) with
  * query q's own model \a model_of_query[q] and the models' classes \a model_labels, over all
  * queries into \a overall and per class (sorted by label) into \a per_class. Rankings are sorted
  * by similarity, ties in database order, as scoreRetrieval ranks; for the instance a tie with
  * another model counts against the own model. Fails when the sizes disagree, a model index is
  * out of range, or a row holds NaN. */
Status
scoreRecognition (const std::vector<std::vector<double>>& similarity, const std::vector<std::size_t>& model_of_query,
                  const std::vector<std::string>& model_labels, RecognitionScores& overall,
                  std::vector<ClassRecognitionScores>& per_class);

} // namespace pcl_flowseg

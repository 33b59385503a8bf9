/*
 * pcl_flowseg evaluation - the report of a single-view recognition: a table per method and class,
 * as a TSV file and as text.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include <pcl_flowseg/common/status.h>
#include <pcl_flowseg/evaluation/single_view_recognition.h>

#include <string>
#include <vector>

namespace pcl_flowseg {

/** \brief Writes \a results as tab-separated values: a header row (method, class, queries,
  * category_nn, first_tier, instance_top1, ms_per_query, ms_per_model), then for each method that
  * was evaluated one row per class and one for all queries (class "all"). Skipped methods have no
  * rows. Atomic. */
Status
writeRecognitionTsv (const std::string& path, const std::vector<MethodRecognition>& results);

/** \brief \a results as text for a terminal: one line per method (NN, FT, instance, ms per query
  * and per model; the reason for a skipped method), then one line per class with each evaluated
  * method's NN / FT / instance. */
std::string
recognitionTable (const std::vector<MethodRecognition>& results);

} // namespace pcl_flowseg

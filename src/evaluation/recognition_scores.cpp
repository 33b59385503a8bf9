/*
 * pcl_flowseg evaluation - category and instance recognition scores of queries against labelled models.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include <pcl_flowseg/evaluation/recognition_scores.h>

#include <algorithm>
#include <cmath>
#include <map>

namespace pcl_flowseg {

namespace {

/** Why the inputs cannot be scored, or success. */
Status
checkRecognitionInput (const std::vector<std::vector<double>>& similarity, const std::vector<std::size_t>& model_of_query,
                       std::size_t models)
{
  if (similarity.size () != model_of_query.size ())
    return Status::error ("the similarity matrix has " + std::to_string (similarity.size ()) + " rows for " +
                          std::to_string (model_of_query.size ()) + " queries");
  for (std::size_t q = 0; q < similarity.size (); ++q)
  {
    if (similarity[q].size () != models)
      return Status::error ("row " + std::to_string (q) + " of the similarity matrix has " +
                            std::to_string (similarity[q].size ()) + " entries, not one per model (" + std::to_string (models) + ")");
    if (model_of_query[q] >= models)
      return Status::error ("query " + std::to_string (q) + " names model " + std::to_string (model_of_query[q]) + " of " +
                            std::to_string (models));
    if (std::any_of (similarity[q].begin (), similarity[q].end (), [] (double v) { return std::isnan (v); }))
      return Status::error ("row " + std::to_string (q) + " of the similarity matrix holds NaN");
  }
  return Status::success ();
}

/** One query's hits (sums of one query): \a row its similarities, \a own its model. */
RecognitionScores
scoreQuery (const std::vector<double>& row, std::size_t own, const std::vector<std::string>& labels, std::size_t class_size)
{
  RecognitionScores s;
  s.queries = 1;
  bool instance = true;
  for (std::size_t m = 0; m < row.size () && instance; ++m)
    instance = m == own || row[m] < row[own];
  s.instance_top1 += instance ? 1.0 : 0.0;
  if (class_size < 2)
    return s;
  std::vector<std::size_t> order;
  for (std::size_t m = 0; m < row.size (); ++m)
    if (m != own)
      order.push_back (m);
  std::stable_sort (order.begin (), order.end (), [&] (std::size_t a, std::size_t b) { return row[a] > row[b]; });
  const std::size_t relevant = class_size - 1;
  std::size_t first = 0;
  for (std::size_t r = 0; r < relevant; ++r)
    first += labels[order[r]] == labels[own];
  ++s.category_queries;
  s.nearest_neighbour += labels[order[0]] == labels[own] ? 1.0 : 0.0;
  s.first_tier += static_cast<double> (first) / static_cast<double> (relevant);
  return s;
}

/** Adds the sums of \a b to \a a. */
void
add (RecognitionScores& a, const RecognitionScores& b)
{
  a.nearest_neighbour += b.nearest_neighbour;
  a.first_tier += b.first_tier;
  a.instance_top1 += b.instance_top1;
  a.queries += b.queries;
  a.category_queries += b.category_queries;
}

/** Sums to means. */
void
finish (RecognitionScores& s)
{
  if (s.queries)
    s.instance_top1 /= static_cast<double> (s.queries);
  if (s.category_queries)
  {
    s.nearest_neighbour /= static_cast<double> (s.category_queries);
    s.first_tier /= static_cast<double> (s.category_queries);
  }
}

} // namespace

Status
scoreRecognition (const std::vector<std::vector<double>>& similarity, const std::vector<std::size_t>& model_of_query,
                  const std::vector<std::string>& model_labels, RecognitionScores& overall,
                  std::vector<ClassRecognitionScores>& per_class)
{
  overall = RecognitionScores ();
  per_class.clear ();
  if (const Status s = checkRecognitionInput (similarity, model_of_query, model_labels.size ()); !s)
    return s;
  std::map<std::string, std::size_t> class_size;
  for (const auto& l : model_labels)
    ++class_size[l];
  std::map<std::string, RecognitionScores> by_class;
  for (std::size_t q = 0; q < similarity.size (); ++q)
  {
    const std::string& label = model_labels[model_of_query[q]];
    const RecognitionScores one = scoreQuery (similarity[q], model_of_query[q], model_labels, class_size[label]);
    add (overall, one);
    add (by_class[label], one);
  }
  finish (overall);
  for (auto& [label, scores] : by_class)
  {
    finish (scores);
    per_class.push_back ({label, scores});
  }
  return Status::success ();
}

} // namespace pcl_flowseg

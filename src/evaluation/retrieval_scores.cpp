/*
 * pcl_flowseg evaluation - retrieval scores of a similarity matrix over labelled shapes (Princeton Shape Benchmark conventions).
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include <pcl_flowseg/evaluation/retrieval_scores.h>

#include <pcl_flowseg/common/parallel_jobs.h>

#include <algorithm>
#include <cmath>
#include <map>

namespace pcl_flowseg {

Status
scoreRetrieval (const std::vector<std::vector<double>>& similarity, const std::vector<std::string>& labels,
                RetrievalScores& s)
{
  s = RetrievalScores ();
  const std::size_t n = labels.size ();
  if (similarity.size () != n)
    return Status::error ("the similarity matrix has " + std::to_string (similarity.size ()) + " rows for " +
                          std::to_string (n) + " labels");
  for (std::size_t q = 0; q < n; ++q)
  {
    if (similarity[q].size () != n)
      return Status::error ("row " + std::to_string (q) + " of the similarity matrix has " +
                            std::to_string (similarity[q].size ()) + " entries, not " + std::to_string (n));
    if (std::any_of (similarity[q].begin (), similarity[q].end (), [] (double v) { return std::isnan (v); }))
      return Status::error ("row " + std::to_string (q) + " of the similarity matrix holds NaN");
  }
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
  return Status::success ();
}

namespace {

/** The n x n matrix of \a similarity, rows in parallel; \a symmetric: each pair once. */
std::vector<std::vector<double>>
fillSimilarityMatrix (std::size_t n, const std::function<double (std::size_t, std::size_t)>& similarity, unsigned threads,
                      const std::function<void (std::size_t)>& progress, bool symmetric)
{
  std::vector<std::vector<double>> m (n, std::vector<double> (n, 0.0));
  // With symmetric, row i writes the pairs (i, j >= i) and their mirror images: every entry has
  // one writer.
  runParallelJobs (
      n, threads,
      [&] (std::size_t i) {
        for (std::size_t j = symmetric ? i : 0; j < n; ++j)
        {
          m[i][j] = similarity (i, j);
          if (symmetric)
            m[j][i] = m[i][j];
        }
      },
      [&] (std::size_t done, std::size_t) {
        if (progress)
          progress (done);
      });
  return m;
}

} // namespace

std::vector<std::vector<double>>
similarityMatrix (std::size_t n, const std::function<double (std::size_t, std::size_t)>& similarity, unsigned threads,
                  const std::function<void (std::size_t)>& progress)
{
  return fillSimilarityMatrix (n, similarity, threads, progress, false);
}

std::vector<std::vector<double>>
symmetricSimilarityMatrix (std::size_t n, const std::function<double (std::size_t, std::size_t)>& similarity, unsigned threads,
                           const std::function<void (std::size_t)>& progress)
{
  return fillSimilarityMatrix (n, similarity, threads, progress, true);
}

} // namespace pcl_flowseg

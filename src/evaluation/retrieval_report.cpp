/*
 * pcl_flowseg evaluation - the files of a retrieval evaluation: figures per method, scores as JSON.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include <pcl_flowseg/evaluation/retrieval_report.h>

#include <pcl_flowseg/evaluation/retrieval_figures.h>
#include <pcl_flowseg/io/atomic_file.h>
#include <pcl_flowseg/io/json_text.h>

#include <cstdio>
#include <ostream>

namespace pcl_flowseg {

Status
writeRetrievalFigures (const std::string& dir, const std::string& method, const std::vector<std::string>& names,
                       const std::vector<std::string>& labels, const std::vector<std::vector<double>>& similarity,
                       const std::vector<std::vector<Eigen::Vector3d>>& drawings)
{
  if (const Status s = writeSimilarityCsv (dir + "/similarity_" + method + ".csv", names, similarity); !s)
    return s;
  if (const Status s = writeSimilarityPng (dir + "/similarity_" + method + ".png", similarity); !s)
    return s;
  // The paper's Figure 10: the first shape of up to eight classes and its five best matches.
  std::vector<std::size_t> queries;
  for (std::size_t i = 0; i < labels.size () && queries.size () < 8; ++i)
    if (i == 0 || labels[i] != labels[i - 1])
      queries.push_back (i);
  return writeTopMatchesPng (dir + "/top5_" + method + ".png", drawings, labels, similarity, queries);
}

Status
writeRetrievalScoresJson (const std::string& path, const std::string& root, std::size_t shapes, bool planar,
                          const std::vector<MethodEvaluation>& methods)
{
  return writeTextFileAtomically (path, [&] (std::ostream& out) {
    out << "{\n  \"root\": " << jsonString (root) << ",\n  \"shapes\": " << shapes << ",\n  \"methods\": {";
    for (std::size_t k = 0; k < methods.size (); ++k)
    {
      const MethodEvaluation& m = methods[k];
      const RetrievalScores& s = m.scores;
      char buf[512];
      std::snprintf (buf, sizeof (buf),
                     "\"nearest_neighbour\": %.4f, \"first_tier\": %.4f, \"second_tier\": %.4f, \"dcg\": %.4f", s.nearest_neighbour,
                     s.first_tier, s.second_tier, s.dcg);
      out << (k ? "," : "") << "\n    " << jsonString (m.name) << ": {" << buf;
      if (planar)
        out << ", \"bulls_eye\": " << jsonNumber (s.bulls_eye);
      std::snprintf (buf, sizeof (buf), ", \"queries\": %zu, \"describe_ms_per_shape\": %.3f, \"compare_ms_per_pair\": %.4f}",
                     s.queries, m.describe_ms_per_shape, m.compare_ms_per_pair);
      out << buf;
    }
    out << "\n  }\n}\n";
  });
}

} // namespace pcl_flowseg

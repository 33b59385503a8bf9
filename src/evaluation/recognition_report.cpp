/*
 * pcl_flowseg evaluation - the report of a single-view recognition: TSV and text.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include <pcl_flowseg/evaluation/recognition_report.h>

#include <pcl_flowseg/io/atomic_file.h>

#include <algorithm>
#include <cstdio>
#include <ostream>

namespace pcl_flowseg {

namespace {

/** \a line without its trailing spaces, and a newline. */
std::string
endLine (std::string line)
{
  line.erase (line.find_last_not_of (' ') + 1);
  return line + "\n";
}

/** printf into a string. */
template <class... Args>
std::string
format (const char* pattern, Args... args)
{
  char buf[512];
  std::snprintf (buf, sizeof (buf), pattern, args...);
  return buf;
}

std::string
tsvRow (const std::string& method, const std::string& label, const RecognitionScores& s, double query_ms, double model_ms)
{
  return method + "\t" + label +
         format ("\t%zu\t%.4f\t%.4f\t%.4f\t%.3f\t%.3f\n", s.queries, s.nearest_neighbour, s.first_tier, s.instance_top1, query_ms,
                 model_ms);
}

} // namespace

Status
writeRecognitionTsv (const std::string& path, const std::vector<MethodRecognition>& results)
{
  return writeTextFileAtomically (path, [&] (std::ostream& out) {
    out << "method\tclass\tqueries\tcategory_nn\tfirst_tier\tinstance_top1\tms_per_query\tms_per_model\n";
    for (const auto& r : results)
    {
      if (!r.skipped.empty ())
        continue;
      for (std::size_t c = 0; c < r.per_class.size (); ++c)
        out << tsvRow (r.name, r.per_class[c].label, r.per_class[c].scores, r.class_query_ms[c], r.model_ms);
      out << tsvRow (r.name, "all", r.scores, r.query_ms, r.model_ms);
    }
  });
}

std::string
recognitionTable (const std::vector<MethodRecognition>& results)
{
  std::size_t width = 10;
  for (const auto& r : results)
    width = std::max (width, r.name.size () + 2);
  const int w = static_cast<int> (width);
  std::string text = format ("%-*s%8s%8s%10s%13s%13s\n", w, "method", "NN", "FT", "instance", "ms/query", "ms/model");
  for (const auto& r : results)
  {
    if (!r.skipped.empty ())
      text += format ("%-*s", w, r.name.c_str ()) + "skipped: " + r.skipped + "\n";
    else
      text += format ("%-*s%8.3f%8.3f%10.3f%13.1f%13.1f\n", w, r.name.c_str (), r.scores.nearest_neighbour, r.scores.first_tier,
                      r.scores.instance_top1, r.query_ms, r.model_ms);
  }
  const MethodRecognition* first = nullptr;
  for (const auto& r : results)
    if (r.skipped.empty () && !first)
      first = &r;
  if (!first)
    return text;
  std::string line = format ("%-14s%6s", "class", "n");
  for (const auto& r : results)
    if (r.skipped.empty ())
      line += format ("  %-19s", r.name.c_str ());
  text += "\nper class, NN / FT / instance:\n" + endLine (line);
  for (std::size_t c = 0; c < first->per_class.size (); ++c)
  {
    line = format ("%-14s%6zu", first->per_class[c].label.c_str (), first->per_class[c].scores.queries);
    for (const auto& r : results)
      if (r.skipped.empty ())
      {
        const RecognitionScores& s = r.per_class[c].scores;
        line += format ("  %.3f/%.3f/%.3f  ", s.nearest_neighbour, s.first_tier, s.instance_top1);
      }
    text += endLine (line);
  }
  return text;
}

} // namespace pcl_flowseg

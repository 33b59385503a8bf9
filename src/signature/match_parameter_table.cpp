/*
 * pcl_flowseg - every parameter of matching (MatchParameters), described once.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include <pcl_flowseg/common/parameter_fields.h>
#include <pcl_flowseg/signature/match_parameter_table.h>

namespace pcl_flowseg {

namespace {

using MP = MatchParameters;

const std::vector<std::pair<std::string, double DescriptionWeights::*>>&
weightFields ()
{
  return descriptionWeightFields ();
}

/** A row of a set of description weights, written NAME=WEIGHT,... (names left out keep their weight). */
ParameterSpec<MP>
weightsField (ParameterInfo info, ParameterField<MP, DescriptionWeights> field)
{
  info.type = ParameterType::Weights;
  for (const auto& f : weightFields ())
    info.choices.push_back (f.first);
  const std::vector<std::string> names = info.choices;
  return {std::move (info),
          [field, names] (const MP& p) {
            MP c = p;
            std::vector<double> values;
            for (const auto& f : weightFields ())
              values.push_back (field (c).*f.second);
            return weightsText (names, values);
          },
          [field, names] (MP& p, const std::string& text) {
            std::vector<double> values;
            for (const auto& f : weightFields ())
              values.push_back (field (p).*f.second);
            const Status s = parseWeights (text, names, values);
            if (s)
              for (std::size_t k = 0; k < values.size (); ++k)
                field (p).*weightFields ()[k].second = values[k];
            return s;
          }};
}

void
addMethodAndWeights (std::vector<ParameterSpec<MP>>& t)
{
  std::vector<std::pair<std::string, MatchMethod>> methods;
  for (const MatchMethod m : kMatchMethods)
    methods.emplace_back (matchMethodName (m), m);
  t.push_back (choiceField<MP, MatchMethod> (
      {"method", "", "matching", ParameterType::Choice, "", "one of the names",
       "how shapes are compared: flowseg (the description distances, weighted), paper (the paper's alignment), or one distance alone"},
      [] (MP& p) -> MatchMethod& { return p.method; }, methods));
  t.push_back (weightsField ({"weights_3d", "", "matching", ParameterType::Weights, "", "each finite, >= 0; not all 0",
                              "the weight of each description distance in method flowseg, for 3D shapes; names left out keep theirs"},
                             [] (MP& p) -> DescriptionWeights& { return p.weights_3d; }));
  t.push_back (weightsField ({"weights_2d", "", "matching", ParameterType::Weights, "", "each finite, >= 0; not all 0",
                              "the weight of each description distance in method flowseg, for 2D shapes; names left out keep theirs"},
                             [] (MP& p) -> DescriptionWeights& { return p.weights_2d; }));
}

void
addPaper (std::vector<ParameterSpec<MP>>& t)
{
  t.push_back (numberField<MP> ({"threshold", "", "paper", ParameterType::Number, "the signatures' normalised length unit",
                                 "finite, > 0", "method paper: largest distance between matched features"},
                                [] (MP& p) -> double& { return p.paper.threshold; }));
  t.push_back (switchField<MP> ({"allow_mirror", "", "paper", ParameterType::Switch, "", "true, false",
                                 "method paper: also try mirrored alignments (the description methods are mirror-invariant)", {},
                                 {"mirror"}},
                                [] (MP& p) -> bool& { return p.paper.allow_mirror; }));
  t.push_back (countField<MP, int> ({"alignment_points", "", "paper", ParameterType::Count, "features", "1 to 100",
                                     "method paper: the heaviest features of each signature that generate alignments"},
                                    [] (MP& p) -> int& { return p.paper.alignment_points; }, 100));
}

} // namespace

const ParameterTable<MatchParameters>&
matchParameterTable ()
{
  static const ParameterTable<MP> table = [] {
    ParameterTable<MP> t;
    t.title = "matching (MatchParameters)";
    addMethodAndWeights (t.specs);
    addPaper (t.specs);
    t.check = [] (const MP& p) { return checkMatchParameters (p); };
    return t;
  }();
  return table;
}

} // namespace pcl_flowseg

/*
 * pcl_flowseg tests - the parameter tables: every row reads back what it writes, names are unique,
 * ranges are checked, old spellings still work, and docs/parameters.md shows the tables as they are.
 */
#include <pcl_flowseg/common/flow_parameter_table.h>
#include <pcl_flowseg/signature/match_parameter_table.h>
#include <pcl_flowseg/signature/parameter_reference.h>
#include <pcl_flowseg/signature/signature_parameters.h>

#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <set>
#include <sstream>

namespace {

using namespace pcl_flowseg;

/** Every row's text of \a params, in table order. */
template <class Params>
std::vector<std::string>
texts (const ParameterTable<Params>& table, const Params& params)
{
  std::vector<std::string> out;
  for (const auto& spec : table.specs)
    out.push_back (spec.get (params));
  return out;
}

/** Writing each row's text of \a changed into the defaults gives \a changed back. */
template <class Params>
void
expectRoundTrip (const ParameterTable<Params>& table, const Params& changed)
{
  Params rebuilt;
  for (const auto& spec : table.specs)
  {
    const Status s = setParameter (table, spec, rebuilt, spec.get (changed));
    EXPECT_TRUE (s) << spec.info.name << ": " << s.message;
  }
  EXPECT_EQ (texts (table, rebuilt), texts (table, changed));
}

TEST (ParameterTable, EveryRowReadsBackWhatItWrites)
{
  FlowParameters flow;
  flow.preparation.dimension = DimensionMode::Spatial;
  flow.preparation.smoothing = Smoothing::Always;
  flow.merge.rho = 1.2345678901234567;
  flow.merge.min_part_share = 0.1;
  flow.interior.separate = false;
  flow.interior.viewpoint = Eigen::Vector3d (0.1, -2.5, 1e-7);
  flow.features = FeatureSide::Both;
  flow.execution.threads = 3;
  flow.execution.memory_limit = std::size_t (1) << 40;
  expectRoundTrip (flowParameterTable (), flow);
  expectRoundTrip (flowParameterTable (), FlowParameters ());
  SignatureParameters signature;
  signature.significance = 0.125;
  signature.input.mesh_points = 1234;
  signature.input.seed = 4000000000u;
  expectRoundTrip (signatureParameterTable (), signature);
  MatchParameters match;
  match.method = MatchMethod::InnerContext;
  match.weights_3d.parts = 0.25;
  match.weights_2d.contour = 12.5;
  match.paper.threshold = 0.3;
  match.paper.allow_mirror = false;
  match.paper.alignment_points = 7;
  expectRoundTrip (matchParameterTable (), match);
}

TEST (ParameterTable, WeightsAreSetByName)
{
  const auto& table = matchParameterTable ();
  MatchParameters m;
  const MatchParameters defaults;
  ASSERT_TRUE (setParameter (table, *findParameter (table, "weights_3d"), m, "thickness=2,inner_context=0"));
  EXPECT_EQ (m.weights_3d.thickness, 2.0);
  EXPECT_EQ (m.weights_3d.inner_context, 0.0);
  EXPECT_EQ (m.weights_3d.parts, defaults.weights_3d.parts); // not named: kept
  EXPECT_EQ (m.weights_2d.contour, defaults.weights_2d.contour);
  for (const char* bad : {"thickness=-1", "girth=1", "thickness", "thickness=x",
                          "parts=0,thickness=0,inner_distance=0,solid_distance=0,inner_profile=0,thickness_profile=0,contour=0,inner_context=0"})
    EXPECT_FALSE (setParameter (table, *findParameter (table, "weights_3d"), m, bad)) << bad;
  EXPECT_EQ (m.weights_3d.thickness, 2.0);
}

TEST (ParameterTable, NamesAndOptionsAreUniqueAndDescribed)
{
  std::set<std::string> names, short_options;
  const auto check = [&] (const ParameterInfo& info) {
    EXPECT_TRUE (names.insert (info.name).second) << info.name;
    for (const auto& old : info.old_names)
      EXPECT_TRUE (names.insert (old).second) << old;
    if (!info.short_option.empty ())
      EXPECT_TRUE (short_options.insert (info.short_option).second) << info.short_option;
    EXPECT_FALSE (info.description.empty () || info.range.empty () || info.group.empty ()) << info.name;
    EXPECT_EQ (info.name.find_first_not_of ("abcdefghijklmnopqrstuvwxyz_0123456789"), std::string::npos) << info.name;
  };
  for (const auto& spec : flowParameterTable ().specs)
    check (spec.info);
  for (const auto& spec : signatureParameterTable ().specs)
    check (spec.info);
  for (const auto& spec : matchParameterTable ().specs)
    check (spec.info);
  EXPECT_EQ (optionName ("single_view_min_part_share"), "--single-view-min-part-share");
}

TEST (ParameterTable, RefusedValuesLeaveTheParametersUnchanged)
{
  const auto& table = flowParameterTable ();
  FlowParameters p;
  const auto* rho = findParameter (table, "rho");
  ASSERT_NE (rho, nullptr);
  for (const char* bad : {"-1", "nan", "big", "", "1.0x"})
  {
    const Status s = setParameter (table, *rho, p, bad);
    EXPECT_FALSE (s) << bad;
    EXPECT_NE (s.message.find ("rho"), std::string::npos) << s.message;
  }
  EXPECT_EQ (p.merge.rho, FlowParameters ().merge.rho);
  const auto* passes = findParameter (table, "smoothing_passes");
  EXPECT_FALSE (setParameter (table, *passes, p, "0"));
  EXPECT_FALSE (setParameter (table, *passes, p, "9"));
  EXPECT_FALSE (setParameter (table, *findParameter (table, "viewpoint"), p, "1,2"));
  EXPECT_FALSE (setParameter (table, *findParameter (table, "features"), p, "outside"));
  EXPECT_EQ (texts (table, p), texts (table, FlowParameters ()));
}

TEST (ParameterTable, OldSpellingsStillWork)
{
  const auto& table = flowParameterTable ();
  bool old = false;
  const auto* tolerance = findParameter (table, "tolerance", &old);
  ASSERT_NE (tolerance, nullptr);
  EXPECT_TRUE (old);
  EXPECT_EQ (tolerance->info.name, "sampling_tolerance");
  FlowParameters p;
  std::string warning;
  ASSERT_TRUE (setParameter (table, *findParameter (table, "smoothing"), p, "always", &warning));
  EXPECT_EQ (p.preparation.smoothing, Smoothing::Always);
  EXPECT_NE (warning.find ("deprecated"), std::string::npos);
  ASSERT_TRUE (setParameter (table, *findParameter (table, "dimension"), p, "planar", &warning));
  EXPECT_EQ (p.preparation.dimension, DimensionMode::Planar);
  const auto* separate = findParameter (table, "separate", &old);
  ASSERT_NE (separate, nullptr);
  EXPECT_EQ (separate->info.name, "separate_interior");
}

/** Where the part of \a text between the reference's begin and end lines starts, and its length;
  * npos when the lines are missing. */
std::pair<std::size_t, std::size_t>
referenceSection (const std::string& text)
{
  const std::size_t begin = text.find (kParameterReferenceBegin), end = text.find (kParameterReferenceEnd);
  const std::size_t from = begin + std::string (kParameterReferenceBegin).size () + 1;
  if (begin == std::string::npos || end == std::string::npos || end < from)
    return {std::string::npos, 0};
  return {from, end - from};
}

/** docs/parameters.md is made from the tables; PCL_FLOWSEG_UPDATE_DOCS=1 rewrites its tables. */
TEST (ParameterTable, DocumentationShowsTheTables)
{
  const std::string path = std::string (PCL_FLOWSEG_SOURCE_DIR) + "/docs/parameters.md";
  std::ifstream in (path);
  ASSERT_TRUE (in) << path;
  std::stringstream text;
  text << in.rdbuf ();
  const std::string document = text.str (), wanted = parameterReferenceMarkdown ();
  const auto [from, length] = referenceSection (document);
  ASSERT_NE (from, std::string::npos) << path << " lacks the lines " << kParameterReferenceBegin << " / " << kParameterReferenceEnd;
  const std::string section = document.substr (from, length);
  if (section != wanted && std::getenv ("PCL_FLOWSEG_UPDATE_DOCS"))
  {
    std::ofstream (path) << document.substr (0, from) << wanted << document.substr (from + length);
    return;
  }
  EXPECT_EQ (section, wanted) << "docs/parameters.md is out of date: run PCL_FLOWSEG_UPDATE_DOCS=1 "
                                 "build/test/flowseg_tests --gtest_filter=ParameterTable.*";
}

} // namespace

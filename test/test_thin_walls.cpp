/*
 * Thin walls under noise: a thin-walled cup keeps its cavity outside (InteriorParameters::exterior_opening).
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include "test_support.h"

#include <pcl_flowseg/segmentation/flow_pipeline.h>

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <random>

using namespace pcl_flowseg;
using V = Eigen::Vector3d;

namespace {

/** A cup: outer radius 1, height 2, walls and bottom \a wall thick, open at the top. */
struct ThinCup
{
  double wall = 0.1;

  bool contains (const V& p) const
  {
    const double r = std::hypot (p.x (), p.y ());
    const bool solid = r <= 1.0 && p.z () >= 0.0 && p.z () <= 2.0;
    const bool cavity = r < 1.0 - wall && p.z () > wall;
    return solid && !cavity;
  }

  bool inCavity (const V& p) const
  {
    return std::hypot (p.x (), p.y ()) < 1.0 - 2 * wall && p.z () > 3 * wall && p.z () < 2.0 - wall;
  }

  /** \a count points area-uniformly on its five faces, with Gaussian noise of \a sigma. */
  std::vector<V> sample (std::size_t count, double sigma, std::uint32_t seed) const
  {
    const double inner = 1.0 - wall;
    // Areas: outer side, inner side, outer bottom, inner bottom, rim.
    const double areas[5] = {2 * M_PI * 2.0, 2 * M_PI * inner * (2.0 - wall), M_PI, M_PI * inner * inner, M_PI * (1.0 - inner * inner)};
    std::discrete_distribution<int> face (std::begin (areas), std::end (areas));
    std::uniform_real_distribution<double> u (0.0, 1.0);
    std::normal_distribution<double> noise (0.0, sigma);
    std::mt19937 rng (seed);
    std::vector<V> pts;
    while (pts.size () < count)
    {
      const double a = 2 * M_PI * u (rng), s = u (rng);
      V p;
      switch (face (rng))
      {
        case 0: p = V (std::cos (a), std::sin (a), 2.0 * s); break;
        case 1: p = V (inner * std::cos (a), inner * std::sin (a), wall + (2.0 - wall) * s); break;
        case 2: p = std::sqrt (s) * V (std::cos (a), std::sin (a), 0.0); break;
        case 3: p = inner * std::sqrt (s) * V (std::cos (a), std::sin (a), 0.0) + V (0, 0, wall); break;
        default: p = std::sqrt (inner * inner + (1.0 - inner * inner) * s) * V (std::cos (a), std::sin (a), 0.0) + V (0, 0, 2.0); break;
      }
      pts.push_back (p + V (noise (rng), noise (rng), noise (rng)));
    }
    return pts;
  }
};

FlowResult
segmentCup (const std::vector<V>& pts, double opening)
{
  FlowParameters params;
  params.preparation.dimension = DimensionMode::Spatial;
  params.interior.exterior_opening = opening;
  return flowseg_test::segmentWithParameters (pts, params);
}

/** Share of the volume of the cells whose centroid passes \a where that is labelled inside. */
double
insideShare (const FlowResult& r, const std::function<bool (const V&)>& where)
{
  double volume = 0.0, inside = 0.0;
  for (const auto& c : r.cells)
    if (where (c.centroid))
    {
      volume += c.volume;
      inside += c.inside == 1 ? c.volume : 0.0;
    }
  return volume > 0.0 ? inside / volume : 0.0;
}

/** Volume IoU of the cells labelled inside with the cells whose centroid \a truth holds. */
double
volumeIou (const FlowResult& r, const std::function<bool (const V&)>& truth)
{
  double both = 0.0, either = 0.0;
  for (const auto& c : r.cells)
  {
    const bool labelled = c.inside == 1, truly = truth (c.centroid);
    both += labelled && truly ? c.volume : 0.0;
    either += labelled || truly ? c.volume : 0.0;
  }
  return either > 0.0 ? both / either : 0.0;
}

} // namespace

TEST (ThinWalls, ANoisyCupKeepsItsCavityOutside)
{
  // Walls 2.9% of the diagonal thick, noise 0.5% of it: about two sample spacings and a third of one.
  const ThinCup cup;
  const auto pts = cup.sample (10000, 0.005 * std::sqrt (12.0), 5);
  const FlowResult with = segmentCup (pts, 4.0);
  EXPECT_GT (with.interior.opening_cells, 0u);
  const auto cavity = [&] (const V& p) { return cup.inCavity (p); };
  EXPECT_LT (insideShare (with, cavity), 0.02);
  const FlowResult without = segmentCup (pts, 0.0);
  EXPECT_EQ (without.interior.opening_cells, 0u);
  EXPECT_LT (insideShare (with, cavity), insideShare (without, cavity));
  const auto solid = [&] (const V& p) { return cup.contains (p); };
  // The walls keep part of their inside: the samples face the side the flood reached them from.
  EXPECT_GT (volumeIou (with, solid), 0.35);
  EXPECT_GT (volumeIou (with, solid), volumeIou (without, solid) + 0.2);
}

TEST (ThinWalls, TheFloodDoesNotEnterTheWalls)
{
  // A clean sample at the narrowest opening allowed: the walls stay inside, the cavity outside.
  const ThinCup cup;
  const auto pts = cup.sample (10000, 0.0, 6);
  const FlowResult r = segmentCup (pts, kMinExteriorOpening);
  const auto wall = [&] (const V& p) { return cup.contains (p); };
  EXPECT_GT (insideShare (r, wall), 0.97);
  EXPECT_LT (insideShare (r, [&] (const V& p) { return cup.inCavity (p); }), 0.02);
}

TEST (ThinWalls, OpeningsNarrowerThanTheSamplesGapsAreRefused)
{
  FlowParameters params;
  for (double bad : {1.0, 2.9, -1.0, std::nan (""), HUGE_VAL})
  {
    params.interior.exterior_opening = bad;
    const Status s = checkParameters (params);
    EXPECT_FALSE (s.ok) << bad;
    EXPECT_NE (s.message.find ("exterior opening"), std::string::npos) << s.message;
  }
  for (double good : {0.0, kMinExteriorOpening, 10.0})
  {
    params.interior.exterior_opening = good;
    EXPECT_TRUE (checkParameters (params).ok) << good;
  }
}

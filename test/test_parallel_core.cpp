/*
 * The fast paths of the core agree with the slow exact ones: the filtered flow predicate with
 * CGAL's exact predicate, the parallel triangulation with the sequential one, the greedy labelling's
 * heap with an ordered set.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include "core/delaunay/delaunay_cells.h"
#include "core/delaunay/canonical_cells.h"
#include "core/delaunay/flow_predicate.h"
#include "core/geometry/cell_geometry.h"
#include "core/support/cell_heap.h"
#include "core/support/huge_page_arena.h"
#include "core/support/parallel.h"
#include "core/support/system_load.h"
#include "test_support.h"

#include <pcl_flowseg/evaluation/shape_generator.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <csignal>
#include <random>
#include <thread>
#include <set>
#include <utility>

using namespace pcl_flowseg;
using V = Eigen::Vector3d;

namespace {
bool
cgalInside (const V& a, const V& b, const V& c, const V& p)
{
  using P = CGAL::Exact_predicates_inexact_constructions_kernel::Point_3;
  return CGAL::side_of_bounded_sphere (P (a.x (), a.y (), a.z ()), P (b.x (), b.y (), b.z ()), P (c.x (), c.y (), c.z ()),
                                       P (p.x (), p.y (), p.z ())) == CGAL::ON_BOUNDED_SIDE;
}
} // namespace

TEST (FlowPredicate, AgreesWithCgalOnRandomAndDegenerateInput)
{
  std::mt19937 rng (7);
  std::uniform_real_distribution<double> unit (-1.0, 1.0);
  std::uniform_int_distribution<int> grid (-3, 3);
  int inside = 0, outside = 0;
  for (int k = 0; k < 20000; ++k)
  {
    V a, b, c, p;
    switch (k % 4)
    {
    case 0: // general position, far from the origin
      a = V (unit (rng), unit (rng), unit (rng)) + V (1e5, -2e5, 3e5);
      b = a + V (unit (rng), unit (rng), unit (rng));
      c = a + V (unit (rng), unit (rng), unit (rng));
      p = a + V (unit (rng), unit (rng), unit (rng));
      break;
    case 1: // small integer grid: many points exactly on the sphere, collinear triangles
      a = V (grid (rng), grid (rng), grid (rng));
      b = V (grid (rng), grid (rng), grid (rng));
      c = V (grid (rng), grid (rng), grid (rng));
      p = V (grid (rng), grid (rng), grid (rng));
      break;
    case 2: // p on the diametral sphere up to rounding: the sign is decided by the last bits
    {
      a = V (1, 0, 0);
      b = V (-1, 0, 0);
      c = V (0, 1, 0);
      const V dir = V (unit (rng), unit (rng), unit (rng)).normalized ();
      p = dir * (1.0 + (k % 8 - 4) * 1e-16);
      break;
    }
    default: // needle triangles
      a = V (unit (rng), unit (rng), unit (rng));
      b = a + 1e-9 * V (unit (rng), unit (rng), unit (rng));
      c = a + V (unit (rng), unit (rng), unit (rng));
      p = a + V (unit (rng), unit (rng), unit (rng));
    }
    const bool expected = cgalInside (a, b, c, p);
    ASSERT_EQ (core::insideDiametralSphere (a, b, c, p), expected) << "case " << k;
    (expected ? inside : outside)++;
  }
  EXPECT_GT (inside, 1000); // both answers are exercised
  EXPECT_GT (outside, 1000);
}

TEST (ParallelCore, ThreadCountDoesNotChangeTheResult)
{
  const auto shape = sampleShape ("animal3d");
  const auto points = sampleBoundary (shape, 12000, 3); // above the parallel triangulation's threshold
  FlowParameters sequential;
  sequential.execution.threads = 1;
  FlowParameters parallel = sequential;
  parallel.execution.threads = 2;
  FlowResult a, b;
  ASSERT_TRUE (runFlowSegmentation (points, sequential, a));
  ASSERT_TRUE (runFlowSegmentation (points, parallel, b));
  ASSERT_EQ (a.cells.size (), b.cells.size ());
  for (std::size_t k = 0; k < a.cells.size (); ++k)
  {
    ASSERT_EQ (a.cells[k].vertices, b.cells[k].vertices) << k;
    ASSERT_EQ (a.cells[k].neighbors, b.cells[k].neighbors) << k;
    ASSERT_EQ (a.cells[k].flow_mask, b.cells[k].flow_mask) << k;
    ASSERT_EQ (a.cells[k].segment, b.cells[k].segment) << k;
    ASSERT_EQ (a.cells[k].inside, b.cells[k].inside) << k;
  }
  EXPECT_EQ (a.maxima.size (), b.maxima.size ());
  EXPECT_EQ (a.segments.size (), b.segments.size ());
  EXPECT_EQ (a.point_labels, b.point_labels);
}

TEST (ParallelCore, ParallelInsertionGivesTheSequentialCells)
{
  // Forced parallel (the automatic choice also looks at the system load).
  const auto points = sampleBoundary (sampleShape ("snowman3d"), 20000, 4);
  const core::WorkerThreads two (2);
  std::vector<FlowCell> sequential, parallel;
  const Status s = core::triangulate3D (points, sequential, core::Insertion::Sequential);
  ASSERT_TRUE (s) << s.message;
  // The parallel triangulation keeps its cells in the huge-page arena and gives them all back.
  auto& arena = core::HugePageArena::instance ();
  const std::size_t mapped_before = arena.mappedBytes (), handed_out_before = arena.handedOutBytes ();
  const Status p = core::triangulate3D (points, parallel, core::Insertion::Parallel);
  ASSERT_TRUE (p) << p.message;
  EXPECT_GT (arena.handedOutBytes () - handed_out_before, parallel.size () * 64);
  EXPECT_EQ (arena.mappedBytes (), mapped_before);
  ASSERT_EQ (sequential.size (), parallel.size ());
  for (std::size_t k = 0; k < sequential.size (); ++k)
  {
    ASSERT_EQ (sequential[k].vertices, parallel[k].vertices) << k;
    ASSERT_EQ (sequential[k].neighbors, parallel[k].neighbors) << k;
  }
}

TEST (HugePageArena, HandsOutAlignedDisjointBlocksAndUnmapsFreedChunks)
{
  auto& arena = core::HugePageArena::instance ();
  const std::size_t mapped_before = arena.mappedBytes ();
  // Sizes like a CGAL container's growing blocks, from both workers at once, and one block larger
  // than a chunk.
  std::vector<std::size_t> sizes;
  for (std::size_t n = 14; sizes.size () < 600; n += 16)
    sizes.push_back (n * 72);
  sizes.push_back (std::size_t (100) << 20);
  std::vector<char*> blocks (sizes.size ());
  const core::WorkerThreads two (2);
  core::parallelFor (sizes.size (), [&] (std::size_t k) {
    blocks[k] = static_cast<char*> (arena.allocate (sizes[k]));
    std::fill (blocks[k], blocks[k] + sizes[k], static_cast<char> (k % 128)); // writable, all of it
  });
  EXPECT_GT (arena.mappedBytes (), mapped_before);
  std::vector<std::pair<char*, char*>> ranges;
  for (std::size_t k = 0; k < sizes.size (); ++k)
  {
    EXPECT_EQ (reinterpret_cast<std::uintptr_t> (blocks[k]) % 64, 0u) << k;
    EXPECT_EQ (blocks[k][sizes[k] - 1], static_cast<char> (k % 128)) << k; // no other block wrote here
    ranges.emplace_back (blocks[k], blocks[k] + sizes[k]);
  }
  std::sort (ranges.begin (), ranges.end ());
  for (std::size_t k = 1; k < ranges.size (); ++k)
    EXPECT_LE (ranges[k - 1].second, ranges[k].first) << k;
  for (std::size_t k = 0; k < sizes.size (); ++k)
    arena.release (blocks[k], sizes[k]);
  EXPECT_EQ (arena.mappedBytes (), mapped_before);
}

TEST (ParallelCore, VertexIncidenceListsEachVertexsCellsInOrderOnAnyThreads)
{
  const auto points = sampleBoundary (sampleShape ("snowman3d"), 20000, 4);
  std::vector<FlowCell> cells;
  ASSERT_TRUE (core::triangulate3D (points, cells, core::Insertion::Sequential));
  // The plain construction: every vertex's cells, in ascending order.
  std::vector<std::vector<int>> rows (points.size ());
  for (std::size_t c = 0; c < cells.size (); ++c)
    for (int v : cells[c].vertices)
      rows[static_cast<std::size_t> (v)].push_back (static_cast<int> (c));
  for (unsigned threads : {1u, 2u, 3u})
  {
    const core::WorkerThreads workers (threads);
    const core::VertexIncidence inc = core::vertexIncidence (cells, points.size (), 3);
    ASSERT_EQ (inc.first.size (), points.size () + 1);
    ASSERT_EQ (inc.cells.size (), 4 * cells.size ());
    for (std::size_t v = 0; v < points.size (); ++v)
      ASSERT_EQ (std::vector<int> (inc.cells.begin () + static_cast<std::ptrdiff_t> (inc.first[v]),
                                   inc.cells.begin () + static_cast<std::ptrdiff_t> (inc.first[v + 1])),
                 rows[v])
          << "vertex " << v << ", " << threads << " threads";
  }
}

TEST (CanonicalCells, VerticesSortedAndOrientationKept)
{
  // Every order of 3 and 4 distinct vertices: sorted, except the last two swapped back after an
  // odd permutation (the sign of the permutation decides, whatever the sorting method).
  for (int f : {3, 4})
  {
    std::array<int, 4> start{{7, 2, 9, 4}};
    std::sort (start.begin (), start.begin () + f);
    std::array<int, 4> perm = start;
    do
    {
      int inversions = 0;
      for (int i = 0; i < f; ++i)
        for (int j = i + 1; j < f; ++j)
          inversions += perm[static_cast<std::size_t> (i)] > perm[static_cast<std::size_t> (j)];
      std::array<int, 4> v = perm, slot;
      core::canonicalVertexOrder (v, f, slot);
      std::array<int, 4> expected = start;
      if (inversions % 2 == 1)
        std::swap (expected[static_cast<std::size_t> (f - 2)], expected[static_cast<std::size_t> (f - 1)]);
      for (int i = 0; i < f; ++i)
      {
        EXPECT_EQ (v[static_cast<std::size_t> (i)], expected[static_cast<std::size_t> (i)]) << f << " vertices";
        EXPECT_EQ (perm[static_cast<std::size_t> (slot[static_cast<std::size_t> (i)])], v[static_cast<std::size_t> (i)]);
      }
    } while (std::next_permutation (perm.begin (), perm.begin () + f));
  }
}

TEST (CellHeap, PopsInTheOrderOfAnOrderedSetWhileKeysMove)
{
  // Keys rise and fall (ties are frequent: few distinct values), cells are inserted, moved and
  // popped in random order; the heap must always give the set's largest (key, cell) pair.
  constexpr int kCells = 2000;
  std::mt19937 rng (11);
  std::uniform_int_distribution<int> cell_of (0, kCells - 1), key_of (0, 40), action (0, 3);
  core::CellHeap heap (kCells);
  std::set<std::pair<double, int>> reference;
  std::vector<double> key (kCells, -1.0);
  std::vector<bool> popped (kCells, false);
  int pops = 0;
  for (int step = 0; step < 50000; ++step)
  {
    const int cell = cell_of (rng);
    if (action (rng) > 0 && !popped[static_cast<std::size_t> (cell)])
    {
      reference.erase ({key[static_cast<std::size_t> (cell)], cell});
      key[static_cast<std::size_t> (cell)] = key_of (rng) * 0.25;
      reference.insert ({key[static_cast<std::size_t> (cell)], cell});
      heap.update (cell, key[static_cast<std::size_t> (cell)]);
      ASSERT_FALSE (heap.retired (cell));
    }
    else if (!reference.empty ())
    {
      ASSERT_FALSE (heap.empty ());
      const int expected = std::prev (reference.end ())->second;
      ASSERT_EQ (heap.top (), expected);
      ASSERT_EQ (heap.pop (), expected);
      reference.erase (std::prev (reference.end ()));
      popped[static_cast<std::size_t> (expected)] = true;
      ASSERT_TRUE (heap.retired (expected));
      ++pops;
    }
    ASSERT_EQ (heap.empty (), reference.empty ());
  }
  EXPECT_GT (pops, 1000);
}

TEST (SystemLoad, SeesABusyProcess)
{
  if (core::otherRunnableThreads () < 0)
    GTEST_SKIP () << "/proc cannot be read here";
  const pid_t busy = fork ();
  ASSERT_GE (busy, 0);
  if (busy == 0)
  {
    volatile unsigned long spin = 0;
    for (;;) // a process that always wants a core
      spin = spin + 1;
  }
  std::this_thread::sleep_for (std::chrono::milliseconds (50));
  const int with_busy_process = core::otherRunnableThreads ();
  kill (busy, SIGKILL);
  waitpid (busy, nullptr, 0);
  EXPECT_GE (with_busy_process, 1);
}

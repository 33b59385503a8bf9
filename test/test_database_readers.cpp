/*
 * One signature database shared by threads: queries while another thread adds, merges, loads and
 * assigns (the database's reader-writer lock).
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include <pcl_flowseg/signature/signature_database.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <thread>
#include <unistd.h>
#include <vector>

using namespace pcl_flowseg;

namespace {

/** 3 to 6 random points with decreasing weights summing to 1: a signature the paper's method
  * compares (it needs no description). */
Signature
randomSignature (std::mt19937& rng)
{
  std::uniform_real_distribution<double> coordinate (-1.0, 1.0), weight (0.1, 1.0);
  Signature s;
  const int n = 3 + static_cast<int> (rng () % 4);
  std::vector<double> weights;
  double total = 0.0;
  for (int i = 0; i < n; ++i)
    total += weights.emplace_back (weight (rng));
  std::sort (weights.rbegin (), weights.rend ());
  for (double w : weights)
    s.points.push_back (WeightedPoint{Eigen::Vector3d (coordinate (rng), coordinate (rng), coordinate (rng)), w / total});
  return s;
}

ShapeEntry
named (const std::string& name, const std::string& label, const Signature& signature)
{
  return ShapeEntry{name, label, signature};
}

/** Whether \a hits of a query for the shape stored as "fixed" are sane: it first, at similarity 1;
  * then the other compared shapes by decreasing similarity, the rest not compared (NaN); every
  * name one the writer uses. */
bool
saneHits (const std::vector<QueryHit>& hits, std::size_t candidates, std::size_t most)
{
  if (hits.empty () || hits.size () > most || hits[0].name != "fixed" || std::abs (hits[0].similarity - 1.0) > 1e-9)
    return false;
  for (std::size_t r = 0; r < hits.size (); ++r)
  {
    const QueryHit& h = hits[r];
    if (h.compared != (r < candidates) || (h.name != "fixed" && h.label != "added" && h.label != "shard"))
      return false;
    if (h.compared ? !(h.similarity <= 1.0 + 1e-9) || (r > 0 && h.similarity > hits[r - 1].similarity)
                   : !std::isnan (h.similarity))
      return false;
  }
  return true;
}

} // namespace

TEST (DatabaseReaders, QueriesWhileAnotherThreadChangesTheDatabase)
{
  std::mt19937 rng (11);
  std::vector<Signature> pool;
  for (int i = 0; i < 20; ++i)
    pool.push_back (randomSignature (rng));
  SignatureDatabase db;
  db.setQueryThreads (1);
  db.add (named ("fixed", "fixed", pool[0]));
  SignatureDatabase shard;
  for (int i = 0; i < 5; ++i)
    shard.add (named ("shard-" + std::to_string (i), "shard", pool[static_cast<std::size_t> (15 + i)]));
  const std::string path = "/tmp/flowseg_db_readers_" + std::to_string (::getpid ()) + ".db";
  ASSERT_TRUE (db.save (path));

  pcl::SignatureMatcher matcher;
  matcher.setMethod (MatchMethod::Paper);
  constexpr std::size_t kCandidates = 6, kNames = 60, kMost = 1 + kNames + 5;
  std::atomic<bool> done{false};
  std::atomic<std::size_t> queries{0}, insane{0};
  std::vector<std::thread> readers;
  for (int t = 0; t < 3; ++t)
    readers.emplace_back ([&, t] {
      do
      {
        const auto hits = db.query (pool[0], 0, matcher, kCandidates);
        insane += saneHits (hits, kCandidates, kMost) ? 0 : 1;
        if (t == 0) // the other readers
          insane += db.contains ("fixed") && db.copyEntries ().size () <= kMost && db.size () >= 1 ? 0 : 1;
        ++queries;
      } while (!done);
    });
  while (queries == 0)
    std::this_thread::yield ();
  // The writer: adds (new names, then replacing), merges, loads, assigns.
  for (std::size_t i = 0; i < 400; ++i)
  {
    db.add (named ("added-" + std::to_string (i % kNames), "added", pool[1 + i % 14]));
    if (i % 100 == 50)
      db.merge (shard);
    if (i % 100 == 99)
      ASSERT_TRUE (db.load (path)); // back to "fixed" alone
    if (i == 250)
      db = SignatureDatabase (db);
  }
  db.merge (shard);
  done = true;
  for (auto& r : readers)
    r.join ();
  std::remove (path.c_str ());
  EXPECT_GT (queries.load (), 3u);
  EXPECT_EQ (insane.load (), 0u);
  EXPECT_EQ (db.size (), 6u); // "fixed" and the shard
  EXPECT_TRUE (saneHits (db.query (pool[0], 0, matcher, kCandidates), kCandidates, 6));
}

TEST (DatabaseReaders, CopiesMovesAndSelfMergeKeepTheShapes)
{
  std::mt19937 rng (3);
  SignatureDatabase db;
  for (int i = 0; i < 4; ++i)
    db.add (named ("s" + std::to_string (i), "s", randomSignature (rng)));
  EXPECT_EQ (db.merge (db), 0u); // every shape replaces itself
  ASSERT_EQ (db.size (), 4u);
  SignatureDatabase copy (db);
  SignatureDatabase moved (std::move (copy));
  EXPECT_EQ (moved.size (), 4u);
  SignatureDatabase assigned;
  assigned = moved;
  EXPECT_EQ (assigned.size (), 4u);
  EXPECT_EQ (assigned.copyEntries ()[2].name, "s2");
  EXPECT_EQ (assigned.copyEntries ()[2].signature.points.size (), db.entries ()[2].signature.points.size ());
  assigned = std::move (moved);
  EXPECT_EQ (assigned.size (), 4u);
  EXPECT_TRUE (assigned.contains ("s3"));
}

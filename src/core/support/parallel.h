/*
 * pcl_flowseg - internal: the worker threads of one run, and a parallel loop over them.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include <tbb/blocked_range.h>
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_invoke.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <cstddef>
#include <memory>
#include <utility>
#include <vector>

namespace pcl_flowseg {
namespace core {

/** \brief Limits TBB (CGAL's parallel triangulation and parallelFor) to \a threads workers while
  * it lives; 0 leaves all hardware threads. The limit is process-wide (TBB's global_control). */
class WorkerThreads
{
public:
  explicit WorkerThreads (unsigned threads)
  {
    if (threads > 0)
      control_.reset (new tbb::global_control (tbb::global_control::max_allowed_parallelism, threads));
  }

private:
  std::unique_ptr<tbb::global_control> control_;
};

/** \brief Threads TBB may use now. */
inline std::size_t
workerThreads ()
{
  return tbb::global_control::active_value (tbb::global_control::max_allowed_parallelism);
}

/** \brief Calls \a body (std::size_t index) for every index in [0, n), in parallel chunks. Each
  * index must touch only its own data. */
template <class Body>
void
parallelFor (std::size_t n, const Body& body)
{
  if (n < 4096 || workerThreads () < 2)
  {
    for (std::size_t i = 0; i < n; ++i)
      body (i);
    return;
  }
  tbb::parallel_for (tbb::blocked_range<std::size_t> (0, n, 2048), [&] (const tbb::blocked_range<std::size_t>& r) {
    for (std::size_t i = r.begin (); i != r.end (); ++i)
      body (i);
  });
}

/** \brief Splits [0, n) into one contiguous chunk per worker, calls \a body (begin, end, result) for
  * each in parallel, and returns the chunks' results in index order. For loops that gather: the
  * caller combines the results in that order, so the outcome is the sequential loop's. */
template <class Result, class Body>
std::vector<Result>
gatherInChunks (std::size_t n, const Body& body)
{
  const std::size_t chunks = n < 4096 ? 1 : std::max<std::size_t> (1, workerThreads ());
  std::vector<Result> results (chunks);
  if (chunks == 1)
    body (std::size_t (0), n, results[0]);
  else
    tbb::parallel_for (std::size_t (0), chunks, [&] (std::size_t k) { body (n * k / chunks, n * (k + 1) / chunks, results[k]); });
  return results;
}

/** \brief Calls \a body (k) for each of a few heavy \a tasks (one per chunk of gatherInChunks, say),
  * in parallel. */
template <class Body>
void
forEachTask (std::size_t tasks, const Body& body)
{
  if (tasks == 1)
    body (std::size_t (0));
  else
    tbb::parallel_for (std::size_t (0), tasks, [&] (std::size_t k) { body (k); });
}

/** \brief The items \a body (begin, end, out) appends for its chunk of [0, n), gathered on all
  * workers and joined in index order: the list the sequential loop would have made. */
template <class Item, class Body>
std::vector<Item>
gatherListInOrder (std::size_t n, const Body& body)
{
  std::vector<std::vector<Item>> parts = gatherInChunks<std::vector<Item>> (n, body);
  for (std::size_t k = 1; k < parts.size (); ++k)
    parts.front ().insert (parts.front ().end (), parts[k].begin (), parts[k].end ());
  return std::move (parts.front ());
}

/** \brief Runs \a first and \a second, at the same time when two workers are allowed. They must
  * not write the same data. */
template <class First, class Second>
void
runSideBySide (const First& first, const Second& second)
{
  if (workerThreads () < 2)
  {
    first ();
    second ();
    return;
  }
  tbb::parallel_invoke (first, second);
}

} // namespace core
} // namespace pcl_flowseg

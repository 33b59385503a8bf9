/*
 * pcl_flowseg - internal: an addressable max-heap of cells keyed by a score that changes.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include <algorithm>
#include <cstddef>
#include <utility>
#include <vector>

namespace pcl_flowseg {
namespace core {

/** \brief A 4-ary heap of cells ordered by key (highest first; equal keys: higher cell index first), each cell at
  * most once. Keys live in the caller's vector and may move up or down: update() restores the order
  * after a change. Unlike a priority queue with stale copies, the heap never holds more than the
  * cells waiting, and every update is O(log waiting). */
class CellHeap
{
public:
  CellHeap (const std::vector<double>& keys) : keys_ (keys), position_ (keys.size (), -1) {}

  bool empty () const { return heap_.empty (); }

  /** Inserts \a cell, or repositions it after its key changed. */
  void
  update (int cell)
  {
    int& at = position_[static_cast<std::size_t> (cell)];
    if (at < 0)
    {
      at = static_cast<int> (heap_.size ());
      heap_.push_back (cell);
    }
    siftDown (siftUp (at));
  }

  /** Removes and returns the cell with the highest key. */
  int
  pop ()
  {
    const int top = heap_.front ();
    position_[static_cast<std::size_t> (top)] = -1;
    const int last = heap_.back ();
    heap_.pop_back ();
    if (!heap_.empty ())
    {
      heap_[0] = last;
      position_[static_cast<std::size_t> (last)] = 0;
      siftDown (0);
    }
    return top;
  }

private:
  static constexpr int kArity = 4; // shallower than binary: fewer cache misses per operation

  bool
  above (int a, int b) const
  {
    const double ka = keys_[static_cast<std::size_t> (a)], kb = keys_[static_cast<std::size_t> (b)];
    return ka != kb ? ka > kb : a > b;
  }

  void
  place (int at, int cell)
  {
    heap_[static_cast<std::size_t> (at)] = cell;
    position_[static_cast<std::size_t> (cell)] = at;
  }

  int
  siftUp (int at)
  {
    const int cell = heap_[static_cast<std::size_t> (at)];
    while (at > 0)
    {
      const int parent = (at - 1) / kArity;
      if (!above (cell, heap_[static_cast<std::size_t> (parent)]))
        break;
      place (at, heap_[static_cast<std::size_t> (parent)]);
      at = parent;
    }
    place (at, cell);
    return at;
  }

  void
  siftDown (int at)
  {
    const int n = static_cast<int> (heap_.size ());
    const int cell = heap_[static_cast<std::size_t> (at)];
    for (;;)
    {
      const int first_child = kArity * at + 1;
      if (first_child >= n)
        break;
      int child = first_child;
      for (int k = first_child + 1; k < std::min (n, first_child + kArity); ++k)
        if (above (heap_[static_cast<std::size_t> (k)], heap_[static_cast<std::size_t> (child)]))
          child = k;
      if (!above (heap_[static_cast<std::size_t> (child)], cell))
        break;
      place (at, heap_[static_cast<std::size_t> (child)]);
      at = child;
    }
    place (at, cell);
  }

  const std::vector<double>& keys_;
  std::vector<int> heap_;
  std::vector<int> position_;
};

} // namespace core
} // namespace pcl_flowseg

/*
 * pcl_flowseg - internal: an addressable max-heap of cells keyed by a score that changes.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include "core/support/huge_pages.h"

#include <algorithm>
#include <cstddef>
#include <vector>

namespace pcl_flowseg {
namespace core {

/** \brief A 4-ary heap of cells ordered by key (highest first; equal keys: higher cell index first), each cell at
  * most once, and only until it is popped: a popped cell is retired and may not come back. A key may move up or down: update() repositions the cell. Unlike a priority queue with
  * stale copies, the heap never holds more than the cells waiting, and every update is O(log waiting).
  * Each entry carries its key, so comparing the four children of a node reads one cache line instead
  * of four scattered keys. */
class CellHeap
{
public:
  /** A heap for cells 0 .. \a cell_count - 1. */
  explicit CellHeap (std::size_t cell_count) { assignOnHugePages (position_, cell_count, -1); }

  bool empty () const { return heap_.empty (); }

  /** Whether \a cell has been popped. */
  bool retired (int cell) const { return position_[static_cast<std::size_t> (cell)] == kRetired; }

  /** Inserts \a cell with \a key, or repositions it under its new \a key. \a cell must not be retired. */
  void
  update (int cell, double key)
  {
    const int at = position_[static_cast<std::size_t> (cell)];
    if (at < 0)
    {
      position_[static_cast<std::size_t> (cell)] = static_cast<int> (heap_.size ());
      heap_.push_back ({key, cell});
      siftUp (static_cast<int> (heap_.size ()) - 1);
      return;
    }
    Entry& entry = heap_[static_cast<std::size_t> (at)];
    const Entry before = entry;
    entry.key = key;
    // A cell that rose cannot have to sink, nor one that fell rise: one direction is enough.
    if (above (entry, before))
      siftUp (at);
    else
      siftDown (at);
  }

  /** The cell with the highest key, without removing it. */
  int top () const { return heap_.front ().cell; }

  /** Removes and returns the cell with the highest key. */
  int
  pop ()
  {
    const int top = heap_.front ().cell;
    position_[static_cast<std::size_t> (top)] = kRetired;
    const Entry last = heap_.back ();
    heap_.pop_back ();
    if (!heap_.empty ())
    {
      heap_[0] = last;
      position_[static_cast<std::size_t> (last.cell)] = 0;
      siftDown (0);
    }
    return top;
  }

private:
  static constexpr int kArity = 4; // shallower than binary: fewer cache misses per operation
  static constexpr int kRetired = -2; ///< position of a popped cell (-1: never inserted)

  struct Entry
  {
    double key;
    int cell;
  };

  static bool
  above (const Entry& a, const Entry& b)
  {
    return a.key != b.key ? a.key > b.key : a.cell > b.cell;
  }

  void
  place (int at, const Entry& entry)
  {
    heap_[static_cast<std::size_t> (at)] = entry;
    position_[static_cast<std::size_t> (entry.cell)] = at;
  }

  int
  siftUp (int at)
  {
    const Entry entry = heap_[static_cast<std::size_t> (at)];
    while (at > 0)
    {
      const int parent = (at - 1) / kArity;
      if (!above (entry, heap_[static_cast<std::size_t> (parent)]))
        break;
      place (at, heap_[static_cast<std::size_t> (parent)]);
      at = parent;
    }
    place (at, entry);
    return at;
  }

  void
  siftDown (int at)
  {
    const int n = static_cast<int> (heap_.size ());
    const Entry entry = heap_[static_cast<std::size_t> (at)];
    for (;;)
    {
      const int first_child = kArity * at + 1;
      if (first_child >= n)
        break;
      int child = first_child;
      for (int k = first_child + 1; k < std::min (n, first_child + kArity); ++k)
        if (above (heap_[static_cast<std::size_t> (k)], heap_[static_cast<std::size_t> (child)]))
          child = k;
      if (!above (heap_[static_cast<std::size_t> (child)], entry))
        break;
      place (at, heap_[static_cast<std::size_t> (child)]);
      at = child;
    }
    place (at, entry);
  }

  std::vector<Entry> heap_;
  std::vector<int> position_;
};

} // namespace core
} // namespace pcl_flowseg

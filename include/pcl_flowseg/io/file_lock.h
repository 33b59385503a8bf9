/*
 * pcl_flowseg - an exclusive lock on a file, between processes, with a bounded wait.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include <pcl_flowseg/common/status.h>

#include <string>

namespace pcl_flowseg {

/** \brief Default longest wait for a file lock, in seconds. */
constexpr double kDefaultLockWait = 120.0;

/** \brief An exclusive advisory lock (flock) on the lock file `PATH.lock` beside \a path, held from
  * acquire() until release() or destruction. Every process and thread that locks the same path this
  * way waits for the others, so a read-modify-write of \a path under the lock loses no update. The
  * lock file is created when missing and left in place (removing it would let two writers lock two
  * different files); the operating system releases the lock when its holder dies, even by SIGKILL. */
class FileLock
{
public:
  FileLock () = default;
  FileLock (const FileLock&) = delete;
  FileLock& operator= (const FileLock&) = delete;
  ~FileLock () { release (); }

  /** \brief Takes the lock of \a path, waiting at most \a wait_seconds (finite, >= 0) for its holder.
    * \return success, or why not: the lock file cannot be created, or another process held the lock
    *         for the whole wait (the message names the lock file). */
  Status acquire (const std::string& path, double wait_seconds = kDefaultLockWait);

  /** \brief Gives the lock back (nothing when not held). */
  void release ();

  bool held () const { return fd_ >= 0; }

private:
  int fd_ = -1;
};

} // namespace pcl_flowseg

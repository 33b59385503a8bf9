/*
 * pcl_flowseg - an exclusive lock on a file, between processes, with a bounded wait.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include <pcl_flowseg/io/file_lock.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstring>
#include <fcntl.h>
#include <sys/file.h>
#include <thread>
#include <unistd.h>

namespace pcl_flowseg {

Status
FileLock::acquire (const std::string& path, double wait_seconds)
{
  release ();
  if (!std::isfinite (wait_seconds) || wait_seconds < 0.0)
    return Status::error ("the lock wait must be a finite number of seconds >= 0, got " + std::to_string (wait_seconds));
  const std::string lock_path = path + ".lock";
  const int fd = ::open (lock_path.c_str (), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (fd < 0)
    return Status::error ("cannot create the lock file " + lock_path + ": " + std::strerror (errno));
  const auto deadline = std::chrono::steady_clock::now () + std::chrono::duration<double> (wait_seconds);
  auto pause = std::chrono::milliseconds (2);
  while (::flock (fd, LOCK_EX | LOCK_NB) != 0)
  {
    if (errno != EWOULDBLOCK && errno != EINTR)
    {
      const std::string why = std::strerror (errno);
      ::close (fd);
      return Status::error ("cannot lock " + lock_path + ": " + why);
    }
    if (std::chrono::steady_clock::now () >= deadline)
    {
      ::close (fd);
      return Status::error ("another process held the lock " + lock_path + " for more than " +
                            std::to_string (static_cast<long long> (std::ceil (wait_seconds))) +
                            " s; try again when it has finished");
    }
    std::this_thread::sleep_for (pause);
    pause = std::min (pause * 2, std::chrono::milliseconds (50));
  }
  fd_ = fd;
  return Status::success ();
}

void
FileLock::release ()
{
  if (fd_ < 0)
    return;
  ::flock (fd_, LOCK_UN);
  ::close (fd_);
  fd_ = -1;
}

} // namespace pcl_flowseg

/*
 * pcl_flowseg - files that appear whole or not at all.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include <pcl_flowseg/io/atomic_file.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <fcntl.h>
#include <unistd.h>

namespace pcl_flowseg {

namespace {
/** fsync of \a path (a file or a folder); false with errno set when it cannot be done. */
bool
syncToDisk (const std::string& path, bool folder)
{
  const int fd = ::open (path.c_str (), (folder ? O_RDONLY | O_DIRECTORY : O_RDONLY) | O_CLOEXEC);
  if (fd < 0)
    return false;
  const bool ok = ::fsync (fd) == 0;
  const int saved = errno;
  ::close (fd);
  errno = saved;
  return ok;
}

std::string
folderOf (const std::string& path)
{
  const std::size_t slash = path.find_last_of ('/');
  return slash == std::string::npos ? "." : slash == 0 ? "/" : path.substr (0, slash);
}

std::atomic<unsigned long> temporary_files (0);
} // namespace

Status
writeFileAtomically (const std::string& path, const std::function<Status (const std::string& tmp)>& write, bool durable)
{
  const std::string tmp = path + ".tmp." + std::to_string (static_cast<long> (::getpid ())) + "." +
                          std::to_string (temporary_files++);
  Status status;
  try
  {
    status = write (tmp);
  }
  catch (const std::exception& e)
  {
    status = Status::error (std::string ("while writing: ") + e.what ());
  }
  if (status.ok && durable && !syncToDisk (tmp, false))
    status = Status::error (std::string ("cannot flush it to the disk: ") + std::strerror (errno));
  if (!status.ok)
  {
    std::remove (tmp.c_str ());
    return Status::error ("cannot write " + path + ": " + status.message);
  }
  if (std::rename (tmp.c_str (), path.c_str ()) != 0)
  {
    const std::string why = std::strerror (errno);
    std::remove (tmp.c_str ());
    return Status::error ("cannot write " + path + ": " + why);
  }
  if (durable && !syncToDisk (folderOf (path), true))
    return Status::error ("wrote " + path + " but cannot flush its folder to the disk: " + std::strerror (errno));
  return Status::success ();
}

Status
writeTextFileAtomically (const std::string& path, const std::function<void (std::ostream& out)>& write)
{
  return writeFileAtomically (path, [&] (const std::string& tmp) {
    std::ofstream out (tmp, std::ios::binary);
    if (!out)
      return Status::error ("cannot create file");
    write (out);
    out.flush ();
    return out.good () ? Status::success () : Status::error ("write failed (disk full?)");
  });
}

} // namespace pcl_flowseg

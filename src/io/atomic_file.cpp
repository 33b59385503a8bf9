/*
 * pcl_flowseg - files that appear whole or not at all.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include <pcl_flowseg/io/atomic_file.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <unistd.h>

namespace pcl_flowseg {

Status
writeFileAtomically (const std::string& path, const std::function<Status (const std::string& tmp)>& write)
{
  const std::string tmp = path + ".tmp." + std::to_string (static_cast<long> (::getpid ()));
  Status status;
  try
  {
    status = write (tmp);
  }
  catch (const std::exception& e)
  {
    status = Status::error (std::string ("while writing: ") + e.what ());
  }
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

/*
 * pcl_flowseg - internal: opening the plugin with PCL's I/O and filters on first use.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include "common/pcl_backend.h"

#include <dlfcn.h>

#include <vector>

namespace pcl_flowseg {
namespace detail {

namespace {

constexpr const char* kPluginFile = "libpcl_flowseg_pcl.so";

/** The folder of the library holding this code (the build tree or the installed lib folder). */
std::string
libraryFolder ()
{
  Dl_info info{};
  if (dladdr (reinterpret_cast<void*> (&pclBackend), &info) == 0 || info.dli_fname == nullptr)
    return "";
  const std::string file = info.dli_fname;
  const auto slash = file.find_last_of ('/');
  return slash == std::string::npos ? "." : file.substr (0, slash);
}

struct Loaded
{
  const PclBackend* table = nullptr;
  Status why;
};

/** Opens the plugin beside the library (where the build and the install put it), else by the
  * loader's search path (LD_LIBRARY_PATH, for a library copied without it). */
Loaded
load ()
{
  std::vector<std::string> candidates;
  if (const std::string folder = libraryFolder (); !folder.empty ())
    candidates.push_back (folder + "/" + kPluginFile);
  candidates.push_back (kPluginFile);
  std::string errors;
  for (const std::string& path : candidates)
  {
    void* handle = dlopen (path.c_str (), RTLD_NOW | RTLD_LOCAL);
    if (handle == nullptr)
    {
      const char* e = dlerror ();
      errors += "\n  " + (e != nullptr ? std::string (e) : path);
      continue;
    }
    using Entry = const PclBackend* (*) ();
    const auto entry = reinterpret_cast<Entry> (dlsym (handle, kPclBackendSymbol));
    if (entry == nullptr)
    {
      errors += "\n  " + path + ": no " + kPclBackendSymbol + " (a plugin from another version of pcl_flowseg)";
      dlclose (handle);
      continue;
    }
    return Loaded{entry (), Status::success ()};
  }
  return Loaded{nullptr, Status::error (std::string ("PCL's I/O and filters (") + kPluginFile +
                                        ", part of pcl_flowseg) could not be loaded:" + errors)};
}

} // namespace

const PclBackend*
pclBackend (Status& why)
{
  static const Loaded loaded = load (); // thread-safe initialisation, once per process
  why = loaded.why;
  return loaded.table;
}

} // namespace detail
} // namespace pcl_flowseg

// Fuzzes the database's read-modify-write path: SignatureDatabase::update on an arbitrary file must
// either refuse it and leave it byte for byte as it was, or keep every stored shape and add one.
#include "fuzz_support.h"

#include <pcl_flowseg/signature/signature_database.h>

#include <cstdlib>
#include <fstream>
#include <sstream>

namespace {
std::string
contentOf (const std::string& path)
{
  std::ifstream in (path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf ();
  return text.str ();
}
} // namespace

extern "C" int
LLVMFuzzerTestOneInput (const std::uint8_t* data, std::size_t size)
{
  const std::string path = fuzzFile (data, size, "db");
  const std::string before = contentOf (path);
  pcl_flowseg::SignatureDatabase old;
  const bool readable = old.load (path).ok;
  pcl_flowseg::ShapeEntry added;
  added.name = "fuzz added shape";
  added.label = "fuzz";
  added.signature.points = {{Eigen::Vector3d (0, 0, 0), 0.5}, {Eigen::Vector3d (1, 0, 0), 0.5}};
  const pcl_flowseg::Status s = pcl_flowseg::SignatureDatabase::update (path, [&] (pcl_flowseg::SignatureDatabase& db) {
    db.add (added);
    return pcl_flowseg::Status::success ();
  });
  if (s.ok != readable)
    std::abort (); // update must succeed exactly on the files load reads
  if (!s.ok)
  {
    if (contentOf (path) != before)
      std::abort (); // a refused file is left as it was
    return 0;
  }
  pcl_flowseg::SignatureDatabase after;
  if (!after.load (path).ok || !after.contains (added.name))
    std::abort ();
  for (const auto& e : old.entries ())
    if (!after.contains (e.name))
      std::abort (); // nothing stored is lost
  return 0;
}

// Fuzzes the signature database reader, and matching what it loaded.
#include "fuzz_support.h"

#include <pcl_flowseg/signature/signature_database.h>

extern "C" int
LLVMFuzzerTestOneInput (const std::uint8_t* data, std::size_t size)
{
  const std::string path = fuzzFile (data, size, "db");
  pcl_flowseg::SignatureDatabase db;
  if (db.load (path).ok && db.size () > 0)
  {
    pcl::SignatureMatcher matcher;
    const auto& first = db.entries ().front ().signature;
    if (first.points.size () <= 12)
      db.query (first, 3, matcher);
  }
  return 0;
}

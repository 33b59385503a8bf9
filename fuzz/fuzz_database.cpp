// Fuzzes the signature database reader, and matching what it loaded by every method.
#include "fuzz_support.h"

#include <pcl_flowseg/signature/signature_database.h>

extern "C" int
LLVMFuzzerTestOneInput (const std::uint8_t* data, std::size_t size)
{
  const std::string path = fuzzFile (data, size, "db");
  pcl_flowseg::SignatureDatabase db;
  if (db.load (path).ok && db.size () > 0)
  {
    const auto& first = db.entries ().front ().signature;
    for (pcl_flowseg::MatchMethod method : pcl_flowseg::kMatchMethods)
      if (first.points.size () <= 12 || method != pcl_flowseg::MatchMethod::Paper)
      {
        pcl::SignatureMatcher matcher;
        matcher.setMethod (method);
        db.query (first, 3, matcher);
      }
  }
  return 0;
}

/*
 * pcl_flowseg evaluation - the methods single-view recognition compares, by name.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include <pcl_flowseg/evaluation/recognition_method.h>

#include <algorithm>

namespace pcl_flowseg {

namespace {

/** The method called \a name, or false. */
bool
methodNamed (const std::string& name, RecognitionMethod& method)
{
  method = RecognitionMethod ();
  method.name = name;
  if (name == "esf" || name == "esf-views")
  {
    method.kind = name == "esf" ? RecognitionMethodKind::kEsf : RecognitionMethodKind::kEsfViews;
    return true;
  }
  return static_cast<bool> (parseMatchMethod (name, method.match));
}

} // namespace

Status
parseRecognitionMethods (const std::string& list, std::vector<RecognitionMethod>& methods)
{
  methods.clear ();
  std::size_t start = 0;
  while (start <= list.size ())
  {
    const std::size_t end = std::min (list.find (',', start), list.size ());
    const std::string name = list.substr (start, end - start);
    start = end + 1;
    if (std::any_of (methods.begin (), methods.end (), [&] (const RecognitionMethod& m) { return m.name == name; }))
      return Status::error ("the method " + name + " is named twice");
    RecognitionMethod method;
    if (!methodNamed (name, method))
    {
      std::string names;
      for (MatchMethod m : kMatchMethods)
        names += std::string (matchMethodName (m)) + ", ";
      methods.clear ();
      return Status::error ("'" + name + "' is none of the methods " + names + "esf, esf-views");
    }
    methods.push_back (method);
  }
  return Status::success ();
}

} // namespace pcl_flowseg

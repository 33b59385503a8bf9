/*
 * pcl_flowseg evaluation - the model of each query: the same relative path, extensions aside.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include <pcl_flowseg/evaluation/query_models.h>

#include <map>

namespace pcl_flowseg {

std::string
withoutExtension (const std::string& relative_path)
{
  const std::size_t slash = relative_path.rfind ('/');
  const std::size_t dot = relative_path.rfind ('.');
  const bool in_name = dot != std::string::npos && (slash == std::string::npos || dot > slash + 1);
  return in_name ? relative_path.substr (0, dot) : relative_path;
}

Status
modelsOfQueries (const std::vector<std::string>& models, const std::vector<std::string>& queries,
                 std::vector<std::size_t>& model_of_query)
{
  model_of_query.clear ();
  std::map<std::string, std::size_t> index;
  for (std::size_t m = 0; m < models.size (); ++m)
  {
    const auto [it, added] = index.emplace (withoutExtension (models[m]), m);
    if (!added)
      return Status::error ("the models " + models[it->second] + " and " + models[m] +
                            " differ only in their extension: which one a query shows is unclear");
  }
  for (const auto& q : queries)
  {
    const auto it = index.find (withoutExtension (q));
    if (it == index.end ())
    {
      model_of_query.clear ();
      return Status::error ("the query " + q + " has no model in the database (none named " + withoutExtension (q) + ".*)");
    }
    model_of_query.push_back (it->second);
  }
  return Status::success ();
}

} // namespace pcl_flowseg

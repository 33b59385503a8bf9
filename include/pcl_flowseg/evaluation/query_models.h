/*
 * pcl_flowseg evaluation - which model of a database each query (a scan of it, say) was made from:
 * the one at the same relative path, extensions aside.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include <pcl_flowseg/common/status.h>

#include <string>
#include <vector>

namespace pcl_flowseg {

/** \brief A relative path without the extension of its file name ("chair/3.off" -> "chair/3"). */
std::string
withoutExtension (const std::string& relative_path);

/** \brief For each of \a queries (paths relative to the queries' root), the index in \a models
  * (paths relative to the database's root) of the model at the same path without extension:
  * chair/3.pcd is a view of chair/3.off. Fails naming the first query without a model, or two
  * models that differ only in their extension. */
Status
modelsOfQueries (const std::vector<std::string>& models, const std::vector<std::string>& queries,
                 std::vector<std::size_t>& model_of_query);

} // namespace pcl_flowseg

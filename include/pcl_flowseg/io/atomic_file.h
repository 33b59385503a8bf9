/*
 * pcl_flowseg - files that appear whole or not at all.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include <pcl_flowseg/common/status.h>

#include <functional>
#include <ostream>
#include <string>

namespace pcl_flowseg {

/** \brief Calls \a write with a temporary path next to \a path; when it succeeds the temporary
  * file is renamed to \a path (atomic on POSIX), otherwise it is removed. An interrupted or
  * failed write therefore never leaves a partial \a path. */
Status
writeFileAtomically (const std::string& path, const std::function<Status (const std::string& tmp)>& write);

/** \brief writeFileAtomically for text: \a write puts the content on a stream; the file appears
  * only when the stream reports no error (a full disk, say) after the last byte. */
Status
writeTextFileAtomically (const std::string& path, const std::function<void (std::ostream& out)>& write);

} // namespace pcl_flowseg

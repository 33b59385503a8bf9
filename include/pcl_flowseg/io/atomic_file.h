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

/** \brief Calls \a write with a temporary path next to \a path (unique per process and call); when
  * it succeeds the temporary file is renamed to \a path (atomic on POSIX), otherwise it is
  * removed. An interrupted or failed write therefore never leaves a partial \a path: readers see
  * the old file or the new one. With \a durable the content is flushed to the disk (fsync) before
  * the rename and the folder after it, so that a crash of the machine, not only of the process,
  * also leaves the old or the new file. */
Status
writeFileAtomically (const std::string& path, const std::function<Status (const std::string& tmp)>& write,
                     bool durable = false);

/** \brief writeFileAtomically for text: \a write puts the content on a stream; the file appears
  * only when the stream reports no error (a full disk, say) after the last byte. */
Status
writeTextFileAtomically (const std::string& path, const std::function<void (std::ostream& out)>& write);

} // namespace pcl_flowseg

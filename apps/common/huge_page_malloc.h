/*
 * pcl_flowseg apps - glibc's malloc asked to use transparent huge pages, by one re-execution.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include <string>

namespace flowseg_app {

/** \brief The glibc tunable that makes malloc advise the kernel to back its memory with
  * transparent huge pages (glibc 2.35 and later; older ones ignore it). */
constexpr const char* kHugePageTunable = "glibc.malloc.hugetlb";

/** \brief Set in the environment of the re-executed program, so that it never re-executes twice. */
constexpr const char* kRelaunchMarker = "PCL_FLOWSEG_RELAUNCHED";

/** \brief Whether to re-execute with the tunable: not when \a tunables (GLIBC_TUNABLES, or null)
  * names it already (the user's choice, say =0 to keep small pages), not when \a marker
  * (kRelaunchMarker, or null) is set, not in secure mode (\a secure: glibc then ignores
  * tunables), and only when \a thp_enabled (the text of
  * /sys/kernel/mm/transparent_hugepage/enabled) selects "[madvise]": with "[always]" malloc gets
  * huge pages anyway, with "[never]" not at all. */
bool
wantsHugePageRelaunch (const char* tunables, const char* marker, bool secure, const std::string& thp_enabled);

/** \brief GLIBC_TUNABLES \a tunables (or null) with kHugePageTunable=1 added. */
std::string
withHugePageTunable (const char* tunables);

/** \brief Call first in main (before any thread starts). Where wantsHugePageRelaunch holds,
  * re-executes this program (/proc/self/exe, same \a argv) with kHugePageTunable=1 added to
  * GLIBC_TUNABLES; it returns only when it does not, or when the execution fails (the program
  * then runs as it is). The kernel then maps large blocks of malloc's memory with one fault per
  * 2 MiB instead of one per 4 KiB page: the figures are in docs/measurements.md. */
void
relaunchWithHugePageMalloc (char** argv);

} // namespace flowseg_app

/*
 * The apps' huge-page relaunch: when it re-executes, and that this program (which relaunches itself
 * first, as the apps do) runs with glibc's huge-page tunable set.
 * A program of its own: it must call the relaunch before anything else runs.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include "common/huge_page_malloc.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>

#include <sys/auxv.h>

namespace {

using flowseg_app::kHugePageTunable;
using flowseg_app::wantsHugePageRelaunch;
using flowseg_app::withHugePageTunable;

const std::string kMadvise = "always [madvise] never\n";

TEST (HugePageRelaunch, OnlyWhenTheKernelGivesHugePagesOnRequestAndNobodyChoseAlready)
{
  EXPECT_TRUE (wantsHugePageRelaunch (nullptr, nullptr, false, kMadvise));
  EXPECT_TRUE (wantsHugePageRelaunch ("glibc.malloc.arena_max=2", "", false, kMadvise));
  EXPECT_FALSE (wantsHugePageRelaunch (nullptr, nullptr, false, "[always] madvise never\n"));
  EXPECT_FALSE (wantsHugePageRelaunch (nullptr, nullptr, false, "always madvise [never]\n"));
  EXPECT_FALSE (wantsHugePageRelaunch (nullptr, nullptr, false, "")); // no such file
  EXPECT_FALSE (wantsHugePageRelaunch ("glibc.malloc.hugetlb=0", nullptr, false, kMadvise)); // the user's choice
  EXPECT_FALSE (wantsHugePageRelaunch (nullptr, "1", false, kMadvise)); // relaunched once already
  EXPECT_FALSE (wantsHugePageRelaunch (nullptr, nullptr, true, kMadvise)); // secure mode ignores tunables
}

TEST (HugePageRelaunch, AddsTheTunableToThoseSet)
{
  EXPECT_EQ (withHugePageTunable (nullptr), std::string (kHugePageTunable) + "=1");
  EXPECT_EQ (withHugePageTunable (""), std::string (kHugePageTunable) + "=1");
  EXPECT_EQ (withHugePageTunable ("glibc.malloc.arena_max=2"), "glibc.malloc.arena_max=2:" + std::string (kHugePageTunable) + "=1");
}

TEST (HugePageRelaunch, ThisProgramRunsWithTheTunable)
{
  std::ifstream file ("/sys/kernel/mm/transparent_hugepage/enabled");
  std::ostringstream thp;
  thp << file.rdbuf ();
  if (thp.str ().find ("[madvise]") == std::string::npos || getauxval (AT_SECURE) != 0)
    GTEST_SKIP () << "transparent huge pages are not in madvise mode here: nothing to relaunch for";
  const char* tunables = std::getenv ("GLIBC_TUNABLES");
  ASSERT_NE (tunables, nullptr);
  EXPECT_NE (std::strstr (tunables, kHugePageTunable), nullptr) << tunables;
}

} // namespace

int
main (int argc, char** argv)
{
  flowseg_app::relaunchWithHugePageMalloc (argv);
  ::testing::InitGoogleTest (&argc, argv);
  return RUN_ALL_TESTS ();
}

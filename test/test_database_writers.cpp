/*
 * The signature database under concurrent writer processes and writers killed mid-write.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include <pcl_flowseg/io/file_lock.h>
#include <pcl_flowseg/signature/signature_database.h>

#include <gtest/gtest.h>

#include <chrono>
#include <csignal>
#include <cstdio>
#include <dirent.h>
#include <string>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>
#include <vector>

using namespace pcl_flowseg;

namespace {

std::string
tempPath (const std::string& name)
{
  return "/tmp/flowseg_writers_" + std::to_string (::getpid ()) + "_" + name;
}

void
removeDatabase (const std::string& path)
{
  std::remove (path.c_str ());
  std::remove ((path + ".lock").c_str ());
}

ShapeEntry
entry (const std::string& name, double x = 0.0)
{
  ShapeEntry e;
  e.name = name;
  e.label = "c";
  e.signature.points = {{Eigen::Vector3d (x, 0, 0), 0.75}, {Eigen::Vector3d (x, 1, 0), 0.25}};
  return e;
}

/** Runs \a child in a forked process, which exits with 0 when it returns true. */
pid_t
forkRunning (const std::function<bool ()>& child)
{
  const pid_t pid = ::fork ();
  if (pid == 0)
    ::_exit (child () ? 0 : 1);
  return pid;
}

int
exitCodeOf (pid_t pid)
{
  int status = 0;
  ::waitpid (pid, &status, 0);
  return WIFEXITED (status) ? WEXITSTATUS (status) : -1;
}

/** Temporary files a writer has beside \a path (in /tmp), removed when \a remove. */
std::size_t
temporariesBeside (const std::string& path, bool remove)
{
  const std::string base = path.substr (path.find_last_of ('/') + 1) + ".tmp.";
  std::size_t found = 0;
  if (DIR* d = ::opendir ("/tmp"))
  {
    while (const dirent* e = ::readdir (d))
      if (std::string (e->d_name).rfind (base, 0) == 0)
      {
        ++found;
        if (remove)
          std::remove (("/tmp/" + std::string (e->d_name)).c_str ());
      }
    ::closedir (d);
  }
  return found;
}

/** Returns once a writer of \a path has a temporary file open (it is inside a write), or after 10 s. */
void
waitUntilInsideAWrite (const std::string& path)
{
  const auto give_up = std::chrono::steady_clock::now () + std::chrono::seconds (10);
  while (temporariesBeside (path, false) == 0 && std::chrono::steady_clock::now () < give_up)
    std::this_thread::yield ();
}

} // namespace

TEST (FileLock, ExclusiveBetweenProcessesWithABoundedWait)
{
  const std::string path = tempPath ("lock.db");
  int ready[2];
  ASSERT_EQ (::pipe (ready), 0);
  const pid_t holder = forkRunning ([&] {
    FileLock lock;
    if (!lock.acquire (path, 1.0))
      return false;
    char c = 1;
    if (::write (ready[1], &c, 1) != 1)
      return false;
    std::this_thread::sleep_for (std::chrono::milliseconds (800));
    return true; // released by the destructor
  });
  char c = 0;
  ASSERT_EQ (::read (ready[0], &c, 1), 1);
  FileLock lock;
  const Status busy = lock.acquire (path, 0.1);
  EXPECT_FALSE (busy.ok);
  EXPECT_NE (busy.message.find ("held the lock"), std::string::npos) << busy.message;
  EXPECT_FALSE (lock.held ());
  const Status waited = lock.acquire (path, 30.0);
  EXPECT_TRUE (waited.ok) << waited.message;
  EXPECT_TRUE (lock.held ());
  EXPECT_EQ (exitCodeOf (holder), 0);
  lock.release ();
  EXPECT_FALSE (lock.acquire (path, -1.0).ok);
  EXPECT_FALSE (lock.acquire ("/nonexistent/folder/x.db", 0.0).ok);
  ::close (ready[0]);
  ::close (ready[1]);
  removeDatabase (path);
}

TEST (DatabaseWriters, ConcurrentProcessesLoseNoShape)
{
  const std::string path = tempPath ("concurrent.db");
  removeDatabase (path);
  SignatureDatabase first;
  first.add (entry ("first"));
  ASSERT_TRUE (first.save (path));
  constexpr int kWriters = 12, kShapesEach = 5;
  std::vector<pid_t> writers;
  for (int w = 0; w < kWriters; ++w)
    writers.push_back (forkRunning ([&, w] {
      for (int k = 0; k < kShapesEach; ++k)
      {
        const Status s = SignatureDatabase::update (path, [&] (SignatureDatabase& db) {
          db.add (entry ("w" + std::to_string (w) + "_" + std::to_string (k), w + 0.1 * k));
          return Status::success ();
        });
        if (!s)
          return false;
      }
      return true;
    }));
  for (pid_t pid : writers)
    EXPECT_EQ (exitCodeOf (pid), 0);
  SignatureDatabase db;
  ASSERT_TRUE (db.load (path));
  EXPECT_EQ (db.size (), static_cast<std::size_t> (1 + kWriters * kShapesEach));
  for (int w = 0; w < kWriters; ++w)
    for (int k = 0; k < kShapesEach; ++k)
      EXPECT_TRUE (db.contains ("w" + std::to_string (w) + "_" + std::to_string (k))) << w << " " << k;
  EXPECT_TRUE (db.contains ("first"));
  removeDatabase (path);
}

TEST (DatabaseWriters, AWriterKilledMidWriteLeavesTheLastCompleteDatabase)
{
  // A database large enough that writing it takes a while; the writer rewrites it in a loop, each
  // version one shape larger, and is killed inside a write: once it has written one version (so
  // that slow builds, e.g. with sanitizers, cannot be killed before they write at all) and a
  // temporary file shows, at a moment that moves from round to round.
  const std::string path = tempPath ("killed.db");
  removeDatabase (path);
  SignatureDatabase big;
  for (int k = 0; k < 20000; ++k)
    big.add (entry ("shape " + std::to_string (k), 0.001 * k));
  ASSERT_TRUE (big.save (path));
  std::size_t killed_mid_write = 0;
  for (int round = 0; round < 8; ++round)
  {
    int wrote_one[2];
    ASSERT_EQ (::pipe (wrote_one), 0);
    const pid_t writer = forkRunning ([&] {
      SignatureDatabase db = big;
      for (int version = 0;; ++version)
      {
        db.add (entry ("extra " + std::to_string (version)));
        if (!db.save (path))
          return false;
        const char c = 1;
        if (version == 0 && ::write (wrote_one[1], &c, 1) != 1)
          return false;
      }
    });
    ::close (wrote_one[1]); // a writer that fails closes the pipe: the read below returns 0
    char c = 0;
    const bool wrote = ::read (wrote_one[0], &c, 1) == 1;
    ::close (wrote_one[0]);
    if (wrote)
      waitUntilInsideAWrite (path);
    std::this_thread::sleep_for (std::chrono::microseconds (300 * round));
    ::kill (writer, SIGKILL);
    EXPECT_EQ (exitCodeOf (writer), -1) << "round " << round << ": the writer ended before it was killed";
    killed_mid_write += temporariesBeside (path, true) > 0;
    SignatureDatabase back;
    const Status loaded = back.load (path);
    ASSERT_TRUE (loaded.ok) << "round " << round << ": " << loaded.message;
    ASSERT_GE (back.size (), big.size ());
    for (std::size_t k = 0; k < big.size (); k += 997)
      EXPECT_TRUE (back.contains (big.entries ()[k].name));
    // Versions grow by one shape each: a complete file holds extras 0 .. n-1 and nothing else.
    const std::size_t extras = back.size () - big.size ();
    for (std::size_t v = 0; v < extras; ++v)
      EXPECT_TRUE (back.contains ("extra " + std::to_string (v))) << round;
    // The lock died with its holder: the next writer gets it at once.
    FileLock lock;
    EXPECT_TRUE (lock.acquire (path, 1.0).ok) << round;
  }
  std::printf ("%zu of 8 kills landed inside a write\n", killed_mid_write);
  EXPECT_GT (killed_mid_write, 0u) << "no kill landed inside a write: the test proved nothing";
  removeDatabase (path);
}

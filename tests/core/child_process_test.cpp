// runInChild: what the child answers comes back; its crash, abort, exception or hang ends it
// and not the caller, and says which.

#include "gdpn/core/child_process.h"

#include <gtest/gtest.h>
#include <signal.h>
#include <sys/mman.h>
#include <unistd.h>

#include <cstdlib>
#include <new>
#include <stdexcept>

namespace gdpn::core {
namespace {

TEST(ChildProcess, ItsAnswerComesBackWhole) {
  std::string out, why;
  // more than a pipe holds at once, with a zero byte inside
  const std::string big(300000, 'x');
  ASSERT_EQ(ChildEnd::done, runInChild(
      [&](std::string& o, std::string&) {
        o = big + std::string(1, '\0') + "end";
        return true;
      },
      30, 0, out, why))
      << why;
  EXPECT_EQ(out, big + std::string(1, '\0') + "end");
}

TEST(ChildProcess, ItsReasonComesBack) {
  std::string out, why;
  EXPECT_EQ(ChildEnd::failed, runInChild(
      [](std::string&, std::string& w) {
        w = "line 3: no faces";
        return false;
      },
      30, 0, out, why));
  EXPECT_EQ(why, "line 3: no faces");
  EXPECT_TRUE(out.empty());
}

TEST(ChildProcess, WhatItChangesStaysThere) {
  int value = 1;
  std::string out, why;
  ASSERT_EQ(ChildEnd::done, runInChild(
      [&](std::string& o, std::string&) {
        value = 2;
        o = std::to_string(value);
        return true;
      },
      30, 0, out, why));
  EXPECT_EQ(out, "2");
  EXPECT_EQ(value, 1);
}

TEST(ChildProcess, AnExceptionIsItsReason) {
  std::string out, why;
  EXPECT_EQ(ChildEnd::failed, runInChild([](std::string&, std::string&) -> bool { throw std::runtime_error("bad header"); }, 30, 0,
                          out, why));
  EXPECT_EQ(why, "bad header");
}

TEST(ChildProcess, ACrashEndsOnlyTheChild) {
  std::string out, why;
  EXPECT_EQ(ChildEnd::lost, runInChild(
      [](std::string&, std::string&) {
        ::raise(SIGSEGV);
        return true;
      },
      30, 0, out, why));
  EXPECT_EQ(why.rfind("crashed (signal 11", 0), 0u) << why;
}

TEST(ChildProcess, AnAbortEndsOnlyTheChild) {
  std::string out, why;
  EXPECT_EQ(ChildEnd::lost, runInChild(
      [](std::string&, std::string&) -> bool { std::abort(); }, 30, 0, out, why));
  EXPECT_EQ(why.rfind("crashed (signal 6", 0), 0u) << why;
}

TEST(ChildProcess, AnExitWithoutAnAnswerIsALoss) {
  std::string out, why;
  EXPECT_EQ(ChildEnd::lost, runInChild([](std::string&, std::string&) -> bool { ::_exit(3); }, 30, 0, out, why));
  EXPECT_EQ(why, "stopped with exit status 3");
}

TEST(ChildProcess, AnAllocationPastTheCapFails) {
  if (!childMemoryCapped()) GTEST_SKIP() << "sanitizer builds cap no memory";
  std::string out, why;
  ASSERT_EQ(ChildEnd::done, runInChild(
      [](std::string& o, std::string&) {
        try {
          // 2 GiB under a 1 GiB cap (a direct call, which no compiler may leave out)
          void* big = ::operator new(std::size_t{1} << 31);
          ::operator delete(big);
          o = "allocated";
        } catch (const std::bad_alloc&) {
          o = "refused";
        }
        return true;
      },
      30, std::size_t{1} << 30, out, why))
      << why;
  EXPECT_EQ(out, "refused");
}

TEST(ChildProcess, TheCapCountsFromWhatAProcessAlreadyMaps) {
  if (!childMemoryCapped()) GTEST_SKIP() << "sanitizer builds cap no memory";
  // a large process (an IDE with a software renderer maps gigabytes): 3 GiB reserved here
  const std::size_t reserved = std::size_t{3} << 30;
  void* big = ::mmap(nullptr, reserved, PROT_NONE, MAP_PRIVATE | MAP_ANONYMOUS | MAP_NORESERVE, -1, 0);
  ASSERT_NE(big, MAP_FAILED);
  std::string out, why;
  const auto end = runInChild(
      [](std::string& o, std::string&) {
        void* half = ::operator new(std::size_t{512} << 20);  // within a 1 GiB cap
        ::operator delete(half);
        o = "allocated";
        return true;
      },
      30, std::size_t{1} << 30, out, why);
  ::munmap(big, reserved);
  ASSERT_EQ(end, ChildEnd::done) << why;
  EXPECT_EQ(out, "allocated");
}

TEST(ChildProcess, AHangIsKilledAtTheTimeLimit) {
  std::string out, why;
  EXPECT_EQ(ChildEnd::lost, runInChild(
      [](std::string&, std::string&) {
        for (;;) ::pause();
        return true;
      },
      0.2, 0, out, why));
  EXPECT_EQ(why, "took longer than 0.2 s");
}

}  // namespace
}  // namespace gdpn::core

// Reading input files: only regular files, never more than maxInputBytes(); /dev/zero, a FIFO,
// a folder or a sparse gigabyte is refused at once, naming the path and what it is.

#include "gdpn/core/file.h"

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <filesystem>

#include "support/temp_files.h"

namespace gdpn::core {
namespace {

namespace fs = std::filesystem;

/// Reads `path` expecting a refusal within a few seconds; the one diagnostic as printed.
std::string refusal(const std::string& path) {
  Diagnostics diags;
  EXPECT_LT(testing::secondsFor([&] { EXPECT_FALSE(readFile(path, diags)) << path; }), 5.0) << path;
  EXPECT_EQ(diags.errorCount(), 1u) << diags.str();
  return diags.str();
}

class FileRead : public testing::TempDirTest {};

TEST_F(FileRead, ARegularFileIsReadWhole) {
  Diagnostics diags;
  const std::string bytes("a\0b\nc", 5);
  EXPECT_EQ(readFile(write("x.txt", bytes), diags), bytes);
  EXPECT_FALSE(diags.hasErrors());
}

TEST_F(FileRead, WhatIsNotARegularFileIsRefusedAtOnce) {
  EXPECT_EQ(refusal("/dev/zero"), "/dev/zero: error: is a character device, not a regular file\n");
  const auto fifo = (dir_ / "pipe").string();
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  // nobody writes to it: opening must not wait for a writer
  EXPECT_EQ(refusal(fifo), fifo + ": error: is a FIFO, not a regular file\n");
  EXPECT_EQ(refusal(dir_.string()), dir_.string() + ": error: is a folder, not a file\n");
  EXPECT_EQ(refusal((dir_ / "none").string()), (dir_ / "none").string() + ": error: cannot read the file\n");
}

TEST_F(FileRead, AFileOverTheLimitIsRefusedNamingTheLimit) {
  // a gigabyte, sparse on disk
  const auto big = write("big", "");
  fs::resize_file(big, std::uintmax_t{1} << 30);
  EXPECT_EQ(refusal(big), big + ": error: the file is 1024 MiB; gdpn reads input files of at most 256 MiB\n");
  // a lowered limit, as the fuzzers and tests set it; exactly at the limit still reads
  InputLimit limit(100);
  EXPECT_EQ(maxInputBytes(), 100u);
  const auto over = write("over", std::string(101, 'x'));
  EXPECT_EQ(refusal(over), over + ": error: the file is 101 bytes; gdpn reads input files of at most 100 bytes\n");
  Diagnostics diags;
  EXPECT_TRUE(readFile(write("at", std::string(100, 'x')), diags)) << diags.str();
}

TEST(InputLimitTest, PutsTheLimitBefore) {
  const auto before = maxInputBytes();
  {
    InputLimit limit(5);
    EXPECT_EQ(maxInputBytes(), 5u);
  }
  EXPECT_EQ(maxInputBytes(), before);
  EXPECT_EQ(before, std::uintmax_t{256} << 20);
}

}  // namespace
}  // namespace gdpn::core

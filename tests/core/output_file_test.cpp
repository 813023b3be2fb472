#include "gdpn/core/output_file.h"

#include <gtest/gtest.h>
#include <sys/resource.h>

#include <csignal>
#include <filesystem>
#include <fstream>

#include "support/scratch.h"

namespace gdpn::core {
namespace {

namespace fs = std::filesystem;

using gdpn::testing::fileBytes;
using Folder = gdpn::testing::ScratchFolder;

/// A folder holding out.txt ("old"), and an output for it with `text` written, not committed.
struct Started {
  Folder folder;
  std::string path = folder.file("out.txt");
  OutputFile out{path};
  Started(const std::string& name, const std::string& text) : folder(name) {
    std::ofstream(path) << "old";
    std::string why;
    EXPECT_TRUE(out.open(why)) << why;
    out.stream() << text;
  }
};

TEST(OutputFile, ACommittedFileReplacesTheOldOneAndLeavesNoTemporary) {
  Started s("gdpn_output_commit", "new text");
  EXPECT_EQ(fileBytes(s.path), "old");  // nothing replaced before the commit
  EXPECT_EQ(fs::path(s.out.tempPath()).parent_path(), s.folder.dir());
  EXPECT_TRUE(fs::path(s.out.tempPath()).filename().string().starts_with(".out.txt.tmp-"));
  std::string why;
  ASSERT_TRUE(s.out.commit(why)) << why;
  EXPECT_EQ(fileBytes(s.path), "new text");
  EXPECT_EQ(s.folder.names().size(), 1u);
}

TEST(OutputFile, AFileNotCommittedLeavesTheOldOneByteForByte) {
  Started s("gdpn_output_abandon", "half of it");
  {
    OutputFile other(s.path);
    std::string why;
    ASSERT_TRUE(other.open(why)) << why;
  }  // dies uncommitted: its temporary file goes with it
  EXPECT_EQ(s.folder.names().size(), 2u);  // out.txt and the temporary file of s.out
  s.out.discard();
  EXPECT_EQ(fileBytes(s.path), "old");
  EXPECT_EQ(s.folder.names(), std::vector<std::string>{"out.txt"});
}

TEST(OutputFile, AWriteThatHitsTheFileSizeLimitFailsAndKeepsTheOldFile) {
  // a limit on file size stands for a full disk: the write fails with EFBIG
  Folder folder("gdpn_output_full");
  const auto path = folder.file("out.txt");
  std::ofstream(path) << "old";
  rlimit old_limit{};
  ASSERT_EQ(getrlimit(RLIMIT_FSIZE, &old_limit), 0);
  const auto old_handler = std::signal(SIGXFSZ, SIG_IGN);
  rlimit limit = old_limit;
  limit.rlim_cur = 1000;
  ASSERT_EQ(setrlimit(RLIMIT_FSIZE, &limit), 0);
  std::string why;
  const bool ok = writeOutput(path, std::string(100'000, 'x'), why);
  setrlimit(RLIMIT_FSIZE, &old_limit);
  std::signal(SIGXFSZ, old_handler);
  EXPECT_FALSE(ok);
  EXPECT_NE(why.find("cannot write the file"), std::string::npos) << why;
  EXPECT_EQ(fileBytes(path), "old");
  EXPECT_EQ(folder.names().size(), 1u);
}

TEST(OutputFile, AFullDeviceIsReportedAsAFailedWrite) {
  std::string why;
  EXPECT_FALSE(writeOutput("/dev/full", std::string(100'000, 'x'), why));
  EXPECT_NE(why.find("cannot write the file"), std::string::npos) << why;
}

TEST(OutputFile, AMissingFolderOrAFolderTargetIsRefused) {
  Folder folder("gdpn_output_folders");
  std::string why;
  EXPECT_FALSE(writeOutput(folder.file("no/such/out.txt"), "x", why));
  EXPECT_NE(why.find("cannot create a file in the folder"), std::string::npos) << why;
  EXPECT_FALSE(writeOutput(folder.dir().string(), "x", why));
  EXPECT_EQ(why, "is a folder, not a file");
}

TEST(OutputFile, ANewFileTakesTheOldFilesPermissions) {
  Folder folder("gdpn_output_mode");
  const auto path = folder.file("out.sh");
  std::ofstream(path) << "old";
  fs::permissions(path, fs::perms::owner_all);
  std::string why;
  ASSERT_TRUE(writeOutput(path, "new", why)) << why;
  EXPECT_EQ(fs::status(path).permissions() & fs::perms::all, fs::perms::owner_all);
}

TEST(OutputFile, ALinkKeepsPointingAtTheReplacedFile) {
  Folder folder("gdpn_output_link");
  const auto real = folder.file("real.txt");
  const auto link = folder.file("link.txt");
  std::ofstream(real) << "old";
  fs::create_symlink(real, link);
  std::string why;
  ASSERT_TRUE(writeOutput(link, "new", why)) << why;
  EXPECT_TRUE(fs::is_symlink(link));
  EXPECT_EQ(fileBytes(real), "new");
}

TEST(OutputFile, SameFileSeesThroughDotsAndLinks) {
  Folder folder("gdpn_output_same");
  const auto path = folder.file("a.txt");
  std::ofstream(path) << "a";
  fs::create_symlink(path, folder.file("b.txt"));
  EXPECT_TRUE(sameFile(path, (folder.dir() / "." / "a.txt").string()));
  EXPECT_TRUE(sameFile(path, folder.file("b.txt")));
  EXPECT_FALSE(sameFile(path, folder.file("missing.txt")));
  EXPECT_TRUE(sameFile(folder.file("new.txt"), (folder.dir() / "x" / ".." / "new.txt").string()));
}

}  // namespace
}  // namespace gdpn::core

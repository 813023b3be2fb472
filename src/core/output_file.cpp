#include "gdpn/core/output_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <random>

namespace gdpn::core {
namespace {

namespace fs = std::filesystem;

std::string errnoText(int error) { return std::strerror(error); }

/// Six letters or digits, different in each call and each process.
std::string randomSuffix() {
  static constexpr char kAlphabet[] = "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789";
  static thread_local std::mt19937_64 random{std::random_device{}() ^ static_cast<std::uint64_t>(::getpid())};
  std::string s(6, 'x');
  for (auto& c : s) c = kAlphabet[random() % (sizeof kAlphabet - 1)];
  return s;
}

/// Flushes `path` (a file or a folder) to disk; best effort.
void syncPath(const std::string& path) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return;
  ::fsync(fd);
  ::close(fd);
}

}  // namespace

OutputFile::OutputFile(std::string path) : path_(std::move(path)) {}

OutputFile::~OutputFile() { discard(); }

bool OutputFile::open(std::string& why) {
  std::error_code ec;
  const auto status = fs::status(path_, ec);  // of what a link names
  if (fs::is_directory(status)) {
    why = "is a folder, not a file";
    return false;
  }
  // a device or a pipe cannot be renamed over: it is written directly
  if (fs::exists(status) && !fs::is_regular_file(status)) {
    direct_ = true;
    temp_ = path_;
    stream_.open(temp_, std::ios::binary | std::ios::trunc);
    if (!stream_) why = "cannot write the file: " + errnoText(errno);
    return static_cast<bool>(stream_);
  }
  // a link is followed: the file it names is replaced, the link stays
  fs::path target = path_;
  if (fs::is_symlink(target, ec) && fs::exists(status)) {
    if (auto real = fs::canonical(target, ec); !ec) target = real;
  }
  if (target.filename().empty()) {
    why = "is not a file name";
    return false;
  }
  const fs::path dir = target.has_parent_path() ? target.parent_path() : fs::path(".");
  for (int attempt = 0; attempt < 100; ++attempt) {
    const std::string temp = (dir / ("." + target.filename().string() + ".tmp-" + randomSuffix())).string();
    const int fd = ::open(temp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd < 0 && errno == EEXIST) continue;
    if (fd < 0) {
      why = "cannot create a file in the folder '" + dir.string() + "': " + errnoText(errno);
      return false;
    }
    // the new file keeps the old one's permissions
    struct stat old {};
    if (::stat(target.c_str(), &old) == 0) ::fchmod(fd, old.st_mode & 07777);
    ::close(fd);
    temp_ = temp;
    pending_ = true;
    stream_.open(temp_, std::ios::binary | std::ios::trunc);
    if (!stream_) {
      why = "cannot write the file: " + errnoText(errno);
      discard();
      return false;
    }
    path_ = target.string();
    return true;
  }
  why = "cannot find a free temporary name in '" + dir.string() + "'";
  return false;
}

void OutputFile::closeStream() {
  if (stream_.is_open()) stream_.close();
}

bool OutputFile::commit(std::string& why) {
  // every byte out: a full disk shows here, at the latest when the buffer is flushed
  bool written = true;
  if (stream_.is_open()) {
    written = static_cast<bool>(stream_.flush());
    stream_.close();
    written = written && !stream_.fail();
  }
  if (!written) {
    // the stream keeps no error code: name the cause when errno holds a write error
    const int error = errno;
    const bool known = error == ENOSPC || error == EFBIG || error == EDQUOT || error == EIO || error == EPIPE;
    why = "cannot write the file" + (known ? ": " + errnoText(error) : std::string());
    discard();
    return false;
  }
  if (direct_) return true;
  std::error_code ec;
  if (!pending_ || !fs::is_regular_file(temp_, ec)) {
    why = "the written file is missing";
    discard();
    return false;
  }
  // on disk before it replaces the old file, and the folder's entry on disk after
  syncPath(temp_);
  if (::rename(temp_.c_str(), path_.c_str()) != 0) {
    why = "cannot replace the file: " + errnoText(errno);
    discard();
    return false;
  }
  pending_ = false;
  const fs::path target = path_;
  syncPath(target.has_parent_path() ? target.parent_path().string() : ".");
  return true;
}

void OutputFile::discard() {
  if (stream_.is_open()) stream_.close();
  if (!pending_) return;
  std::error_code ec;
  fs::remove(temp_, ec);
  pending_ = false;
}

bool writeOutput(const std::string& path, const std::string& text, std::string& why) {
  return writeOutput(path, [&text](std::ostream& out) { out << text; }, why);
}

bool writeOutput(const std::string& path, const std::function<void(std::ostream&)>& write, std::string& why) {
  OutputFile out(path);
  if (!out.open(why)) return false;
  write(out.stream());
  return out.commit(why);
}

bool sameFile(const std::string& a, const std::string& b) {
  std::error_code ec;
  if (fs::equivalent(a, b, ec) && !ec) return true;
  std::error_code ec_a, ec_b;
  const auto path_a = fs::weakly_canonical(fs::absolute(a), ec_a);
  const auto path_b = fs::weakly_canonical(fs::absolute(b), ec_b);
  return !ec_a && !ec_b && path_a == path_b;
}

}  // namespace gdpn::core

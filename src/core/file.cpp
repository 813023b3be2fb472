#include "gdpn/core/file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <cerrno>
#include <cstdio>

#include "gdpn/core/text.h"

namespace gdpn::core {

namespace {

std::atomic<std::uintmax_t> g_max_input_bytes{256ull << 20};

/// `bytes` for people: "300 MiB", "12 KiB" or "17 bytes".
std::string sizeText(std::uintmax_t bytes) {
  if (bytes >= (1ull << 20) && bytes % (1ull << 20) == 0) return std::to_string(bytes >> 20) + " MiB";
  if (bytes >= (1ull << 10) && bytes % (1ull << 10) == 0) return std::to_string(bytes >> 10) + " KiB";
  return std::to_string(bytes) + " bytes";
}

/// What a stat mode names when it is not a regular file.
const char* kindOf(mode_t mode) {
  if (S_ISDIR(mode)) return "is a folder, not a file";
  if (S_ISFIFO(mode)) return "is a FIFO, not a regular file";
  if (S_ISCHR(mode)) return "is a character device, not a regular file";
  if (S_ISBLK(mode)) return "is a block device, not a regular file";
  if (S_ISSOCK(mode)) return "is a socket, not a regular file";
  return "is not a regular file";
}

/// The size of the open file `fd` when it is a regular file within the limit; else `why`.
std::optional<std::uintmax_t> checkedSize(int fd, std::string& why) {
  struct stat st {};
  if (::fstat(fd, &st) != 0) {
    why = "cannot read the file";
    return std::nullopt;
  }
  if (!S_ISREG(st.st_mode)) {
    why = kindOf(st.st_mode);
    return std::nullopt;
  }
  const auto size = static_cast<std::uintmax_t>(st.st_size);
  const auto limit = maxInputBytes();
  if (size > limit) {
    why = "the file is " + sizeText(size) + "; gdpn reads input files of at most " + sizeText(limit);
    return std::nullopt;
  }
  return size;
}

/// A file descriptor closed when it goes.
struct Fd {
  int fd = -1;
  explicit Fd(const std::string& path) : fd(::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC)) {}
  Fd(const Fd&) = delete;
  Fd& operator=(const Fd&) = delete;
  ~Fd() {
    if (fd >= 0) ::close(fd);
  }
};

/// Why opening failed, from errno.
std::string openError(int error) {
  if (error == ENOENT || error == ENOTDIR) return "no such file";
  if (error == EACCES || error == EPERM) return "permission denied";
  return "cannot read the file";
}

}  // namespace

std::uintmax_t maxInputBytes() { return g_max_input_bytes.load(); }

std::uintmax_t setMaxInputBytes(std::uintmax_t bytes) { return g_max_input_bytes.exchange(bytes); }

std::optional<std::uintmax_t> inputFileSize(const std::string& path, std::string& why) {
  // opened without blocking, so that a FIFO with no writer is refused rather than waited on
  Fd file(path);
  if (file.fd < 0) {
    why = openError(errno);
    return std::nullopt;
  }
  return checkedSize(file.fd, why);
}

std::optional<std::string> readFile(const std::string& path, Diagnostics& diags) {
  std::string why;
  Fd file(path);
  if (file.fd < 0) why = "cannot read the file";
  const auto size = file.fd < 0 ? std::nullopt : checkedSize(file.fd, why);
  if (!size) {
    diags.error({path, 0, 0}, why);
    return std::nullopt;
  }
  // read no more than the limit even when the file grows meanwhile
  const auto limit = maxInputBytes();
  std::string text;
  text.reserve(static_cast<std::size_t>(*size));
  std::array<char, 65536> chunk{};
  for (;;) {
    const ssize_t n = ::read(file.fd, chunk.data(), chunk.size());
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) {
      diags.error({path, 0, 0}, "cannot read the file");
      return std::nullopt;
    }
    if (n == 0) break;
    if (text.size() + static_cast<std::size_t>(n) > limit) {
      diags.error({path, 0, 0}, "the file grew past " + sizeText(limit) + ", the most gdpn reads");
      return std::nullopt;
    }
    text.append(chunk.data(), static_cast<std::size_t>(n));
  }
  return text;
}

bool checkUtf8(const std::string& text, const std::string& file, Diagnostics& diags) {
  // YAML and XML both allow no C0 control character but tab, line feed and carriage return
  for (std::size_t i = 0; i < text.size(); ++i) {
    const auto c = static_cast<unsigned char>(text[i]);
    if ((c < 0x20 && c != '\t' && c != '\n' && c != '\r') || c == 0x7f) {
      const auto [line, column] = lineColumn(text, i);
      char code[8];
      std::snprintf(code, sizeof code, "%04X", c);
      diags.error({file, line, column}, std::string("control character U+") + code + " is not allowed in the file");
      return false;
    }
  }
  const auto bad = firstInvalidUtf8(text);
  if (bad == std::string::npos) return true;
  const auto [line, column] = lineColumn(text, bad);
  diags.error({file, line, column}, "the file is not valid UTF-8 text here");
  return false;
}

}  // namespace gdpn::core

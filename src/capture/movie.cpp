#include "gdpn/capture/movie.h"

#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace gdpn::capture {

namespace {

std::string quote(const std::string& s) {
  std::string out = "'";
  for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

}  // namespace

MovieWriter::~MovieWriter() { cancel(); }

void MovieWriter::cancel() {
  if (pipe_ != nullptr) ::pclose(pipe_);
  pipe_ = nullptr;
  out_.reset();  // removes the temporary file
  restoreSigpipe();
}

void MovieWriter::restoreSigpipe() {
  if (sigpipe_ignored_) std::signal(SIGPIPE, previous_sigpipe_);
  sigpipe_ignored_ = false;
}

bool MovieWriter::open(const std::string& path, int width, int height, double fps, std::string& why) {
  if (width <= 0 || height <= 0 || width % 2 != 0 || height % 2 != 0) {
    why = "a movie needs an even width and height";
    return false;
  }
  // ffmpeg writes a temporary file beside the movie, renamed over it once ffmpeg succeeded
  out_ = std::make_unique<core::OutputFile>(path);
  if (!out_->open(why)) return false;
  out_->closeStream();
  log_ = (std::filesystem::temp_directory_path() / ("gdpn-ffmpeg-" + std::to_string(::getpid()) + ".log")).string();
  std::ostringstream cmd;
  // -xerror: a write that fails (a full disk, a file size limit) ends ffmpeg with a failure;
  // without it ffmpeg logs "Error writing trailer" and exits 0, the movie cut short
  cmd << "ffmpeg -hide_banner -loglevel error -xerror -y -f rawvideo -pix_fmt rgb24 -s " << width << "x" << height
      << " -r " << fps << " -i - -c:v libx264 -preset veryfast -pix_fmt yuv420p -movflags +faststart -f mp4 "
      << quote(out_->tempPath())
      << " 2> " << quote(log_);
  // an encoder that dies makes a write fail, not a SIGPIPE that kills gdpn with the file half made
  if (!sigpipe_ignored_) previous_sigpipe_ = std::signal(SIGPIPE, SIG_IGN);
  sigpipe_ignored_ = true;
  pipe_ = ::popen(cmd.str().c_str(), "w");
  if (pipe_ == nullptr) {
    why = "cannot start ffmpeg";
    cancel();
    return false;
  }
  frame_bytes_ = static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 3;
  frames_ = 0;
  return true;
}

bool MovieWriter::write(const std::vector<std::uint8_t>& rgb) {
  if (pipe_ == nullptr || rgb.size() != frame_bytes_) return false;
  if (std::fwrite(rgb.data(), 1, rgb.size(), pipe_) != rgb.size()) return false;
  ++frames_;
  return true;
}

bool MovieWriter::close(std::string& why, bool keep) {
  if (pipe_ == nullptr) return true;
  // the last frames still buffered go to ffmpeg now: a failure here is a movie cut short
  const bool flushed = std::fflush(pipe_) == 0;
  const int status = ::pclose(pipe_);
  pipe_ = nullptr;
  restoreSigpipe();
  std::ifstream log(log_);
  std::string last, line;
  while (std::getline(log, line)) {
    if (!line.empty()) last = line;
  }
  std::error_code ec;
  std::filesystem::remove(log_, ec);
  auto out = std::move(out_);
  // the temporary file goes with `out` on every failure: the old movie stays
  if (status == -1 || !WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    why = WIFSIGNALED(status) ? "ffmpeg was killed by signal " + std::to_string(WTERMSIG(status))
                              : "ffmpeg failed" + (last.empty() ? std::string() : ": " + last);
    return false;
  }
  // ffmpeg logs errors only (-loglevel error): one it survived still spoils the movie
  if (!last.empty()) {
    why = "ffmpeg failed: " + last;
    return false;
  }
  if (!flushed) {
    why = "ffmpeg did not take every frame";
    return false;
  }
  if (!keep) return true;
  std::error_code size_ec;
  if (!out->direct() && std::filesystem::file_size(out->tempPath(), size_ec) == 0) {
    why = "ffmpeg wrote an empty movie";
    return false;
  }
  return out->commit(why);
}

}  // namespace gdpn::capture

#include "gdpn/capture/movie.h"

#include <sys/wait.h>
#include <unistd.h>

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

MovieWriter::~MovieWriter() {
  std::string why;
  if (pipe_ != nullptr) close(why);
}

bool MovieWriter::open(const std::string& path, int width, int height, double fps, std::string& why) {
  if (width <= 0 || height <= 0 || width % 2 != 0 || height % 2 != 0) {
    why = "a movie needs an even width and height";
    return false;
  }
  log_ = (std::filesystem::temp_directory_path() / ("gdpn-ffmpeg-" + std::to_string(::getpid()) + ".log")).string();
  std::ostringstream cmd;
  cmd << "ffmpeg -hide_banner -loglevel error -y -f rawvideo -pix_fmt rgb24 -s " << width << "x" << height
      << " -r " << fps << " -i - -c:v libx264 -preset veryfast -pix_fmt yuv420p -movflags +faststart " << quote(path)
      << " 2> " << quote(log_);
  pipe_ = ::popen(cmd.str().c_str(), "w");
  if (pipe_ == nullptr) {
    why = "cannot start ffmpeg";
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

bool MovieWriter::close(std::string& why) {
  if (pipe_ == nullptr) return true;
  const int status = ::pclose(pipe_);
  pipe_ = nullptr;
  std::ifstream log(log_);
  std::string last, line;
  while (std::getline(log, line)) {
    if (!line.empty()) last = line;
  }
  std::error_code ec;
  std::filesystem::remove(log_, ec);
  if (status == -1 || !WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    why = "ffmpeg failed" + (last.empty() ? std::string() : ": " + last);
    return false;
  }
  return true;
}

}  // namespace gdpn::capture

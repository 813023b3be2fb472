#pragma once
/// \file
/// Movies: RGB frames piped into ffmpeg, which encodes H.264 in an MP4 file.

#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

namespace gdpn::capture {

/// Writes frames of one size into a movie through an ffmpeg process.
class MovieWriter {
 public:
  MovieWriter() = default;
  ~MovieWriter();
  MovieWriter(const MovieWriter&) = delete;
  MovieWriter& operator=(const MovieWriter&) = delete;
  /// Starts ffmpeg writing `path` (`width` x `height` pixels, even numbers, at `fps` frames
  /// per second). False with `why` when ffmpeg cannot start.
  bool open(const std::string& path, int width, int height, double fps, std::string& why);
  /// Adds one frame: RGB, top row first, width * height * 3 bytes. False when ffmpeg stopped.
  bool write(const std::vector<std::uint8_t>& rgb);
  /// Finishes the file. False with `why` when ffmpeg failed (its last words in `why`).
  bool close(std::string& why);
  /// Frames written so far.
  [[nodiscard]] std::int64_t frames() const { return frames_; }

 private:
  std::FILE* pipe_ = nullptr;
  std::string log_;
  std::int64_t frames_ = 0;
  std::size_t frame_bytes_ = 0;
};

}  // namespace gdpn::capture

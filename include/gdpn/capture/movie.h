#pragma once
/// \file
/// Movies: RGB frames piped into ffmpeg, which encodes H.264 in an MP4 file.

#include <cstdint>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "gdpn/core/output_file.h"

namespace gdpn::capture {

/// Writes frames of one size into a movie through an ffmpeg process.
class MovieWriter {
 public:
  MovieWriter() = default;
  ~MovieWriter();
  MovieWriter(const MovieWriter&) = delete;
  MovieWriter& operator=(const MovieWriter&) = delete;
  /// Starts ffmpeg writing a temporary file beside `path` (`width` x `height` pixels, even
  /// numbers, at `fps` frames per second). False with `why` when ffmpeg cannot start.
  bool open(const std::string& path, int width, int height, double fps, std::string& why);
  /// Adds one frame: RGB, top row first, width * height * 3 bytes. False when ffmpeg stopped.
  bool write(const std::vector<std::uint8_t>& rgb);
  /// Finishes the file and renames it over `path` (with `keep`; without, the movie is thrown
  /// away). False with `why` when ffmpeg failed or was killed (its last words in `why`); the
  /// old file at `path` is then unchanged and the temporary file removed.
  bool close(std::string& why, bool keep = true);
  /// Stops ffmpeg and removes its temporary file; the old file at `path` is unchanged (also
  /// what the destructor does to a movie not closed).
  void cancel();
  /// Frames written so far.
  [[nodiscard]] std::int64_t frames() const { return frames_; }

 private:
  void restoreSigpipe();

  std::FILE* pipe_ = nullptr;
  void (*previous_sigpipe_)(int) = nullptr;  // the SIGPIPE handler while ffmpeg runs
  bool sigpipe_ignored_ = false;
  std::unique_ptr<core::OutputFile> out_;
  std::string log_;
  std::int64_t frames_ = 0;
  std::size_t frame_bytes_ = 0;
};

}  // namespace gdpn::capture

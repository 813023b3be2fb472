#pragma once
/// \file
/// Pictures and movies of a running model, headless: `gdpn render` and `gdpn record`.

#include <atomic>
#include <cstdint>
#include <optional>
#include <string>

#include "gdpn/model/simulation.h"

namespace gdpn::capture {

/// How pictures are taken.
struct CaptureOptions {
  int width = 1280;         ///< pixels
  int height = 720;         ///< pixels
  int samples = 4;          ///< samples per pixel (anti-aliasing); 1 for none
  std::string camera;       ///< path of the Camera node ("" : the scene's first, or a framing view)
  bool sensors = false;     ///< draw sensor overlays
  bool joints = false;      ///< draw joint axes
  bool shadows = true;      ///< the first directional light casts shadows
  bool ground = true;       ///< the sky down to the horizon and the ground grid
  double fps = 30.0;        ///< movie frames per second
};

/// Smallest width or height of a picture or movie, pixels.
inline constexpr int kMinSide = 16;
/// Largest width or height of a picture or movie, pixels.
inline constexpr int kMaxSide = 16384;

/// "1280x720" as width and height in pixels; nullopt when it is not two whole numbers from
/// kMinSide to kMaxSide around an 'x'.
std::optional<std::pair<int, int>> parseSize(const std::string& text);

/// The width and height in pixels of the ColorCamera or DepthCamera at `camera` in `scene`:
/// the size a picture from it takes unless one is asked for; nullopt when `camera` names no
/// camera sensor.
std::optional<std::pair<int, int>> cameraSensorSize(const scene::Scene& scene, const std::string& camera);

/// What a recording made.
struct RecordResult {
  std::int64_t frames = 0;          ///< frames written
  std::size_t triangles = 0;        ///< triangles drawn in the last frame
  model::RunOutcome outcome;        ///< how the run ended
};

/// Runs `sim` to `at` seconds and writes the picture to `png`. False with `error` on failure.
bool renderAt(model::Simulation& sim, double at, const CaptureOptions& options, const std::string& png,
              std::string& error);

/// What `gdpn render --net` draws.
struct NetPictureOptions {
  std::string page;          ///< the page, page type or instance path ("line/cellA"); "" the first page
  std::optional<double> at;  ///< model time, seconds; none: the initial marking, before time 0 fires
  int width = 0;             ///< pixels; 0 (with height 0): a size that fits the page
  int height = 0;            ///< pixels
};

/// Runs `sim` to `options.at` (when given) and writes a picture of the net of one page with
/// its marking to `out` (.svg or .png). False with `error` on failure; an unknown page's
/// error lists the pages. Warnings (a page too large for Graphviz) go to `warnings`.
bool renderNetAt(model::Simulation& sim, const NetPictureOptions& options, const std::string& out,
                 core::Diagnostics& warnings, std::string& error);

/// Runs `sim` to `until` seconds at its own dt, taking a frame each 1/fps seconds of model
/// time (the first at 0), and encodes them into `movie` through ffmpeg. False with `error` on
/// failure (the run's own outcome is in `result`).
bool record(model::Simulation& sim, double until, const CaptureOptions& options, const std::string& movie,
            const model::ProgressFn& progress, const std::atomic<bool>* interrupt, RecordResult& result,
            std::string& error);

}  // namespace gdpn::capture

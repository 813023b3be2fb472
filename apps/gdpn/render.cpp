// `gdpn render` (a picture of the plant, or with --net of the net) and `gdpn record` (a movie
// of the plant).

#include <unistd.h>

#include <csignal>
#include <iostream>
#include <tuple>

#include "cli_checks.h"
#include "commands.h"
#include "gdpn/capture/capture.h"
#include "gdpn/model/simulation.h"

namespace gdpn::app {

namespace {

namespace model = gdpn::model;
using gdpn::core::Diagnostics;

/// `gdpn render`'s and `gdpn record`'s arguments.
struct CaptureArgs {
  std::string model;
  std::string out;
  std::string size = "1280x720";
  double at = 0.0;
  double until = 10.0;
  std::optional<std::uint64_t> seed;
  gdpn::capture::CaptureOptions options;
  bool net = false;         // render --net: the net of a page rather than the plant
  std::string page;         // render --net --page
  bool at_given = false;    // --at was on the command line
  bool size_given = false;  // --size was on the command line
  bool quiet = false;       // no sim.log lines, no progress
  std::vector<std::string> params;  // --param NAME=VALUE
  gdpn::script::ScriptLimits limits;  // --script-timeout, --script-memory
};

/// `gdpn render --net`: the net of one page with its marking at --at (the initial marking
/// without it), as SVG or PNG.
int renderNet(const CaptureArgs& a) {
  gdpn::capture::NetPictureOptions o;
  o.page = a.page;
  if (a.at_given) o.at = a.at;
  if (a.size_given) {
    const auto size = sizeArg(a.size);
    if (!size) return 2;
    o.width = size->first;
    o.height = size->second;
  }
  if (!a.out.ends_with(".svg") && !a.out.ends_with(".png")) {
    std::cerr << "error: -o " << quoteArg(a.out) << ": a net picture is written as .svg or .png\n";
    return 2;
  }
  if (overwritesInput("-o", a.out, {{"the model file", modelFile(a.model)}})) return 2;
  auto session = open(a.model, a.seed, a.limits, a.params, session::RunRequest{.report = false, .echo_log = !a.quiet});
  if (!session) return 1;
  std::string error;
  Diagnostics warnings;
  const bool ok = gdpn::capture::renderNetAt(session->simulation(), o, a.out, warnings, error);
  warnings.print(std::cerr);
  if (!ok) {
    std::cerr << (error.starts_with("--page") || error.find(": error: ") != std::string::npos ? "error: " : a.out + ": error: ")
              << error << (error.ends_with('\n') ? "" : "\n");
    return 1;
  }
  std::cout << a.out << ": the net of " << (a.page.empty() ? "the first page" : "'" + a.page + "'") << " at t = "
            << session->simulation().kernel().now() << " s\n";
  return 0;
}

/// The size of a movie is even on each side (ffmpeg's yuv420p); otherwise says so. `source`
/// says where the size came from.
bool evenSize(const gdpn::capture::CaptureOptions& o, const std::string& source) {
  if (o.width % 2 == 0 && o.height % 2 == 0) return true;
  std::cerr << "error: a movie needs an even width and height, not " << o.width << "x" << o.height << " (" << source
            << ")\n";
  return false;
}

/// `gdpn render` (movie = false) and `gdpn record` (movie = true). Without --size, a picture
/// from a camera sensor takes the camera's own width and height, any other 1280x720.
int capture(CaptureArgs a, bool movie) {
  const auto size = sizeArg(a.size);
  if (!size) {
    return 2;
  }
  a.options.width = size->first;
  a.options.height = size->second;
  if (movie && a.size_given && !evenSize(a.options, "--size " + quoteArg(a.size))) return 2;
  if (overwritesInput("-o", a.out, {{"the model file", modelFile(a.model)}})) return 2;
  if (!movie && !a.out.ends_with(".png")) {
    std::cerr << "error: -o " << quoteArg(a.out) << ": a picture of the plant is written as .png (PNG data in a file "
              << "named otherwise would mislead)\n";
    return 2;
  }
  auto session = open(a.model, a.seed, a.limits, a.params, session::RunRequest{.report = false, .echo_log = !a.quiet});
  if (!session) return 1;
  if (const auto* plant = session->simulation().plant(); plant != nullptr && !a.size_given) {
    if (const auto own = gdpn::capture::cameraSensorSize(*plant, a.options.camera)) {
      std::tie(a.options.width, a.options.height) = *own;
      if (movie && !evenSize(a.options, "the size of camera '" + a.options.camera + "'; give --size")) return 2;
    }
  }
  model::Simulation* sim = &session->simulation();
  std::string error;
  bool ok = false;
  if (!movie) {
    ok = gdpn::capture::renderAt(*sim, a.at, a.options, a.out, error);
    if (ok) std::cout << a.out << ": " << a.options.width << "x" << a.options.height << " at t = " << sim->kernel().now() << " s\n";
  } else {
    std::signal(SIGINT, onSigint);
    gdpn::capture::RecordResult result;
    {
      ProgressBar bar(!a.quiet && isatty(STDERR_FILENO));
      ok = gdpn::capture::record(*sim, a.until, a.options, a.out, std::ref(bar), &g_interrupted, result, error);
    }
    std::signal(SIGINT, SIG_DFL);
    if (ok) {
      std::cout << a.out << ": " << result.frames << " frames of " << a.options.width << "x" << a.options.height
                << " at " << a.options.fps << " fps (" << result.outcome.steps << " steps, "
                << model::stopReasonName(result.outcome.reason) << ")\n";
    }
  }
  if (!ok) {
    std::cerr << (error.find(": error: ") != std::string::npos ? "" : a.out + ": error: ") << error
              << (error.ends_with('\n') ? "" : "\n");
    return 1;
  }
  return 0;
}

/// The options of the picture and the movie alike: camera, size, look, seed, output, --param.
void addLook(CLI::App* cmd, CaptureArgs& args) {
  cmd->add_option("--camera", args.options.camera, "path of the Camera node or camera sensor (default: the scene's first Camera, or a framing "
                  "view); a DepthCamera shows its depth in grey, near white, far black");
  cmd->add_option("--size", args.size,
                  "WIDTHxHEIGHT in pixels, each side 16 to 16384 (default 1280x720, or a camera sensor's own size)");
  cmd->add_option("--samples", args.options.samples, "samples per pixel for anti-aliasing (default 4)")
      ->check(number(1, 16, "a whole number of samples from 1 to 16"));
  cmd->add_flag("--sensors", args.options.sensors, "draw sensor volumes and rays");
  cmd->add_flag("--joints", args.options.joints, "draw joint axes");
  cmd->add_flag("!--no-shadows", args.options.shadows, "no shadows (they cost about half a frame more on a software renderer)");
  cmd->add_flag("!--no-ground", args.options.ground, "no sky and no ground grid: the background in one colour");
  cmd->add_option("--seed", args.seed, "the random seed (default: the model's)")->check(seedCheck());
  cmd->add_option("-o,--output", args.out, "the file to write")->required();
  cmd->add_flag("--quiet,-q", args.quiet, "no sim.log lines and no progress on stderr");
  addParamOption(cmd, args.params);
  addScriptLimitOptions(cmd, args.limits);
}

/// `gdpn render`: the plant's options and the net's do not mix; then the picture of the one
/// or the other.
int render(const CLI::App& cmd, CaptureArgs a) {
  const auto given = [&cmd](const char* option) { return cmd.get_option(option)->count() > 0; };
  for (const char* plant_only : {"--camera", "--samples", "--sensors", "--joints", "--no-shadows", "--no-ground"}) {
    if (a.net && given(plant_only)) {
      std::cerr << "error: " << plant_only << " draws the plant; it does not go with --net\n";
      return 2;
    }
  }
  if (!a.net && given("--page")) {
    std::cerr << "error: --page chooses the page of the net: add --net\n";
    return 2;
  }
  a.size_given = given("--size");
  if (a.net) {
    a.at_given = given("--at");
    return renderNet(a);
  }
  return capture(a, false);
}

}  // namespace

Subcommand addRender(CLI::App& app) {
  auto args = std::make_shared<CaptureArgs>();
  auto* render_cmd =
      app.add_subcommand("render", "Run a model headless to a time and save a picture of its plant (or, with --net, of its net)");
  render_cmd->add_option("MODEL", args->model, "a .gdpn.yaml file, or a folder holding one")->required();
  render_cmd->add_option("--at", args->at, "model time of the picture, seconds")
      ->check(number(0.0, kMaxTime, "seconds from 0 to 1e9"));
  addLook(render_cmd, *args);
  render_cmd->add_flag("--net", args->net, "draw the net of a page with its marking (.svg or .png) instead of the plant; without --size, as large as the page needs");
  render_cmd->add_option("--page", args->page,
                         "with --net: the page, page type or instance path (page/instance/...) to draw (default: the first page)");
  setExamples(render_cmd, {"gdpn render examples/factory --at 58 -o factory.png        # the plant at 58 s",
               "gdpn render examples/factory --net --page station -o station.svg  # a page of the net"});
  return {render_cmd, [args, render_cmd] { return render(*render_cmd, *args); }};
}

Subcommand addRecord(CLI::App& app) {
  auto args = std::make_shared<CaptureArgs>();
  auto* record_cmd = app.add_subcommand("record", "Run a model headless and encode a movie of its plant (through ffmpeg)");
  record_cmd->add_option("MODEL", args->model, "a .gdpn.yaml file, or a folder holding one")->required();
  record_cmd->add_option("--until", args->until, "model time at which the movie ends, seconds (default 10)")
      ->check(number(0.0, kMaxTime, "seconds above 0, at most 1e9", true));
  record_cmd->add_option("--fps", args->options.fps, "frames per second of model time (default 30)")
      ->check(number(0.0, 1000.0, "frames per second above 0, at most 1000", true));
  addLook(record_cmd, *args);
  setExamples(record_cmd, {"gdpn record examples/factory --until 60 --fps 30 -o factory.mp4"});
  return {record_cmd, [args, record_cmd] {
            CaptureArgs a = *args;
            a.size_given = record_cmd->get_option("--size")->count() > 0;
            return capture(a, true);
          }};
}

}  // namespace gdpn::app

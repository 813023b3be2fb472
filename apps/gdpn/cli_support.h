#pragma once
/// \file
/// What gdpn's subcommands share: opening a model with its --param options, refusing to write
/// an output over an input, the progress bar, Ctrl-C, and the one shape of a subcommand
/// (added to the program with its options, run when it was parsed).

#include <CLI/CLI.hpp>

#include <atomic>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "gdpn/model/model.h"
#include "gdpn/session/session.h"

namespace gdpn::app {

/// A subcommand of gdpn: its CLI11 app (options bound to its own arguments) and what runs it
/// once it was parsed, returning the exit code.
struct Subcommand {
  CLI::App* app = nullptr;   ///< the subcommand, owned by the program's CLI::App
  std::function<int()> run;  ///< runs it with the parsed arguments; the exit code
};

/// Set by SIGINT and SIGTERM (onSigint) while a run or recording is going: it stops at the next step.
extern std::atomic<bool> g_interrupted;
/// The handler of SIGINT and SIGTERM during a run: sets g_interrupted, and a script running
/// now raises KeyboardInterrupt.
void onSigint(int);

/// Longest model time a run, picture or movie may ask for, seconds (about 31 years).
inline constexpr double kMaxTime = 1e9;

/// The check of a --seed value: a whole number from 0 to 2^64-1.
CLI::Validator seedCheck();

/// The model file that MODEL names (a file, or the one in a folder); MODEL when there is none.
std::string modelFile(const std::string& arg);

/// True (after saying so) when the output `out`, given as `option`, would write over one of
/// `inputs` (what each is, and its path), before anything is written. A device or a pipe
/// (/dev/stdout) is never refused.
bool overwritesInput(const std::string& option, const std::string& out,
                     const std::vector<std::pair<std::string, std::string>>& inputs);

/// The --param arguments (NAME=VALUE each, checked by the option's validator).
std::vector<model::ParamOverride> paramOverrides(const std::vector<std::string>& args);

/// `--param NAME=VALUE` on `cmd` (repeatable), into `out`.
void addParamOption(CLI::App* cmd, std::vector<std::string>& out);

/// `--script-timeout SECONDS` and `--script-memory MIB` on `cmd` into `out` (which holds the
/// defaults): a script call, the globals script included, that runs longer, or Python holding
/// more, stops the command with a located error; 0: no bound.
void addScriptLimitOptions(CLI::App* cmd, script::ScriptLimits& out);

/// Ends `cmd`'s --help, and its section of docs/cli.md and of the man page, with `lines`: each
/// a command line that works from the repository's root, what it does after a `#`.
void setExamples(CLI::App* cmd, const std::vector<std::string>& lines);

/// Loads and compiles MODEL (file or folder) into a session whose runs collect what `run`
/// asks, printing diagnostics; nullptr on error.
std::unique_ptr<session::Session> open(const std::string& arg, std::optional<std::uint64_t> seed,
                                       script::ScriptLimits limits, const std::vector<std::string>& params,
                                       session::RunRequest run = {});

/// The --size argument as width and height in pixels; nullopt after saying what is wrong.
std::optional<std::pair<int, int>> sizeArg(const std::string& text);

/// A progress bar on stderr for a run of so many steps (model::ProgressFn), drawn at most
/// every 100 ms and wiped when it goes; nothing when off.
class ProgressBar {
 public:
  /// A bar drawn when `on`.
  explicit ProgressBar(bool on) : on_(on) {}
  /// Draws `done` of `total` steps (total 0: open-ended).
  void operator()(std::int64_t done, std::int64_t total) {
    if (!on_) return;
    const auto now = std::chrono::steady_clock::now();
    if (now - last_ < std::chrono::milliseconds(100) && done != total) return;
    last_ = now;
    if (total > 0) {
      const int width = 30;
      const double f = std::min(1.0, static_cast<double>(done) / static_cast<double>(total));
      const int filled = static_cast<int>(f * width);
      std::fprintf(stderr, "\r[%s%s] %5.1f%%  step %lld/%lld", std::string(static_cast<std::size_t>(filled), '#').c_str(),
                   std::string(static_cast<std::size_t>(width - filled), ' ').c_str(), 100.0 * f,
                   static_cast<long long>(done), static_cast<long long>(total));
    } else {
      std::fprintf(stderr, "\rstep %lld", static_cast<long long>(done));
    }
    drawn_ = true;
  }
  /// Wipes the bar when it was drawn.
  ~ProgressBar() {
    if (drawn_) std::fprintf(stderr, "\r\033[K");
  }

 private:
  bool on_;
  bool drawn_ = false;
  std::chrono::steady_clock::time_point last_{};
};

}  // namespace gdpn::app

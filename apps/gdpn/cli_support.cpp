#include "cli_support.h"

#include <filesystem>
#include <iostream>

#include "cli_checks.h"
#include "gdpn/capture/capture.h"
#include "gdpn/capture/sensor_imager.h"
#include "gdpn/core/file.h"
#include "gdpn/core/output_file.h"
#include "gdpn/script/engine.h"

namespace gdpn::app {

namespace model = gdpn::model;
using gdpn::core::Diagnostics;

std::atomic<bool> g_interrupted{false};

void onSigint(int) {
  g_interrupted.store(true);
  gdpn::script::requestInterrupt();  // a script running now raises KeyboardInterrupt
}

CLI::Validator seedCheck() { return number<std::uint64_t>(0, UINT64_MAX, "a whole number from 0 to 2^64-1"); }

void setExamples(CLI::App* cmd, const std::vector<std::string>& lines) {
  std::string text = lines.size() == 1 ? "Example:" : "Examples:";
  for (const auto& line : lines) text += "\n  " + line;
  cmd->footer(text);
}

std::string modelFile(const std::string& arg) {
  Diagnostics ignored;  // the run itself reports a missing model
  return model::resolveModelPath(arg, ignored).value_or(arg);
}

bool overwritesInput(const std::string& option, const std::string& out,
                     const std::vector<std::pair<std::string, std::string>>& inputs) {
  std::error_code ec;
  if (out.empty() || (std::filesystem::exists(out, ec) && !std::filesystem::is_regular_file(out, ec))) return false;
  for (const auto& [what, path] : inputs) {
    if (path.empty() || !gdpn::core::sameFile(out, path)) continue;
    std::cerr << "error: " << option << " '" << out << "' is " << what << "; gdpn writes no output over it\n";
    return true;
  }
  return false;
}

std::vector<model::ParamOverride> paramOverrides(const std::vector<std::string>& args) {
  std::vector<model::ParamOverride> out;
  for (const auto& a : args) {
    if (auto o = model::parseParamArgument(a)) out.push_back(std::move(*o));
  }
  return out;
}

void addScriptLimitOptions(CLI::App* cmd, script::ScriptLimits& out) {
  cmd->add_option("--script-timeout", out.timeout_s,
                  "stop when one script call (the globals script included) runs longer than SECONDS; 0: never")
      ->default_val(script::kDefaultScriptTimeout)
      ->check(number(0.0, 1e6, "seconds from 0 (never) to 1e6"));
  cmd->add_option("--script-memory", out.memory_mib,
                  "stop when the scripts' Python holds more than MIB mebibytes (NumPy's arrays not counted); 0: no bound")
      ->default_val(script::kDefaultScriptMemory)
      ->check(number(0.0, 1e9, "mebibytes from 0 (no bound) to 1e9"));
}

void addParamOption(CLI::App* cmd, std::vector<std::string>& out) {
  cmd->add_option("--param", out, "set a parameter of the model's params section: NAME=VALUE (repeatable)")
      ->allow_extra_args(false)
      ->check(CLI::Validator(
          [](std::string& s) {
            return model::parseParamArgument(s) ? std::string() : "expects NAME=VALUE, got '" + s + "'";
          },
          "NAME=VALUE"));
}

std::unique_ptr<session::Session> open(const std::string& arg, std::optional<std::uint64_t> seed,
                                       gdpn::script::ScriptLimits limits, const std::vector<std::string>& params,
                                       session::RunRequest run) {
  Diagnostics diags;
  std::unique_ptr<gdpn::session::Session> sim;
  if (auto path = model::resolveModelPath(arg, diags)) {
    if (auto m = model::loadModel(*path, diags, paramOverrides(params))) {
      sim = gdpn::session::Session::create(std::move(*m), diags, {seed, limits, gdpn::capture::makeSensorImager, run});
    }
  }
  diags.print(std::cerr);
  if (!sim && diags.errorCount() > 1) std::cerr << diags.errorCount() << " errors\n";
  return sim;
}

std::optional<std::pair<int, int>> sizeArg(const std::string& text) {
  auto size = gdpn::capture::parseSize(text);
  if (!size) {
    std::cerr << "error: --size " << quoteArg(text) << " is not WIDTHxHEIGHT (for example 1280x720), each side "
              << gdpn::capture::kMinSide << " to " << gdpn::capture::kMaxSide << " pixels\n";
  }
  return size;
}

}  // namespace gdpn::app

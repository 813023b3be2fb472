#pragma once
// Internal: no promises. Typed, located access to a yaml-cpp tree for the loaders.

#include "yaml.h"

#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "gdpn/core/diagnostics.h"

namespace gdpn::model::detail {

/// One key of a YAML map, with its location.
struct Entry {
  std::string key;
  core::SourceLoc loc;
  YAML::Node value;
};

/// "a map", "a list", "nothing" or the quoted scalar.
std::string describe(const YAML::Node& node);
/// Parses YAML text; a syntax error becomes a located diagnostic and nullopt.
std::optional<YAML::Node> parseYaml(const std::string& text, const std::string& file, core::Diagnostics& diags);

/// A model parameter as the fields that refer to it see it.
struct ParamValue {
  double value = 0.0;    ///< in effect
  bool integer = false;  ///< a whole number
};

/// Reads typed values out of a parsed tree, reporting mistakes at their location.
class YamlReader {
 public:
  YamlReader(std::string file, core::Diagnostics& diags) : file_(std::move(file)), diags_(diags) {}

  /// Location of `node`, or `fallback` when yaml-cpp has none (empty values).
  [[nodiscard]] core::SourceLoc loc(const YAML::Node& node, const core::SourceLoc& fallback = {}) const;
  void error(const YAML::Node& node, std::string message);
  void error(const core::SourceLoc& loc, std::string message);
  /// A warning at `loc` (the load goes on).
  void warning(const core::SourceLoc& loc, std::string message) { diags_.warning(loc, std::move(message)); }
  /// A note at `loc`, explaining the diagnostic before it.
  void note(const core::SourceLoc& loc, std::string message) { diags_.note(loc, std::move(message)); }
  /// True when at least one error was reported through this reader.
  [[nodiscard]] bool failed() const { return failed_; }

  bool expectMap(const YAML::Node& node, const std::string& what);
  bool expectList(const YAML::Node& node, const std::string& what);
  /// The keys of a map in order; reports duplicate keys, non-scalar keys and, when `allowed`
  /// is not empty, unknown keys with a suggestion (what `hint` says of the key, when given,
  /// else the closest allowed key). Only accepted keys are returned.
  std::vector<Entry> entries(const YAML::Node& map, const std::string& what, const std::vector<std::string>& allowed,
                             const std::function<std::string(const std::string&)>& hint = {});
  /// The parameters a field may refer to as `$name` (null: none; must outlive the reader).
  void setParams(const std::map<std::string, ParamValue>* params) { params_ = params; }
  /// The parameters fields may refer to now (null: none).
  [[nodiscard]] const std::map<std::string, ParamValue>* params() const { return params_; }
  /// A number; with `param`, the value may be `$name` of a parameter, whose name is then put
  /// in `*param` (else `*param` is cleared). Without `param`, `$name` is an error.
  std::optional<double> number(const YAML::Node& node, const std::string& field, std::string* param = nullptr);
  /// A whole number, as number() (a parameter must hold a whole value).
  std::optional<std::int64_t> integer(const YAML::Node& node, const std::string& field, std::string* param = nullptr);
  std::optional<std::string> string(const YAML::Node& node, const std::string& field);

 private:
  std::string file_;
  /// The parameter `$name` at `node` (reported and nullopt when unknown or not allowed);
  /// `ref` false when the node is no `$name`.
  std::optional<ParamValue> param(const YAML::Node& node, const std::string& field, std::string* name, bool& ref);
  core::Diagnostics& diags_;
  bool failed_ = false;
  const std::map<std::string, ParamValue>* params_ = nullptr;
};

}  // namespace gdpn::model::detail

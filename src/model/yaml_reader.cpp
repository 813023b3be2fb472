#include "yaml_reader.h"

#include <filesystem>
#include <fstream>
#include <sstream>
#include <unordered_map>

#include "gdpn/core/file.h"
#include "gdpn/core/text.h"

namespace gdpn::model::detail {

std::string describe(const YAML::Node& node) {
  switch (node.Type()) {
    case YAML::NodeType::Map: return "a map";
    case YAML::NodeType::Sequence: return "a list";
    case YAML::NodeType::Scalar: return "\"" + node.Scalar() + "\"";
    default: return "nothing";
  }
}

std::optional<YAML::Node> parseYaml(const std::string& text, const std::string& file, core::Diagnostics& diags) {
  // YAML is UTF-8; other bytes would not survive a save
  if (!core::checkUtf8(text, file, diags)) return std::nullopt;
  try {
    return YAML::Load(text);
  } catch (const YAML::Exception& e) {
    const int line = e.mark.is_null() ? 0 : e.mark.line + 1;
    const int column = e.mark.is_null() ? 0 : e.mark.column + 1;
    diags.error({file, line, column}, "YAML syntax: " + e.msg);
  }
  return std::nullopt;
}

core::SourceLoc YamlReader::loc(const YAML::Node& node, const core::SourceLoc& fallback) const {
  const YAML::Mark mark = node.Mark();
  if (mark.is_null() || mark.line < 0) return fallback.file.empty() ? core::SourceLoc{file_, 0, 0} : fallback;
  return {file_, mark.line + 1, mark.column + 1};
}

void YamlReader::error(const YAML::Node& node, std::string message) { error(loc(node), std::move(message)); }

void YamlReader::error(const core::SourceLoc& where, std::string message) {
  failed_ = true;
  diags_.error(where, std::move(message));
}

bool YamlReader::expectMap(const YAML::Node& node, const std::string& what) {
  if (node.IsMap()) return true;
  error(node, what + " expects a map of keys and values, got " + describe(node));
  return false;
}

bool YamlReader::expectList(const YAML::Node& node, const std::string& what) {
  if (node.IsSequence()) return true;
  error(node, what + " expects a list, got " + describe(node));
  return false;
}

std::vector<Entry> YamlReader::entries(const YAML::Node& map, const std::string& what,
                                       const std::vector<std::string>& allowed) {
  std::vector<Entry> out;
  std::unordered_map<std::string, core::SourceLoc> seen;
  for (auto it = map.begin(); it != map.end(); ++it) {
    // copies: the iterator hands out a temporary pair of handles
    const YAML::Node key = it->first;
    if (!key.IsScalar()) {
      error(key, "a key in " + what + " must be a plain name, got " + describe(key));
      continue;
    }
    Entry e{key.Scalar(), loc(key), it->second};
    if (!allowed.empty() && std::find(allowed.begin(), allowed.end(), e.key) == allowed.end()) {
      error(e.loc, "unknown key '" + e.key + "' in " + what + core::didYouMean(e.key, allowed));
      continue;
    }
    auto [prev, fresh] = seen.emplace(e.key, e.loc);
    if (!fresh) {
      error(e.loc, "key '" + e.key + "' appears twice in " + what + " (first at line " +
                       std::to_string(prev->second.line) + ")");
      continue;
    }
    out.push_back(std::move(e));
  }
  return out;
}

std::optional<double> YamlReader::number(const YAML::Node& node, const std::string& field) {
  double v = 0.0;
  if (node.IsScalar() && node.Tag() != "!" && YAML::convert<double>::decode(node, v)) return v;
  error(node, "'" + field + "' expects a number, got " + describe(node));
  return std::nullopt;
}

std::optional<std::int64_t> YamlReader::integer(const YAML::Node& node, const std::string& field) {
  long long v = 0;
  if (node.IsScalar() && node.Tag() != "!" && YAML::convert<long long>::decode(node, v)) return v;
  error(node, "'" + field + "' expects a whole number, got " + describe(node));
  return std::nullopt;
}

std::optional<std::string> YamlReader::string(const YAML::Node& node, const std::string& field) {
  if (node.IsScalar()) return node.Scalar();
  error(node, "'" + field + "' expects text, got " + describe(node));
  return std::nullopt;
}

}  // namespace gdpn::model::detail

#include "yaml_reader.h"

#include "gdpn/core/expression.h"

#include <cmath>

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
    case YAML::NodeType::Null:
    case YAML::NodeType::Undefined: return "nothing";
  }
  return "nothing";  // no value of the enum
}

namespace {

/// Where a quoted scalar opens.
struct Quote {
  int line = 0;
  int column = 0;
  char mark = '"';
};

/// The quote of a quoted scalar that is never closed, if any. YAML reads everything after
/// such a quote as its text: to the end of the file (which yaml-cpp accepts without a word)
/// or to a syntax error far below. Quotes count only where a value begins (at a line's start,
/// after `: `, `- `, `[`, `{` or `,`); comments and block scalars (`|`, `>`) are skipped.
std::optional<Quote> unclosedQuote(std::string_view text) {
  enum class State { Plain, Double, Single } state = State::Plain;
  Quote open;
  int block = -1;  // inside a block scalar: lines indented more than this are its text
  int flow = 0;    // depth of [ ] and { }: `,` begins a value only inside them
  int number = 0;
  for (std::size_t begin = 0; begin <= text.size();) {
    std::size_t end = text.find('\n', begin);
    if (end == std::string_view::npos) end = text.size();
    const std::string_view line = text.substr(begin, end - begin);
    begin = end + 1;
    ++number;
    const std::size_t first = line.find_first_not_of(" \t\r");
    if (state == State::Plain && block >= 0) {
      if (first == std::string_view::npos || static_cast<int>(first) > block) continue;
      block = -1;
    }
    // the column of the line's key: past the indentation and any "- " of list items
    std::size_t key = first == std::string_view::npos ? 0 : first;
    while (key + 1 < line.size() && line[key] == '-' && line[key + 1] == ' ') {
      key = line.find_first_not_of(' ', key + 1);
      if (key == std::string_view::npos) key = line.size();
    }
    bool value_start = true;
    for (std::size_t i = 0; i < line.size(); ++i) {
      const char c = line[i];
      if (state == State::Double) {
        if (c == '\\') ++i;
        else if (c == '"') state = State::Plain;
        continue;
      }
      if (state == State::Single) {
        if (c == '\'' && i + 1 < line.size() && line[i + 1] == '\'') ++i;
        else if (c == '\'') state = State::Plain;
        continue;
      }
      if (c == ' ' || c == '\t' || c == '\r') continue;
      if (c == '#' && (i == 0 || line[i - 1] == ' ' || line[i - 1] == '\t')) break;
      if (value_start && (c == '"' || c == '\'')) {
        state = c == '"' ? State::Double : State::Single;
        open = {number, static_cast<int>(i) + 1, c};
        continue;
      }
      if (value_start && (c == '|' || c == '>')) {
        // a block scalar when only indicators (and a comment) follow
        const std::size_t rest = line.find_first_not_of("0123456789+- \t\r", i + 1);
        if (rest == std::string_view::npos || line[rest] == '#') {
          block = static_cast<int>(key);
          break;
        }
      }
      // inside a plain scalar (`x - 'y`, `a, "b`, `a [ 'b`) nothing but `: ` begins a value
      const bool colon = c == ':' && (i + 1 == line.size() || line[i + 1] == ' ' || line[i + 1] == '\t');
      const bool dash = c == '-' && i < key && (i + 1 == line.size() || line[i + 1] == ' ');
      const bool opens = value_start && (c == '[' || c == '{');
      if (opens) ++flow;
      if (flow > 0 && (c == ']' || c == '}')) --flow;
      value_start = colon || dash || opens || (c == ',' && flow > 0) || (c == '?' && value_start);
    }
  }
  if (state == State::Plain) return std::nullopt;
  return open;
}

/// Whether `node` holds a quoted scalar (yaml-cpp tags those "!") that begins at `q`.
bool quotedScalarAt(const YAML::Node& node, const Quote& q) {
  if (node.IsScalar()) {
    return node.Tag() == "!" && node.Mark().line + 1 == q.line && node.Mark().column + 1 == q.column;
  }
  if (!node.IsMap() && !node.IsSequence()) return false;
  for (auto it = node.begin(); it != node.end(); ++it) {
    if (node.IsMap() ? quotedScalarAt(it->first, q) || quotedScalarAt(it->second, q) : quotedScalarAt(*it, q)) {
      return true;
    }
  }
  return false;
}

}  // namespace

std::optional<YAML::Node> parseYaml(const std::string& text, const std::string& file, core::Diagnostics& diags) {
  // YAML is UTF-8; other bytes would not survive a save
  if (!core::checkUtf8(text, file, diags)) return std::nullopt;
  const auto quote = unclosedQuote(text);
  auto unclosed = [&] {
    diags.error({file, quote->line, quote->column}, std::string("YAML syntax: this quote (") + quote->mark +
                                                        ") is never closed, so the rest of the file would be its text");
  };
  try {
    YAML::Node root = YAML::Load(text);
    // a file that reads is refused only when the quote really opens a scalar (which then runs
    // to the end of the file), never for a quote inside plain text the scan misjudged
    if (!quote || !quotedScalarAt(root, *quote)) return root;
    unclosed();
  } catch (const YAML::Exception& e) {
    const int line = e.mark.is_null() ? 0 : e.mark.line + 1;
    const int column = e.mark.is_null() ? 0 : e.mark.column + 1;
    // the quote is the cause when it opens before the place the parser gave up
    if (quote && (line == 0 || quote->line <= line)) {
      unclosed();
    } else {
      diags.error({file, line, column}, "YAML syntax: " + e.msg);
    }
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
                                       const std::vector<std::string>& allowed,
                                       const std::function<std::string(const std::string&)>& hint) {
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
      const std::string why = hint ? hint(e.key) : std::string();
      error(e.loc, "unknown key '" + e.key + "' in " + what + (why.empty() ? core::didYouMean(e.key, allowed) : why));
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

std::optional<ParamValue> YamlReader::param(const YAML::Node& node, const std::string& field, std::string* name,
                                            bool& ref) {
  // `$name` written plain (a quoted "$name" is text), or an `=expression`, quoted or not (one
  // with a comma, `"=min(a, b)"`, is quoted inside a flow list, and savers write it so)
  ref = node.IsScalar() && node.Scalar().size() > 1 &&
        ((node.Scalar()[0] == '$' && node.Tag() != "!") || node.Scalar()[0] == '=');
  if (name) name->clear();
  if (!ref) return std::nullopt;
  if (node.Scalar()[0] == '=') {
    const std::string text = node.Scalar().substr(1);
    if (!name) {
      error(node, "'" + field + "' takes no expression (" + node.Scalar() + "); write a number");
      return std::nullopt;
    }
    std::vector<std::string> known;
    if (params_) {
      for (const auto& p : *params_) known.push_back(p.first);
    }
    core::ExpressionError why;
    const auto value = core::evaluate(
        text,
        [&](std::string_view n) -> std::optional<double> {
          const auto it = params_ ? params_->find(std::string(n)) : decltype(params_->end()){};
          if (!params_ || it == params_->end()) return std::nullopt;
          return it->second.value;
        },
        why, known);
    if (!value) {
      core::SourceLoc at = loc(node);
      at.column += static_cast<int>(why.column) + 1;  // past the '='
      error(at, why.message);
      return std::nullopt;
    }
    *name = node.Scalar();
    return ParamValue{*value, std::floor(*value) == *value};
  }
  const std::string wanted = node.Scalar().substr(1);
  if (!name) {
    error(node, "'" + field + "' takes no parameter ($" + wanted + "); write a number");
    return std::nullopt;
  }
  const auto it = params_ ? params_->find(wanted) : decltype(params_->end()){};
  if (!params_ || it == params_->end()) {
    std::vector<std::string> known;
    if (params_) {
      for (const auto& p : *params_) known.push_back(p.first);
    }
    error(node, "no parameter '" + wanted + "' in the model's params" +
                    (known.empty() ? std::string(" (it declares none)") : core::didYouMean(wanted, known)));
    return std::nullopt;
  }
  *name = wanted;
  return it->second;
}

std::optional<double> YamlReader::number(const YAML::Node& node, const std::string& field, std::string* name) {
  bool ref = false;
  if (auto p = param(node, field, name, ref)) return p->value;
  if (ref) return std::nullopt;
  double v = 0.0;
  if (node.IsScalar() && node.Tag() != "!" && YAML::convert<double>::decode(node, v)) return v;
  error(node, "'" + field + "' expects a number, got " + describe(node));
  return std::nullopt;
}

std::optional<std::int64_t> YamlReader::integer(const YAML::Node& node, const std::string& field,
                                                std::string* name) {
  bool ref = false;
  if (auto p = param(node, field, name, ref)) {
    if (std::floor(p->value) == p->value && std::abs(p->value) < 9.0e15) return static_cast<std::int64_t>(p->value);
    error(node, "'" + field + "' expects a whole number; parameter '" + *name + "' is " + core::formatDouble(p->value));
    return std::nullopt;
  }
  if (ref) return std::nullopt;
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

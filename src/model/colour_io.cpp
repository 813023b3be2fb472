// Value tokens in the model file: colour sets, variables, and inscriptions located to the
// character.

#include "colour_io.h"

#include <algorithm>
#include <functional>
#include <map>

#include "gdpn/core/text.h"
#include "gdpn/model/colour_text.h"
#include "gdpn/model/schema.h"
#include "gdpn/net/inscription.h"

namespace gdpn::model::detail {
namespace {

using core::SourceLoc;
using schema::Section;

/// The words of the built-in sets a colour set may be declared as, and their kinds.
struct BuiltinWord {
  const char* word;
  net::ColourKind kind;
};
constexpr BuiltinWord kBuiltinWords[] = {{"bool", net::ColourKind::Bool},
                                         {"int", net::ColourKind::Integer},
                                         {"string", net::ColourKind::String},
                                         {"dot", net::ColourKind::Dot}};

/// What a colour set may be, for messages.
const char* const kColourForms =
    "bool, int, string, dot, or a map of one key: {range: [lo, hi]}, {enum: [a, b]}, {cyclic: [a, b]}, "
    "{product: [A, B]} or {record: {f: A}}";

/// The text of scalar `node` (key `what`), reported where it stands (or at `fallback`) when it
/// is none.
std::optional<std::string> scalarText(const YAML::Node& node, const SourceLoc& fallback, const std::string& what,
                                      YamlReader& r) {
  if (node.IsScalar()) return node.Scalar();
  r.error(r.loc(node, fallback), "'" + what + "' expects text, got " + describe(node));
  return std::nullopt;
}

/// The name `node` holds (`what`: "a constant of colour set 'C'"), reported when it is no
/// identifier.
std::optional<std::string> nameIn(const YAML::Node& node, const SourceLoc& fallback, const std::string& what,
                                  YamlReader& r) {
  if (!node.IsScalar()) {
    r.error(r.loc(node, fallback), what + " is a name, got " + describe(node));
    return std::nullopt;
  }
  if (core::isIdentifier(node.Scalar())) return node.Scalar();
  r.error(r.loc(node, fallback),
          what + " is a name of letters, digits and _ (not starting with a digit), got '" + node.Scalar() + "'");
  return std::nullopt;
}

/// The names of list `node`, the value of key `what` of colour set `set` (each once, when
/// `distinct`: an enumeration's constants); false when any is wrong (reported).
bool colourNames(const YAML::Node& node, const SourceLoc& fallback, const std::string& what, const std::string& set,
                 bool distinct, std::vector<std::string>& out, YamlReader& r) {
  if (!node.IsSequence()) {
    r.error(r.loc(node, fallback), "'" + what + "' expects a list of names, got " + describe(node));
    return false;
  }
  bool ok = true;
  std::map<std::string, int> lines;
  for (const auto& item : node) {
    auto name = nameIn(item, fallback, std::string(distinct ? "a constant" : "a component") + " of colour set '" + set + "'", r);
    if (!name) {
      ok = false;
      continue;
    }
    const SourceLoc at = r.loc(item, fallback);
    if (distinct) {
      const auto [seen, fresh] = lines.emplace(*name, at.line);
      if (!fresh) {
        r.error(at, "constant '" + *name + "' stands twice in the enumeration (first at line " +
                        std::to_string(seen->second) + ")");
        ok = false;
        continue;
      }
    }
    out.push_back(std::move(*name));
  }
  if (ok && out.empty()) {
    r.error(r.loc(node, fallback), "'" + what + "' is empty: " +
                                       (distinct ? "an enumeration needs at least one constant"
                                                 : "a product needs at least one component"));
    ok = false;
  }
  return ok;
}

/// A colour set written as a map of one key (`forms`: what it is).
bool readColourForm(const Entry& e, net::ColourSetSpec& c, YamlReader& r) {
  const std::string what = "colour set '" + c.name + "'";
  if (e.value.size() != 1) {
    r.error(r.loc(e.value, e.loc), what + " is one of: " + kColourForms);
    return false;
  }
  const auto forms = r.entries(e.value, what, schema::keyNames(Section::Colour));
  if (forms.size() != 1) return false;  // its key is unknown (reported)
  const Entry& f = forms.front();
  const SourceLoc at = r.loc(f.value, f.loc);
  if (f.key == "range") {
    c.kind = net::ColourKind::Integer;
    c.range = true;
    if (!f.value.IsSequence() || f.value.size() != 2) {
      r.error(at, "'range' expects two whole numbers [lo, hi], got " + describe(f.value));
      return false;
    }
    const auto lo = r.integer(f.value[0], "range");
    const auto hi = r.integer(f.value[1], "range");
    if (!lo || !hi) return false;
    if (*lo > *hi) {
      r.error(at, "range [" + std::to_string(*lo) + ", " + std::to_string(*hi) +
                      "] is empty: its first number must be at most its second");
      return false;
    }
    c.lo = *lo;
    c.hi = *hi;
    return true;
  }
  if (f.key == "enum" || f.key == "cyclic") {
    c.kind = net::ColourKind::Enum;
    c.cyclic = f.key == "cyclic";
    return colourNames(f.value, f.loc, f.key, c.name, true, c.constants, r);
  }
  if (f.key == "product") {
    c.kind = net::ColourKind::Product;
    return colourNames(f.value, f.loc, f.key, c.name, false, c.components, r);
  }
  // a record: fields in the order written, each of a set
  c.kind = net::ColourKind::Record;
  if (!f.value.IsMap() || f.value.size() == 0) {
    r.error(at, "'record' expects a map of fields, each naming its colour set ({id: Id, name: Name}), got " +
                    describe(f.value));
    return false;
  }
  bool ok = true;
  for (const auto& field : r.entries(f.value, "record of " + what, {})) {
    if (!core::isIdentifier(field.key)) {
      r.error(field.loc, "a field's name is a word of letters, digits and _ (not starting with a digit), got '" +
                             field.key + "'");
      ok = false;
      continue;
    }
    auto set = nameIn(field.value, field.loc, "the colour set of field '" + field.key + "'", r);
    if (!set) {
      ok = false;
      continue;
    }
    c.fields.push_back(field.key);
    c.components.push_back(std::move(*set));
  }
  return ok && c.fields.size() == f.value.size();
}

/// Where each byte of `decoded`, the text of the scalar whose first raw character stands at
/// byte `start` of `raw`, stands in `raw`; one more entry for the end. The decoded text is the
/// raw one less quotes, escapes, indentation and folded line breaks: each of its characters but
/// blanks is found in order, over blanks, backslashes and (for a single-quoted scalar, where
/// `''` is one quote) quotes, or a little further on (past an escape such as `\x41`). A blank
/// stands where the next raw character is.
std::vector<std::size_t> alignScalar(std::string_view raw, std::size_t start, std::string_view decoded, char quote) {
  constexpr std::size_t kEscape = 12;  // the longest escape, `\U0001F600`, and some
  const auto skippable = [&](char c) {
    return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\\' || (quote == '\'' && c == '\'');
  };
  std::vector<std::size_t> at(decoded.size() + 1, start);
  std::size_t p = std::min(start, raw.size());
  std::size_t end = p;  // one past the last character found
  for (std::size_t i = 0; i < decoded.size(); ++i) {
    const char c = decoded[i];
    if (c == ' ' || c == '\t' || c == '\n' || c == '\r') {
      at[i] = p;
      continue;
    }
    std::size_t q = p;
    if (q >= raw.size() || raw[q] != c) {
      while (q < raw.size() && skippable(raw[q]) && raw[q] != c) ++q;
      if (q >= raw.size() || raw[q] != c) {
        // an escape: the character a little further on, on the same line
        const std::size_t near = raw.substr(p, kEscape).find(c);
        const std::size_t line_end = raw.find('\n', p);
        q = near != std::string_view::npos && (line_end == std::string_view::npos || p + near < line_end) ? p + near
                                                                                                          : raw.size();
      }
    }
    if (q >= raw.size()) {
      at[i] = p;  // not found: where the search stands
      continue;
    }
    at[i] = q;
    p = end = q + 1;
  }
  at[decoded.size()] = end;
  return at;
}

/// The offset of the first raw character of the text of scalar `node`, which starts at byte
/// `mark` (its quote, its block indicator or its first character), and the quote it is in.
std::pair<std::size_t, char> scalarStart(std::string_view raw, std::size_t mark) {
  if (mark >= raw.size()) return {raw.size(), 0};
  const char first = raw[mark];
  if (first == '"' || first == '\'') return {mark + 1, first};
  if (first == '|' || first == '>') {
    const std::size_t line_end = raw.find('\n', mark);
    return {line_end == std::string_view::npos ? raw.size() : line_end + 1, 0};
  }
  return {mark, 0};
}

}  // namespace

SourceMap::SourceMap(const std::string& file, std::string_view text) : file_(file), text_(text) {
  starts_.push_back(0);
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '\n') starts_.push_back(i + 1);
  }
}

std::size_t SourceMap::offset(int line, int column) const {
  if (line < 1) return 0;
  const auto l = std::min(static_cast<std::size_t>(line - 1), starts_.size() - 1);
  const std::size_t col = column > 1 ? static_cast<std::size_t>(column - 1) : 0;
  return std::min(starts_[l] + col, text_.size());
}

SourceLoc SourceMap::loc(std::size_t offset) const {
  offset = std::min(offset, text_.size());
  const auto it = std::upper_bound(starts_.begin(), starts_.end(), offset);
  const auto line = static_cast<std::size_t>(it - starts_.begin());  // 1-based: the line whose start is at or before
  return {file_, static_cast<int>(line), static_cast<int>(offset - starts_[line - 1] + 1)};
}

SourceLoc textStart(const YAML::Node& node, const SourceLoc& fallback, const SourceMap& source, const YamlReader& r) {
  const SourceLoc mark = r.loc(node, fallback);
  if (mark.line < 1) return mark;
  const std::size_t at = source.offset(mark.line, mark.column);
  const std::size_t start = scalarStart(source.text(), at).first;
  if (start >= source.text().size()) return mark;
  const char indicator = source.text()[at];
  if (indicator != '|' && indicator != '>') return source.loc(start);
  // a block's text begins past its indentation
  const std::size_t first = source.text().find_first_not_of(" \t", start);
  return source.loc(first == std::string_view::npos ? start : first);
}

std::vector<net::ColourSetSpec> readColours(const YAML::Node& section, YamlReader& r) {
  std::vector<net::ColourSetSpec> out;
  if (section.IsNull()) return out;
  if (!r.expectMap(section, "colours")) return out;
  for (const auto& e : r.entries(section, "colours", {})) {
    if (!core::isIdentifier(e.key)) {
      r.error(e.loc, "a colour set's name is a word of letters, digits and _ (not starting with a digit), got '" +
                         e.key + "'");
      continue;
    }
    net::ColourSetSpec c;
    c.name = e.key;
    c.loc = e.loc;
    if (e.value.IsScalar()) {
      const std::string& word = e.value.Scalar();
      const auto* builtin = std::find_if(std::begin(kBuiltinWords), std::end(kBuiltinWords),
                                         [&](const BuiltinWord& b) { return word == b.word; });
      if (builtin == std::end(kBuiltinWords)) {
        std::vector<std::string> words;
        for (const auto& b : kBuiltinWords) words.emplace_back(b.word);
        for (const auto& k : schema::keyNames(Section::Colour)) words.push_back(k);
        r.error(e.value, "unknown colour set kind '" + word + "'" + core::didYouMean(word, words) + "; a colour set is " +
                             kColourForms);
        continue;
      }
      c.kind = builtin->kind;
      out.push_back(std::move(c));
      continue;
    }
    if (!e.value.IsMap()) {
      r.error(r.loc(e.value, e.loc), "colour set '" + c.name + "' is " + kColourForms + "; got " + describe(e.value));
      continue;
    }
    if (readColourForm(e, c, r)) out.push_back(std::move(c));
  }
  return out;
}

std::vector<net::VariableSpec> readVariables(const YAML::Node& section, YamlReader& r) {
  std::vector<net::VariableSpec> out;
  if (section.IsNull()) return out;
  if (!r.expectMap(section, "variables")) return out;
  for (const auto& e : r.entries(section, "variables", {})) {
    if (!core::isIdentifier(e.key)) {
      r.error(e.loc, "a variable's name is a word of letters, digits and _ (not starting with a digit), got '" +
                         e.key + "'");
      continue;
    }
    if (auto set = nameIn(e.value, e.loc, "the colour set of variable '" + e.key + "'", r)) {
      out.push_back({e.key, std::move(*set), e.loc});
    }
  }
  return out;
}

std::optional<net::SlotText> readInscription(const YAML::Node& node, const SourceLoc& fallback, net::SlotId slot,
                                             const std::string& what, const SourceMap& source, YamlReader& r) {
  const SourceLoc mark = r.loc(node, fallback);
  auto text = scalarText(node, fallback, what, r);
  if (!text) return std::nullopt;
  text->erase(text->find_last_not_of(" \t\r\n") + 1);
  if (text->empty()) {
    r.error(mark, "'" + what + "' is empty");
    return std::nullopt;
  }
  // where each character of the text stands in the file
  const auto [start, quote] = scalarStart(source.text(), source.offset(mark.line, mark.column));
  const bool located = mark.line > 0 && start < source.text().size();
  const std::vector<std::size_t> at = located ? alignScalar(source.text(), start, *text, quote) : std::vector<std::size_t>{};
  const auto fileLoc = [&](const SourceLoc& in_text) {
    // a place in the text (lines and columns from 1) to its place in the file
    if (!located || in_text.line < 1) return mark;
    std::size_t offset = 0;
    for (int line = 1; line < in_text.line && offset < text->size(); ++line) {
      const auto nl = text->find('\n', offset);
      offset = nl == std::string::npos ? text->size() : nl + 1;
    }
    offset = std::min(offset + static_cast<std::size_t>(std::max(in_text.column, 1) - 1), text->size());
    return source.loc(at[offset]);
  };
  net::SlotText out{slot, *text, fileLoc({mark.file, 1, 1})};
  // where its characters stand, kept where they do not simply follow its first one, so that
  // the compiler's messages (types) are at their character too
  if (located) {
    bool plain = true;
    std::vector<std::pair<int, int>> layout;
    for (std::size_t i = 0; i <= text->size(); ++i) {
      const SourceLoc c = source.loc(at[std::min(i, at.size() - 1)]);
      layout.emplace_back(c.line, c.column);
      plain = plain && c.line == out.loc.line && c.column == out.loc.column + static_cast<int>(i);
    }
    if (!plain) out.layout = std::move(layout);
  }
  // parse it now, so that a syntax error is said at load, at its character
  core::Diagnostics found;
  (void)net::parseInscription(*text, {mark.file, 1, 1}, found);
  for (const auto& d : found.all()) {
    const SourceLoc where = fileLoc(d.loc);
    switch (d.severity) {
      case core::Severity::Error: r.error(where, d.message); break;
      case core::Severity::Warning: r.warning(where, d.message); break;
      case core::Severity::Note: r.note(where, d.message); break;
    }
  }
  return out;
}

void writeColours(YAML::Emitter& out, const std::vector<net::ColourSetSpec>& colours) {
  if (colours.empty()) return;
  out << YAML::Key << "colours" << YAML::Value << YAML::BeginMap;
  for (const auto& c : colours) {
    out << YAML::Key << c.name << YAML::Value;
    const auto list = [&](const std::vector<std::string>& items) {
      out << YAML::Flow << YAML::BeginSeq;
      for (const auto& i : items) out << i;
      out << YAML::EndSeq;
    };
    // one key of the map form, when it is the set's
    const auto form = [&](std::string_view key, bool mine, const std::function<void()>& value) {
      return schema::KeyWriter{key, [&out, key, mine, value] {
                                 if (!mine) return;
                                 out << YAML::Key << std::string(key) << YAML::Value;
                                 value();
                               }};
    };
    switch (c.kind) {
      case net::ColourKind::Dot: out << "dot"; continue;
      case net::ColourKind::Bool: out << "bool"; continue;
      case net::ColourKind::String: out << "string"; continue;
      case net::ColourKind::Integer:
        if (!c.range) {
          out << "int";
          continue;
        }
        break;
      case net::ColourKind::Enum:
      case net::ColourKind::Product:
      case net::ColourKind::Record: break;
    }
    out << YAML::Flow << YAML::BeginMap;
    schema::inSchemaOrder(
        Section::Colour,
        {
            form("range", c.kind == net::ColourKind::Integer,
                 [&] { out << YAML::Flow << YAML::BeginSeq << c.lo << c.hi << YAML::EndSeq; }),
            form("enum", c.kind == net::ColourKind::Enum && !c.cyclic, [&] { list(c.constants); }),
            form("cyclic", c.kind == net::ColourKind::Enum && c.cyclic, [&] { list(c.constants); }),
            form("product", c.kind == net::ColourKind::Product, [&] { list(c.components); }),
            form("record", c.kind == net::ColourKind::Record,
                 [&] {
                   out << YAML::Flow << YAML::BeginMap;
                   for (std::size_t i = 0; i < c.fields.size() && i < c.components.size(); ++i) {
                     out << YAML::Key << c.fields[i] << YAML::Value << c.components[i];
                   }
                   out << YAML::EndMap;
                 }),
        });
    out << YAML::EndMap;
  }
  out << YAML::EndMap;
}

void writeVariables(YAML::Emitter& out, const std::vector<net::VariableSpec>& variables) {
  if (variables.empty()) return;
  out << YAML::Key << "variables" << YAML::Value << YAML::BeginMap;
  for (const auto& v : variables) out << YAML::Key << v.name << YAML::Value << v.colour;
  out << YAML::EndMap;
}

bool inscriptionIsBlock(const std::string& text) {
  if (text.find('\n') == std::string::npos) return false;
  // a '|' block gives back its lines with one newline after the last, which the reader drops
  const std::string block = text + "\n";
  if (block.front() == ' ' || block.front() == '\n' || block.front() == '\t') return false;
  std::size_t line_start = 0;
  for (std::size_t i = 0; i < block.size(); ++i) {
    const char c = block[i];
    if (c == '\n') {
      if (i > line_start && (block[i - 1] == ' ' || block[i - 1] == '\t')) return false;
      line_start = i + 1;
    } else if (static_cast<unsigned char>(c) < 0x20 && c != '\t') {
      return false;
    }
  }
  return true;
}

void writeInscription(YAML::Emitter& out, const std::string& text) {
  if (inscriptionIsBlock(text)) out << YAML::Literal << text;
  else out << YAML::DoubleQuoted << text;
}

}  // namespace gdpn::model::detail

namespace gdpn::model {

std::optional<net::ColourSetSpec> readColourDefinition(const std::string& name, std::string_view definition,
                                                       core::Diagnostics& diags) {
  const std::string file = "definition";
  if (!core::isIdentifier(name)) {
    diags.error({file, 1, 1}, "a colour set's name is a word of letters, digits and _ (not starting with a digit), got '" +
                                  name + "'");
    return std::nullopt;
  }
  const auto nl = definition.find_first_of("\r\n");
  if (nl != std::string_view::npos) {
    diags.error({file, 1, static_cast<int>(nl) + 1}, "a definition is one line");
    return std::nullopt;
  }
  const auto first = definition.find_first_not_of(" \t");
  if (first == std::string_view::npos) {
    diags.error({file, 1, 1}, "the definition is empty: a colour set is bool, int, string, dot, or {range: [lo, hi]}, "
                              "{enum: [a, b]}, {cyclic: [a, b]}, {product: [A, B]} or {record: {f: A}}");
    return std::nullopt;
  }
  // read as the file's section would be: `colours: {NAME: DEFINITION}` on one line, each
  // message's column moved back to the definition's own
  const std::string prefix = "colours:\n  " + name + ": ";
  const int shift = static_cast<int>(name.size()) + 4;
  core::Diagnostics found;
  const auto root = detail::parseYaml(prefix + std::string(definition) + "\n", file, found);
  std::optional<net::ColourSetSpec> out;
  if (root) {
    detail::YamlReader r(file, found);
    auto sets = detail::readColours((*root)["colours"], r);
    if (!r.failed() && sets.size() == 1) out = std::move(sets.front());
  }
  for (const auto& d : found.all()) {
    // past the definition's line: the parser reached its end (an unclosed bracket)
    const int column = d.loc.line == 2   ? std::max(1, d.loc.column - shift)
                       : d.loc.line > 2 ? static_cast<int>(definition.size()) + 1
                                        : 1;
    const core::SourceLoc at{file, 1, column};
    switch (d.severity) {
      case core::Severity::Error: diags.error(at, d.message); break;
      case core::Severity::Warning: diags.warning(at, d.message); break;
      case core::Severity::Note: diags.note(at, d.message); break;
    }
  }
  if (out) out->loc = {};
  return found.hasErrors() ? std::nullopt : out;
}

std::string colourDefinition(const net::ColourSetSpec& c) {
  YAML::Emitter out;
  out << YAML::BeginMap;
  detail::writeColours(out, {c});
  out << YAML::EndMap;
  // "colours:\n  NAME: DEFINITION": the text after the name
  const std::string text = out.c_str();
  const auto line = text.find('\n');
  const auto colon = line == std::string::npos ? std::string::npos : text.find(": ", line);
  return colon == std::string::npos ? std::string() : text.substr(colon + 2);
}

}  // namespace gdpn::model

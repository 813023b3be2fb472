// Reading model files: YAML text -> Model, with every problem located at file:line:col.

#include "yaml.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <unordered_map>

#include "gdpn/core/expression.h"
#include "gdpn/core/file.h"
#include "gdpn/core/text.h"
#include "gdpn/model/model.h"
#include "gdpn/model/schema.h"
#include "gdpn/scene/actions.h"
#include "colour_io.h"
#include "io_section.h"
#include "scene_io.h"
#include "yaml_reader.h"

namespace gdpn::model {
namespace {

using core::Diagnostics;
using core::SourceLoc;
using detail::Entry;
using detail::YamlReader;

using schema::keyNames;
using schema::Section;

/// The largest whole parameter, 2^53: a double holds every whole number up to it.
constexpr double kMaxWhole = 9007199254740992.0;

/// True when `value` lies in the schema's range for key `name` of `section`.
bool inRange(Section section, const std::string& name, double value) {
  return schema::inRange(schema::key(section, name), value);
}

/// True when `word` is one of the words Word key `name` of `section` takes.
bool isChoice(Section section, const std::string& name, const std::string& word) {
  const auto& choices = schema::key(section, name).choices;
  return std::find(choices.begin(), choices.end(), word) != choices.end();
}

/// A node path: identifiers joined by '/' (and `*`s for every child, where `any`).
bool isNodePath(const std::string& s, bool any = false) {
  std::size_t begin = 0;
  while (true) {
    const auto end = s.find('/', begin);
    const std::string_view segment = std::string_view(s).substr(begin, end - begin);
    if (!core::isIdentifier(segment) && !(any && segment == "*")) return false;
    if (end == std::string::npos) return true;
    begin = end + 1;
  }
}

class ModelReader {
 public:
  ModelReader(const std::string& file, const std::string& text, Diagnostics& diags,
              const std::vector<ParamOverride>& overrides)
      : r_(file, diags), file_(file), text_(text), source_(file_, text_), overrides_(overrides) {}

  std::optional<Model> read(const YAML::Node& root) {
    Model model;
    // an empty file (or one of only comments) is more likely a mistake than a model
    if (root.IsNull()) {
      r_.error({file_, 1, 1}, "the model file is empty");
      return std::nullopt;
    }
    if (!r_.expectMap(root, "the model file")) return std::nullopt;
    // the settings first: they say in what unit the scene's angles are written
    if (const YAML::Node s = root["settings"]) readSettings(s, model.settings);
    angles_ = model.settings.angles;
    // then the parameters, which every other section's fields may refer to
    if (const YAML::Node p = root["params"]) readParams(p, model.params);
    setOverrides(model.params);
    for (const auto& p : model.params) param_values_[p.name] = {p.value, p.integer};
    r_.setParams(&param_values_);
    for (const auto& e : r_.entries(root, "model file", keyNames(Section::Model))) {
      if (e.key == "gdpn") {
        if (auto v = r_.integer(e.value, "gdpn"); v && *v != 1) {
          r_.error(e.value, "this is gdpn format " + std::to_string(*v) + "; this gdpn reads format 1");
        }
      } else if (e.key == "description") {
        if (auto s = r_.string(e.value, "description")) model.description = *s;
      } else if (e.key == "settings" || e.key == "params") {
        continue;  // read above
      } else if (e.key == "signals") {
        readSignals(e.value, model.signals);
      } else if (e.key == "pages") {
        readPages(e.value, model.net.pages, false);
      } else if (e.key == "page_types") {
        type_scenes_ = &model.type_scenes;
        parts_ = &model.parts;
        readPages(e.value, model.net.page_types, true);
      } else if (e.key == "fusion") {
        readFusions(e, model.net.fusions);
      } else if (e.key == "colours") {
        model.net.colours = detail::readColours(e.value, r_);
      } else if (e.key == "variables") {
        model.net.variables = detail::readVariables(e.value, r_);
      } else if (e.key == "scene") {
        model.scene = detail::readScene(e.value, r_, e.loc, angles_);
      } else if (e.key == "io") {
        model.io = detail::readIo(e.value, r_, source_);
      } else if (e.key == "scripts") {
        if (!r_.expectMap(e.value, "scripts")) continue;
        for (const auto& g : r_.entries(e.value, "scripts", keyNames(Section::Scripts))) {
          model.net.globals = readScript(g, "globals");
        }
      }
    }
    if (r_.failed()) return std::nullopt;
    return model;
  }

 private:
  /// The text of line `line` (1-based) of the source.
  std::string_view sourceLine(int line) const {
    std::size_t begin = 0;
    for (int l = 1; l < line && begin != std::string::npos; ++l) {
      begin = text_.find('\n', begin);
      if (begin != std::string::npos) ++begin;
    }
    if (begin == std::string::npos || begin > text_.size()) return {};
    const auto end = text_.find('\n', begin);
    return std::string_view(text_).substr(begin, end == std::string::npos ? std::string::npos : end - begin);
  }

  /// A script: inline code (a YAML string) or {file: x.py, function: name}.
  net::ScriptSpec readScript(const Entry& e, const std::string& what) {
    net::ScriptSpec script;
    script.loc = r_.loc(e.value, e.loc);
    if (e.value.IsMap()) {
      for (const auto& k : r_.entries(e.value, what, keyNames(Section::ScriptFile))) {
        if (auto v = r_.string(k.value, k.key)) (k.key == "file" ? script.file : script.function) = *v;
      }
      if (script.file.empty()) r_.error(e.loc, what + " in a file needs 'file'");
      if (script.function.empty() && what != "globals") r_.error(e.loc, what + " in a file needs 'function'");
      return script;
    }
    auto code = r_.string(e.value, what);
    if (!code) return script;
    script.code = *code;
    if (script.code.find_first_not_of(" \t\r\n") == std::string::npos) {
      r_.error(r_.loc(e.value, e.loc), what + " is empty");
      script.code.clear();
      return script;
    }
    // multi-line code ends with exactly one newline (what a '|' block gives back)
    if (script.code.find('\n') != std::string::npos) {
      script.code.erase(script.code.find_last_not_of('\n') + 1);
      script.code += '\n';
    }
    // where the code's first character stands in the model file, for Python's line numbers
    const SourceLoc at = r_.loc(e.value, e.loc);
    const std::string_view line = sourceLine(at.line);
    const std::size_t col = at.column > 0 ? static_cast<std::size_t>(at.column - 1) : 0;
    const char first = col < line.size() ? line[col] : ' ';
    script.loc = at;
    if (first == '|' || first == '>') {
      int l = at.line + 1;
      std::string_view body = sourceLine(l);
      while (body.find_first_not_of(" \t\r") == std::string_view::npos && l < at.line + 10000 && !body.empty()) {
        body = sourceLine(++l);
      }
      const auto indent = body.find_first_not_of(' ');
      script.indent = indent == std::string_view::npos ? 0 : static_cast<int>(indent);
      script.loc = {file_, l, script.indent + 1};
    } else if (first == '"' || first == '\'') {
      script.indent = static_cast<int>(col) + 1;
      script.loc.column = at.column + 1;
    } else {
      script.indent = static_cast<int>(col);
    }
    if (first != '|') script.lines = codeLines(script.code, script.loc, first != '>');
    return script;
  }

  /// The model file's line of each line of `code`, a scalar whose lines do not follow the
  /// file's one for one (a folded `>` block joins lines and drops blank ones; a quoted string
  /// may hold `\n`), found by reading on from `start`: each code line's first characters (up to
  /// a quote or backslash, which a quoted string writes otherwise) stand on the file line it
  /// came from, the next line of the file for a folded block (`on_same_line` false), or further
  /// along the same line for a quoted one. A line not found keeps the line before's. Empty
  /// when the lines follow one another from `start.line`.
  std::vector<int> codeLines(const std::string& code, SourceLoc start, bool on_same_line) const {
    std::vector<int> lines;
    if (code.find('\n') == std::string::npos || code.find('\n') + 1 == code.size()) return lines;
    int line = start.line;
    std::size_t col = start.column > 0 ? static_cast<std::size_t>(start.column - 1) : 0;
    std::string_view text = sourceLine(line);
    const int total = static_cast<int>(std::count(text_.begin(), text_.end(), '\n')) + 1;
    bool consecutive = true;
    std::size_t begin = 0;
    while (begin < code.size()) {
      const std::size_t end = std::min(code.find('\n', begin), code.size());
      std::string_view key = std::string_view(code).substr(begin, end - begin);
      const std::size_t lead = key.find_first_not_of(" \t");
      key.remove_prefix(lead == std::string_view::npos ? key.size() : lead);
      key = key.substr(0, std::min({key.find_first_of("\"'\\"), std::size_t{24}}));
      while (!key.empty() && key.back() == ' ') key.remove_suffix(1);
      if (!key.empty()) {
        // search this line from `col` (a quoted string), else the lines after it
        for (int l = (on_same_line || lines.empty()) ? line : line + 1; l <= total && l < line + 1000; ++l) {
          const std::string_view t = l == line ? text : sourceLine(l);
          const std::size_t from = l == line ? std::min(col, t.size()) : 0;
          if (const auto at = t.find(key, from); at != std::string_view::npos) {
            line = l;
            text = t;
            col = at + key.size();
            break;
          }
        }
      }
      if (line != start.line + static_cast<int>(lines.size())) consecutive = false;
      lines.push_back(line);
      begin = end + 1;
    }
    if (consecutive) lines.clear();
    return lines;
  }

  /// Per-slot scripts: a script (for slot a0, or for `default_slot`) or a map slot -> script.
  template <class F>
  void perSlotScript(const Entry& e, const std::string& what, net::SlotId default_slot, F&& f) {
    const auto& file_keys = keyNames(Section::ScriptFile);
    const bool file_form = e.value.IsMap() && std::any_of(file_keys.begin(), file_keys.end(),
                                                          [&](const std::string& k) { return bool(e.value[k]); });
    if (!e.value.IsMap() || file_form) {
      f(default_slot, readScript(e, what));
      return;
    }
    forEachSlot(e.value, what, [&](net::SlotId slot, const Entry& s) { f(slot, readScript(s, what)); });
  }

  /// Calls `f(slot, entry)` for each key of a map keyed by slot names, reporting other keys.
  template <class F>
  void forEachSlot(const YAML::Node& map, const std::string& what, F&& f) {
    for (const auto& s : r_.entries(map, what, {})) {
      if (auto slot = net::parseSlot(s.key)) {
        f(*slot, s);
      } else {
        r_.error(s.loc, "'" + s.key + "' is not a slot name (a0 ... d7)");
      }
    }
  }

  /// True when the key of `e` is an identifier; reported (as `whose` name) when not.
  bool identifier(const Entry& e, const std::string& whose) {
    if (core::isIdentifier(e.key)) return true;
    r_.error(e.loc, whose + " name is a word of letters, digits and _ (not starting with a digit), got '" + e.key + "'");
    return false;
  }

  /// The `params` section: `name: value` or `name: {value: .., unit: .., description: ..}`.
  void readParams(const YAML::Node& node, std::vector<Param>& out) {
    if (node.IsNull()) return;
    if (!r_.expectMap(node, "params")) return;
    for (const auto& e : r_.entries(node, "params", {})) {
      if (!identifier(e, "a parameter's")) continue;
      Param p;
      p.name = e.key;
      p.loc = e.loc;
      bool has_value = false;
      if (!e.value.IsMap()) {
        has_value = readParamValue(e.value, e.loc, p);
      } else {
        for (const auto& f : r_.entries(e.value, "parameter '" + p.name + "'", keyNames(Section::Param))) {
          if (f.key == "value") {
            has_value = readParamValue(f.value, f.loc, p);
          } else if (auto text = r_.string(f.value, f.key)) {
            (f.key == "unit" ? p.unit : p.description) = *text;
          }
        }
        if (!has_value && !r_.failed()) r_.error(e.loc, "parameter '" + p.name + "' has no 'value'");
      }
      if (has_value) out.push_back(std::move(p));
    }
  }

  /// A parameter's value: a whole number (written without a point) or a finite number.
  bool readParamValue(const YAML::Node& v, const SourceLoc& at, Param& p) {
    long long whole = 0;
    if (v.IsScalar() && v.Tag() != "!" && YAML::convert<long long>::decode(v, whole)) {
      if (whole > (1LL << 53) || whole < -(1LL << 53)) {
        r_.error(v, "parameter '" + p.name + "' is a whole number beyond 2^53, which a run cannot hold exactly");
        return false;
      }
      p.integer = true;
      p.value = p.declared = static_cast<double>(whole);
      return true;
    }
    if (v.IsNull()) {
      r_.error(at, "parameter '" + p.name + "' expects a number, got nothing");
      return false;
    }
    double x = 0.0;
    if (!v.IsScalar() || v.Tag() == "!" || !YAML::convert<double>::decode(v, x)) {
      r_.error(v, "parameter '" + p.name + "' expects a number, got " + detail::describe(v));
      return false;
    }
    if (!std::isfinite(x)) {
      r_.error(v, "parameter '" + p.name + "' must be a finite number");
      return false;
    }
    p.value = p.declared = x;
    return true;
  }

  /// The `signals` section: `name: {place: P}` (with `value: V`, one value's tokens),
  /// `{node: PATH, of: QUANTITY}` or `{expression: PYTHON}`, each with an optional sampling
  /// period `every` (seconds).
  void readSignals(const YAML::Node& node, std::vector<SignalSpec>& out) {
    if (node.IsNull() || !r_.expectMap(node, "signals")) return;
    for (const auto& e : r_.entries(node, "signals", {})) {
      if (!identifier(e, "a signal's")) continue;
      SignalSpec s;
      s.name = e.key;
      s.loc = e.loc;
      if (!r_.expectMap(e.value, "signal '" + s.name + "'")) continue;
      int kinds = 0;
      bool has_of = false;
      bool has_value = false;
      for (const auto& f : r_.entries(e.value, "signal '" + s.name + "'", keyNames(Section::Signal))) {
        if (f.key == "every") {
          if (auto v = r_.number(f.value, "every")) {
            if (!inRange(Section::Signal, f.key, *v)) r_.error(f.value, "'every' is a period of more than 0 seconds");
            s.every = *v;
          }
          continue;
        }
        if (f.key == "value") {
          // one value's tokens: its syntax is checked now, its type when a run is made ready
          if (auto text = detail::readInscription(f.value, f.loc, net::kDefaultSlot, "value", source_, r_)) {
            s.value = std::move(text->text);
            s.value_loc = text->loc;
          }
          has_value = true;
          continue;
        }
        auto text = r_.string(f.value, f.key);
        if (!text) continue;
        if (f.key == "of") {
          s.quantity = *text;
          has_of = true;
          continue;
        }
        ++kinds;
        s.kind = f.key == "place" ? SignalSpec::Kind::Place
                 : f.key == "node" ? SignalSpec::Kind::Node
                                   : SignalSpec::Kind::Expression;
        s.target = *text;
        s.loc = r_.loc(f.value, f.loc);
      }
      if (kinds != 1) {
        r_.error(e.loc, "signal '" + s.name + "' reads one of: place, node (with 'of'), expression");
        continue;
      }
      if ((s.kind == SignalSpec::Kind::Node) != has_of) {
        r_.error(e.loc, s.kind == SignalSpec::Kind::Node
                            ? "signal '" + s.name + "' needs 'of': position, velocity, angle, rate, reading or a field"
                            : "'of' goes with 'node' only (signal '" + s.name + "')");
        continue;
      }
      if (has_value && s.kind != SignalSpec::Kind::Place) {
        r_.error(e.loc, "'value' goes with 'place' only (signal '" + s.name + "')");
        continue;
      }
      out.push_back(std::move(s));
    }
  }

  /// Applies the overrides (--param) to the parameters read.
  void setOverrides(std::vector<Param>& params) {
    for (const auto& o : overrides_) {
      const SourceLoc where{o.where, 0, 0};
      auto it = std::find_if(params.begin(), params.end(), [&](const Param& p) { return p.name == o.name; });
      if (it == params.end()) {
        std::vector<std::string> names;
        for (const auto& p : params) names.push_back(p.name);
        r_.error(where, "no parameter '" + o.name + "' in " + file_ +
                            (names.empty() ? std::string(" (it declares none)") : core::didYouMean(o.name, names)));
        continue;
      }
      const auto value = core::parseNumber(o.text);
      if (!value || !std::isfinite(*value)) {
        r_.error(where, "parameter '" + o.name + "' expects a number, got '" + o.text + "'");
      } else if (it->integer && (std::floor(*value) != *value || std::abs(*value) > kMaxWhole)) {
        r_.error(where, "parameter '" + o.name + "' is a whole number (at most 2^53), got '" + o.text + "'");
      } else {
        it->value = *value;
      }
    }
  }

  void readSettings(const YAML::Node& node, Settings& s) {
    if (!r_.expectMap(node, "settings")) return;
    for (const auto& e : r_.entries(node, "settings", keyNames(Section::Settings))) {
      if (e.key == "dt") {
        if (auto v = r_.number(e.value, "dt")) {
          if (!inRange(Section::Settings, e.key, *v)) r_.error(e.value, "dt must be a positive number of seconds");
          s.dt = *v;
          s.dt_given = true;
        }
      } else if (e.key == "seed") {
        if (auto v = r_.integer(e.value, "seed")) {
          if (!inRange(Section::Settings, e.key, static_cast<double>(*v))) r_.error(e.value, "seed must not be negative");
          s.seed = static_cast<std::uint64_t>(*v);
          s.seed_given = true;
        }
      } else if (e.key == "until") {
        if (auto v = r_.number(e.value, "until")) {
          if (!inRange(Section::Settings, e.key, *v)) r_.error(e.value, "until must be a time of at least 0 seconds");
          s.until = *v;
        }
      } else if (e.key == "angles") {
        if (auto v = r_.string(e.value, "angles")) {
          if (isChoice(Section::Settings, e.key, *v)) {
            s.angles = *v == "radians" ? scene::AngleUnit::Radians : scene::AngleUnit::Degrees;
          } else {
            r_.error(e.value, "angles are 'radians' or 'degrees', got '" + *v + "'");
          }
        }
      } else if (e.key == "ties") {
        if (auto v = r_.string(e.value, "ties")) {
          if (isChoice(Section::Settings, e.key, *v)) {
            s.random_ties = *v == "random";
          } else {
            r_.error(e.value, "ties are 'order' (declaration order) or 'random' (drawn from the seed), got '" + *v + "'");
          }
        }
      }
    }
  }

  /// `fusion`: each set's name and scope (`pool: global`).
  void readFusions(const Entry& section, std::vector<net::FusionSpec>& out) {
    forEachNamed(section, "fusion", [&](const Entry& e) {
      net::FusionSpec f;
      f.name = e.key;
      f.loc = e.loc;
      const auto word = r_.string(e.value, "a fusion set's scope");
      if (!word) return;
      const auto scope = net::parseFusionScope(*word);
      if (!scope) {
        const std::vector<std::string> scopes = {net::fusionScopeName(net::FusionScope::Global),
                                                 net::fusionScopeName(net::FusionScope::Instance)};
        r_.error(e.value, "fusion set '" + f.name + "' has scope '" + *word + "'" + core::didYouMean(*word, scopes) +
                              "; expected global (one place for the net) or instance (one place per instance of "
                              "the page type that holds its members)");
        return;
      }
      f.scope = *scope;
      out.push_back(std::move(f));
    });
  }

  void readPages(const YAML::Node& node, std::vector<net::PageSpec>& out, bool types) {
    const char* what = types ? "page_types" : "pages";
    if (!r_.expectMap(node, what)) return;
    for (const auto& e : r_.entries(node, what, {})) {
      net::PageSpec page;
      page.name = e.key;
      page.loc = e.loc;
      readPage(e, page, types);
      out.push_back(std::move(page));
    }
  }

  void readPage(const Entry& pe, net::PageSpec& page, bool type) {
    const std::string what = std::string(type ? "page type '" : "page '") + page.name + "'";
    if (pe.value.IsNull()) return;
    if (!r_.expectMap(pe.value, what)) return;
    // a part's parameters first: its scene's fields refer to them, besides the model's
    PartSpec part;
    part.loc = page.loc;
    std::map<std::string, detail::ParamValue> with_own = param_values_;
    const bool is_part = type && (pe.value["part"] || pe.value["params"] || pe.value["io"] || pe.value["uses"]);
    if (type && pe.value["params"]) {
      readParams(pe.value["params"], part.params);
      for (const auto& p : part.params) with_own[p.name] = {p.value, p.integer};
    }
    r_.setParams(&with_own);
    struct Restore {
      YamlReader& r;
      const std::map<std::string, detail::ParamValue>* p;
      ~Restore() { r.setParams(p); }
    } restore{r_, &param_values_};
    for (const auto& e : r_.entries(pe.value, what, keyNames(type ? Section::PageType : Section::Page))) {
      if (e.key == "description") {
        if (auto s = r_.string(e.value, "description")) page.description = *s;
      } else if (e.key == "references") {
        if (!r_.expectList(e.value, "references")) continue;
        for (const auto& item : e.value) {
          if (auto s = r_.string(item, "a reference")) page.references.push_back({*s, r_.loc(item, e.loc)});
        }
      } else if (e.key == "places") {
        forEachNamed(e, "places", [&](const Entry& c) { page.places.push_back(readPlace(c)); });
      } else if (e.key == "transitions") {
        forEachNamed(e, "transitions", [&](const Entry& c) { page.transitions.push_back(readTransition(c)); });
      } else if (e.key == "arcs") {
        if (!r_.expectList(e.value, "arcs")) continue;
        for (const auto& item : e.value) {
          if (auto arc = readArc(item, e.loc)) page.arcs.push_back(std::move(*arc));
        }
      } else if (e.key == "instances") {
        forEachNamed(e, "instances", [&](const Entry& c) { page.instances.push_back(readInstance(c)); });
      } else if (e.key == "scene" && type_scenes_) {
        (*type_scenes_)[page.name] = detail::readScene(e.value, r_, e.loc, angles_);
      } else if (e.key == "part") {
        readPartMeta(e, part);
      } else if (e.key == "io") {
        readPartIo(e, part);
      } else if (e.key == "uses") {
        readPartUses(e, part);
      }
    }
    if (is_part && parts_) (*parts_)[page.name] = std::move(part);
  }

  /// A page type's `part`: how the palette shows it.
  void readPartMeta(const Entry& pe, PartSpec& part) {
    part.listed = true;
    if (pe.value.IsNull()) return;
    if (!r_.expectMap(pe.value, "part")) return;
    for (const auto& e : r_.entries(pe.value, "part", keyNames(Section::Part))) {
      if (e.key == "version") {
        if (auto v = r_.integer(e.value, "version")) {
          if (inRange(Section::Part, "version", static_cast<double>(*v))) {
            part.version = static_cast<int>(*v);
          } else {
            r_.error(e.value, "a part's version is a whole number from 1, got " + std::to_string(*v));
          }
        }
      } else if (auto text = r_.string(e.value, e.key)) {
        if (e.key == "group") part.group = *text;
        else if (e.key == "picture") part.picture = *text;
        else if (e.key == "control") part.control = *text;
        else if (e.key == "controls") part.controls = *text;
      }
    }
  }

  /// A control pattern's `uses`: the roles other parts fill.
  void readPartUses(const Entry& section, PartSpec& part) {
    if (section.value.IsNull() || !r_.expectMap(section.value, "uses")) return;
    for (const auto& e : r_.entries(section.value, "uses", {})) {
      if (!identifier(e, "a role's")) continue;
      if (core::isPythonKeyword(e.key)) {
        r_.error(e.loc, "role '" + e.key + "' is a word Python reserves: scripts could not write self.uses." + e.key);
        continue;
      }
      PartUse use;
      use.name = e.key;
      use.loc = e.loc;
      const std::string what = "role '" + use.name + "'";
      if (!r_.expectMap(e.value, what)) continue;
      for (const auto& f : r_.entries(e.value, what, keyNames(Section::PartUse))) {
        if (f.key == "io") {
          if (!r_.expectList(f.value, "io")) continue;
          for (const auto& item : f.value) {
            if (auto s = r_.string(item, "an I/O's name")) use.io.push_back(*s);
          }
        } else if (auto text = r_.string(f.value, f.key)) {
          if (f.key == "description") {
            use.description = *text;
          } else if (f.key == "optional") {
            if (!isChoice(Section::PartUse, f.key, *text)) {
              r_.error(f.value, "'optional' is true or false, got '" + *text + "'");
              continue;
            }
            use.optional = *text == "true";
          }
        }
      }
      if (use.io.empty()) {
        r_.error(e.loc, what + " needs 'io': the I/O a part must have to fill it");
        continue;
      }
      if (part.findUse(use.name)) continue;  // entries() reported the duplicate key
      part.uses.push_back(std::move(use));
    }
  }

  /// The texts of a digital output's `on` or `off`: one number, or a list of them (a vector
  /// field's), each a number, a `$param` or an `=expression`.
  std::vector<std::string> readOnOff(const Entry& e) {
    std::vector<std::string> out;
    const auto one = [&](const YAML::Node& n) {
      std::string bound;
      if (r_.number(n, e.key, &bound)) out.push_back(bound.empty() ? n.Scalar() : referenceText(bound));
    };
    if (e.value.IsSequence()) {
      for (const auto& n : e.value) one(n);
      if (out.size() != e.value.size()) out.clear();
    } else {
      one(e.value);
    }
    return out;
  }

  /// A page type's `io`: its named inputs and outputs.
  void readPartIo(const Entry& section, PartSpec& part) {
    if (section.value.IsNull() || !r_.expectMap(section.value, "io")) return;
    for (const auto& e : r_.entries(section.value, "io", {})) {
      if (!identifier(e, "an I/O's")) continue;
      PartIoSpec io;
      io.name = e.key;
      io.loc = e.loc;
      if (!r_.expectMap(e.value, "I/O '" + io.name + "'")) continue;
      bool has_direction = false;
      for (const auto& f : r_.entries(e.value, "I/O '" + io.name + "'", keyNames(Section::PartIo))) {
        if (f.key == "on" || f.key == "off") {
          (f.key == "on" ? io.on : io.off) = readOnOff(f);
          continue;
        }
        auto text = r_.string(f.value, f.key);
        if (!text) continue;
        if (f.key == "direction" || f.key == "signal") {
          if (!isChoice(Section::PartIo, f.key, *text)) {
            r_.error(f.value, "'" + f.key + "' is " + schema::choiceList(schema::key(Section::PartIo, f.key), "'") +
                                  ", got '" + *text + "'");
            continue;
          }
          if (f.key == "direction") {
            io.direction = *text == ioDirectionName(IoDirection::Input) ? IoDirection::Input : IoDirection::Output;
            has_direction = true;
          } else {
            io.signal = *text == ioSignalName(IoSignal::Digital) ? IoSignal::Digital : IoSignal::Analog;
          }
        } else if (f.key == "unit") {
          io.unit = *text;
        } else if (f.key == "description") {
          io.description = *text;
        } else if (f.key == "node") {
          if (!isNodePath(*text, true)) {
            r_.error(f.value, "'" + *text + "' is not a node path (names joined by '/', or `*` for every child)");
          }
          io.node = *text;
        } else if (f.key == "of") {
          io.of = *text;
        } else if (f.key == "field") {
          io.field = *text;
        }
      }
      const std::string name = "I/O '" + io.name + "'";
      if (!has_direction) {
        r_.error(e.loc, name + " needs 'direction': input (a sensor) or output (an actuator)");
        continue;
      }
      if (io.node.empty()) {
        r_.error(e.loc, name + " needs 'node', the node of the part's scene it is bound to");
        continue;
      }
      const bool input = io.direction == IoDirection::Input;
      if (input && (io.of.empty() || !io.field.empty())) {
        r_.error(e.loc, name + " is an input: it reads 'of' (active, reading, a channel, a field), not 'field'");
        continue;
      }
      if (input && io.node.find('*') != std::string::npos) {
        r_.error(e.loc, name + " is an input: it reads one node ('*' is for an output that sets several alike)");
        continue;
      }
      if (!input && (io.field.empty() || !io.of.empty())) {
        r_.error(e.loc, name + " is an output: it sets 'field' (speed, target1, emissive), not 'of'");
        continue;
      }
      if ((!io.on.empty() || !io.off.empty()) && (input || io.signal != IoSignal::Digital)) {
        r_.error(e.loc, name + ": 'on' and 'off' are for digital outputs");
        continue;
      }
      if (part.findIo(io.name)) continue;  // entries() reported the duplicate key
      part.io.push_back(std::move(io));
    }
  }

  template <class F>
  void forEachNamed(const Entry& section, const char* what, F&& f) {
    if (section.value.IsNull()) return;
    if (!r_.expectMap(section.value, what)) return;
    for (const auto& e : r_.entries(section.value, what, {})) f(e);
  }

  /// A per-slot map ("a0: 2") or a scalar for slot a0; calls `f(slot, value node, loc)`.
  template <class F>
  void perSlot(const Entry& e, const char* what, F&& f) {
    if (!e.value.IsMap()) {
      f(net::kDefaultSlot, e.value, r_.loc(e.value, e.loc));
      return;
    }
    forEachSlot(e.value, what, [&](net::SlotId slot, const Entry& s) { f(slot, s.value, s.loc); });
  }

  /// A position `[x, y]` in editor units, the value of key `key` (finite numbers only).
  std::optional<net::EditorPos> readPos(const YAML::Node& node, const std::string& key = "at") {
    if (!node.IsSequence() || node.size() != 2) {
      r_.error(node, "'" + key + "' expects a position [x, y], got " + detail::describe(node));
      return std::nullopt;
    }
    net::EditorPos at{};
    for (std::size_t i = 0; i < 2; ++i) {
      const char* axis = i == 0 ? "x" : "y";
      const auto v = r_.number(node[i], axis);
      if (!v) return std::nullopt;
      if (!std::isfinite(*v)) {
        r_.error(node[i], "'" + key + "': " + axis + " must be a finite number, got " + detail::describe(node[i]));
        return std::nullopt;
      }
      at[i] = *v;
    }
    return at;
  }

  /// An arc's bend points: a list of positions `[[x, y], ...]`, editor units.
  std::vector<net::EditorPos> readRoute(const YAML::Node& node) {
    std::vector<net::EditorPos> route;
    if (!node.IsSequence()) {
      r_.error(node, "'via' expects a list of bend points [[x, y], ...], got " + detail::describe(node));
      return route;
    }
    for (const auto& item : node) {
      const auto at = readPos(item, "via");
      if (!at) return {};
      route.push_back(*at);
    }
    return route;
  }

  std::vector<std::string> readNodeList(const YAML::Node& list, const SourceLoc& fallback) {
    std::vector<std::string> names;
    for (const auto& item : list) {
      auto s = r_.string(item, "a node token");
      if (!s) continue;
      if (!isNodePath(*s)) {
        r_.error(r_.loc(item, fallback), "node token '" + *s + "' is not a node path (names joined by '/')");
        continue;
      }
      names.push_back(*s);
    }
    return names;
  }

  net::PlaceSpec readPlace(const Entry& pe) {
    net::PlaceSpec p;
    p.name = pe.key;
    p.loc = pe.loc;
    if (pe.value.IsNull()) return p;
    if (!r_.expectMap(pe.value, "place '" + p.name + "'")) return p;
    for (const auto& e : r_.entries(pe.value, "place", keyNames(Section::Place))) {
      if (e.key == "description") {
        if (auto s = r_.string(e.value, "description")) p.description = *s;
      } else if (e.key == "fusion") {
        if (auto s = r_.string(e.value, "fusion")) p.fusion = *s, p.fusion_loc = r_.loc(e.value, e.loc);
      } else if (e.key == "slots") {
        if (!r_.expectMap(e.value, "slots")) continue;
        perSlot(e, "slots", [&](net::SlotId slot, const YAML::Node& v, const SourceLoc& loc) {
          auto s = r_.string(v, "a slot kind");
          if (!s) return;
          auto kind = net::parseSlotKind(*s);
          if (!kind) {
            const auto& slots = schema::key(Section::Place, "slots");
            r_.error(v, "unknown slot kind '" + *s + "'" + core::didYouMean(*s, slots.choices) + "; expected " +
                            schema::choiceList(slots));
            return;
          }
          p.kinds.push_back({slot, *kind, loc});
        });
      } else if (e.key == "tokens") {
        perSlot(e, "tokens", [&](net::SlotId slot, const YAML::Node& v, const SourceLoc& loc) {
          if (v.IsSequence()) {
            p.nodes.push_back({slot, readNodeList(v, loc), loc});
          } else if (std::string param; auto n = r_.integer(v, "tokens", &param)) {
            p.tokens.push_back({slot, *n, loc, param});
          }
        });
      } else if (e.key == "colour") {
        perSlot(e, "colour", [&](net::SlotId slot, const YAML::Node& v, const SourceLoc& loc) {
          const SourceLoc at = detail::textStart(v, loc, source_, r_);
          if (!v.IsScalar()) {
            r_.error(at, "'colour' expects the name of a colour set, got " + detail::describe(v));
          } else if (!core::isIdentifier(v.Scalar())) {
            r_.error(at, "'colour' expects the name of a colour set, got '" + v.Scalar() + "'");
          } else {
            p.colours.push_back({slot, v.Scalar(), at});
          }
        });
      } else if (e.key == "values") {
        perSlot(e, "values", [&](net::SlotId slot, const YAML::Node& v, const SourceLoc& loc) {
          if (auto text = detail::readInscription(v, loc, slot, "values", source_, r_)) p.values.push_back(std::move(*text));
        });
      } else if (e.key == "continuous") {
        p.fluid = readContinuous(e);
      } else if (e.key == "capacity") {
        perSlot(e, "capacity", [&](net::SlotId slot, const YAML::Node& v, const SourceLoc& loc) {
          std::string param;
          if (auto n = r_.integer(v, "capacity", &param)) p.capacity.push_back({slot, *n, loc, param});
        });
      } else if (e.key == "sensors") {
        if (!r_.expectMap(e.value, "sensors")) continue;
        forEachSlot(e.value, "sensors", [&](net::SlotId slot, const Entry& s) {
          auto path = r_.string(s.value, "a sensor path");
          if (!path) return;
          if (!isNodePath(*path)) {
            r_.error(r_.loc(s.value, s.loc), "sensor '" + *path + "' is not a node path (names joined by '/')");
            return;
          }
          p.sensors.push_back({slot, *path, r_.loc(s.value, s.loc)});
        });
      } else if (const auto kind = net::parseScriptKind(e.key, net::ScriptOwner::PlaceSlot)) {
        // on_deposit, on_remove, on_enter, on_exit, on_sample, on_change: a script per slot;
        // a sensor's scripts go to the first sensor slot unless they name one
        const bool any_slot = *kind == net::ScriptKind::OnDeposit || *kind == net::ScriptKind::OnRemove;
        const net::SlotId fallback = any_slot || p.sensors.empty() ? net::kDefaultSlot : p.sensors.front().slot;
        perSlotScript(e, e.key, fallback, [&](net::SlotId slot, net::ScriptSpec script) {
          auto it = std::find_if(p.scripts.begin(), p.scripts.end(),
                                 [&](const net::SlotScripts& ss) { return ss.slot == slot; });
          if (it == p.scripts.end()) it = p.scripts.insert(p.scripts.end(), net::SlotScripts{slot, {}, {}, {}, {}, {}, {}});
          net::scriptOf(*it, *kind) = std::move(script);
        });
      } else if (e.key == "at") {
        p.position = readPos(e.value);
      }
    }
    checkValueSlots(p);
    return p;
  }

  /// A place's value slots: each has a colour, and a slot with a colour holds nothing else.
  void checkValueSlots(const net::PlaceSpec& p) {
    const auto colourOf = [&](net::SlotId slot) {
      return std::find_if(p.colours.begin(), p.colours.end(), [&](const net::SlotText& c) { return c.slot == slot; });
    };
    for (const auto& k : p.kinds) {
      const bool coloured = colourOf(k.slot) != p.colours.end();
      if (k.kind == net::SlotKind::Value && !coloured) {
        r_.error(k.loc, "value slot " + net::slotName(k.slot) + " of place '" + p.name +
                            "' has no colour: name its colour set in 'colour'");
      } else if (k.kind != net::SlotKind::Value && coloured) {
        r_.error(colourOf(k.slot)->loc, "slot " + net::slotName(k.slot) + " of place '" + p.name + "' is a " +
                                            net::slotKindName(k.kind) + " slot: only a value slot has a colour");
      }
    }
    for (const auto& c : p.colours) {
      const std::string slot = net::slotName(c.slot);
      const auto on = [&](const auto& list) {
        return std::any_of(list.begin(), list.end(), [&](const auto& x) { return x.slot == c.slot; });
      };
      if (on(p.sensors)) {
        r_.error(c.loc, "slot " + slot + " of place '" + p.name + "' is bound to a sensor: only a value slot has a colour");
      } else if (on(p.nodes)) {
        r_.error(c.loc, "slot " + slot + " of place '" + p.name + "' holds node tokens: only a value slot has a colour");
      } else if (on(p.tokens)) {
        r_.error(c.loc, "value slot " + slot + " of place '" + p.name +
                            "' has 'tokens': a value slot's initial tokens are its 'values'");
      }
    }
    for (const auto& v : p.values) {
      if (colourOf(v.slot) != p.colours.end()) continue;
      r_.error(v.loc, "'values' on slot " + net::slotName(v.slot) + " of place '" + p.name +
                          "', which has no colour: a value slot names its colour set in 'colour'");
    }
  }

  net::Duration readDuration(const Entry& e) {
    net::Duration d;
    d.loc = e.loc;
    if (!e.value.IsMap()) {
      d.loc = r_.loc(e.value, e.loc);
      if (auto v = r_.number(e.value, "duration", &d.params[0])) {
        d.a = *v;
        // a duration of 0 written (or a parameter of 0): immediate, within the firing phase
        if (*v == 0.0) d.law = net::Duration::Law::Immediate;
      }
      return d;
    }
    auto laws = r_.entries(e.value, "duration", keyNames(Section::Duration));
    if (laws.size() != 1) {
      r_.error(e.loc, "duration expects a number of seconds or one law: {uniform: [lo, hi]}, "
                      "{normal: [mean, sd]} or {exponential: mean}");
      return d;
    }
    const auto& law = laws[0];
    d.loc = law.loc;
    if (law.key == "exponential") {
      d.law = net::Duration::Law::Exponential;
      d.loc = r_.loc(law.value, law.loc);
      if (auto v = r_.number(law.value, "exponential mean", &d.params[0])) d.a = *v;
      return d;
    }
    d.law = law.key == "uniform" ? net::Duration::Law::Uniform : net::Duration::Law::Normal;
    if (!law.value.IsSequence() || law.value.size() != 2) {
      r_.error(r_.loc(law.value, law.loc), law.key + " expects two numbers, " +
                                               (law.key == "uniform" ? "[lo, hi]" : "[mean, sd]") + ", got " +
                                               detail::describe(law.value));
      return d;
    }
    auto a = r_.number(law.value[0], law.key, &d.params[0]);
    auto b = r_.number(law.value[1], law.key, &d.params[1]);
    if (a && b) {
      d.a = *a;
      d.b = *b;
    }
    return d;
  }

  /// A place's `continuous`: `true`, or a map of its amount, capacity, unit and drives.
  std::optional<net::FluidSpec> readContinuous(const Entry& e) {
    net::FluidSpec f;
    f.loc = e.loc;
    if (e.value.IsScalar()) {
      if (e.value.Scalar() == "true") return f;
      if (e.value.Scalar() == "false") return std::nullopt;
      r_.error(e.value, "'continuous' expects true or a map {amount, capacity, unit, drives}, got " + detail::describe(e.value));
      return std::nullopt;
    }
    if (!r_.expectMap(e.value, "continuous")) return std::nullopt;
    for (const auto& c : r_.entries(e.value, "continuous", keyNames(Section::Continuous))) {
      if (c.key == "amount") {
        if (auto x = r_.number(c.value, "amount")) {
          if (*x < 0.0) r_.error(c.value, "'amount' must be >= 0, got " + c.value.Scalar());
          else f.amount = *x;
        }
      } else if (c.key == "capacity") {
        if (auto x = r_.number(c.value, "capacity")) {
          if (!(*x > 0.0)) r_.error(c.value, "'capacity' must be > 0, got " + c.value.Scalar());
          else f.capacity = *x;
        }
      } else if (c.key == "unit") {
        if (auto u = r_.string(c.value, "unit")) f.unit = *u;
      } else if (c.key == "drives") {
        if (!r_.expectList(c.value, "drives")) continue;
        for (const auto& item : c.value) {
          if (!r_.expectMap(item, "a drive")) continue;
          net::FluidDrive d;
          d.loc = r_.loc(item, c.loc);
          for (const auto& k : r_.entries(item, "drive", keyNames(Section::Drive))) {
            if (k.key == "node") {
              if (auto v = r_.string(k.value, "node")) d.node = *v;
            } else if (k.key == "field") {
              if (auto v = r_.string(k.value, "field")) d.field = *v;
            } else if (k.key == "scale") {
              if (auto v = r_.number(k.value, "scale")) d.scale = *v;
            } else if (k.key == "offset") {
              if (auto v = r_.number(k.value, "offset")) d.offset = *v;
            }
          }
          if (d.node.empty() || d.field.empty()) r_.error(d.loc, "a drive names a 'node' and its 'field'");
          else f.drives.push_back(std::move(d));
        }
      }
    }
    return f;
  }

  /// A transition's `continuous`: its rate and what of the plant the rate reads.
  std::optional<net::FlowSpec> readFlow(const Entry& e) {
    net::FlowSpec f;
    f.loc = e.loc;
    if (const auto* params = r_.params()) {
      for (const auto& [name, value] : *params) f.params.emplace_back(name, value.value);
    }
    if (!r_.expectMap(e.value, "continuous")) return std::nullopt;
    for (const auto& c : r_.entries(e.value, "continuous", keyNames(Section::Flow))) {
      if (c.key == "rate") {
        if (!c.value.IsScalar() || c.value.Scalar().empty()) {
          r_.error(r_.loc(c.value, c.loc), "'rate' expects a number or an expression, got " + detail::describe(c.value));
          continue;
        }
        f.rate.text = c.value.Scalar();
        f.rate.loc = detail::textStart(c.value, c.loc, source_, r_);
      } else if (c.key == "reads") {
        if (!r_.expectMap(c.value, "reads")) continue;
        for (const auto& re : r_.entries(c.value, "reads", {})) {
          net::FlowRead read;
          read.name = re.key;
          read.loc = re.loc;
          if (!core::isIdentifier(re.key)) {
            r_.error(re.loc, "a read's name is a name a rate can use (letters, digits, _), not '" + re.key + "'");
            continue;
          }
          if (!r_.expectMap(re.value, "read '" + re.key + "'")) continue;
          for (const auto& k : r_.entries(re.value, "read", keyNames(Section::FlowRead))) {
            if (k.key == "node") {
              if (auto v = r_.string(k.value, "node")) read.node = *v;
            } else if (k.key == "of") {
              if (auto v = r_.string(k.value, "of")) read.of = *v;
            }
          }
          if (read.node.empty() || read.of.empty()) r_.error(read.loc, "read '" + read.name + "' names a 'node' and what it reads 'of' it");
          else f.reads.push_back(std::move(read));
        }
      }
    }
    return f;
  }

  net::TransitionSpec readTransition(const Entry& te) {
    net::TransitionSpec t;
    t.name = te.key;
    t.loc = te.loc;
    t.duration.loc = te.loc;
    t.probability_loc = te.loc;
    t.servers_loc = te.loc;
    if (te.value.IsNull()) return t;
    if (!r_.expectMap(te.value, "transition '" + t.name + "'")) return t;
    for (const auto& e : r_.entries(te.value, "transition", keyNames(Section::Transition))) {
      if (e.key == "description") {
        if (auto s = r_.string(e.value, "description")) t.description = *s;
      } else if (e.key == "duration") {
        t.duration = readDuration(e);
      } else if (e.key == "priority") {
        if (auto v = r_.integer(e.value, "priority", &t.priority_param)) t.priority = *v;
      } else if (e.key == "probability") {
        t.probability_loc = r_.loc(e.value, e.loc);
        if (auto v = r_.number(e.value, "probability", &t.probability_param)) t.probability = *v;
      } else if (e.key == "servers") {
        t.servers_loc = r_.loc(e.value, e.loc);
        long long whole = 0;
        const bool word = e.value.IsScalar() && !e.value.Scalar().starts_with('$') &&
                          !YAML::convert<long long>::decode(e.value, whole);
        if (word && e.value.Scalar() == "unlimited") {
          t.servers = net::kUnlimitedServers;
        } else if (word) {
          r_.error(e.value, "'servers' expects a whole number of at least 1 or 'unlimited', got '" + e.value.Scalar() + "'");
        } else if (auto v = r_.integer(e.value, "servers", &t.servers_param)) {
          if (*v >= 1) t.servers = *v;
          else r_.error(e.value, "'servers' expects a whole number of at least 1 or 'unlimited', got " + std::to_string(*v));
        }
      } else if (e.key == "continuous") {
        t.flow = readFlow(e);
      } else if (e.key == "when") {
        if (auto text = detail::readInscription(e.value, e.loc, net::kDefaultSlot, "when", source_, r_)) {
          t.when = std::move(*text);
        }
      } else if (const auto kind = net::parseScriptKind(e.key, net::ScriptOwner::Transition)) {
        net::scriptOf(t, *kind) = readScript(e, e.key);
      } else if (e.key == "at") {
        t.position = readPos(e.value);
      }
    }
    return t;
  }

  std::optional<net::ArcSpec> readArc(const YAML::Node& node, const SourceLoc& fallback) {
    net::ArcSpec a;
    a.loc = r_.loc(node, fallback);
    if (node.IsScalar()) {
      // shorthand "P1 -> T1"
      const std::string text = node.Scalar();
      const auto arrow = text.find("->");
      auto trim = [](std::string s) {
        const auto b = s.find_first_not_of(' ');
        const auto e = s.find_last_not_of(' ');
        return b == std::string::npos ? std::string() : s.substr(b, e - b + 1);
      };
      if (arrow == std::string::npos || trim(text.substr(0, arrow)).empty() ||
          trim(text.substr(arrow + 2)).empty()) {
        r_.error(node, "an arc is written 'from -> to' or {from: ..., to: ...}, got \"" + text + "\"");
        return std::nullopt;
      }
      a.from = trim(text.substr(0, arrow));
      a.to = trim(text.substr(arrow + 2));
      a.from_loc = a.to_loc = a.loc;
      return a;
    }
    if (!r_.expectMap(node, "an arc")) return std::nullopt;
    bool has_from = false, has_to = false;
    std::optional<Entry> predicate, condition;
    for (const auto& e : r_.entries(node, "arc", keyNames(Section::Arc))) {
      if (e.key == "predicate") predicate = e;
      if (e.key == "condition") condition = e;
      if (e.key == "from") {
        if (auto s = r_.string(e.value, "from")) a.from = *s, has_from = true;
        a.from_loc = r_.loc(e.value, e.loc);
      } else if (e.key == "to") {
        if (auto s = r_.string(e.value, "to")) a.to = *s, has_to = true;
        a.to_loc = r_.loc(e.value, e.loc);
      } else if (e.key == "kind") {
        auto s = r_.string(e.value, "kind");
        if (!s) continue;
        const auto& kinds = schema::key(Section::Arc, "kind");
        if (*s == "normal") a.kind = net::ArcKind::Normal;
        else if (*s == "test") a.kind = net::ArcKind::Test;
        else if (*s == "inhibitor") a.kind = net::ArcKind::Inhibitor;
        else r_.error(e.value, "unknown arc kind '" + *s + "'" + core::didYouMean(*s, kinds.choices) + "; expected " +
                                   schema::choiceList(kinds));
      } else if (e.key == "weight") {
        perSlot(e, "weight", [&](net::SlotId slot, const YAML::Node& v, const SourceLoc& loc) {
          std::string param;
          // a number that is not whole (or a parameter holding one): the weight of an arc with
          // a continuous place
          if (v.IsScalar() && slot == net::kDefaultSlot) {
            std::optional<double> x;
            if (v.Scalar().starts_with('$')) {
              x = r_.number(v, "weight", &param);
              if (!x) return;
            } else {
              x = core::parseNumber(v.Scalar());
            }
            if (x && *x != std::floor(*x)) {
              if (!(*x > 0.0)) r_.error(v, "'weight' must be > 0, got " + core::formatDouble(*x));
              else a.amount = *x, a.amount_param = param;
              return;
            }
          }
          if (auto n = r_.integer(v, "weight", &param)) a.weights.push_back({slot, *n, loc, param});
        });
      } else if (e.key == "inscription") {
        perSlot(e, "inscription", [&](net::SlotId slot, const YAML::Node& v, const SourceLoc& loc) {
          if (auto text = detail::readInscription(v, loc, slot, "inscription", source_, r_)) {
            a.inscriptions.push_back(std::move(*text));
          }
        });
      } else if (e.key == "via") {
        a.via = readRoute(e.value);
      } else if (e.key == "label_at") {
        a.label_at = readPos(e.value, "label_at");
      }
    }
    if (predicate) {
      // a lone predicate applies to the arc's one weighted slot (a0 when it names none)
      const net::SlotId only = a.weights.size() == 1 ? a.weights[0].slot : net::kDefaultSlot;
      perSlotScript(*predicate, "predicate", only, [&](net::SlotId slot, net::ScriptSpec script) {
        a.predicates.push_back({slot, std::move(script)});
      });
    }
    if (condition) {
      // a lone condition reads sensor slot c0
      perSlotScript(*condition, "condition", net::parseSlot("c0").value(),
                    [&](net::SlotId slot, net::ScriptSpec script) { a.conditions.push_back({slot, std::move(script)}); });
    }
    // a value slot's arc says what it moves in its inscription, not by a count
    for (const auto& i : a.inscriptions) {
      if (std::any_of(a.weights.begin(), a.weights.end(), [&](const net::SlotCount& w) { return w.slot == i.slot; })) {
        r_.error(i.loc, "slot " + net::slotName(i.slot) +
                            " has both 'weight' and 'inscription': an inscription says how many values the arc moves "
                            "(`2'x`)");
      }
    }
    if (!has_from) r_.error(a.loc, "arc has no 'from'");
    if (!has_to) r_.error(a.loc, "arc has no 'to'");
    if (!has_from || !has_to) return std::nullopt;
    return a;
  }

  net::InstanceSpec readInstance(const Entry& ie) {
    net::InstanceSpec i;
    i.name = ie.key;
    i.loc = ie.loc;
    i.type_loc = ie.loc;
    if (ie.value.IsScalar()) {
      // shorthand "cellA: cell"
      i.type = ie.value.Scalar();
      i.type_loc = r_.loc(ie.value, ie.loc);
      return i;
    }
    if (!r_.expectMap(ie.value, "instance '" + i.name + "'")) return i;
    bool has_type = false;
    for (const auto& e : r_.entries(ie.value, "instance", keyNames(Section::Instance))) {
      if (e.key == "type") {
        if (auto s = r_.string(e.value, "type")) i.type = *s, has_type = true;
        i.type_loc = r_.loc(e.value, e.loc);
      } else if (e.key == "at") {
        i.position = readPos(e.value);
      } else if (e.key == "translation" || e.key == "rotation") {
        const std::size_t n = e.key == "translation" ? 3 : 4;
        if (!e.value.IsSequence() || e.value.size() != n) {
          r_.error(r_.loc(e.value, e.loc), "'" + e.key + "' expects " +
                                               (n == 3 ? "[x, y, z]" : "[axis x, axis y, axis z, degrees]") +
                                               ", got " + detail::describe(e.value));
          continue;
        }
        std::array<double, 4> v{};
        bool ok = true;
        for (std::size_t k = 0; k < n; ++k) {
          auto x = r_.number(e.value[k], e.key);
          ok = ok && x;
          if (x) v[k] = *x;
        }
        if (!ok) continue;
        if (n == 3) i.translation = {v[0], v[1], v[2]};
        else i.rotation = v;
      } else if (e.key == "params") {
        if (e.value.IsNull() || !r_.expectMap(e.value, "params")) continue;
        for (const auto& p : r_.entries(e.value, "params", {})) {
          if (auto v = r_.number(p.value, p.key)) {
            if (!std::isfinite(*v)) {
              r_.error(p.value, "parameter '" + p.key + "' must be a finite number");
              continue;
            }
            i.params.push_back({p.key, *v, p.loc});
          }
        }
      } else if (e.key == "part") {
        if (auto s = r_.string(e.value, "part")) i.part = *s;
        i.part_loc = r_.loc(e.value, e.loc);
      } else if (e.key == "uses") {
        if (e.value.IsNull() || !r_.expectMap(e.value, "uses")) continue;
        for (const auto& u : r_.entries(e.value, "uses", {})) {
          if (auto s = r_.string(u.value, u.key)) i.uses.push_back({u.key, *s, r_.loc(u.value, u.loc)});
        }
      }
    }
    if (!has_type) r_.error(ie.loc, "instance '" + i.name + "' has no 'type'");
    return i;
  }

  YamlReader r_;
  std::map<std::string, std::shared_ptr<const scene::Scene>>* type_scenes_ = nullptr;
  std::map<std::string, PartSpec>* parts_ = nullptr;
  scene::AngleUnit angles_ = scene::AngleUnit::Degrees;  // the unit the file writes angles in
  std::string file_;
  const std::string& text_;
  detail::SourceMap source_;  // the text's lines, to locate an inscription's characters
  const std::vector<ParamOverride>& overrides_;
  std::map<std::string, detail::ParamValue> param_values_;
};

}  // namespace

void keepParamsOf(Model& fragment, const std::vector<Param>& declared) {
  const auto undeclared = [&](const std::string& name) {
    return std::none_of(declared.begin(), declared.end(), [&](const Param& p) { return p.name == name; });
  };
  // a reference the model does not declare; an expression's, when any name it reads
  const auto unknown = [&](const std::string& name) {
    if (name.empty()) return false;
    if (name[0] != '=') return undeclared(name);
    const auto names = core::expressionNames(std::string_view(name).substr(1));
    return std::any_of(names.begin(), names.end(), undeclared);
  };
  const auto counts = [&](std::vector<net::SlotCount>& list) {
    for (auto& c : list) {
      if (unknown(c.param)) c.param.clear();
    }
  };
  for (auto* pages : {&fragment.net.pages, &fragment.net.page_types}) {
    for (auto& page : *pages) {
      for (auto& p : page.places) counts(p.tokens), counts(p.capacity);
      for (auto& a : page.arcs) counts(a.weights);
      for (auto& t : page.transitions) {
        for (auto& name : t.duration.params) {
          if (unknown(name)) name.clear();
        }
        if (unknown(t.priority_param)) t.priority_param.clear();
        if (unknown(t.probability_param)) t.probability_param.clear();
        if (unknown(t.servers_param)) t.servers_param.clear();
      }
    }
  }
  if (!fragment.scene) return;
  auto scene = fragment.scene->clone();
  scene::traverse(scene->root(), [&](scene::Node& n, const scene::TraversalState&) {
    std::erase_if(n.params, [&](const auto& b) { return unknown(b.text); });
  });
  fragment.scene = std::move(scene);
  fragment.params.clear();
}

std::optional<ParamOverride> parseParamArgument(const std::string& argument) {
  const auto eq = argument.find('=');
  if (eq == std::string::npos || eq == 0) return std::nullopt;
  return ParamOverride{argument.substr(0, eq), argument.substr(eq + 1)};
}

std::optional<Model> parseModel(const std::string& text, const std::string& file, Diagnostics& diags,
                                const std::vector<ParamOverride>& params) {
  auto root = detail::parseYaml(text, file, diags);
  if (!root) return std::nullopt;
  auto model = ModelReader(file, text, diags, params).read(*root);
  if (model) model->path = file;
  return model;
}

std::optional<Model> loadModel(const std::string& path, Diagnostics& diags, const std::vector<ParamOverride>& params) {
  auto text = core::readFile(path, diags);
  if (!text) return std::nullopt;
  return parseModel(*text, path, diags, params);
}

std::optional<std::vector<sensors::InputEvent>> loadInput(const std::string& path, Diagnostics& diags) {
  auto text = core::readFile(path, diags);
  if (!text) return std::nullopt;
  auto root = detail::parseYaml(*text, path, diags);
  if (!root) return std::nullopt;
  YamlReader r(path, diags);
  std::vector<sensors::InputEvent> events;
  if (root->IsNull()) return events;
  if (!r.expectList(*root, "an input file")) return std::nullopt;
  auto vec3 = [&](const YAML::Node& n, const char* what) -> std::optional<core::Vec3> {
    if (!n.IsSequence() || n.size() != 3) {
      r.error(n, std::string("'") + what + "' expects [x, y, z], got " + detail::describe(n));
      return std::nullopt;
    }
    auto x = r.number(n[0], what), y = r.number(n[1], what), z = r.number(n[2], what);
    if (!x || !y || !z) return std::nullopt;
    return core::Vec3{*x, *y, *z};
  };
  for (const auto& item : *root) {
    if (!r.expectMap(item, "an input event")) continue;
    sensors::InputEvent ev;
    ev.loc = r.loc(item);
    int kinds = 0;
    bool has_t = false;
    for (const auto& e : r.entries(item, "an input event", {"t", "key", "down", "click", "viewpoint"})) {
      if (e.key == "t") {
        if (auto t = r.number(e.value, "t")) {
          if (*t < 0 || !std::isfinite(*t)) r.error(e.value, "'t' must be a time of at least 0 seconds");
          ev.t = *t;
          has_t = true;
        }
      } else if (e.key == "key") {
        ++kinds;
        ev.kind = sensors::InputEvent::Kind::Key;
        if (auto k = r.string(e.value, "key")) ev.key = *k;
      } else if (e.key == "down") {
        bool b = true;
        if (e.value.IsScalar() && YAML::convert<bool>::decode(e.value, b)) ev.down = b;
        else r.error(e.value, "'down' expects true or false, got " + detail::describe(e.value));
      } else if (e.key == "click") {
        ++kinds;
        ev.kind = sensors::InputEvent::Kind::Click;
        if (!r.expectMap(e.value, "click")) continue;
        std::optional<core::Vec3> from, to;
        for (const auto& c : r.entries(e.value, "click", {"from", "to"})) {
          (c.key == "from" ? from : to) = vec3(c.value, c.key == "from" ? "from" : "to");
        }
        if (!from || !to) {
          r.error(e.loc, "a click needs 'from' and 'to' points");
          continue;
        }
        ev.ray = {*from, (*to - *from).normalized()};
      } else if (e.key == "viewpoint") {
        ++kinds;
        ev.kind = sensors::InputEvent::Kind::Viewpoint;
        if (auto p = vec3(e.value, "viewpoint")) ev.position = *p;
      }
    }
    if (!has_t) r.error(ev.loc, "an input event needs its time 't'");
    if (kinds != 1) r.error(ev.loc, "an input event is one of: key, click, viewpoint");
    events.push_back(std::move(ev));
  }
  if (r.failed()) return std::nullopt;
  std::stable_sort(events.begin(), events.end(), [](const auto& a, const auto& b) { return a.t < b.t; });
  return events;
}

bool startsNewModel(const std::string& path) {
  if (!path.ends_with(kModelSuffix)) return false;
  std::error_code ec;
  // a link (a dangling one too) is no new model: what it names is not this path's to write
  if (std::filesystem::is_symlink(path, ec)) return false;
  if (!std::filesystem::exists(path, ec)) return !ec;
  if (!std::filesystem::is_regular_file(path, ec)) return false;
  std::ifstream in(path, std::ios::binary);
  if (!in.is_open()) return false;  // unreadable: loading it says why, nothing writes over it
  char c = 0;
  while (in.get(c)) {
    if (c != ' ' && c != '\n' && c != '\r' && c != '\t') return false;
  }
  return !in.bad();
}

Model emptyModel(const std::string& path) {
  Model model;
  model.path = path;
  net::PageSpec main;
  main.name = "main";
  model.net.pages.push_back(std::move(main));
  model.scene = std::make_shared<scene::Scene>();
  return model;
}

std::string untitledModelPath(const std::string& folder) {
  const std::filesystem::path dir(folder);
  std::error_code ec;
  std::string name = std::string("untitled") + kModelSuffix;
  for (int n = 2; std::filesystem::exists(dir / name, ec); ++n)
    name = "untitled-" + std::to_string(n) + kModelSuffix;
  return (dir / name).string();
}

std::optional<std::string> resolveModelPath(const std::string& arg, Diagnostics& diags) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::path p(arg);
  if (fs::is_directory(p, ec)) {
    std::vector<std::string> found;
    for (const auto& entry : fs::directory_iterator(p, ec)) {
      const std::string name = entry.path().filename().string();
      if (name.size() > std::string(kModelSuffix).size() && name.ends_with(kModelSuffix)) {
        found.push_back(entry.path().string());
      }
    }
    std::sort(found.begin(), found.end());
    if (found.size() == 1) return found[0];
    if (found.empty()) {
      diags.error({arg, 0, 0}, std::string("folder holds no model file (*") + kModelSuffix + ")");
    } else {
      std::string list;
      for (const auto& f : found) list += (list.empty() ? "" : ", ") + fs::path(f).filename().string();
      diags.error({arg, 0, 0}, "folder holds " + std::to_string(found.size()) + " model files (" + list +
                                   "); name one");
    }
    return std::nullopt;
  }
  if (!fs::exists(p, ec)) {
    diags.error({arg, 0, 0}, "no such file or folder");
    return std::nullopt;
  }
  return arg;
}

}  // namespace gdpn::model

// Reading replay files: a YAML list of one-key maps, each an action, located for messages.

#include "gdpn/ide/replay.h"

#include "gdpn/ide/actions.h"
#include "gdpn/session/breakpoint_syntax.h"

#include <yaml-cpp/yaml.h>

#include <cmath>
#include <fstream>
#include <sstream>

namespace gdpn::ide {

namespace {

core::SourceLoc locOf(const YAML::Node& node, const std::string& file) {
  const auto m = node.Mark();
  return {file, m.line + 1, m.column + 1};
}

/// Reads one action; false after an error.
class ActionReader {
 public:
  ActionReader(const std::string& file, core::Diagnostics& diags) : file_(file), diags_(diags) {}

  bool read(const YAML::Node& item, Action& a) {
    if (!item.IsMap() || item.size() != 1) return fail(item, "an action is a map with one key, such as 'press: step'");
    // copies: the iterator's pair dies with it
    const auto entry = *item.begin();
    const YAML::Node name = entry.first;
    const YAML::Node v = entry.second;
    const auto key = name.as<std::string>();
    a.loc = locOf(name, file_);
    if (key == "select") return word(v, a, ActionKind::Select);
    if (key == "fire") return word(v, a, ActionKind::Fire);
    if (key == "key") return word(v, a, ActionKind::Key);
    if (key == "type") return word(v, a, ActionKind::Type);
    if (key == "hold" || key == "release") {
      a.field = key;
      return word(v, a, ActionKind::Key);
    }
    if (key == "view") return word(v, a, ActionKind::View);
    if (key == "screenshot") return word(v, a, ActionKind::Screenshot);
    if (key == "press") {
      if (!word(v, a, ActionKind::Press)) return false;
      if (findAction(a.text)) return true;
      return fail(v, "unknown action '" + a.text + "' (" + actionNames() + ")");
    }
    if (key == "run") return number(v, a, ActionKind::RunFor, false);
    if (key == "steps") return number(v, a, ActionKind::Steps, true);
    if (key == "frames") return v.IsMap() ? slowFrames(v, a) : number(v, a, ActionKind::Frames, true);
    if (key == "click") {
      a.kind = ActionKind::Click;
      if (v.IsMap()) {
        if (!v["at"]) return fail(v, "expects {at: [X, Y] or [VIEW, KEY, ...], button: left|right|middle}");
        return target(v["at"], a.x, a.y, a.on) && button(v, a);
      }
      return target(v, a.x, a.y, a.on);
    }
    if (key == "drag") return drag(v, a);
    if (key == "wheel") return wheel(v, a);
    if (key == "set") return set(v, a);
    if (key == "break") return breakpoint(v, a);
    return fail(name, "unknown action '" + key +
                                         "' (select, press, fire, run, steps, frames, key, hold, release, type, click, drag, wheel, set, view, "
                                         "screenshot)");
  }

 private:
  bool fail(const YAML::Node& at, const std::string& message) {
    diags_.error(locOf(at, file_), message);
    return false;
  }
  bool word(const YAML::Node& v, Action& a, ActionKind kind) {
    a.kind = kind;
    if (!v.IsScalar() || v.Scalar().empty()) return fail(v, "expects a name");
    a.text = v.Scalar();
    return true;
  }
  bool number(const YAML::Node& v, Action& a, ActionKind kind, bool whole) {
    a.kind = kind;
    double x = 0;
    if (!v.IsScalar() || !YAML::convert<double>::decode(v, x) || !(x >= 0 && x <= 1e7)) {
      return fail(v, whole ? "expects a whole number from 0 to 10^7" : "expects seconds from 0 to 10^7");
    }
    if (whole && x != static_cast<double>(static_cast<long long>(x))) return fail(v, "expects a whole number");
    a.number = x;
    return true;
  }
  /// A point [X, Y] in window pixels, or where the last frame's report says an item stands:
  /// the keys that lead to it ([tree, rows, belt]).
  bool target(const YAML::Node& v, double& x, double& y, std::vector<std::string>& keys) {
    if (v.IsSequence() && v.size() >= 2 && v[0].IsScalar() && !YAML::convert<double>::decode(v[0], x)) {
      for (const auto& k : v) {
        if (!k.IsScalar()) return fail(k, "an item is named by the report's keys that lead to it");
        keys.push_back(k.Scalar());
      }
      return true;
    }
    if (!v.IsSequence() || v.size() != 2 || !YAML::convert<double>::decode(v[0], x) ||
        !YAML::convert<double>::decode(v[1], y)) {
      return fail(v, "expects a point [X, Y] in window pixels, or an item as the report's keys [VIEW, KEY, ...]");
    }
    return true;
  }
  bool drag(const YAML::Node& v, Action& a) {
    a.kind = ActionKind::Drag;
    if (!v.IsMap() || !v["from"] || !v["to"]) return fail(v, "expects {from: [X, Y], to: [X, Y], button: left|right|middle, hold: true|false}");
    if (!target(v["from"], a.x, a.y, a.on) || !target(v["to"], a.x2, a.y2, a.on2)) return false;
    if (const auto h = v["hold"]) {
      if (!h.IsScalar() || !YAML::convert<bool>::decode(h, a.hold)) return fail(h, "expects hold: true or false");
    }
    return button(v, a);
  }
  bool button(const YAML::Node& v, Action& a) {
    if (const auto b = v["button"]) {
      const auto name = b.IsScalar() ? b.Scalar() : std::string();
      if (name == "left") a.button = 0;
      else if (name == "right") a.button = 1;
      else if (name == "middle") a.button = 2;
      else return fail(b, "expects a button: left, right or middle");
    }
    return true;
  }
  /// `frames: {count: N, seconds: S}`: N frames, each standing for S wall seconds.
  bool slowFrames(const YAML::Node& v, Action& a) {
    const char* kUsage = "expects {count: N, seconds: S}: N frames, each S wall seconds long (at most 10)";
    if (!v["count"] || !v["seconds"] || v.size() != 2) return fail(v, kUsage);
    if (!number(v["count"], a, ActionKind::Frames, true)) return false;
    const auto s = v["seconds"];
    if (!s.IsScalar() || !YAML::convert<double>::decode(s, a.seconds) || !(a.seconds > 0 && a.seconds <= 10)) {
      return fail(s, kUsage);
    }
    return true;
  }
  bool wheel(const YAML::Node& v, Action& a) {
    a.kind = ActionKind::Wheel;
    if (!v.IsMap() || !v["at"] || !v["clicks"]) return fail(v, "expects {at: [X, Y], clicks: N}");
    if (!target(v["at"], a.x, a.y, a.on)) return false;
    const auto c = v["clicks"];
    if (!c.IsScalar() || !YAML::convert<double>::decode(c, a.number) || !(std::abs(a.number) <= 100)) {
      return fail(c, "expects clicks from -100 to 100");
    }
    return true;
  }
  bool set(const YAML::Node& v, Action& a) {
    a.kind = ActionKind::Set;
    if (!v.IsMap() || !v["node"] || !v["field"] || !v["value"]) {
      return fail(v, "expects {node: PATH, field: NAME, value: VALUE}");
    }
    if (!v["node"].IsScalar() || !v["field"].IsScalar()) return fail(v, "node and field are names");
    a.text = v["node"].Scalar();
    a.field = v["field"].Scalar();
    const auto value = v["value"];
    if (value.IsScalar()) {
      a.value = {value.Scalar()};
      a.quoted = value.Tag() == "!";
    } else if (value.IsSequence()) {
      a.list = true;
      for (const auto& x : value) {
        if (!x.IsScalar()) return fail(x, "a value's list holds numbers");
        a.value.push_back(x.Scalar());
      }
    } else {
      return fail(value, "a value is a number, a word or a list of numbers");
    }
    return true;
  }
  bool breakpoint(const YAML::Node& v, Action& a) {
    a.kind = ActionKind::Break;
    const char* kUsage =
        "expects 'start:T', 'complete:T', 'P>=N' (or <, <=, ==, !=, >), 'when:PYTHON', {starts: T}, {completes: T}, "
        "{place: P, at_least: N} or {when: PYTHON}";
    if (v.IsScalar()) {
      // as gdpn run --break writes it (session::parseBreakpoint), located in the file; a
      // quoted scalar's text starts after its quote
      core::SourceLoc start = locOf(v, file_);
      if (v.Tag() == "!") ++start.column;
      const auto bp = session::parseBreakpoint(v.Scalar(), start);
      if (!bp) {
        diags_.error(bp.error().loc, bp.error().message);
        return false;
      }
      a.field = "written";
      a.text = v.Scalar();
      return true;
    }
    if (!v.IsMap()) return fail(v, kUsage);
    bool counted = false;
    for (const auto& kv : v) {
      const auto key = kv.first.Scalar();
      if (key == "at_least") {
        counted = YAML::convert<double>::decode(kv.second, a.number);
      } else if ((key == "starts" || key == "completes" || key == "place" || key == "when") && kv.second.IsScalar()) {
        a.field = key;
        a.text = kv.second.Scalar();
      } else {
        return fail(kv.first, kUsage);
      }
    }
    if (a.field.empty()) return fail(v, kUsage);
    if (a.field == "place" && !counted) return fail(v, "a place's breakpoint expects at_least: N tokens");
    return true;
  }
  const std::string& file_;
  core::Diagnostics& diags_;
};

}  // namespace

std::optional<std::vector<Action>> parseReplay(const std::string& text, const std::string& file,
                                               core::Diagnostics& diags) {
  YAML::Node root;
  try {
    root = YAML::Load(text);
  } catch (const YAML::Exception& e) {
    diags.error({file, e.mark.line + 1, e.mark.column + 1}, e.msg);
    return std::nullopt;
  }
  std::vector<Action> actions;
  if (root.IsNull()) return actions;
  if (!root.IsSequence()) {
    diags.error(locOf(root, file), "a replay file is a list of actions");
    return std::nullopt;
  }
  ActionReader reader(file, diags);
  bool ok = true;
  for (const auto& item : root) {
    Action a;
    if (reader.read(item, a)) actions.push_back(std::move(a));
    else ok = false;
  }
  if (!ok) return std::nullopt;
  return actions;
}

std::optional<std::vector<Action>> loadReplay(const std::string& path, core::Diagnostics& diags) {
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    diags.error({path, 0, 0}, "cannot read the replay file");
    return std::nullopt;
  }
  std::stringstream text;
  text << in.rdbuf();
  return parseReplay(text.str(), path, diags);
}

}  // namespace gdpn::ide

// Writing model files: Model -> canonical YAML text, and a save that never loses the old file.

#include "yaml.h"

#include "gdpn/core/output_file.h"
#include "gdpn/core/text.h"
#include "gdpn/model/model.h"
#include "gdpn/model/schema.h"
#include "io_section.h"
#include "scene_io.h"
#include "yaml_reader.h"

namespace gdpn::model {
namespace {

using core::formatDouble;
using schema::Section;

void pos(YAML::Emitter& out, const std::optional<net::EditorPos>& p) {
  if (!p) return;
  out << YAML::Key << "at" << YAML::Value << YAML::Flow << YAML::BeginSeq << formatDouble((*p)[0])
      << formatDouble((*p)[1]) << YAML::EndSeq;
}

void description(YAML::Emitter& out, const std::string& text) {
  if (!text.empty()) out << YAML::Key << "description" << YAML::Value << YAML::DoubleQuoted << text;
}

/// A number, or `$name` of the parameter it comes from.
std::string numberText(double value, const std::string& param) {
  return param.empty() ? formatDouble(value) : "$" + param;
}
/// A per-slot count, or `$name` of the parameter it comes from.
void count(YAML::Emitter& out, const net::SlotCount& c) {
  if (c.param.empty()) out << c.value;
  else out << "$" + c.param;
}

/// A per-slot integer list as a scalar (only a0) or a map.
void perSlot(YAML::Emitter& out, const char* key, const std::vector<net::SlotCount>& values) {
  if (values.empty()) return;
  out << YAML::Key << key << YAML::Value;
  if (values.size() == 1 && values[0].slot == net::kDefaultSlot) {
    count(out, values[0]);
    return;
  }
  out << YAML::Flow << YAML::BeginMap;
  for (const auto& v : values) {
    out << YAML::Key << net::slotName(v.slot) << YAML::Value;
    count(out, v);
  }
  out << YAML::EndMap;
}

/// True when a '|' block gives `code` back byte for byte.
bool literalSafe(const std::string& code) {
  if (code.empty() || code.back() != '\n' || code.front() == ' ' || code.front() == '\n') return false;
  std::size_t line_start = 0;
  for (std::size_t i = 0; i < code.size(); ++i) {
    const char c = code[i];
    if (c == '\n') {
      if (i > line_start && (code[i - 1] == ' ' || code[i - 1] == '\t')) return false;
      line_start = i + 1;
    } else if (static_cast<unsigned char>(c) < 0x20 && c != '\t') {
      return false;
    }
  }
  return true;
}

void writeScript(YAML::Emitter& out, std::string_view key, const net::ScriptSpec& script) {
  if (script.empty()) return;
  out << YAML::Key << std::string(key) << YAML::Value;
  if (!script.file.empty()) {
    out << YAML::Flow << YAML::BeginMap << YAML::Key << "file" << YAML::Value << script.file;
    if (!script.function.empty()) out << YAML::Key << "function" << YAML::Value << script.function;
    out << YAML::EndMap;
  } else if (literalSafe(script.code)) {
    out << YAML::Literal << script.code;
  } else {
    out << YAML::DoubleQuoted << script.code;
  }
}

void writeSlotScripts(YAML::Emitter& out, net::ScriptKind kind, const std::vector<net::SlotScripts>& scripts) {
  bool any = false;
  for (const auto& s : scripts) any = any || !net::scriptOf(s, kind).empty();
  if (!any) return;
  out << YAML::Key << std::string(net::info(kind).key) << YAML::Value << YAML::BeginMap;
  for (const auto& s : scripts) writeScript(out, net::slotName(s.slot), net::scriptOf(s, kind));
  out << YAML::EndMap;
}

/// Constructs with scripts are written as block maps, so their code can stand in '|' blocks.
YAML::EMITTER_MANIP styleFor(bool scripted) { return scripted ? YAML::Block : YAML::Flow; }

void writePlace(YAML::Emitter& out, const net::PlaceSpec& p) {
  out << YAML::Key << p.name << YAML::Value << styleFor(!p.scripts.empty()) << YAML::BeginMap;
  description(out, p.description);
  if (!p.kinds.empty()) {
    out << YAML::Key << "slots" << YAML::Value << YAML::Flow << YAML::BeginMap;
    for (const auto& k : p.kinds) out << YAML::Key << net::slotName(k.slot) << YAML::Value << net::slotKindName(k.kind);
    out << YAML::EndMap;
  }
  if (p.nodes.empty()) {
    perSlot(out, "tokens", p.tokens);
  } else {
    out << YAML::Key << "tokens" << YAML::Value << YAML::Flow << YAML::BeginMap;
    for (const auto& t : p.tokens) {
      out << YAML::Key << net::slotName(t.slot) << YAML::Value;
      count(out, t);
    }
    for (const auto& n : p.nodes) {
      out << YAML::Key << net::slotName(n.slot) << YAML::Value << YAML::Flow << YAML::BeginSeq;
      for (const auto& name : n.nodes) out << name;
      out << YAML::EndSeq;
    }
    out << YAML::EndMap;
  }
  perSlot(out, "capacity", p.capacity);
  if (!p.sensors.empty()) {
    out << YAML::Key << "sensors" << YAML::Value << YAML::Flow << YAML::BeginMap;
    for (const auto& b : p.sensors) out << YAML::Key << net::slotName(b.slot) << YAML::Value << b.path;
    out << YAML::EndMap;
  }
  for (const net::ScriptKind k : net::kSlotScripts) writeSlotScripts(out, k, p.scripts);
  pos(out, p.position);
  out << YAML::EndMap;
}

void writeDuration(YAML::Emitter& out, const net::Duration& d) {
  using Law = net::Duration::Law;
  if (d.law == Law::Fixed && d.a == 0.0 && d.params[0].empty()) return;
  out << YAML::Key << "duration" << YAML::Value;
  const std::string a = numberText(d.a, d.params[0]), b = numberText(d.b, d.params[1]);
  switch (d.law) {
    case Law::Fixed:
    case Law::Immediate: out << a; break;
    case Law::Exponential:
      out << YAML::Flow << YAML::BeginMap << YAML::Key << "exponential" << YAML::Value << a << YAML::EndMap;
      break;
    case Law::Uniform:
    case Law::Normal:
      out << YAML::Flow << YAML::BeginMap << YAML::Key << (d.law == Law::Uniform ? "uniform" : "normal")
          << YAML::Value << YAML::BeginSeq << a << b << YAML::EndSeq << YAML::EndMap;
      break;
  }
}

void writeTransition(YAML::Emitter& out, const net::TransitionSpec& t) {
  // what a transition leaves out: the schema's defaults
  const double priority_default = schema::defaultNumber(Section::Transition, "priority");
  const double probability_default = schema::defaultNumber(Section::Transition, "probability");
  const double servers_default = schema::defaultNumber(Section::Transition, "servers");
  out << YAML::Key << t.name << YAML::Value << styleFor(t.scripted()) << YAML::BeginMap;
  description(out, t.description);
  writeDuration(out, t.duration);
  if (!t.priority_param.empty()) out << YAML::Key << "priority" << YAML::Value << "$" + t.priority_param;
  else if (static_cast<double>(t.priority) != priority_default) out << YAML::Key << "priority" << YAML::Value << t.priority;
  if (t.probability != probability_default || !t.probability_param.empty()) {
    out << YAML::Key << "probability" << YAML::Value << numberText(t.probability, t.probability_param);
  }
  if (!t.servers_param.empty()) out << YAML::Key << "servers" << YAML::Value << "$" + t.servers_param;
  else if (t.servers == net::kUnlimitedServers) out << YAML::Key << "servers" << YAML::Value << "unlimited";
  else if (static_cast<double>(t.servers) != servers_default) out << YAML::Key << "servers" << YAML::Value << t.servers;
  for (const net::ScriptKind k : net::kTransitionScripts) writeScript(out, net::info(k).key, net::scriptOf(t, k));
  pos(out, t.position);
  out << YAML::EndMap;
}

void writeArc(YAML::Emitter& out, const net::ArcSpec& a) {
  out << styleFor(!a.predicates.empty() || !a.conditions.empty()) << YAML::BeginMap << YAML::Key << "from" << YAML::Value << a.from
      << YAML::Key << "to"
      << YAML::Value << a.to;
  if (net::arcKindName(a.kind) != schema::key(Section::Arc, "kind").initial) out << YAML::Key << "kind" << YAML::Value << net::arcKindName(a.kind);
  perSlot(out, "weight", a.weights);
  for (const auto* list : {&a.predicates, &a.conditions}) {
    if (list->empty()) continue;
    out << YAML::Key << (list == &a.predicates ? "predicate" : "condition") << YAML::Value << YAML::BeginMap;
    for (const auto& p : *list) writeScript(out, net::slotName(p.slot).c_str(), p.expression);
    out << YAML::EndMap;
  }
  out << YAML::EndMap;
}

void writePage(YAML::Emitter& out, const net::PageSpec& page, bool type, const scene::Scene* type_scene,
               scene::AngleUnit angles) {
  out << YAML::Key << page.name << YAML::Value << YAML::BeginMap;
  description(out, page.description);
  if (type && !page.references.empty()) {
    out << YAML::Key << "references" << YAML::Value << YAML::Flow << YAML::BeginSeq;
    for (const auto& r : page.references) out << r.place;
    out << YAML::EndSeq;
  }
  if (!page.places.empty()) {
    out << YAML::Key << "places" << YAML::Value << YAML::BeginMap;
    for (const auto& p : page.places) writePlace(out, p);
    out << YAML::EndMap;
  }
  if (!page.transitions.empty()) {
    out << YAML::Key << "transitions" << YAML::Value << YAML::BeginMap;
    for (const auto& t : page.transitions) writeTransition(out, t);
    out << YAML::EndMap;
  }
  if (!page.instances.empty()) {
    out << YAML::Key << "instances" << YAML::Value << YAML::BeginMap;
    for (const auto& i : page.instances) {
      out << YAML::Key << i.name << YAML::Value << YAML::Flow << YAML::BeginMap << YAML::Key << "type"
          << YAML::Value << i.type;
      pos(out, i.position);
      if (i.translation != std::array<double, 3>{0, 0, 0}) {
        out << YAML::Key << "translation" << YAML::Value << YAML::Flow << YAML::BeginSeq;
        for (double x : i.translation) out << formatDouble(x);
        out << YAML::EndSeq;
      }
      if (i.rotation != std::array<double, 4>{0, 0, 1, 0}) {
        out << YAML::Key << "rotation" << YAML::Value << YAML::Flow << YAML::BeginSeq;
        for (double x : i.rotation) out << formatDouble(x);
        out << YAML::EndSeq;
      }
      out << YAML::EndMap;
    }
    out << YAML::EndMap;
  }
  if (!page.arcs.empty()) {
    out << YAML::Key << "arcs" << YAML::Value << YAML::BeginSeq;
    for (const auto& a : page.arcs) writeArc(out, a);
    out << YAML::EndSeq;
  }
  if (type_scene) {
    out << YAML::Key << "scene" << YAML::Value;
    detail::writeScene(out, *type_scene, angles);
  }
  out << YAML::EndMap;
}


}  // namespace

std::string writeModel(const Model& model) {
  YAML::Emitter out;
  out << YAML::BeginMap;
  out << YAML::Key << "gdpn" << YAML::Value << 1;
  description(out, model.description);
  const auto& s = model.settings;
  const bool radians = s.angles == scene::AngleUnit::Radians;
  if (s.dt_given || s.seed_given || s.until || radians || s.random_ties) {
    out << YAML::Key << "settings" << YAML::Value << YAML::BeginMap;
    if (s.dt_given) out << YAML::Key << "dt" << YAML::Value << formatDouble(s.dt);
    if (s.seed_given) out << YAML::Key << "seed" << YAML::Value << s.seed;
    if (s.until) out << YAML::Key << "until" << YAML::Value << formatDouble(*s.until);
    if (radians) out << YAML::Key << "angles" << YAML::Value << "radians";
    if (s.random_ties) out << YAML::Key << "ties" << YAML::Value << "random";
    out << YAML::EndMap;
  }
  if (!model.params.empty()) {
    out << YAML::Key << "params" << YAML::Value << YAML::BeginMap;
    for (const auto& p : model.params) {
      out << YAML::Key << p.name << YAML::Value;
      const std::string value = p.integer ? std::to_string(static_cast<std::int64_t>(p.declared)) : formatDouble(p.declared);
      // a number with no point reads back as a whole one: a decimal parameter keeps its point
      const bool point = p.integer || value.find_first_of(".eEn") != std::string::npos;
      const std::string text = point ? value : value + ".0";
      if (p.unit.empty() && p.description.empty()) {
        out << text;
        continue;
      }
      out << YAML::Flow << YAML::BeginMap << YAML::Key << "value" << YAML::Value << text;
      if (!p.unit.empty()) out << YAML::Key << "unit" << YAML::Value << p.unit;
      if (!p.description.empty()) out << YAML::Key << "description" << YAML::Value << YAML::DoubleQuoted << p.description;
      out << YAML::EndMap;
    }
    out << YAML::EndMap;
  }
  if (!model.signals.empty()) {
    out << YAML::Key << "signals" << YAML::Value << YAML::BeginMap;
    for (const auto& sig : model.signals) {
      out << YAML::Key << sig.name << YAML::Value << YAML::Flow << YAML::BeginMap;
      switch (sig.kind) {
        case SignalSpec::Kind::Place: out << YAML::Key << "place" << YAML::Value << sig.target; break;
        case SignalSpec::Kind::Node:
          out << YAML::Key << "node" << YAML::Value << sig.target << YAML::Key << "of" << YAML::Value << sig.quantity;
          break;
        case SignalSpec::Kind::Expression:
          out << YAML::Key << "expression" << YAML::Value << YAML::DoubleQuoted << sig.target;
          break;
      }
      if (sig.every > 0) out << YAML::Key << "every" << YAML::Value << formatDouble(sig.every);
      out << YAML::EndMap;
    }
    out << YAML::EndMap;
  }
  if (!model.io.empty()) {
    out << YAML::Key << "io" << YAML::Value;
    detail::writeIo(out, model.io);
  }
  if (!model.net.pages.empty()) {
    out << YAML::Key << "pages" << YAML::Value << YAML::BeginMap;
    for (const auto& p : model.net.pages) writePage(out, p, false, nullptr, s.angles);
    out << YAML::EndMap;
  }
  if (!model.net.page_types.empty()) {
    out << YAML::Key << "page_types" << YAML::Value << YAML::BeginMap;
    for (const auto& p : model.net.page_types) {
      auto it = model.type_scenes.find(p.name);
      writePage(out, p, true, it == model.type_scenes.end() ? nullptr : it->second.get(), s.angles);
    }
    out << YAML::EndMap;
  }
  if (model.scene) {
    out << YAML::Key << "scene" << YAML::Value;
    detail::writeScene(out, *model.scene, s.angles);
  }
  if (!model.net.globals.empty()) {
    out << YAML::Key << "scripts" << YAML::Value << YAML::BeginMap;
    writeScript(out, "globals", model.net.globals);
    out << YAML::EndMap;
  }
  out << YAML::EndMap;
  return std::string(out.c_str()) + "\n";
}

bool saveModel(const Model& model, const std::string& path, core::Diagnostics& diags) {
  std::string why;
  if (core::writeOutput(path, writeModel(model), why)) return true;
  diags.error({path, 0, 0}, why);
  return false;
}

}  // namespace gdpn::model

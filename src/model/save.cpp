// Writing model files: Model -> canonical YAML text, and a save that never loses the old file.

#include "yaml.h"

#include <algorithm>

#include "gdpn/core/output_file.h"
#include "gdpn/core/text.h"
#include "gdpn/model/model.h"
#include "gdpn/model/schema.h"
#include "colour_io.h"
#include "io_section.h"
#include "keep_layout.h"
#include "scene_io.h"
#include "yaml_reader.h"

namespace gdpn::model {
namespace {

using core::formatDouble;
using schema::Section;

/// A position `[x, y]` (editor units) as a flow list.
void point(YAML::Emitter& out, const net::EditorPos& p) {
  out << YAML::Flow << YAML::BeginSeq << formatDouble(p[0]) << formatDouble(p[1]) << YAML::EndSeq;
}

/// Key `key` (`at`) with the position `p`, when there is one.
void pos(YAML::Emitter& out, const std::optional<net::EditorPos>& p, const char* key = "at") {
  if (!p) return;
  out << YAML::Key << key << YAML::Value;
  point(out, *p);
}

void description(YAML::Emitter& out, const std::string& text) {
  if (!text.empty()) out << YAML::Key << "description" << YAML::Value << YAML::DoubleQuoted << text;
}

/// A number, or `$name` of the parameter it comes from.
std::string numberText(double value, const std::string& param) {
  return param.empty() ? formatDouble(value) : referenceText(param);
}
/// A per-slot count, or `$name` of the parameter it comes from.
void count(YAML::Emitter& out, const net::SlotCount& c) {
  if (c.param.empty()) out << c.value;
  else out << referenceText(c.param);
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

/// True when any of `texts` is written as a '|' block (its construct must be a block map).
bool anyBlock(const std::vector<net::SlotText>& texts) {
  return std::any_of(texts.begin(), texts.end(), [](const net::SlotText& t) { return detail::inscriptionIsBlock(t.text); });
}

/// Per-slot texts of key `key`: a lone one on a0 as the value, else a map slot -> text; each
/// written by `write`.
template <class F>
void perSlotText(YAML::Emitter& out, const char* key, const std::vector<net::SlotText>& texts, F&& write) {
  if (texts.empty()) return;
  out << YAML::Key << key << YAML::Value;
  if (texts.size() == 1 && texts[0].slot == net::kDefaultSlot) {
    write(texts[0].text);
    return;
  }
  out << (anyBlock(texts) ? YAML::Block : YAML::Flow) << YAML::BeginMap;
  for (const auto& t : texts) {
    out << YAML::Key << net::slotName(t.slot) << YAML::Value;
    write(t.text);
  }
  out << YAML::EndMap;
}

// a place's `continuous`: `true` when it keeps every default, else its map
void writeContinuous(YAML::Emitter& out, const std::optional<net::FluidSpec>& f) {
  if (!f) return;
  out << YAML::Key << "continuous" << YAML::Value;
  if (*f == net::FluidSpec{}) {
    out << true;
    return;
  }
  out << YAML::BeginMap;
  schema::inSchemaOrder(
      Section::Continuous,
      {
          {"amount", [&] { if (f->amount != 0.0) out << YAML::Key << "amount" << YAML::Value << core::formatDouble(f->amount); }},
          {"capacity",
           [&] { if (f->capacity) out << YAML::Key << "capacity" << YAML::Value << core::formatDouble(*f->capacity); }},
          {"unit", [&] { if (!f->unit.empty()) out << YAML::Key << "unit" << YAML::Value << f->unit; }},
          {"drives",
           [&] {
             if (f->drives.empty()) return;
             out << YAML::Key << "drives" << YAML::Value << YAML::BeginSeq;
             for (const auto& d : f->drives) {
               out << YAML::Flow << YAML::BeginMap;
               schema::inSchemaOrder(
                   Section::Drive,
                   {
                       {"node", [&] { out << YAML::Key << "node" << YAML::Value << d.node; }},
                       {"field", [&] { out << YAML::Key << "field" << YAML::Value << d.field; }},
                       {"scale", [&] { if (d.scale != 1.0) out << YAML::Key << "scale" << YAML::Value << core::formatDouble(d.scale); }},
                       {"offset", [&] { if (d.offset != 0.0) out << YAML::Key << "offset" << YAML::Value << core::formatDouble(d.offset); }},
                   });
               out << YAML::EndMap;
             }
             out << YAML::EndSeq;
           }},
      });
  out << YAML::EndMap;
}

// a transition's `continuous`: its rate and reads
void writeFlow(YAML::Emitter& out, const std::optional<net::FlowSpec>& f) {
  if (!f) return;
  out << YAML::Key << "continuous" << YAML::Value << YAML::BeginMap;
  schema::inSchemaOrder(
      Section::Flow,
      {
          {"rate", [&] { if (!f->rate.text.empty()) out << YAML::Key << "rate" << YAML::Value << f->rate.text; }},
          {"reads",
           [&] {
             if (f->reads.empty()) return;
             out << YAML::Key << "reads" << YAML::Value << YAML::BeginMap;
             for (const auto& r : f->reads) {
               out << YAML::Key << r.name << YAML::Value << YAML::Flow << YAML::BeginMap << YAML::Key << "node"
                   << YAML::Value << r.node << YAML::Key << "of" << YAML::Value << r.of << YAML::EndMap;
             }
             out << YAML::EndMap;
           }},
      });
  out << YAML::EndMap;
}

void writePlace(YAML::Emitter& out, const net::PlaceSpec& p) {
  out << YAML::Key << p.name << YAML::Value << styleFor(!p.scripts.empty() || anyBlock(p.values)) << YAML::BeginMap;
  std::vector<schema::KeyWriter> keys = {
      {"description", [&] { description(out, p.description); }},
      {"fusion", [&] { if (!p.fusion.empty()) out << YAML::Key << "fusion" << YAML::Value << p.fusion; }},
      {"slots",
       [&] {
         if (p.kinds.empty()) return;
         out << YAML::Key << "slots" << YAML::Value << YAML::Flow << YAML::BeginMap;
         for (const auto& k : p.kinds) out << YAML::Key << net::slotName(k.slot) << YAML::Value << net::slotKindName(k.kind);
         out << YAML::EndMap;
       }},
      {"tokens",
       [&] {
         if (p.nodes.empty()) {
           perSlot(out, "tokens", p.tokens);
           return;
         }
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
       }},
      {"colour", [&] { perSlotText(out, "colour", p.colours, [&](const std::string& name) { out << name; }); }},
      {"values",
       [&] { perSlotText(out, "values", p.values, [&](const std::string& text) { detail::writeInscription(out, text); }); }},
      {"capacity", [&] { perSlot(out, "capacity", p.capacity); }},
      {"sensors",
       [&] {
         if (p.sensors.empty()) return;
         out << YAML::Key << "sensors" << YAML::Value << YAML::Flow << YAML::BeginMap;
         for (const auto& b : p.sensors) out << YAML::Key << net::slotName(b.slot) << YAML::Value << b.path;
         out << YAML::EndMap;
       }},
      {"continuous", [&] { writeContinuous(out, p.fluid); }},
      {"at", [&] { pos(out, p.position); }},
  };
  for (const net::ScriptKind k : net::kSlotScripts) {
    keys.push_back({net::info(k).key, [&out, &p, k] { writeSlotScripts(out, k, p.scripts); }});
  }
  schema::inSchemaOrder(Section::Place, keys);
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
  out << YAML::Key << t.name << YAML::Value << styleFor(t.scripted() || detail::inscriptionIsBlock(t.when.text))
      << YAML::BeginMap;
  std::vector<schema::KeyWriter> keys = {
      {"description", [&] { description(out, t.description); }},
      {"duration", [&] { writeDuration(out, t.duration); }},
      {"priority",
       [&] {
         if (!t.priority_param.empty()) out << YAML::Key << "priority" << YAML::Value << referenceText(t.priority_param);
         else if (static_cast<double>(t.priority) != priority_default) out << YAML::Key << "priority" << YAML::Value << t.priority;
       }},
      {"probability",
       [&] {
         if (t.probability == probability_default && t.probability_param.empty()) return;
         out << YAML::Key << "probability" << YAML::Value << numberText(t.probability, t.probability_param);
       }},
      {"servers",
       [&] {
         if (!t.servers_param.empty()) out << YAML::Key << "servers" << YAML::Value << referenceText(t.servers_param);
         else if (t.servers == net::kUnlimitedServers) out << YAML::Key << "servers" << YAML::Value << "unlimited";
         else if (static_cast<double>(t.servers) != servers_default) out << YAML::Key << "servers" << YAML::Value << t.servers;
       }},
      {"continuous", [&] { writeFlow(out, t.flow); }},
      {"when",
       [&] {
         if (!t.conditioned()) return;
         out << YAML::Key << "when" << YAML::Value;
         detail::writeInscription(out, t.when.text);
       }},
      {"at", [&] { pos(out, t.position); }},
  };
  for (const net::ScriptKind k : net::kTransitionScripts) {
    keys.push_back({net::info(k).key, [&out, &t, k] { writeScript(out, net::info(k).key, net::scriptOf(t, k)); }});
  }
  schema::inSchemaOrder(Section::Transition, keys);
  out << YAML::EndMap;
}

void writeArc(YAML::Emitter& out, const net::ArcSpec& a) {
  const std::string& kind_default = schema::key(Section::Arc, "kind").initial;
  out << styleFor(!a.predicates.empty() || !a.conditions.empty() || anyBlock(a.inscriptions)) << YAML::BeginMap;
  // predicates and conditions: a map slot -> expression
  const auto scripts = [&](const char* key, const std::vector<net::SlotPredicate>& list) {
    if (list.empty()) return;
    out << YAML::Key << key << YAML::Value << YAML::BeginMap;
    for (const auto& p : list) writeScript(out, net::slotName(p.slot), p.expression);
    out << YAML::EndMap;
  };
  schema::inSchemaOrder(
      Section::Arc,
      {
          {"from", [&] { out << YAML::Key << "from" << YAML::Value << a.from; }},
          {"to", [&] { out << YAML::Key << "to" << YAML::Value << a.to; }},
          {"kind",
           [&] {
             if (net::arcKindName(a.kind) != kind_default) out << YAML::Key << "kind" << YAML::Value << net::arcKindName(a.kind);
           }},
          {"weight",
           [&] {
             if (a.amount) out << YAML::Key << "weight" << YAML::Value << numberText(*a.amount, a.amount_param);
             else perSlot(out, "weight", a.weights);
           }},
          {"inscription",
           [&] {
             perSlotText(out, "inscription", a.inscriptions,
                         [&](const std::string& text) { detail::writeInscription(out, text); });
           }},
          {net::info(net::ScriptKind::Predicate).key, [&] { scripts("predicate", a.predicates); }},
          {net::info(net::ScriptKind::Condition).key, [&] { scripts("condition", a.conditions); }},
          {"via",
           [&] {
             if (a.via.empty()) return;
             out << YAML::Key << "via" << YAML::Value << YAML::Flow << YAML::BeginSeq;
             for (const auto& p : a.via) point(out, p);
             out << YAML::EndSeq;
           }},
          {"label_at", [&] { pos(out, a.label_at, "label_at"); }},
      });
  out << YAML::EndMap;
}

void writeInstance(YAML::Emitter& out, const net::InstanceSpec& i) {
  out << YAML::Key << i.name << YAML::Value << YAML::Flow << YAML::BeginMap;
  // a list of numbers, when it is not the schema's default
  const auto numbers = [&](const char* key, const auto& values) {
    const std::vector<double> initial = schema::defaultNumbers(Section::Instance, key);
    if (std::equal(values.begin(), values.end(), initial.begin(), initial.end())) return;
    out << YAML::Key << key << YAML::Value << YAML::Flow << YAML::BeginSeq;
    for (double x : values) out << formatDouble(x);
    out << YAML::EndSeq;
  };
  schema::inSchemaOrder(Section::Instance,
                        {
                            {"type", [&] { out << YAML::Key << "type" << YAML::Value << i.type; }},
                            {"at", [&] { pos(out, i.position); }},
                            {"translation", [&] { numbers("translation", i.translation); }},
                            {"rotation", [&] { numbers("rotation", i.rotation); }},
                            {"params",
                             [&] {
                               if (i.params.empty()) return;
                               out << YAML::Key << "params" << YAML::Value << YAML::Flow << YAML::BeginMap;
                               for (const auto& p : i.params) out << YAML::Key << p.name << YAML::Value << formatDouble(p.value);
                               out << YAML::EndMap;
                             }},
                            {"part", [&] { if (!i.part.empty()) out << YAML::Key << "part" << YAML::Value << i.part; }},
                            {"uses",
                             [&] {
                               if (i.uses.empty()) return;
                               out << YAML::Key << "uses" << YAML::Value << YAML::Flow << YAML::BeginMap;
                               for (const auto& u : i.uses) out << YAML::Key << u.role << YAML::Value << u.part;
                               out << YAML::EndMap;
                             }},
                        });
  out << YAML::EndMap;
}

/// A map name -> construct written by `write`, when `list` is not empty.
template <class T, class F>
void namedMap(YAML::Emitter& out, const char* key, const std::vector<T>& list, F&& write) {
  if (list.empty()) return;
  out << YAML::Key << key << YAML::Value << YAML::BeginMap;
  for (const auto& item : list) write(out, item);
  out << YAML::EndMap;
}

void writeParam(YAML::Emitter& out, const Param& p);

/// A digital output's `on` or `off`: one number, or a list of them.
void writeOnOff(YAML::Emitter& out, const char* key, const std::vector<std::string>& texts) {
  if (texts.empty()) return;
  out << YAML::Key << key << YAML::Value;
  if (texts.size() == 1) {
    out << texts[0];
    return;
  }
  out << YAML::Flow << YAML::BeginSeq;
  for (const auto& t : texts) out << t;
  out << YAML::EndSeq;
}

/// A page type's `part`, `params` and `io` sections.
std::vector<schema::KeyWriter> partWriters(YAML::Emitter& out, const PartSpec& part) {
  return {
      {"part",
       [&] {
         if (!part.listed) return;
         out << YAML::Key << "part" << YAML::Value << YAML::Flow << YAML::BeginMap;
         schema::inSchemaOrder(
             Section::Part,
             {
                 {"version", [&] { out << YAML::Key << "version" << YAML::Value << part.version; }},
                 {"group", [&] { if (!part.group.empty()) out << YAML::Key << "group" << YAML::Value << part.group; }},
                 {"picture",
                  [&] { if (!part.picture.empty()) out << YAML::Key << "picture" << YAML::Value << part.picture; }},
                 {"control",
                  [&] { if (!part.control.empty()) out << YAML::Key << "control" << YAML::Value << part.control; }},
                 {"controls",
                  [&] { if (!part.controls.empty()) out << YAML::Key << "controls" << YAML::Value << part.controls; }},
             });
         out << YAML::EndMap;
       }},
      {"params", [&] { namedMap(out, "params", part.params, writeParam); }},
      {"io",
       [&] {
         namedMap(out, "io", part.io, [](YAML::Emitter& o, const PartIoSpec& io) {
           o << YAML::Key << io.name << YAML::Value << YAML::Flow << YAML::BeginMap;
           const auto text = [&](const char* key, const std::string& value) {
             if (!value.empty()) o << YAML::Key << key << YAML::Value << value;
           };
           schema::inSchemaOrder(
               Section::PartIo,
               {
                   {"direction", [&] { text("direction", ioDirectionName(io.direction)); }},
                   {"signal", [&] { text("signal", ioSignalName(io.signal)); }},
                   {"unit", [&] { text("unit", io.unit); }},
                   {"description", [&] { if (!io.description.empty()) o << YAML::Key << "description" << YAML::Value << YAML::DoubleQuoted << io.description; }},
                   {"node", [&] { text("node", io.node); }},
                   {"of", [&] { text("of", io.of); }},
                   {"field", [&] { text("field", io.field); }},
                   {"on", [&] { writeOnOff(o, "on", io.on); }},
                   {"off", [&] { writeOnOff(o, "off", io.off); }},
               });
           o << YAML::EndMap;
         });
       }},
      {"uses",
       [&] {
         namedMap(out, "uses", part.uses, [](YAML::Emitter& o, const PartUse& use) {
           o << YAML::Key << use.name << YAML::Value << YAML::Flow << YAML::BeginMap;
           schema::inSchemaOrder(
               Section::PartUse,
               {
                   {"io",
                    [&] {
                      o << YAML::Key << "io" << YAML::Value << YAML::Flow << YAML::BeginSeq;
                      for (const auto& n : use.io) o << n;
                      o << YAML::EndSeq;
                    }},
                   {"optional", [&] { if (use.optional) o << YAML::Key << "optional" << YAML::Value << true; }},
                   {"description",
                    [&] {
                      if (!use.description.empty()) {
                        o << YAML::Key << "description" << YAML::Value << YAML::DoubleQuoted << use.description;
                      }
                    }},
               });
           o << YAML::EndMap;
         });
       }},
  };
}

void writePage(YAML::Emitter& out, const net::PageSpec& page, bool type, const scene::Scene* type_scene,
               scene::AngleUnit angles, const PartSpec* part) {
  out << YAML::Key << page.name << YAML::Value << YAML::BeginMap;
  std::vector<schema::KeyWriter> keys = {
      {"description", [&] { description(out, page.description); }},
      {"places", [&] { namedMap(out, "places", page.places, writePlace); }},
      {"transitions", [&] { namedMap(out, "transitions", page.transitions, writeTransition); }},
      {"instances", [&] { namedMap(out, "instances", page.instances, writeInstance); }},
      {"arcs",
       [&] {
         if (page.arcs.empty()) return;
         out << YAML::Key << "arcs" << YAML::Value << YAML::BeginSeq;
         for (const auto& a : page.arcs) writeArc(out, a);
         out << YAML::EndSeq;
       }},
  };
  if (type) {
    keys.push_back({"references", [&] {
                      if (page.references.empty()) return;
                      out << YAML::Key << "references" << YAML::Value << YAML::Flow << YAML::BeginSeq;
                      for (const auto& r : page.references) out << r.place;
                      out << YAML::EndSeq;
                    }});
    keys.push_back({"scene", [&] {
                      if (!type_scene) return;
                      out << YAML::Key << "scene" << YAML::Value;
                      detail::writeScene(out, *type_scene, angles);
                    }});
    static const PartSpec none;  // a page type that is no part: its writers write nothing
    for (auto& w : partWriters(out, part ? *part : none)) keys.push_back(std::move(w));
  }
  schema::inSchemaOrder(type ? Section::PageType : Section::Page, keys);
  out << YAML::EndMap;
}

void writeSettings(YAML::Emitter& out, const Settings& s) {
  // a word at the schema's default is left out
  const std::string angles = s.angles == scene::AngleUnit::Radians ? "radians" : "degrees";
  const std::string ties = s.random_ties ? "random" : "order";
  const bool angles_given = angles != schema::key(Section::Settings, "angles").initial;
  const bool ties_given = ties != schema::key(Section::Settings, "ties").initial;
  if (!s.dt_given && !s.seed_given && !s.until && !angles_given && !ties_given) return;
  out << YAML::Key << "settings" << YAML::Value << YAML::BeginMap;
  schema::inSchemaOrder(Section::Settings,
                        {
                            {"dt", [&] { if (s.dt_given) out << YAML::Key << "dt" << YAML::Value << formatDouble(s.dt); }},
                            {"seed", [&] { if (s.seed_given) out << YAML::Key << "seed" << YAML::Value << s.seed; }},
                            {"until", [&] { if (s.until) out << YAML::Key << "until" << YAML::Value << formatDouble(*s.until); }},
                            {"angles", [&] { if (angles_given) out << YAML::Key << "angles" << YAML::Value << angles; }},
                            {"ties", [&] { if (ties_given) out << YAML::Key << "ties" << YAML::Value << ties; }},
                        });
  out << YAML::EndMap;
}

void writeParam(YAML::Emitter& out, const Param& p) {
  out << YAML::Key << p.name << YAML::Value;
  const std::string value = p.integer ? std::to_string(static_cast<std::int64_t>(p.declared)) : formatDouble(p.declared);
  // a number with no point reads back as a whole one: a decimal parameter keeps its point
  const bool point = p.integer || value.find_first_of(".eEn") != std::string::npos;
  const std::string text = point ? value : value + ".0";
  if (p.unit.empty() && p.description.empty()) {
    out << text;
    return;
  }
  out << YAML::Flow << YAML::BeginMap;
  schema::inSchemaOrder(
      Section::Param,
      {
          {"value", [&] { out << YAML::Key << "value" << YAML::Value << text; }},
          {"unit", [&] { if (!p.unit.empty()) out << YAML::Key << "unit" << YAML::Value << p.unit; }},
          {"description",
           [&] { if (!p.description.empty()) out << YAML::Key << "description" << YAML::Value << YAML::DoubleQuoted << p.description; }},
      });
  out << YAML::EndMap;
}

void writeSignal(YAML::Emitter& out, const SignalSpec& sig) {
  using Kind = SignalSpec::Kind;
  // a value written as a block (it spans lines) needs a block map
  out << YAML::Key << sig.name << YAML::Value << (detail::inscriptionIsBlock(sig.value) ? YAML::Block : YAML::Flow)
      << YAML::BeginMap;
  schema::inSchemaOrder(
      Section::Signal,
      {
          {"place", [&] { if (sig.kind == Kind::Place) out << YAML::Key << "place" << YAML::Value << sig.target; }},
          {"value",
           [&] {
             if (sig.kind == Kind::Place && !sig.value.empty()) {
               out << YAML::Key << "value" << YAML::Value;
               detail::writeInscription(out, sig.value);
             }
           }},
          {"node", [&] { if (sig.kind == Kind::Node) out << YAML::Key << "node" << YAML::Value << sig.target; }},
          {"of", [&] { if (sig.kind == Kind::Node) out << YAML::Key << "of" << YAML::Value << sig.quantity; }},
          {"expression",
           [&] {
             if (sig.kind == Kind::Expression) out << YAML::Key << "expression" << YAML::Value << YAML::DoubleQuoted << sig.target;
           }},
          {"every", [&] { if (sig.every > 0) out << YAML::Key << "every" << YAML::Value << formatDouble(sig.every); }},
      });
  out << YAML::EndMap;
}

}  // namespace

std::string writeModel(const Model& model) {
  YAML::Emitter out;
  const auto& s = model.settings;
  out << YAML::BeginMap;
  schema::inSchemaOrder(
      Section::Model,
      {
          {"gdpn", [&] { out << YAML::Key << "gdpn" << YAML::Value << 1; }},
          {"description", [&] { description(out, model.description); }},
          {"settings", [&] { writeSettings(out, s); }},
          {"params", [&] { namedMap(out, "params", model.params, writeParam); }},
          {"signals", [&] { namedMap(out, "signals", model.signals, writeSignal); }},
          {"io",
           [&] {
             if (model.io.empty()) return;
             out << YAML::Key << "io" << YAML::Value;
             detail::writeIo(out, model.io);
           }},
          {"colours", [&] { detail::writeColours(out, model.net.colours); }},
          {"variables", [&] { detail::writeVariables(out, model.net.variables); }},
          {"pages",
           [&] {
             namedMap(out, "pages", model.net.pages,
                      [&](YAML::Emitter& o, const net::PageSpec& p) { writePage(o, p, false, nullptr, s.angles, nullptr); });
           }},
          {"page_types",
           [&] {
             namedMap(out, "page_types", model.net.page_types, [&](YAML::Emitter& o, const net::PageSpec& p) {
               auto it = model.type_scenes.find(p.name);
               const auto part = model.parts.find(p.name);
               writePage(o, p, true, it == model.type_scenes.end() ? nullptr : it->second.get(), s.angles,
                         part == model.parts.end() ? nullptr : &part->second);
             });
           }},
          {"fusion",
           [&] {
             namedMap(out, "fusion", model.net.fusions, [](YAML::Emitter& o, const net::FusionSpec& f) {
               o << YAML::Key << f.name << YAML::Value << net::fusionScopeName(f.scope);
             });
           }},
          {"scene",
           [&] {
             if (!model.scene) return;
             out << YAML::Key << "scene" << YAML::Value;
             detail::writeScene(out, *model.scene, s.angles);
           }},
          {"scripts",
           [&] {
             if (model.net.globals.empty()) return;
             out << YAML::Key << "scripts" << YAML::Value << YAML::BeginMap;
             writeScript(out, "globals", model.net.globals);
             out << YAML::EndMap;
           }},
      });
  out << YAML::EndMap;
  return std::string(out.c_str()) + "\n";
}

std::string writeModelOver(const Model& model, const std::string& original) {
  std::string after = writeModel(model);
  if (original.empty()) return after;
  // the original's own canonical text tells what the edits changed
  const std::string file = model.path.empty() ? std::string("saved") + kModelSuffix : model.path;
  core::Diagnostics quiet;
  const auto before = parseModel(original, file, quiet);
  if (!before || quiet.hasErrors()) return after;
  const std::string before_text = writeModel(*before);
  // unedited: the file itself, which has just read back as the model
  if (before_text == after) return original;
  const auto merged = detail::keepLayout(original, before_text, after);
  if (!merged) return after;
  // the merged text must read back as the canonical text does, or the canonical text is saved
  const auto reread = parseModel(*merged, file, quiet);
  const auto canonical = parseModel(after, file, quiet);
  if (!reread || !canonical || quiet.hasErrors() || !(*reread == *canonical) || writeModel(*reread) != after) return after;
  return *merged;
}

bool saveModel(const Model& model, const std::string& path, core::Diagnostics& diags, const std::string& original) {
  std::string why;
  if (core::writeOutput(path, original.empty() ? writeModel(model) : writeModelOver(model, original), why)) return true;
  diags.error({path, 0, 0}, why);
  return false;
}

}  // namespace gdpn::model

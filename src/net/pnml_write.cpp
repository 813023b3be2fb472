// PNML out: a net as a place/transition net, with what P/T PNML lacks kept in gdpn's
// tool-specific parts (pnml.h; the format is in docs/format.md, "PNML").

#include <array>
#include <cctype>
#include <optional>
#include <string>
#include <unordered_map>
#include <unordered_set>

#include "detail/pnml_colour.h"
#include "detail/pnml_tool.h"
#include "gdpn/core/text.h"
#include "gdpn/net/fluid.h"
#include "gdpn/net/pnml.h"

namespace gdpn::net {
namespace {

using detail::isIdNote;
using detail::kIdNote;

/// `s` escaped for XML text: the five entities, and a carriage return kept as one.
std::string text(std::string_view s) {
  std::string out;
  for (const char c : core::xmlEscape(s)) {
    if (c == '\r') out += "&#13;";
    else out += c;
  }
  return out;
}

/// `s` escaped for an attribute value, whose line breaks and tabs XML would make spaces.
std::string attr(std::string_view s) {
  std::string out;
  for (const char c : text(s)) {
    if (c == '\n') out += "&#10;";
    else if (c == '\t') out += "&#9;";
    else out += c;
  }
  return out;
}

/// The PNML id of a construct: its original id when it came from PNML, else its name.
std::string pnmlId(const std::string& name, const std::string& description) {
  return isIdNote(description) && description.size() > kIdNote.size() ? description.substr(kIdNote.size()) : name;
}

/// The name label to write: the description when it holds one, else the id.
std::string label(const std::string& id, const std::string& description) {
  return description.empty() || isIdNote(description) ? id : description;
}

/// The description the reader gives a node written with id `id` and name `name`, from its label.
std::string describedAs(const std::string& name, const std::string& id, const std::string& description) {
  if (name != id) return std::string(kIdNote) + id;
  // the reader trims the label
  std::string l = label(id, description);
  const auto b = l.find_first_not_of(" \t\r\n"), e = l.find_last_not_of(" \t\r\n");
  l = b == std::string::npos ? std::string() : l.substr(b, e - b + 1);
  return l == name || isIdNote(l) ? std::string() : l;
}

/// True when `s` may be an XML id (an NCName of letters, digits, '_', '-' and '.').
bool isXmlId(std::string_view s) {
  if (s.empty() || s.size() > 100 || !(std::isalpha(static_cast<unsigned char>(s[0])) || s[0] == '_')) return false;
  for (const char c : s) {
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_' && c != '-' && c != '.') return false;
  }
  return true;
}

/// `<NAME x="" y=""/>`: a point of PNML graphics (editor units, as the file's `at`).
std::string pointXml(const char* name, const EditorPos& p) {
  return std::string("<") + name + " x=\"" + core::formatDouble(p[0]) + "\" y=\"" + core::formatDouble(p[1]) + "\"/>";
}

std::string positionXml(const std::optional<EditorPos>& p) {
  if (!p) return {};
  return "<graphics>" + pointXml("position", *p) + "</graphics>";
}

/// Numbers separated by spaces ("1 2.5 0").
template <std::size_t N>
std::string numbers(const std::array<double, N>& v) {
  std::string s;
  for (std::size_t i = 0; i < N; ++i) s += (i ? " " : "") + core::formatDouble(v[i]);
  return s;
}

/// A script as the element `key`: its code as the element's text, or its file and function.
std::string scriptXml(std::string_view key, const ScriptSpec& s, const std::string& slot_attr = {}) {
  const std::string k(key);
  if (!s.file.empty() || !s.function.empty()) {
    return "<" + k + slot_attr + " file=\"" + attr(s.file) + "\"" +
           (s.function.empty() ? "" : " function=\"" + attr(s.function) + "\"") + "/>";
  }
  return "<" + k + slot_attr + ">" + text(s.code) + "</" + k + ">";
}

/// ` slot="d0"`.
std::string slotAttr(SlotId slot) { return " slot=\"" + slotName(slot) + "\""; }

/// The kinds of construct that only gdpn reads, in the order the notes name them.
enum class Unseen : std::uint8_t {
  Duration, Priority, Probability, Servers, Guard, TransitionScript, Capacity, SlotKindDecl, OtherSlots,
  NodeTokens, Sensor, PlaceScript, Predicate, Condition, PageDescription, Instance, Globals, Parameter, Count
};

/// Each kind's words in a note: one of it, several of it.
constexpr std::array<std::array<std::string_view, 2>, static_cast<std::size_t>(Unseen::Count)> kUnseenWords = {{
    {"transition duration", "transition durations"},
    {"transition priority", "transition priorities"},
    {"transition probability", "transition probabilities"},
    {"transition's servers", "transitions' servers"},
    {"guard", "guards"},
    {"transition with scripts (pre_fire, in_fire, post_fire)", "transitions with scripts (pre_fire, in_fire, post_fire)"},
    {"place with a capacity", "places with a capacity"},
    {"place declaring slot kinds", "places declaring slot kinds"},
    {"marking or arc weight on slots other than a0", "markings and arc weights on slots other than a0"},
    {"place holding node tokens", "places holding node tokens"},
    {"place reading sensors", "places reading sensors"},
    {"place with scripts", "places with scripts"},
    {"arc with predicates", "arcs with predicates"},
    {"arc with conditions", "arcs with conditions"},
    {"page description", "page descriptions"},
    {"page type instance's settings (position, translation, rotation, params, part, uses)",
     "page type instances' settings (position, translation, rotation, params, part, uses)"},
    {"globals script", "globals scripts"},
    {"value taken from a model parameter (written as its value)",
     "values taken from model parameters (written as their values)"},
}};

/// Writes a NetSpec as PNML. Ids are chosen first (a construct keeps its name, or the PNML id
/// it came from, where that is free), then the pages are written, nested as instances nest.
class PnmlWriter {
 public:
  PnmlWriter(const NetSpec& spec, std::string& why) : spec_(spec), why_(why) {}

  std::optional<std::string> write(const std::string& name, std::vector<PnmlUnseen>* unseen) {
    // every page type must be instantiated exactly once: it becomes the page inside its instance's page
    std::unordered_map<std::string, std::size_t> count;
    const auto countIn = [&](const PageSpec& p) {
      for (const auto& i : p.instances) ++count[i.type];
    };
    for (const auto& p : spec_.pages) countIn(p);
    for (const auto& p : spec_.page_types) countIn(p);
    for (const auto& t : spec_.page_types) {
      if (count[t.name] != 1) {
        why_ = "page type '" + t.name + "' has " + core::counted(count[t.name], "instance") +
               "; PNML's pages are not reused, so each page type is written as the one page inside its one instance";
        return std::nullopt;
      }
      types_[t.name] = &t;
    }
    // a coloured net is a symmetric net: what one cannot hold is refused
    symmetric_ = !spec_.colours.empty() || !spec_.variables.empty();
    for (const auto* pages : {&spec_.pages, &spec_.page_types}) {
      for (const auto& page : *pages) {
        for (const auto& p : page.places) symmetric_ = symmetric_ || !p.colours.empty();
      }
    }
    if (symmetric_ && !symmetricOnly()) return std::nullopt;
    // ids: the declarations' first (a symmetric net's), then constructs, so that they keep
    // their names wherever they can, then pages
    for (const auto& c : spec_.colours) {
      ids_.insert(detail::declarationId(c.name, c.pnml_id));
      for (std::size_t i = 0; i < c.constants.size(); ++i) {
        ids_.insert(detail::declarationId(c.constants[i], i < c.constant_pnml_ids.size() ? c.constant_pnml_ids[i] : ""));
      }
    }
    for (const auto& v : spec_.variables) ids_.insert(detail::declarationId(v.name, v.pnml_id));
    for (const auto& p : spec_.pages) {
      if (!assignNodes(p)) return std::nullopt;
    }
    for (const auto& t : spec_.page_types) {
      if (!node_ids_.count(&t)) {
        why_ = "page type '" + t.name + "' is not reached from any page";
        return std::nullopt;
      }
    }
    for (const auto& p : spec_.pages) page_ids_[&p] = unique(p.name);
    for (const auto& t : spec_.page_types) page_ids_[&t] = unique(instance_of_.at(&t)->name);

    // the net: its name, the globals, its pages
    const std::string net_id = isXmlId(name) && !ids_.count(name) ? name : unique("net");
    out_ = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
           "<pnml xmlns=\"http://www.pnml.org/version-2009/grammar/pnml\">\n"
           "  <net id=\"" + attr(net_id) + "\" type=\"http://www.pnml.org/version-2009/grammar/" +
           (symmetric_ ? "symmetricnet" : "ptnet") + "\">\n";
    if (!name.empty()) out_ += "    <name><text>" + text(name) + "</text></name>\n";
    std::string net_tool;
    if (!spec_.globals.empty()) {
      see(Unseen::Globals);
      net_tool += scriptXml("globals", spec_.globals);
    }
    for (const auto& f : spec_.fusions) {
      net_tool += "<fusion name=\"" + attr(f.name) + "\" scope=\"" + fusionScopeName(f.scope) + "\"/>";
    }
    if (!net_tool.empty()) out_ += "    " + toolOpen() + net_tool + "</toolspecific>\n";
    for (const auto& p : spec_.pages) {
      if (!writePage(p, nullptr, 2)) return std::nullopt;
    }
    if (failed_) return std::nullopt;
    out_ += detail::declarationsXml(spec_);
    out_ += "  </net>\n</pnml>\n";
    if (unseen) {
      unseen->clear();
      for (std::size_t k = 0; k < counts_.size(); ++k) {
        if (counts_[k]) unseen->push_back({std::string(kUnseenWords[k][counts_[k] == 1 ? 0 : 1]), counts_[k]});
      }
    }
    return std::move(out_);
  }

 private:
  static std::string toolOpen() {
    return "<toolspecific tool=\"" + std::string(detail::kPnmlTool) + "\" version=\"" +
           std::string(detail::kPnmlToolVersion) + "\">";
  }

  void see(Unseen kind, std::size_t n = 1) { counts_[static_cast<std::size_t>(kind)] += n; }

  /// `base` if no id has it yet, else `base` with the first free "_2", "_3" ...
  std::string unique(const std::string& base) {
    std::string id = base;
    for (int n = 2; ids_.count(id); ++n) id = base + "_" + std::to_string(n);
    ids_.insert(id);
    return id;
  }

  /// The id a node would like: the PNML id it came from, or its name; "node" where that is empty.
  static std::string idFor(const std::string& name, const std::string& description) {
    std::string id = pnmlId(name, description);
    return id.empty() ? std::string("node") : id;
  }

  /// Chooses the ids of `page`'s places and transitions, then those of the pages inside it.
  bool assignNodes(const PageSpec& page) {
    auto& ids = node_ids_[&page];
    for (const auto& p : page.places) {
      ids[p.name] = unique(idFor(p.name, p.description));
      if (p.fusion.empty()) continue;
      // the member compile() keeps (the first that declares, else the first) is the place;
      // the others are referencePlaces to it
      auto [it, fresh] = declarer_.try_emplace(p.fusion, &p, ids[p.name]);
      if (!fresh && !it->second.first->declares() && p.declares()) it->second = {&p, ids[p.name]};
    }
    for (const auto& t : page.transitions) ids[t.name] = unique(idFor(t.name, t.description));
    for (const auto& i : page.instances) {
      auto type = types_.find(i.type);
      if (type == types_.end()) {
        why_ = "instance '" + i.name + "' names page type '" + i.type + "', which the model has not";
        return false;
      }
      instance_of_[type->second] = &i;
      if (!assignNodes(*type->second)) return false;
    }
    return true;
  }

  /// The toolspecific part that restores a node's name and description where its id and label do not.
  std::string nameXml(const std::string& name, const std::string& id, const std::string& description) {
    std::string s;
    if (name != id) s += "<name>" + text(name) + "</name>";
    if (describedAs(name, id, description) != description) s += "<description>" + text(description) + "</description>";
    return s;
  }

  void place(const PlaceSpec& p, const std::string& id, const std::string& pad) {
    // a member of a fusion set other than the one kept: a referencePlace to that one, which
    // holds in gdpn's part all the member declares
    const auto declarer = p.fusion.empty() ? declarer_.end() : declarer_.find(p.fusion);
    const bool reference = declarer != declarer_.end() && declarer->second.first != &p;
    std::int64_t a0 = 0;
    bool simple_tokens = !reference && (p.tokens.empty() || (p.tokens.size() == 1 && p.tokens[0].slot == kDefaultSlot &&
                                                             p.tokens[0].value > 0));
    bool other_slots = false;
    for (const auto& t : p.tokens) {
      if (t.slot == kDefaultSlot) a0 += t.value;
      else other_slots = true;
      if (!t.param.empty()) see(Unseen::Parameter);
    }
    std::string tool = nameXml(p.name, id, p.description);
    if (!p.fusion.empty()) tool += "<fusion name=\"" + attr(p.fusion) + "\"/>";
    for (const auto& k : p.kinds) tool += "<slot name=\"" + slotName(k.slot) + "\" kind=\"" + slotKindName(k.kind) + "\"/>";
    if (!p.kinds.empty()) see(Unseen::SlotKindDecl);
    if (!simple_tokens) {
      for (const auto& t : p.tokens) tool += "<tokens" + slotAttr(t.slot) + ">" + std::to_string(t.value) + "</tokens>";
    }
    if (other_slots) see(Unseen::OtherSlots);
    for (const auto& n : p.nodes) {
      tool += "<nodes" + slotAttr(n.slot) + ">";
      for (const auto& path : n.nodes) tool += "<node>" + text(path) + "</node>";
      tool += "</nodes>";
    }
    if (!p.nodes.empty()) see(Unseen::NodeTokens);
    for (const auto& c : p.capacity) {
      tool += "<capacity" + slotAttr(c.slot) + ">" + std::to_string(c.value) + "</capacity>";
      if (!c.param.empty()) see(Unseen::Parameter);
    }
    if (!p.capacity.empty()) see(Unseen::Capacity);
    for (const auto& s : p.sensors) tool += "<sensor" + slotAttr(s.slot) + ">" + text(s.path) + "</sensor>";
    if (!p.sensors.empty()) see(Unseen::Sensor);
    bool scripted = false;
    for (const auto& s : p.scripts) {
      for (const ScriptKind k : kSlotScripts) {
        if (const ScriptSpec& script = scriptOf(s, k); !script.empty()) {
          tool += scriptXml(info(k).key, script, slotAttr(s.slot));
          scripted = true;
        }
      }
      // a slot listed with no script is kept too, as an empty list entry
      if (s == SlotScripts{s.slot, {}, {}, {}, {}, {}, {}}) tool += "<scripts" + slotAttr(s.slot) + "/>";
    }
    if (scripted) see(Unseen::PlaceScript);
    const std::string element = reference ? "referencePlace" : "place";
    out_ += pad + "<" + element + " id=\"" + attr(id) + "\"" +
            (reference ? " ref=\"" + attr(declarer->second.second) + "\"" : std::string()) + "><name><text>" +
            text(label(id, p.description)) + "</text></name>" + positionXml(p.position);
    if (a0 > 0 && !reference) out_ += "<initialMarking><text>" + std::to_string(a0) + "</text></initialMarking>";
    if (!reference) {
      for (const auto& c : p.colours) {
        out_ += "<type><text>" + text(c.text) + "</text><structure>" + detail::sortXml(spec_, c.text) +
                "</structure></type>";
      }
      for (const auto& v : p.values) out_ += highLevel("hlinitialMarking", v, "place '" + p.name + "'");
    }
    if (!tool.empty()) out_ += toolOpen() + tool + "</toolspecific>";
    out_ += "</" + element + ">\n";
  }

  void transition(const TransitionSpec& t, const std::string& id, const std::string& pad) {
    std::string tool = nameXml(t.name, id, t.description);
    const Duration& d = t.duration;
    if (!(d == Duration())) {
      tool += "<duration law=\"" + std::string(detail::kLawNames[static_cast<std::size_t>(d.law)]) + "\" a=\"" +
              core::formatDouble(d.a) + "\"" + (d.b != 0.0 ? " b=\"" + core::formatDouble(d.b) + "\"" : "") + "/>";
      see(Unseen::Duration);
      if (!d.params[0].empty() || !d.params[1].empty()) see(Unseen::Parameter);
    }
    if (t.priority != 0) {
      tool += "<priority>" + std::to_string(t.priority) + "</priority>";
      see(Unseen::Priority);
    }
    if (t.probability != 1.0) {
      tool += "<probability>" + core::formatDouble(t.probability) + "</probability>";
      see(Unseen::Probability);
    }
    if (t.servers != 1) {
      tool += "<servers>" + (t.servers == kUnlimitedServers ? std::string("unlimited") : std::to_string(t.servers)) +
              "</servers>";
      see(Unseen::Servers);
    }
    for (const auto* param : {&t.priority_param, &t.probability_param, &t.servers_param}) {
      if (!param->empty()) see(Unseen::Parameter);
    }
    bool scripted = false;
    for (const ScriptKind k : kTransitionScripts) {
      if (const ScriptSpec& s = scriptOf(t, k); !s.empty()) {
        tool += scriptXml(info(k).key, s);
        if (k == ScriptKind::Guard) see(Unseen::Guard);
        else scripted = true;
      }
    }
    if (scripted) see(Unseen::TransitionScript);
    out_ += pad + "<transition id=\"" + attr(id) + "\"><name><text>" + text(label(id, t.description)) +
            "</text></name>" + positionXml(t.position);
    if (t.conditioned()) out_ += highLevel("condition", t.when, "transition '" + t.name + "'");
    if (!tool.empty()) out_ += toolOpen() + tool + "</toolspecific>";
    out_ += "</transition>\n";
  }

  /// Writes `page` (a page, or a page type inside the page of its instance `inst`) at `depth`.
  bool writePage(const PageSpec& page, const InstanceSpec* inst, int depth) {
    const std::string pad(static_cast<std::size_t>(2 * depth), ' '), in = pad + "  ";
    const auto& ids = node_ids_.at(&page);
    out_ += pad + "<page id=\"" + attr(page_ids_.at(&page)) + "\">";
    std::string tool = "<name>" + text(inst ? inst->name : page.name) + "</name>";
    if (!page.description.empty()) {
      tool += "<description>" + text(page.description) + "</description>";
      see(Unseen::PageDescription);
    }
    if (inst) tool += instanceXml(*inst, page);
    out_ += toolOpen() + tool + "</toolspecific>\n";
    for (const auto& p : page.places) place(p, ids.at(p.name), in);
    for (const auto& t : page.transitions) transition(t, ids.at(t.name), in);
    for (const auto& i : page.instances) {
      if (!writePage(*types_.at(i.type), &i, depth + 1)) return false;
    }
    // arcs: a link `instance/reference` is an arc to a referencePlace of the place inside
    std::unordered_map<std::string, std::string> refs;  // link -> referencePlace id
    std::string arcs;
    for (const auto& a : page.arcs) {
      auto from = end(page, a.from, refs, in), to = end(page, a.to, refs, in);
      if (!from || !to) {
        why_ = "arc '" + a.from + "' -> '" + a.to + "' on page '" + page.name + "' names an unknown node or link";
        return false;
      }
      arcs += in + "<arc id=\"" + attr(unique("arc" + std::to_string(arc_count_++))) + "\" source=\"" + attr(*from) + "\" target=\"" + attr(*to) + "\"";
      if (a.kind == ArcKind::Inhibitor) arcs += " type=\"inhibitor\"";
      if (a.kind == ArcKind::Test) arcs += " type=\"test\"";
      std::string body;
      std::int64_t w = 1;
      for (const auto& x : a.weights) {
        if (x.slot == kDefaultSlot) w = x.value;
        if (!x.param.empty()) see(Unseen::Parameter);
      }
      // the bend points, then the inscription (a weight of 1 written where it holds the label's offset)
      if (!a.via.empty()) {
        body += "<graphics>";
        for (const auto& p : a.via) body += pointXml("position", p);
        body += "</graphics>";
      }
      for (const auto& x : a.inscriptions) {
        std::string h = highLevel("hlinscription", x, "arc '" + a.from + "' -> '" + a.to + "'");
        if (a.label_at) h.insert(h.size() - std::string("</hlinscription>").size(), "<graphics>" + pointXml("offset", *a.label_at) + "</graphics>");
        body += h;
      }
      if (w != 1 || (a.label_at && a.inscriptions.empty())) {
        body += "<inscription><text>" + std::to_string(w) + "</text>";
        if (a.label_at) body += "<graphics>" + pointXml("offset", *a.label_at) + "</graphics>";
        body += "</inscription>";
      }
      std::string tool_arc;
      // weights the inscription alone does not give back are all listed
      const bool simple = a.weights.empty() || (a.weights.size() == 1 && a.weights[0].slot == kDefaultSlot && w != 1);
      if (!simple) {
        for (const auto& x : a.weights) {
          tool_arc += "<weight" + slotAttr(x.slot) + ">" + std::to_string(x.value) + "</weight>";
          if (x.slot != kDefaultSlot) see(Unseen::OtherSlots);
        }
      }
      for (const auto& p : a.predicates) tool_arc += scriptXml("predicate", p.expression, slotAttr(p.slot));
      for (const auto& c : a.conditions) tool_arc += scriptXml("condition", c.expression, slotAttr(c.slot));
      if (!a.predicates.empty()) see(Unseen::Predicate);
      if (!a.conditions.empty()) see(Unseen::Condition);
      if (!tool_arc.empty()) body += toolOpen() + tool_arc + "</toolspecific>";
      arcs += body.empty() ? "/>\n" : ">" + body + "</arc>\n";
    }
    out_ += arcs + pad + "</page>\n";
    return true;
  }

  /// The id an arc end `name` on `page` is written as; a link's referencePlace is written on first use.
  std::optional<std::string> end(const PageSpec& page, const std::string& name,
                                 std::unordered_map<std::string, std::string>& refs, const std::string& pad) {
    const auto& ids = node_ids_.at(&page);
    if (auto it = ids.find(name); it != ids.end()) return it->second;
    if (auto it = refs.find(name); it != refs.end()) return it->second;
    const auto slash = name.find('/');
    if (slash == std::string::npos) return std::nullopt;
    const std::string inst = name.substr(0, slash), ref = name.substr(slash + 1);
    for (const auto& i : page.instances) {
      if (i.name != inst) continue;
      const auto& inner = node_ids_.at(types_.at(i.type));
      auto target = inner.find(ref);
      if (target == inner.end()) return std::nullopt;
      const std::string id = unique(inst + "." + ref);
      out_ += pad + "<referencePlace id=\"" + attr(id) + "\" ref=\"" + attr(target->second) + "\"/>\n";
      return refs[name] = id;
    }
    return std::nullopt;
  }

  /// The toolspecific part of a page inside another: the instance it is and the type's references.
  std::string instanceXml(const InstanceSpec& i, const PageSpec& type) {
    std::string s = "<instance type=\"" + attr(i.type) + "\"";
    bool settings = false;
    if (i.position) {
      s += " at=\"" + numbers(*i.position) + "\"";
      settings = true;
    }
    if (i.translation != std::array<double, 3>{0, 0, 0}) {
      s += " translation=\"" + numbers(i.translation) + "\"";
      settings = true;
    }
    if (i.rotation != std::array<double, 4>{0, 0, 1, 0}) {
      s += " rotation=\"" + numbers(i.rotation) + "\"";
      settings = true;
    }
    if (!i.part.empty()) {
      s += " part=\"" + attr(i.part) + "\"";
      settings = true;
    }
    s += ">";
    for (const auto& p : i.params) s += "<param name=\"" + attr(p.name) + "\">" + core::formatDouble(p.value) + "</param>";
    for (const auto& u : i.uses) s += "<use role=\"" + attr(u.role) + "\">" + text(u.part) + "</use>";
    if (settings || !i.params.empty() || !i.uses.empty()) see(Unseen::Instance);
    s += "</instance>";
    for (const auto& r : type.references) s += "<reference>" + text(r.place) + "</reference>";
    return s;
  }

  const NetSpec& spec_;
  /// A symmetric net's high-level label `element` of inscription text `t` (of `owner`): its
  /// text and its term; "" after a failure, which `why_` then describes.
  std::string highLevel(const std::string& element, const SlotText& t, const std::string& owner) {
    std::string why;
    const auto term = detail::termXml(spec_, t.text, why);
    if (!term) {
      if (!failed_) why_ = "the inscription '" + t.text + "' of " + owner + " is no term of a symmetric net: " + why;
      failed_ = true;
      return {};
    }
    return "<" + element + "><text>" + text(t.text) + "</text><structure>" + *term + "</structure></" + element + ">";
  }

  /// True when the coloured parts of the net are what a symmetric net holds: colour sets of
  /// dot, bool, ranges, enumerations and products, value slots on a0 only; else false with why_.
  bool symmetricOnly() {
    for (const auto& c : spec_.colours) {
      const bool ok = c.kind == ColourKind::Dot || c.kind == ColourKind::Bool || c.kind == ColourKind::Enum ||
                      c.kind == ColourKind::Product || (c.kind == ColourKind::Integer && c.range);
      if (!ok) {
        why_ = "colour set '" + c.name + "' is a " + colourKindName(c.kind) +
               " set that a PNML symmetric net cannot declare (dot, bool, ranges, enumerations and products)";
        return false;
      }
    }
    for (const auto* pages : {&spec_.pages, &spec_.page_types}) {
      for (const auto& page : *pages) {
        for (const auto& p : page.places) {
          for (const auto& c : p.colours) {
            if (c.slot == kDefaultSlot) continue;
            why_ = "place '" + p.name + "' has a value slot other than a0 (" + slotName(c.slot) +
                   "), which a PNML symmetric net cannot hold";
            return false;
          }
        }
      }
    }
    return true;
  }

  bool symmetric_ = false;  // a coloured net, written as a symmetric net
  bool failed_ = false;     // a high-level label could not be written (why_ says why)
  std::string& why_;
  std::string out_;
  std::unordered_map<std::string, const PageSpec*> types_;                 // page type by name
  std::unordered_map<const PageSpec*, const InstanceSpec*> instance_of_;   // a page type's one instance
  std::unordered_map<const PageSpec*, std::unordered_map<std::string, std::string>> node_ids_;  // name -> id
  std::unordered_map<const PageSpec*, std::string> page_ids_;
  std::unordered_set<std::string> ids_;  // every id given so far
  /// per fusion set: the member written as the place, and its id
  std::unordered_map<std::string, std::pair<const PlaceSpec*, std::string>> declarer_;
  int arc_count_ = 0;
  std::array<std::size_t, static_cast<std::size_t>(Unseen::Count)> counts_{};
};

}  // namespace

std::optional<std::string> writePnml(const NetSpec& spec, std::string& why, const std::string& name,
                                     std::vector<PnmlUnseen>* unseen) {
  if (hybrid(spec)) {
    // a P/T net has no amounts: written as places of tokens, the net would mean another thing
    why = "PNML's place/transition nets have no continuous places or transitions (hybrid nets); "
          "this net has some";
    return std::nullopt;
  }
  return PnmlWriter(spec, why).write(name, unseen);
}

}  // namespace gdpn::net

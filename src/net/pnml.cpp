#include "gdpn/net/pnml.h"

#include <cctype>
#include <cmath>
#include <fstream>
#include <sstream>
#include <unordered_map>
#include <unordered_set>

#include "gdpn/core/file.h"
#include "gdpn/core/text.h"
#include "detail/xml.h"

namespace gdpn::net {
namespace {

/// How the description of a construct renamed on reading keeps its PNML id: "PNML id X".
const std::string kIdNote = "PNML id ";

/// True when `description` is such a note rather than a label.
bool isIdNote(const std::string& description) { return description.rfind(kIdNote, 0) == 0; }

using detail::XmlElement;

/// The text of <name><text>..</text></name> (or of any such pair), trimmed.
std::string textOf(const XmlElement* el) {
  if (!el) return {};
  const XmlElement* t = el->child("text");
  std::string s = t ? t->text : el->text;
  const auto b = s.find_first_not_of(" \t\r\n"), e = s.find_last_not_of(" \t\r\n");
  return b == std::string::npos ? std::string() : s.substr(b, e - b + 1);
}

}  // namespace

std::string pnmlName(const std::string& id) {
  if (core::isIdentifier(id)) return id;
  std::string n;
  for (char c : id) n += (std::isalnum(static_cast<unsigned char>(c)) || c == '_') ? c : '_';
  if (n.empty() || std::isdigit(static_cast<unsigned char>(n[0]))) n = "n" + n;
  return n;
}

namespace {

class PnmlReader {
 public:
  PnmlReader(const std::string& file, core::Diagnostics& diags) : file_(file), diags_(diags) {}

  std::optional<NetSpec> read(const XmlElement& root) {
    if (root.name != "pnml") {
      diags_.error(root.loc, "a PNML file starts with <pnml>, this one with <" + root.name + ">");
      return std::nullopt;
    }
    const XmlElement* net = root.child("net");
    if (!net) {
      diags_.error(root.loc, "the PNML file holds no <net>");
      return std::nullopt;
    }
    const std::string* type = net->attr("type");
    if (type && type->find("ptnet") == std::string::npos) {
      diags_.error(net->loc, "only place/transition nets (ptnet) are supported; this net is '" + *type + "'" +
                                 (type->find("symmetricnet") != std::string::npos ? " (a coloured net)" : ""));
      return std::nullopt;
    }
    page_.name = "net";
    page_.loc = net->loc;
    collect(*net);
    for (const auto* arc : arcs_) readArc(*arc);
    if (diags_.hasErrors()) return std::nullopt;
    NetSpec spec;
    spec.pages.push_back(std::move(page_));
    return spec;
  }

 private:
  /// The description of a place or transition read as `name` from PNML id `id`: the id note
  /// when it was renamed, else its name label when that differs from the name. A label that
  /// reads like an id note is dropped, since a save would take it for one.
  std::string describe(const XmlElement& el, const std::string& name, const std::string& id) const {
    if (name != id) return kIdNote + id;
    const std::string label = textOf(el.child("name"));
    return label == name || isIdNote(label) ? std::string() : label;
  }

  /// A name for PNML id `id`: the id itself when it is an identifier, else a cleaned copy.
  std::string nameFor(const std::string& id) {
    std::string n = pnmlName(id);
    if (n != id) {
      while (used_.count(n)) n += "_";
    }
    used_.insert(n);
    return n;
  }

  std::optional<std::string> idOf(const XmlElement& el) {
    const std::string* id = el.attr("id");
    if (!id || id->empty()) {
      diags_.error(el.loc, "<" + el.name + "> has no id");
      return std::nullopt;
    }
    if (ids_.count(*id)) {
      diags_.error(el.loc, "id '" + *id + "' is used twice");
      return std::nullopt;
    }
    return *id;
  }

  std::optional<EditorPos> position(const XmlElement& el) {
    const XmlElement* g = el.child("graphics");
    const XmlElement* p = g ? g->child("position") : nullptr;
    if (!p || !p->attr("x") || !p->attr("y")) return std::nullopt;
    try {
      const EditorPos pos{std::stod(*p->attr("x")), std::stod(*p->attr("y"))};
      if (!std::isfinite(pos[0]) || !std::isfinite(pos[1])) return std::nullopt;
      return pos;
    } catch (const std::exception&) {
      return std::nullopt;
    }
  }

  std::optional<std::int64_t> count(const XmlElement& el, const char* what) {
    const std::string t = textOf(&el);
    std::int64_t v = 0;
    bool ok = !t.empty() && t.size() < 19;
    for (char c : t) ok = ok && c >= '0' && c <= '9';
    if (ok) v = std::stoll(t);
    if (!ok) {
      diags_.error(el.loc, std::string(what) + " expects a whole number of tokens, got \"" + t + "\"");
      return std::nullopt;
    }
    return v;
  }

  void collect(const XmlElement& el) {
    for (const auto& c : el.children) {
      if (c->name == "page") {
        collect(*c);
      } else if (c->name == "place") {
        auto id = idOf(*c);
        if (!id) continue;
        PlaceSpec p;
        p.name = nameFor(*id);
        p.loc = c->loc;
        p.description = describe(*c, p.name, *id);
        if (const XmlElement* m = c->child("initialMarking")) {
          if (auto n = count(*m, "an initial marking"); n && *n > 0) p.tokens.push_back({kDefaultSlot, *n, m->loc, {}});
        }
        p.position = position(*c);
        ids_[*id] = {true, p.name};
        page_.places.push_back(std::move(p));
      } else if (c->name == "transition") {
        auto id = idOf(*c);
        if (!id) continue;
        TransitionSpec t;
        t.name = nameFor(*id);
        t.loc = c->loc;
        t.duration.loc = c->loc;
        t.probability_loc = c->loc;
        t.description = describe(*c, t.name, *id);
        t.position = position(*c);
        ids_[*id] = {false, t.name};
        page_.transitions.push_back(std::move(t));
      } else if (c->name == "arc") {
        arcs_.push_back(c.get());
      }
    }
  }

  void readArc(const XmlElement& el) {
    const std::string* src = el.attr("source");
    const std::string* dst = el.attr("target");
    if (!el.attr("id")) diags_.error(el.loc, "<arc> has no id");
    if (!src || !dst) {
      diags_.error(el.loc, "<arc> needs a source and a target");
      return;
    }
    auto s = ids_.find(*src), t = ids_.find(*dst);
    if (s == ids_.end()) diags_.error(el.loc, "arc source '" + *src + "' names no place or transition");
    if (t == ids_.end()) diags_.error(el.loc, "arc target '" + *dst + "' names no place or transition");
    if (s == ids_.end() || t == ids_.end()) return;
    if (s->second.first == t->second.first) {
      diags_.error(el.loc, "arc '" + *src + "' -> '" + *dst + "' joins two " +
                               (s->second.first ? "places" : "transitions"));
      return;
    }
    ArcSpec a;
    a.from = s->second.second;
    a.to = t->second.second;
    a.loc = a.from_loc = a.to_loc = el.loc;
    std::string kind = el.attr("type") ? *el.attr("type") : "";
    if (const XmlElement* ty = el.child("type"); ty && ty->attr("value")) kind = *ty->attr("value");
    if (kind == "inhibitor") a.kind = ArcKind::Inhibitor;
    else if (kind == "test" || kind == "read") a.kind = ArcKind::Test;
    if (const XmlElement* w = el.child("inscription")) {
      if (auto n = count(*w, "an arc inscription")) {
        if (*n != 1) a.weights.push_back({kDefaultSlot, *n, w->loc, {}});
      }
    }
    page_.arcs.push_back(std::move(a));
  }

  std::string file_;
  core::Diagnostics& diags_;
  PageSpec page_;
  std::vector<const XmlElement*> arcs_;
  std::unordered_map<std::string, std::pair<bool, std::string>> ids_;  // id -> (is place, name)
  std::unordered_set<std::string> used_;
};

}  // namespace

std::optional<NetSpec> parsePnml(const std::string& text, const std::string& file, core::Diagnostics& diags) {
  if (!core::checkUtf8(text, file, diags)) return std::nullopt;
  auto root = detail::parseXml(text, file, diags);
  if (!root) return std::nullopt;
  return PnmlReader(file, diags).read(*root);
}

namespace {

/// The PNML id of a construct: its original id when it came from PNML, else its name.
std::string pnmlId(const std::string& name, const std::string& description) {
  return isIdNote(description) ? description.substr(kIdNote.size()) : name;
}

/// The name label to write: the description when it holds one, else the id.
std::string label(const std::string& id, const std::string& description) {
  return description.empty() || isIdNote(description) ? id : description;
}

std::string positionXml(const std::optional<EditorPos>& p) {
  if (!p) return {};
  return "<graphics><position x=\"" + core::formatDouble((*p)[0]) + "\" y=\"" + core::formatDouble((*p)[1]) +
         "\"/></graphics>";
}

}  // namespace

std::optional<std::string> writePnml(const NetSpec& spec, std::string& why) {
  if (spec.pages.size() != 1 || !spec.page_types.empty() || !spec.pages[0].instances.empty()) {
    why = "PNML holds one flat place/transition net: this model has several pages or instances";
    return std::nullopt;
  }
  const PageSpec& page = spec.pages[0];
  std::unordered_map<std::string, std::string> id;  // name -> PNML id
  std::string out = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
                    "<pnml xmlns=\"http://www.pnml.org/version-2009/grammar/pnml\">\n"
                    "  <net id=\"" + core::xmlEscape(page.name) + "\" type=\"http://www.pnml.org/version-2009/grammar/ptnet\">\n"
                    "    <page id=\"page0\">\n";
  for (const auto& p : page.places) {
    if (!p.nodes.empty() || !p.kinds.empty() || !p.sensors.empty() || !p.capacity.empty()) {
      why = "place '" + p.name + "' uses node slots, sensors or a capacity, which a P/T net has not";
      return std::nullopt;
    }
    std::int64_t tokens = 0;
    for (const auto& t : p.tokens) {
      if (t.slot != kDefaultSlot) {
        why = "place '" + p.name + "' uses slot " + slotName(t.slot) + "; a P/T net has one (a0)";
        return std::nullopt;
      }
      tokens += t.value;
    }
    id[p.name] = pnmlId(p.name, p.description);
    out += "      <place id=\"" + core::xmlEscape(id[p.name]) + "\"><name><text>" + core::xmlEscape(label(id[p.name], p.description)) +
           "</text></name>" +
           positionXml(p.position);
    if (tokens > 0) out += "<initialMarking><text>" + std::to_string(tokens) + "</text></initialMarking>";
    out += "</place>\n";
  }
  for (const auto& t : page.transitions) {
    id[t.name] = pnmlId(t.name, t.description);
    out += "      <transition id=\"" + core::xmlEscape(id[t.name]) + "\"><name><text>" +
           core::xmlEscape(label(id[t.name], t.description)) + "</text></name>" + positionXml(t.position) + "</transition>\n";
  }
  int n = 0;
  for (const auto& a : page.arcs) {
    std::int64_t w = 1;
    for (const auto& x : a.weights) {
      if (x.slot != kDefaultSlot) {
        why = "an arc uses slot " + slotName(x.slot) + "; a P/T net has one (a0)";
        return std::nullopt;
      }
      w = x.value;
    }
    if (!id.count(a.from) || !id.count(a.to)) {
      why = "arc '" + a.from + "' -> '" + a.to + "' names a link or an unknown node";
      return std::nullopt;
    }
    out += "      <arc id=\"arc" + std::to_string(n++) + "\" source=\"" + core::xmlEscape(id[a.from]) + "\" target=\"" +
           core::xmlEscape(id[a.to]) + "\"";
    if (a.kind == ArcKind::Inhibitor) out += " type=\"inhibitor\"";
    if (a.kind == ArcKind::Test) out += " type=\"test\"";
    out += ">";
    if (w != 1) out += "<inscription><text>" + std::to_string(w) + "</text></inscription>";
    out += "</arc>\n";
  }
  out += "    </page>\n  </net>\n</pnml>\n";
  return out;
}

std::optional<NetSpec> loadPnml(const std::string& path, core::Diagnostics& diags) {
  auto text = core::readFile(path, diags);
  return text ? parsePnml(*text, path, diags) : std::nullopt;
}

}  // namespace gdpn::net

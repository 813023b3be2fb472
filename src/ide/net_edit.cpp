// Editing a page's net: each edit works on a copy of the page and replaces it when every check
// passes; the page as it was is kept for undo.

#include "gdpn/ide/net_edit.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <string_view>
#include <unordered_map>
#include <unordered_set>

#include "gdpn/core/text.h"
#include "gdpn/ide/document.h"
#include "gdpn/model/schema.h"

namespace gdpn::ide {

namespace {

constexpr std::int64_t kMaxWeight = 1'000'000'000;

const char* kindName(net::ArcKind k) {
  switch (k) {
    case net::ArcKind::Normal: return "arc";
    case net::ArcKind::Test: return "test arc";
    case net::ArcKind::Inhibitor: return "inhibitor arc";
  }
  return "arc";
}

template <typename T>
auto byName(std::vector<T>& list, const std::string& name) {
  return std::find_if(list.begin(), list.end(), [&](const T& x) { return x.name == name; });
}

bool hasPlace(net::PageSpec& p, const std::string& n) { return byName(p.places, n) != p.places.end(); }
bool hasTransition(net::PageSpec& p, const std::string& n) { return byName(p.transitions, n) != p.transitions.end(); }

/// True when `n` names something on the page already (places, transitions and instances share
/// one namespace).
bool taken(net::PageSpec& p, const std::string& n) {
  return hasPlace(p, n) || hasTransition(p, n) || byName(p.instances, n) != p.instances.end();
}

/// "" when `n` can name a new construct of `p`, else why not.
std::string newNameProblem(net::PageSpec& p, const std::string& n) {
  if (!core::isIdentifier(n)) return "'" + n + "' is not a name (letters, digits and _, not starting with a digit)";
  if (taken(p, n)) return "'" + n + "' is taken on page '" + p.name + "'";
  return {};
}

/// True when place `n` of `p` is published as a reference (other pages' arcs reach it).
bool published(const net::PageSpec& p, const std::string& n) {
  return std::any_of(p.references.begin(), p.references.end(), [&](const auto& r) { return r.place == n; });
}

/// True when `n` is a link on `p`: `instance/reference` of an instance on it.
bool isLink(net::NetSpec& net, net::PageSpec& p, const std::string& n) {
  const auto slash = n.find('/');
  if (slash == std::string::npos) return false;
  const auto instance = byName(p.instances, n.substr(0, slash));
  if (instance == p.instances.end()) return false;
  const auto* type = findPage(net, instance->type);
  return type != nullptr && published(*type, n.substr(slash + 1));
}

auto findArc(net::PageSpec& p, const NetEdit& e) {
  return std::find_if(p.arcs.begin(), p.arcs.end(),
                      [&](const net::ArcSpec& a) { return a.from == e.name && a.to == e.new_name && a.kind == e.arc_kind; });
}

void setWeight(net::ArcSpec& a, std::int64_t w) {
  if (a.weights.empty()) a.weights.push_back({net::kDefaultSlot, 1, {}, {}});
  a.weights.front().value = w;
  a.weights.front().param.clear();  // a value set by hand no longer comes from a parameter
  // a0 with weight 1 is what an arc without weights means: written the short way
  if (a.weights.size() == 1 && a.weights.front().slot == net::kDefaultSlot && w == 1) a.weights.clear();
}

/// Adds a place or transition named e.name at e.at to `list`, one of `p`'s; "" or why not.
template <typename Spec>
std::string addNamed(net::PageSpec& p, std::vector<Spec>& list, const NetEdit& e) {
  if (auto why = newNameProblem(p, e.name); !why.empty()) return why;
  Spec added;
  added.name = e.name;
  added.position = e.at;
  list.push_back(std::move(added));
  return {};
}

/// "" when `d` is a duration a transition can have, else why not.
std::string durationProblem(const net::Duration& d) {
  using Law = net::Duration::Law;
  if (!std::isfinite(d.a) || !std::isfinite(d.b)) return "a duration is a finite number of seconds";
  switch (d.law) {
    case Law::Fixed:
    case Law::Exponential:
      if (d.a < 0) return "a duration is 0 s or more";
      break;
    case Law::Uniform:
      if (d.a < 0 || d.b < d.a) return "a uniform duration's bounds are 0 <= low <= high";
      break;
    case Law::Normal:
      if (d.a < 0 || d.b < 0) return "a normal duration's mean and standard deviation are 0 s or more";
      break;
    case Law::Immediate:
      break;
  }
  return {};
}

/// "" when `p` can stand in place of a place of the same name, else why not.
std::string placeProblem(const net::PlaceSpec& p) {
  for (const auto& t : p.tokens) {
    if (t.value < 0 || t.value > kMaxWeight) return "a slot holds 0 to 10^9 tokens";
  }
  for (const auto& c : p.capacity) {
    if (c.value < 0 || c.value > kMaxWeight) return "a capacity is 0 to 10^9 tokens";
  }
  for (const auto& s : p.sensors) {
    if (s.path.empty()) return "a sensor slot names its sensor node";
  }
  // a slot's initial tokens are a count or a list of nodes, not both (the file has one key)
  for (const auto& t : p.tokens) {
    const bool nodes = std::any_of(p.nodes.begin(), p.nodes.end(), [&](const auto& n) { return n.slot == t.slot; });
    if (nodes) return "slot " + net::slotName(t.slot) + " holds node tokens: it has no count of its own";
  }
  return {};
}

/// Replaces the construct named `name` in `list` with `spec` (keeping its position); "" or why not.
template <typename Spec>
std::string replaceNamed(net::PageSpec& p, std::vector<Spec>& list, const std::string& name, const Spec& spec,
                         const char* what) {
  const auto it = byName(list, name);
  if (it == list.end()) return std::string("no ") + what + " '" + name + "' on page '" + p.name + "'";
  if (spec.name != name) return "a rename is an edit of its own";
  const auto position = it->position;
  *it = spec;
  it->position = position;
  return {};
}

/// Adds `fragment`'s constructs to `p`, renamed where taken; the first one's name into `made`,
/// and all it added into `pasted`.
std::string paste(net::PageSpec& p, const net::PageSpec& fragment, std::string& made, net::PageSpec& pasted) {
  if (fragment.places.empty() && fragment.transitions.empty()) return "nothing to paste";
  std::map<std::string, std::string> renamed;
  const auto fresh = [&](const std::string& name) {
    std::string n = name;
    for (int k = 1; taken(p, n); ++k) n = name + "_" + std::to_string(k);
    renamed[name] = n;
    if (made.empty()) made = n;
    return n;
  };
  const auto shifted = [](std::optional<net::EditorPos> at) {
    if (at) at = net::EditorPos{(*at)[0] + 0.5, (*at)[1] + 0.5};
    return at;
  };
  for (auto place : fragment.places) {
    place.name = fresh(place.name);
    place.position = shifted(place.position);
    pasted.places.push_back(place);
    p.places.push_back(std::move(place));
  }
  for (auto t : fragment.transitions) {
    t.name = fresh(t.name);
    t.position = shifted(t.position);
    pasted.transitions.push_back(t);
    p.transitions.push_back(std::move(t));
  }
  for (auto a : fragment.arcs) {
    const auto from = renamed.find(a.from), to = renamed.find(a.to);
    if (from == renamed.end() || to == renamed.end()) continue;
    a.from = from->second;
    a.to = to->second;
    for (auto& bend : a.via) bend = {bend[0] + 0.5, bend[1] + 0.5};  // with its ends
    pasted.arcs.push_back(a);
    p.arcs.push_back(std::move(a));
  }
  return {};
}

/// Places constructs of `p` without a position where `pins` says they are drawn (a page laid
/// out by Graphviz keeps its look when one of them moves).
void pinAll(net::PageSpec& p, const std::vector<std::pair<std::string, net::EditorPos>>& pins) {
  if (pins.empty()) return;
  std::unordered_map<std::string_view, net::EditorPos> at;
  for (const auto& [name, pos] : pins) at.emplace(name, pos);
  const auto pin = [&](auto& list) {
    for (auto& x : list) {
      if (x.position) continue;
      if (const auto it = at.find(x.name); it != at.end()) x.position = it->second;
    }
  };
  pin(p.places);
  pin(p.transitions);
  pin(p.instances);
}

/// Moves each of `moves` on `p`; "" or why not (a name not on the page). The bends of an arc
/// whose two ends move by the same step move with them.
std::string moveAll(net::PageSpec& p, const std::vector<std::pair<std::string, net::EditorPos>>& moves) {
  std::unordered_map<std::string_view, const net::EditorPos*> to;
  for (const auto& [name, pos] : moves) to[name] = &pos;
  std::unordered_map<std::string_view, net::EditorPos> step;  // how far each moved, when it had a place
  std::size_t found = 0;
  const auto move = [&](auto& list) {
    for (auto& x : list) {
      const auto it = to.find(x.name);
      if (it == to.end()) continue;
      if (x.position) step[x.name] = {(*it->second)[0] - (*x.position)[0], (*it->second)[1] - (*x.position)[1]};
      x.position = *it->second;
      ++found;
    }
  };
  move(p.places);
  move(p.transitions);
  move(p.instances);
  if (found != to.size()) {
    for (const auto& [name, pos] : moves) {
      if (!taken(p, name)) return "no place, transition or instance '" + name + "' on page '" + p.name + "'";
    }
  }
  for (auto& a : p.arcs) {
    if (a.via.empty()) continue;
    const auto from = step.find(std::string_view(a.from).substr(0, a.from.find('/')));
    const auto into = step.find(std::string_view(a.to).substr(0, a.to.find('/')));
    if (from == step.end() || into == step.end() || from->second != into->second) continue;
    for (auto& bend : a.via) bend = {bend[0] + from->second[0], bend[1] + from->second[1]};
  }
  return {};
}

/// True when page `page` is `name` or holds, through its instances at any depth, page type `name`.
bool holds(const net::NetSpec& net, const net::PageSpec& page, const std::string& name, int depth = 0) {
  if (page.name == name) return true;
  if (depth > 64) return true;  // deeper than any sane net: taken as a cycle
  for (const auto& i : page.instances) {
    const auto* type = findPage(net, i.type);
    if (type != nullptr && holds(net, *type, name, depth + 1)) return true;
  }
  return false;
}

/// Deletes `names` (places, transitions, instances) with their arcs, and `arcs`; "" or why not.
std::string deleteAll(net::PageSpec& p, const NetEdit& e) {
  std::unordered_set<std::string_view> gone;
  for (const auto& n : e.names) {
    if (!taken(p, n)) return "no place, transition or instance '" + n + "' on page '" + p.name + "'";
    if (hasPlace(p, n) && published(p, n)) {
      return "'" + n + "' is published as a reference of '" + p.name + "': arcs of other pages reach it";
    }
    gone.insert(n);
  }
  // arcs by source, target and kind (a page's worth of them costs its size)
  const auto key = [](const net::ArcSpec& a) { return a.from + '\n' + a.to + '\n' + net::arcKindName(a.kind); };
  std::unordered_set<std::string> on_page, named;
  for (const auto& a : p.arcs) on_page.insert(key(a));
  for (const auto& a : e.arcs) {
    if (!on_page.contains(key(a))) {
      return std::string("no ") + kindName(a.kind) + " from '" + a.from + "' to '" + a.to + "' on page '" + p.name + "'";
    }
    named.insert(key(a));
  }
  const auto instanceOf = [](std::string_view end) { return end.substr(0, end.find('/')); };
  std::erase_if(p.places, [&](const auto& x) { return gone.contains(x.name); });
  std::erase_if(p.transitions, [&](const auto& x) { return gone.contains(x.name); });
  std::erase_if(p.instances, [&](const auto& x) { return gone.contains(x.name); });
  std::erase_if(p.arcs, [&](const net::ArcSpec& a) {
    // an arc to a link goes with its instance
    return gone.contains(a.from) || gone.contains(a.to) || gone.contains(instanceOf(a.from)) ||
           gone.contains(instanceOf(a.to)) || (!named.empty() && named.contains(key(a)));
  });
  return {};
}

/// Performs `e` on `p` (a copy of the page in `net`); "" or why not. A Paste's name first
/// added goes into `made`, and all it added into `pasted`.
std::string edit(net::NetSpec& net, net::PageSpec& p, const NetEdit& e, std::string& made, net::PageSpec& pasted) {
  switch (e.kind) {
    case NetEditKind::AddPlace: return addNamed(p, p.places, e);
    case NetEditKind::AddTransition: return addNamed(p, p.transitions, e);
    case NetEditKind::Move: {
      // a page Graphviz lays out: every construct pinned where it is drawn, then one moved
      pinAll(p, e.pins);
      if (auto it = byName(p.places, e.name); it != p.places.end()) it->position = e.at;
      else if (auto t = byName(p.transitions, e.name); t != p.transitions.end()) t->position = e.at;
      else if (auto i = byName(p.instances, e.name); i != p.instances.end()) i->position = e.at;
      else return "no place, transition or instance '" + e.name + "' on page '" + p.name + "'";
      return {};
    }
    case NetEditKind::Rename: {
      const bool place = hasPlace(p, e.name);
      if (!place && !hasTransition(p, e.name)) return "no place or transition '" + e.name + "' on page '" + p.name + "'";
      if (place && published(p, e.name)) {
        return "'" + e.name + "' is published as a reference of '" + p.name + "': arcs of other pages reach it";
      }
      if (auto why = newNameProblem(p, e.new_name); !why.empty()) return why;
      if (place) byName(p.places, e.name)->name = e.new_name;
      else byName(p.transitions, e.name)->name = e.new_name;
      for (auto& a : p.arcs) {
        if (a.from == e.name) a.from = e.new_name;
        if (a.to == e.name) a.to = e.new_name;
      }
      return {};
    }
    case NetEditKind::Delete: {
      const bool place = hasPlace(p, e.name);
      if (!place && !hasTransition(p, e.name)) return "no place or transition '" + e.name + "' on page '" + p.name + "'";
      if (place && published(p, e.name)) {
        return "'" + e.name + "' is published as a reference of '" + p.name + "': arcs of other pages reach it";
      }
      if (place) p.places.erase(byName(p.places, e.name));
      else p.transitions.erase(byName(p.transitions, e.name));
      std::erase_if(p.arcs, [&](const net::ArcSpec& a) { return a.from == e.name || a.to == e.name; });
      return {};
    }
    case NetEditKind::AddArc: {
      const auto placeLike = [&](const std::string& n) { return hasPlace(p, n) || isLink(net, p, n); };
      const bool in = placeLike(e.name) && hasTransition(p, e.new_name);
      const bool out = hasTransition(p, e.name) && placeLike(e.new_name);
      if (!in && !out) {
        return "an arc joins a place (or a link) and a transition of page '" + p.name + "': '" + e.name + "' to '" +
               e.new_name + "' does not";
      }
      if (out && e.arc_kind != net::ArcKind::Normal) {
        return std::string(e.arc_kind == net::ArcKind::Test ? "a " : "an ") + kindName(e.arc_kind) +
               " runs from a place to a transition";
      }
      if (e.weight < 1 || e.weight > kMaxWeight) return "an arc's weight is a whole number from 1 to 10^9";
      if (findArc(p, e) != p.arcs.end()) {
        return std::string("there is already ") + (e.arc_kind == net::ArcKind::Test ? "a " : "an ") + kindName(e.arc_kind) +
               " from '" + e.name + "' to '" + e.new_name + "'";
      }
      net::ArcSpec a;
      a.from = e.name;
      a.to = e.new_name;
      a.kind = e.arc_kind;
      setWeight(a, e.weight);
      p.arcs.push_back(std::move(a));
      return {};
    }
    case NetEditKind::DeleteArc:
    case NetEditKind::SetArcWeight: {
      const auto a = findArc(p, e);
      if (a == p.arcs.end()) {
        return std::string("no ") + kindName(e.arc_kind) + " from '" + e.name + "' to '" + e.new_name + "' on page '" +
               p.name + "'";
      }
      if (e.kind == NetEditKind::DeleteArc) {
        p.arcs.erase(a);
        return {};
      }
      if (e.weight < 1 || e.weight > kMaxWeight) return "an arc's weight is a whole number from 1 to 10^9";
      setWeight(*a, e.weight);
      return {};
    }
    case NetEditKind::SetPlace: {
      if (!e.place) return "no place given";
      if (auto why = placeProblem(*e.place); !why.empty()) return why;
      return replaceNamed(p, p.places, e.name, *e.place, "place");
    }
    case NetEditKind::Paste: return e.fragment ? paste(p, *e.fragment, made, pasted) : "nothing to paste";
    case NetEditKind::MoveMany:
      pinAll(p, e.pins);
      return moveAll(p, e.moves);
    case NetEditKind::DeleteMany: return deleteAll(p, e);
    case NetEditKind::AddInstance: {
      if (auto why = newNameProblem(p, e.name); !why.empty()) return why;
      bool type = false;
      const auto* of = findPage(net, e.new_name, &type);
      if (of == nullptr || !type) return "no page type '" + e.new_name + "'";
      if (holds(net, *of, p.name)) return "page type '" + e.new_name + "' holds '" + p.name + "': an instance of it there would hold itself";
      net::InstanceSpec added;
      added.name = e.name;
      added.type = e.new_name;
      added.position = e.at;
      p.instances.push_back(std::move(added));
      return {};
    }
    case NetEditKind::SetArc: {
      const auto a = findArc(p, e);
      if (a == p.arcs.end()) {
        return std::string("no ") + kindName(e.arc_kind) + " from '" + e.name + "' to '" + e.new_name + "' on page '" +
               p.name + "'";
      }
      if (!e.arc) return "no arc given";
      net::ArcSpec changed = *e.arc;
      // checked as a new arc would be, without the arc it replaces
      net::ArcSpec was = std::move(*a);
      const auto at = a - p.arcs.begin();
      p.arcs.erase(a);
      auto check = makeNetEdit(NetEditKind::AddArc, p.name, changed.from, changed.to);
      check.arc_kind = changed.kind;
      std::string unused;
      net::PageSpec none;
      if (auto why = edit(net, p, check, unused, none); !why.empty()) return why;
      for (const auto& w : changed.weights) {
        if (w.value < 1 || w.value > kMaxWeight) return "an arc's weight is a whole number from 1 to 10^9";
      }
      p.arcs.pop_back();  // the check's arc: the changed one takes the old one's place in the list
      changed.loc = was.loc;
      changed.from_loc = was.from_loc;
      changed.to_loc = was.to_loc;
      p.arcs.insert(p.arcs.begin() + at, std::move(changed));
      return {};
    }
    case NetEditKind::SetTransition: {
      if (!e.transition) return "no transition given";
      const auto& t = *e.transition;
      if (auto why = durationProblem(t.duration); !why.empty()) return why;
      // the model file's ranges (the schema's), with the editor's words
      using model::schema::Section;
      if (!model::schema::inRange(model::schema::key(Section::Transition, "probability"), t.probability)) {
        return "a probability lies in (0, 1]";
      }
      if (t.servers != net::kUnlimitedServers &&
          !model::schema::inRange(model::schema::key(Section::Transition, "servers"), static_cast<double>(t.servers))) {
        return "servers are a whole number from 1 to " + std::to_string(net::kMostServers) + ", or unlimited";
      }
      return replaceNamed(p, p.transitions, e.name, t, "transition");
    }
  }
  return "unknown edit";
}

}  // namespace

namespace {

/// findPage() for a NetSpec that may be const.
template <class Net>
auto* findPageIn(Net& net, const std::string& name, bool* is_type) {
  for (auto* list : {&net.pages, &net.page_types}) {
    for (auto& p : *list) {
      if (p.name != name) continue;
      if (is_type != nullptr) *is_type = list == &net.page_types;
      return &p;
    }
  }
  return static_cast<decltype(&net.pages.front())>(nullptr);
}

}  // namespace

net::PageSpec* findPage(net::NetSpec& net, const std::string& name, bool* is_type) {
  return findPageIn(net, name, is_type);
}

const net::PageSpec* findPage(const net::NetSpec& net, const std::string& name, bool* is_type) {
  return findPageIn(net, name, is_type);
}

namespace {

template <typename T>
auto bySlot(std::vector<T>& list, net::SlotId slot) {
  return std::find_if(list.begin(), list.end(), [&](const T& x) { return x.slot == slot; });
}

template <typename T>
void dropSlot(std::vector<T>& list, net::SlotId slot) {
  std::erase_if(list, [&](const T& x) { return x.slot == slot; });
}

}  // namespace

net::SlotKind slotKindOf(const net::PlaceSpec& p, net::SlotId slot) {
  const auto has = [&](const auto& list) {
    return std::any_of(list.begin(), list.end(), [&](const auto& x) { return x.slot == slot; });
  };
  if (has(p.sensors)) return net::SlotKind::Sensor;
  if (has(p.colours)) return net::SlotKind::Value;
  for (const auto& k : p.kinds) {
    if (k.slot == slot) return k.kind;
  }
  return has(p.nodes) ? net::SlotKind::Node : net::SlotKind::Control;
}

void setSlotKind(net::PlaceSpec& p, net::SlotId slot, net::SlotKind kind, const std::string& sensor) {
  const auto was = slotKindOf(p, slot);
  dropSlot(p.kinds, slot);
  if (kind != net::SlotKind::Node) dropSlot(p.nodes, slot);
  if (kind != net::SlotKind::Control) dropSlot(p.tokens, slot);
  if (kind == net::SlotKind::Sensor) dropSlot(p.capacity, slot);
  if (kind != net::SlotKind::Sensor) dropSlot(p.sensors, slot);
  if (kind != net::SlotKind::Value) dropSlot(p.colours, slot), dropSlot(p.values, slot);
  // the scripts only a sensor slot has, or only the others have
  if (was != kind && (was == net::SlotKind::Sensor || kind == net::SlotKind::Sensor)) dropSlot(p.scripts, slot);
  switch (kind) {
    case net::SlotKind::Control: break;  // what a slot is unless said otherwise
    case net::SlotKind::Node: p.kinds.push_back({slot, kind, {}}); break;
    case net::SlotKind::Sensor: p.sensors.push_back({slot, sensor, {}}); break;
    case net::SlotKind::Value: p.kinds.push_back({slot, kind, {}}); break;  // its colour set is to be said
    case net::SlotKind::Continuous: break;  // a place is continuous as a whole (`continuous`), not by a slot
  }
}

void setSlotCount(std::vector<net::SlotCount>& counts, net::SlotId slot, std::optional<std::int64_t> value) {
  const auto it = bySlot(counts, slot);
  if (!value) {
    if (it != counts.end()) counts.erase(it);
  } else if (it != counts.end()) {
    it->value = *value;
    it->param.clear();  // a value set by hand no longer comes from a parameter
  } else {
    counts.push_back({slot, *value, {}, {}});
  }
}

const net::SlotCount* slotEntry(const std::vector<net::SlotCount>& counts, net::SlotId slot) {
  for (const auto& c : counts) {
    if (c.slot == slot) return &c;
  }
  return nullptr;
}

std::optional<std::int64_t> slotCount(const std::vector<net::SlotCount>& counts, net::SlotId slot) {
  const auto* c = slotEntry(counts, slot);
  return c ? std::optional<std::int64_t>(c->value) : std::nullopt;
}

void setInlineCode(net::ScriptSpec& script, const std::string& code, const core::SourceLoc& owner) {
  // a compile error in the edited text is reported where the script stood in the file (or at
  // its construct, for a new one), its line counted from there
  const core::SourceLoc loc = script.loc.line > 0 ? script.loc : owner;
  script = {};
  script.code = code;
  if (!code.empty()) script.loc = loc;
}

void addNodeToken(net::PlaceSpec& p, net::SlotId slot, const std::string& path) {
  if (slotKindOf(p, slot) != net::SlotKind::Node) setSlotKind(p, slot, net::SlotKind::Node);
  auto it = bySlot(p.nodes, slot);
  if (it == p.nodes.end()) {
    p.nodes.push_back({slot, {}, {}});
    it = std::prev(p.nodes.end());
  }
  it->nodes.push_back(path);
}

bool removeNodeToken(net::PlaceSpec& p, net::SlotId slot, const std::string& path) {
  const auto it = bySlot(p.nodes, slot);
  if (it == p.nodes.end()) return false;
  const auto n = std::find(it->nodes.begin(), it->nodes.end(), path);
  if (n == it->nodes.end()) return false;
  it->nodes.erase(n);
  if (it->nodes.empty()) p.nodes.erase(it);
  return true;
}

void setSlotScript(net::PlaceSpec& p, net::SlotId slot, net::ScriptKind kind, const std::string& code) {
  auto it = bySlot(p.scripts, slot);
  if (it == p.scripts.end()) {
    if (code.empty()) return;
    p.scripts.push_back({});
    it = std::prev(p.scripts.end());
    it->slot = slot;
  }
  setInlineCode(net::scriptOf(*it, kind), code, p.loc);
  net::SlotScripts none;
  none.slot = slot;
  if (*it == none) p.scripts.erase(it);
}

std::optional<ConstructAt> locateConstruct(const net::NetSpec& net, const std::string& qualified) {
  std::vector<std::string> parts;
  for (std::size_t start = 0;;) {
    const auto slash = qualified.find('/', start);
    parts.push_back(qualified.substr(start, slash == std::string::npos ? std::string::npos : slash - start));
    if (slash == std::string::npos) break;
    start = slash + 1;
  }
  if (parts.size() < 2) return std::nullopt;
  const auto page = std::find_if(net.pages.begin(), net.pages.end(), [&](const auto& x) { return x.name == parts[0]; });
  if (page == net.pages.end()) return std::nullopt;
  const net::PageSpec* at = &*page;
  for (std::size_t i = 1; i + 1 < parts.size(); ++i) {
    const auto inst = std::find_if(at->instances.begin(), at->instances.end(), [&](const auto& x) { return x.name == parts[i]; });
    if (inst == at->instances.end()) return std::nullopt;
    const auto type = std::find_if(net.page_types.begin(), net.page_types.end(), [&](const auto& x) { return x.name == inst->type; });
    if (type == net.page_types.end()) return std::nullopt;
    at = &*type;
  }
  return ConstructAt{at->name, parts.back()};
}

NetEdit makeNetEdit(NetEditKind kind, std::string page, std::string name, std::string second, net::EditorPos at) {
  NetEdit e;
  e.kind = kind;
  e.page = std::move(page);
  e.name = std::move(name);
  e.new_name = std::move(second);
  e.at = at;
  return e;
}

std::string SetGlobalsCommand::apply(Document& doc) {
  net::ScriptSpec& globals = doc.editableNet().globals;
  before_ = globals;
  setInlineCode(globals, code_, core::SourceLoc{doc.model().path, 1, 1});
  doc.touched(false);
  return {};
}

void SetGlobalsCommand::revert(Document& doc) {
  doc.editableNet().globals = before_;
  doc.touched(false);
}

NetEditCommand::NetEditCommand(NetEdit edit) : edit_(std::move(edit)) {}

namespace {

/// Where `p`'s constructs stand and its arcs bend.
template <class Positions>
Positions positionsOf(const net::PageSpec& p) {
  Positions out;
  out.places.reserve(p.places.size());
  for (const auto& x : p.places) out.places.push_back(x.position);
  out.transitions.reserve(p.transitions.size());
  for (const auto& x : p.transitions) out.transitions.push_back(x.position);
  for (const auto& x : p.instances) out.instances.push_back(x.position);
  out.via.reserve(p.arcs.size());
  for (const auto& a : p.arcs) out.via.push_back(a.via);
  return out;
}

/// Puts `p`'s constructs and bends back where positionsOf() found them (the page is the same
/// but for them).
template <class Positions>
void restorePositions(net::PageSpec& p, const Positions& was) {
  for (std::size_t i = 0; i < p.places.size() && i < was.places.size(); ++i) p.places[i].position = was.places[i];
  for (std::size_t i = 0; i < p.transitions.size() && i < was.transitions.size(); ++i) p.transitions[i].position = was.transitions[i];
  for (std::size_t i = 0; i < p.instances.size() && i < was.instances.size(); ++i) p.instances[i].position = was.instances[i];
  for (std::size_t i = 0; i < p.arcs.size() && i < was.via.size(); ++i) p.arcs[i].via = was.via[i];
}

}  // namespace

std::string NetEditCommand::apply(Document& doc) {
  net::NetSpec& net = doc.editableNet();
  net::PageSpec* page = findPage(net, edit_.page, &type_);
  if (page == nullptr) return "no page or page type '" + edit_.page + "'";
  made_.clear();
  pasted_ = {};
  if (edit_.kind == NetEditKind::SetArc && edit_.arc) {
    // a route or a label changed alone (a bend or a label dragged): the arc alone is kept for undo
    const auto it = findArc(*page, edit_);
    if (it != page->arcs.end()) {
      net::ArcSpec routed = *it;
      routed.via = edit_.arc->via;
      routed.label_at = edit_.arc->label_at;
      if (routed == *edit_.arc) {
        arc_before_.emplace(static_cast<std::size_t>(it - page->arcs.begin()), *it);
        it->via = edit_.arc->via;
        it->label_at = edit_.arc->label_at;
        before_.reset();
        positions_.reset();
        doc.touched(false);
        return {};
      }
    }
  }
  arc_before_.reset();
  if (edit_.kind == NetEditKind::Move || edit_.kind == NetEditKind::MoveMany) {
    // a move changes positions and bends alone: they are kept for undo, not the page
    auto was = positionsOf<Positions>(*page);
    if (auto why = edit(net, *page, edit_, made_, pasted_); !why.empty()) {
      restorePositions(*page, was);
      return why;
    }
    positions_ = std::move(was);
    before_.reset();
    arc_before_.reset();
    doc.touched(false);
    return {};
  }
  net::PageSpec changed = *page;
  if (auto why = edit(net, changed, edit_, made_, pasted_); !why.empty()) return why;
  // a construct added here is written nowhere yet: the model's file is where a message about it
  // points ("factory.gdpn.yaml: warning: transition 'T1' has no input arcs"), not "<input>"
  const auto inFile = [&](auto& list) {
    for (auto& x : list) {
      if (x.name == edit_.name && x.loc.file.empty()) x.loc.file = doc.model().path;
    }
  };
  switch (edit_.kind) {
    case NetEditKind::AddPlace: inFile(changed.places); break;
    case NetEditKind::AddTransition: inFile(changed.transitions); break;
    case NetEditKind::AddInstance: inFile(changed.instances); break;
    case NetEditKind::Move:
    case NetEditKind::Rename:
    case NetEditKind::Delete:
    case NetEditKind::AddArc:
    case NetEditKind::DeleteArc:
    case NetEditKind::SetArcWeight:
    case NetEditKind::SetPlace:
    case NetEditKind::SetTransition:
    case NetEditKind::Paste:
    case NetEditKind::MoveMany:
    case NetEditKind::DeleteMany:
    case NetEditKind::SetArc: break;
  }
  positions_.reset();
  before_ = std::move(*page);
  *page = std::move(changed);
  doc.touched(false);
  return {};
}

void NetEditCommand::revert(Document& doc) {
  net::PageSpec* page = findPage(doc.editableNet(), edit_.page);
  if (page == nullptr) return;
  if (arc_before_ && arc_before_->first < page->arcs.size()) page->arcs[arc_before_->first] = arc_before_->second;
  else if (positions_) restorePositions(*page, *positions_);
  else if (before_) *page = *before_;
  else return;
  doc.touched(false);
}

std::string NetEditCommand::label() const {
  switch (edit_.kind) {
    case NetEditKind::AddPlace: return "add place " + edit_.page + "/" + edit_.name;
    case NetEditKind::AddTransition: return "add transition " + edit_.page + "/" + edit_.name;
    case NetEditKind::Move: return "move " + edit_.page + "/" + edit_.name;
    case NetEditKind::Rename: return "rename " + edit_.page + "/" + edit_.name + " to " + edit_.new_name;
    case NetEditKind::Delete: return "delete " + edit_.page + "/" + edit_.name;
    case NetEditKind::AddArc: return std::string("add ") + kindName(edit_.arc_kind) + " " + edit_.name + " -> " + edit_.new_name;
    case NetEditKind::DeleteArc:
      return std::string("delete ") + kindName(edit_.arc_kind) + " " + edit_.name + " -> " + edit_.new_name;
    case NetEditKind::SetArcWeight: return "set the weight of " + edit_.name + " -> " + edit_.new_name;
    case NetEditKind::SetPlace: return "edit place " + edit_.page + "/" + edit_.name;
    case NetEditKind::SetTransition: return "edit transition " + edit_.page + "/" + edit_.name;
    case NetEditKind::Paste: return "paste into " + edit_.page;
    case NetEditKind::MoveMany:
      return edit_.moves.size() == 1 ? "move " + edit_.page + "/" + edit_.moves.front().first
                                     : "move " + std::to_string(edit_.moves.size()) + " items of " + edit_.page;
    case NetEditKind::DeleteMany:
      if (edit_.names.size() + edit_.arcs.size() == 1) {
        return "delete " + (edit_.names.empty() ? std::string(kindName(edit_.arcs.front().kind)) + " " + edit_.arcs.front().from +
                                                      " -> " + edit_.arcs.front().to
                                                : edit_.page + "/" + edit_.names.front());
      }
      return "delete " + std::to_string(edit_.names.size() + edit_.arcs.size()) + " items of " + edit_.page;
    case NetEditKind::SetArc: return std::string("edit ") + kindName(edit_.arc_kind) + " " + edit_.name + " -> " + edit_.new_name;
    case NetEditKind::AddInstance: return "add instance " + edit_.page + "/" + edit_.name + " of " + edit_.new_name;
  }
  return "edit the net";
}

std::uint64_t NetEditCommand::mergeKey() const {
  const bool drags = edit_.kind == NetEditKind::Move || edit_.kind == NetEditKind::MoveMany || edit_.kind == NetEditKind::SetArc;
  if (!drags || edit_.drag == 0) return 0;
  std::string what = edit_.page + '\n' + net::arcKindName(edit_.arc_kind) + '\n';
  if (edit_.kind == NetEditKind::MoveMany) what += "\x01group";
  else if (edit_.kind == NetEditKind::SetArc) what += "\x02arc " + edit_.name + " -> " + edit_.new_name;  // a bend or label dragged
  else what += edit_.name;
  const auto h = std::hash<std::string>{}(what);
  return (h ^ (edit_.drag * 0x9E3779B97F4A7C15ULL)) | 1U;
}

void NetEditCommand::absorb(const Command& next) {
  // the step keeps the page as it was before the drag and takes the last positions
  const auto& later = static_cast<const NetEditCommand&>(next).edit_;
  edit_.at = later.at;
  edit_.moves = later.moves;
  edit_.arc = later.arc;
}

}  // namespace gdpn::ide

#include "gdpn/net/compile.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <numeric>
#include <optional>
#include <set>
#include <tuple>
#include <unordered_map>
#include <unordered_set>

#include "gdpn/core/text.h"
#include "gdpn/net/builder.h"

namespace gdpn::net {
namespace {

using core::Diagnostics;

/// What a name on a page stands for.
struct Local {
  enum class What : std::uint8_t { Place, Transition, Link };
  What what;
  std::uint32_t index;  // page-local index of the place/transition, or flat PlaceId for links
};

/// One (construct, slot) vertex of the slot-kind graph, with the declaration that fixed it.
struct KindSource {
  SlotKind kind = SlotKind::Control;
  SourceLoc loc;
  std::string place;  // qualified place name that declared it
};

class Compiler {
 public:
  Compiler(const NetSpec& spec, Diagnostics& diags) : spec_(spec), diags_(diags) {}

  std::shared_ptr<const Net> run() {
    indexPageTypes();
    checkUnique(spec_.pages, "page");
    for (const auto& page : spec_.pages) checkPage(page, false);
    for (const auto& type : spec_.page_types) checkPage(type, true);
    if (diags_.hasErrors()) return nullptr;

    for (const auto& page : spec_.pages) {
      std::vector<std::string> stack;
      instantiate(page, page.name, "", stack);
    }
    if (diags_.hasErrors()) return nullptr;
    resolveKinds();
    checkParallelArcs();
    checkBalance();
    checkPredicates();
    if (diags_.hasErrors()) return nullptr;
    emit();
    return builder_.freeze();
  }

 private:
  // ---- checks that depend on one page alone (done once per page or page type) ----

  template <class T>
  void checkUnique(const std::vector<T>& items, const char* what) {
    std::unordered_map<std::string, const T*> seen;
    for (const auto& item : items) {
      auto [it, fresh] = seen.emplace(item.name, &item);
      if (!fresh) {
        diags_.error(item.loc, std::string(what) + " '" + item.name + "' is defined twice");
        diags_.note(it->second->loc, "first defined here");
      }
    }
  }

  void indexPageTypes() {
    checkUnique(spec_.page_types, "page type");
    for (const auto& t : spec_.page_types) types_.try_emplace(t.name, &t);
  }

  void checkName(const std::string& name, const SourceLoc& loc, const char* what) {
    if (!core::isIdentifier(name)) {
      diags_.error(loc, std::string(what) + " name '" + name +
                            "' is not an identifier (letters, digits and '_', not starting with a digit)");
    }
  }

  void checkDuration(const Duration& d, const std::string& who) {
    auto bad = [&](const std::string& why) {
      diags_.error(d.loc, "duration of transition '" + who + "' " + why);
    };
    if (!std::isfinite(d.a) || !std::isfinite(d.b)) return bad("must be a finite number of seconds");
    switch (d.law) {
      case Duration::Law::Fixed:
        if (d.a < 0) bad("is negative (" + core::formatDouble(d.a) + " s)");
        break;
      case Duration::Law::Uniform:
        if (d.a < 0 || d.b < 0) bad("has a negative bound");
        else if (d.b < d.a) bad("has its upper bound below its lower bound");
        break;
      case Duration::Law::Normal:
        if (d.a < 0) bad("has a negative mean");
        if (d.b < 0) bad("has a negative standard deviation");
        break;
      case Duration::Law::Exponential:
        if (d.a <= 0) bad("needs a positive mean");
        break;
    }
  }

  void checkPage(const PageSpec& page, bool is_type) {
    checkName(page.name, page.loc, is_type ? "page type" : "page");
    // places, transitions and instances share the page's namespace; the first of a name is
    // what arcs that name reach
    names_.clear();
    names_.reserve(page.places.size() + page.transitions.size() + page.instances.size());
    auto claim = [&](const std::string& name, const SourceLoc& loc, const char* what, Named named) {
      checkName(name, loc, what);
      named.loc = &loc;
      auto [it, fresh] = names_.emplace(name, named);
      if (!fresh) {
        diags_.error(loc, std::string("name '") + name + "' is used twice on page '" + page.name + "'");
        diags_.note(*it->second.loc, "first used here");
      }
    };
    for (const auto& p : page.places) {
      claim(p.name, p.loc, "place", {nullptr, Local::What::Place, nullptr});
      checkPlaceValues(p);
    }
    for (const auto& t : page.transitions) {
      claim(t.name, t.loc, "transition", {nullptr, Local::What::Transition, nullptr});
      checkDuration(t.duration, t.name);
      if (!(t.probability > 0.0 && t.probability <= 1.0)) {
        diags_.error(t.probability_loc, "probability of transition '" + t.name +
                                            "' must lie in (0, 1], got " + core::formatDouble(t.probability));
      }
    }
    for (const auto& i : page.instances) {
      claim(i.name, i.loc, "instance", {nullptr, std::nullopt, &i});
      if (!types_.count(i.type)) {
        std::vector<std::string> known;
        for (const auto& [name, type] : types_) known.push_back(name);
        std::sort(known.begin(), known.end());
        diags_.error(i.type_loc, "unknown page type '" + i.type + "'" + core::didYouMean(i.type, known));
      }
    }
    for (const auto& r : page.references) {
      const auto named = names_.find(r.place);
      if (named == names_.end() || named->second.end != Local::What::Place) {
        diags_.error(r.loc, "reference '" + r.place + "' names no place of page type '" + page.name + "'" +
                                core::didYouMean(r.place, placeNames(page)));
      }
    }
    for (const auto& a : page.arcs) checkArc(page, a);
    // one pass over the arcs, not one per transition
    std::unordered_set<std::string_view> targets;
    for (const auto& a : page.arcs) targets.insert(a.to);
    for (const auto& t : page.transitions) {
      if (!targets.count(t.name)) {
        diags_.warning(t.loc, "transition '" + t.name + "' has no input arcs: it starts again in every "
                              "step it is not occurring");
      }
    }
  }

  static std::vector<std::string> placeNames(const PageSpec& page) {
    std::vector<std::string> out;
    for (const auto& p : page.places) out.push_back(p.name);
    return out;
  }

  void checkPlaceValues(const PlaceSpec& p) {
    for (const auto& t : p.tokens) {
      if (t.value < 0) diags_.error(t.loc, "place '" + p.name + "' has a negative marking");
    }
    for (const auto& c : p.capacity) {
      if (c.value < 0) {
        diags_.error(c.loc, "place '" + p.name + "' has a negative capacity");
        continue;
      }
      std::int64_t initial = 0;
      for (const auto& t : p.tokens) {
        if (t.slot == c.slot) initial += t.value;
      }
      for (const auto& n : p.nodes) {
        if (n.slot == c.slot) initial += static_cast<std::int64_t>(n.nodes.size());
      }
      if (initial > c.value) {
        diags_.error(c.loc, "capacity " + std::to_string(c.value) + " of place '" + p.name + "' at slot " +
                                slotName(c.slot) + " is below its initial marking of " +
                                std::to_string(initial));
      }
    }
  }

  /// Resolves an arc end on `page` to what it names, reporting unknown names.
  std::optional<Local::What> endKind(const PageSpec& page, const std::string& name, const SourceLoc& loc) {
    if (auto named = names_.find(name); named != names_.end() && named->second.end) return named->second.end;
    const auto slash = name.find('/');
    if (slash != std::string::npos) {
      const std::string inst = name.substr(0, slash);
      const std::string ref = name.substr(slash + 1);
      if (auto found = names_.find(inst); found != names_.end() && found->second.instance) {
        const InstanceSpec& i = *found->second.instance;
        auto type = types_.find(i.type);
        if (type == types_.end()) return std::nullopt;  // reported with the instance
        std::vector<std::string> refs;
        for (const auto& r : type->second->references) {
          if (r.place == ref) return Local::What::Link;
          refs.push_back(r.place);
        }
        diags_.error(loc, "instance '" + inst + "' of page type '" + i.type + "' has no reference '" + ref +
                              "'" + core::didYouMean(ref, refs));
        return std::nullopt;
      }
    }
    std::vector<std::string> known = placeNames(page);
    for (const auto& t : page.transitions) known.push_back(t.name);
    diags_.error(loc, "'" + name + "' names no place, transition or link on page '" + page.name + "'" +
                          core::didYouMean(name, known));
    return std::nullopt;
  }

  void checkArc(const PageSpec& page, const ArcSpec& a) {
    const auto from = endKind(page, a.from, a.from_loc);
    const auto to = endKind(page, a.to, a.to_loc);
    for (const auto& w : a.weights) {
      if (w.value < 1) {
        diags_.error(w.loc, "arc weight must be at least 1, got " + std::to_string(w.value));
      } else if (w.value > kMaxWeight) {
        diags_.error(w.loc, "arc weight " + std::to_string(w.value) + " is too large (at most " +
                                std::to_string(kMaxWeight) + ")");
      }
    }
    for (const auto& pred : a.predicates) {
      bool carried = a.weights.empty() ? pred.slot == kDefaultSlot : false;
      for (const auto& w : a.weights) carried = carried || w.slot == pred.slot;
      if (!carried) {
        diags_.error(pred.expression.loc, "predicate on slot " + slotName(pred.slot) +
                                              ", which the arc does not carry");
      }
      if (a.kind == ArcKind::Inhibitor) {
        diags_.error(pred.expression.loc, "a predicate belongs on a normal or test input arc, not an inhibitor");
      }
    }
    if (!from || !to) return;
    const bool from_t = *from == Local::What::Transition;
    if (from_t && !a.predicates.empty()) {
      diags_.error(a.predicates[0].expression.loc, "a predicate belongs on an input arc (place to transition)");
    }
    const bool to_t = *to == Local::What::Transition;
    if (from_t == to_t) {
      diags_.error(a.loc, std::string("an arc joins a place and a transition, but '") + a.from + "' and '" +
                              a.to + "' are both " + (from_t ? "transitions" : "places"));
    } else if (from_t && a.kind != ArcKind::Normal) {
      diags_.error(a.loc, std::string(a.kind == ArcKind::Inhibitor ? "an " : "a ") + arcKindName(a.kind) +
                              " arc must run from a place to a transition");
    }
  }

  // ---- instantiation: flatten pages and page types into qualified constructs ----

  struct FlatPlace {
    const PlaceSpec* spec;
    std::string name;
    std::string node_prefix;
  };
  struct FlatTransition {
    const TransitionSpec* spec;
    std::string name;
  };
  struct FlatArc {
    PlaceId place;
    TransitionId transition;
    bool output;
    const ArcSpec* spec;
  };

  /// Expands `page` under `prefix`; returns the flat PlaceIds of its places (by local index).
  std::vector<PlaceId> instantiate(const PageSpec& page, const std::string& prefix,
                                   const std::string& node_prefix, std::vector<std::string>& stack) {
    std::vector<PlaceId> place_ids;
    place_ids.reserve(page.places.size());
    std::unordered_map<std::string_view, Local> scope;  // places and transitions
    std::unordered_map<std::string, Local> links;       // "instance/reference"
    scope.reserve(page.places.size() + page.transitions.size());
    for (std::uint32_t i = 0; i < page.places.size(); ++i) {
      const auto& p = page.places[i];
      const auto id = static_cast<PlaceId>(places_.size());
      places_.push_back({&p, prefix + "/" + p.name, node_prefix});
      place_ids.push_back(id);
      scope.emplace(p.name, Local{Local::What::Place, id});
    }
    for (const auto& inst : page.instances) {
      const PageSpec* type = types_.at(inst.type);
      if (std::find(stack.begin(), stack.end(), inst.type) != stack.end()) {
        std::string chain;
        for (const auto& s : stack) chain += s + " -> ";
        diags_.error(inst.loc, "page type '" + inst.type + "' contains itself (" + chain + inst.type + ")");
        continue;
      }
      stack.push_back(inst.type);
      auto inner = instantiate(*type, prefix + "/" + inst.name, node_prefix + inst.name + "/", stack);
      stack.pop_back();
      std::unordered_set<std::string_view> published;
      for (const auto& r : type->references) published.insert(r.place);
      for (std::size_t k = 0; k < type->places.size() && !published.empty(); ++k) {
        if (published.count(type->places[k].name)) {
          links.emplace(inst.name + "/" + type->places[k].name, Local{Local::What::Link, inner[k]});
        }
      }
    }
    for (const auto& t : page.transitions) {
      const auto id = static_cast<TransitionId>(transitions_.size());
      transitions_.push_back({&t, prefix + "/" + t.name});
      scope.emplace(t.name, Local{Local::What::Transition, id});
    }
    auto resolve = [&](const std::string& name) -> const Local* {
      if (auto it = scope.find(name); it != scope.end()) return &it->second;
      if (auto it = links.find(name); it != links.end()) return &it->second;
      return nullptr;
    };
    arcs_.reserve(arcs_.size() + page.arcs.size());
    for (const auto& a : page.arcs) {
      const Local* from = resolve(a.from);
      const Local* to = resolve(a.to);
      if (!from || !to) continue;  // only after a cycle error
      const bool output = from->what == Local::What::Transition;
      const PlaceId place = output ? to->index : from->index;
      const TransitionId transition = output ? from->index : to->index;
      arcs_.push_back({place, transition, output, &a});
    }
    return place_ids;
  }

  // ---- slot kinds: union-find over (place, slot) and (transition, slot) ----

  std::uint32_t placeVertex(PlaceId p, SlotId s) const { return p * kSlotCount + s; }
  std::uint32_t transitionVertex(TransitionId t, SlotId s) const {
    return static_cast<std::uint32_t>(places_.size() + t) * kSlotCount + s;
  }
  std::uint32_t find(std::uint32_t v) {
    while (parent_[v] != v) v = parent_[v] = parent_[parent_[v]];
    return v;
  }

  static std::vector<SlotCount> weightsOf(const ArcSpec& a) {
    if (!a.weights.empty() || !a.conditions.empty()) return a.weights;  // a condition alone moves no tokens
    return {SlotCount{kDefaultSlot, 1, a.loc}};
  }

  void resolveKinds() {
    parent_.resize((places_.size() + transitions_.size()) * kSlotCount);
    std::iota(parent_.begin(), parent_.end(), 0u);
    for (const auto& a : arcs_) {
      for (const auto& w : weightsOf(*a.spec)) {
        parent_[find(placeVertex(a.place, w.slot))] = find(transitionVertex(a.transition, w.slot));
      }
    }
    // declarations in declaration order: the first one fixes the kind of its component
    std::unordered_map<std::uint32_t, KindSource> kinds;
    auto declare = [&](PlaceId p, SlotId slot, SlotKind kind, const SourceLoc& loc) {
      const auto root = find(placeVertex(p, slot));
      auto [it, fresh] = kinds.try_emplace(root, KindSource{kind, loc, places_[p].name});
      if (!fresh && it->second.kind != kind) {
        diags_.error(loc, "slot " + slotName(slot) + " is " + slotKindName(kind) + " on place '" +
                              places_[p].name + "' but " + slotKindName(it->second.kind) + " on place '" +
                              it->second.place + "', and arcs join the two");
        diags_.note(it->second.loc, "slot " + slotName(slot) + " of '" + it->second.place + "' is " +
                                        slotKindName(it->second.kind) + " here");
      }
    };
    for (PlaceId p = 0; p < places_.size(); ++p) {
      const auto& spec = *places_[p].spec;
      for (const auto& d : spec.kinds) declare(p, d.slot, d.kind, d.loc);
      for (const auto& t : spec.tokens) declare(p, t.slot, SlotKind::Control, t.loc);
      for (const auto& n : spec.nodes) declare(p, n.slot, SlotKind::Node, n.loc);
      for (const auto& b : spec.sensors) declare(p, b.slot, SlotKind::Sensor, b.loc);
    }
    // a sensor slot carries no tokens: nothing may flow through it (one pass over the arcs)
    const bool sensors = std::any_of(kinds.begin(), kinds.end(), [](const auto& k) { return k.second.kind == SlotKind::Sensor; });
    for (const auto& a : arcs_) {
      if (!sensors) break;
      for (const auto& w : weightsOf(*a.spec)) {
        if (auto k = kinds.find(find(placeVertex(a.place, w.slot))); k != kinds.end() && k->second.kind == SlotKind::Sensor) {
          diags_.error(w.loc, "slot " + slotName(w.slot) + " of '" + places_[a.place].name +
                                  "' reads a sensor and carries no tokens; give the arc a condition instead");
        }
      }
    }
    kind_of_ = [this, kinds = std::move(kinds)](std::uint32_t vertex) {
      auto it = kinds.find(find(vertex));
      return it == kinds.end() ? SlotKind::Control : it->second.kind;
    };
  }

  void checkPredicates() {
    for (const auto& a : arcs_) {
      for (const auto& c : a.spec->conditions) {
        if (a.output) {
          diags_.error(c.expression.loc, "a condition belongs on an arc from a place to a transition");
        } else if (kind_of_(placeVertex(a.place, c.slot)) != SlotKind::Sensor) {
          diags_.error(c.expression.loc, "a condition reads a sensor slot, but slot " + slotName(c.slot) + " of '" +
                                             places_[a.place].name + "' is not one (declare it under 'sensors')");
        }
      }
      for (const auto& pred : a.spec->predicates) {
        if (kind_of_(placeVertex(a.place, pred.slot)) != SlotKind::Node) {
          diags_.error(pred.expression.loc, "a predicate selects node tokens, but slot " + slotName(pred.slot) +
                                                " of '" + places_[a.place].name + "' is a control slot");
        }
      }
    }
  }

  void checkParallelArcs() {
    // one arc that moves tokens each way between a place slot and a transition: two would
    // each find the tokens (two outputs: the room) that only their sum needs
    struct Key {
      PlaceId place;
      TransitionId transition;
      bool output;
      SlotId slot;
      bool operator==(const Key&) const = default;
    };
    struct Hash {
      std::size_t operator()(const Key& k) const {
        const std::uint64_t ends = (std::uint64_t{k.place} << 32) | k.transition;
        return std::hash<std::uint64_t>()(ends * 0x9e3779b97f4a7c15ull + std::uint64_t{k.slot} * 2 + (k.output ? 1 : 0));
      }
    };
    std::unordered_map<Key, const ArcSpec*, Hash> first;  // hashed: a tree of millions of arcs is slow
    first.reserve(arcs_.size());
    std::set<std::pair<const ArcSpec*, const ArcSpec*>> reported;  // a page type's arcs once, not per instance
    for (const auto& a : arcs_) {
      if (!a.output && a.spec->kind != ArcKind::Normal) continue;
      for (const auto& w : weightsOf(*a.spec)) {
        const auto [it, fresh] = first.try_emplace({a.place, a.transition, a.output, w.slot}, a.spec);
        if (fresh || !reported.insert({it->second, a.spec}).second) continue;
        const std::string& place = places_[a.place].name;
        const std::string& transition = transitions_[a.transition].name;
        diags_.error(a.spec->loc, "a second arc from '" + (a.output ? transition : place) + "' to '" +
                                      (a.output ? place : transition) + "' on slot " + slotName(w.slot) +
                                      ": give one arc the sum of their weights");
        diags_.note(it->second->loc, "the first arc is here");
      }
    }
  }

  void checkBalance() {
    // per transition and node slot: tokens taken in must equal tokens put out
    std::map<std::pair<TransitionId, SlotId>, std::pair<std::int64_t, std::int64_t>> flow;
    for (const auto& a : arcs_) {
      if (!a.output && a.spec->kind != ArcKind::Normal) continue;
      for (const auto& w : weightsOf(*a.spec)) {
        if (kind_of_(transitionVertex(a.transition, w.slot)) != SlotKind::Node) continue;
        auto& [in, out] = flow[{a.transition, w.slot}];
        (a.output ? out : in) += w.value;
      }
    }
    for (const auto& [key, io] : flow) {
      if (io.first == io.second) continue;
      const auto& t = transitions_[key.first];
      diags_.error(t.spec->loc, "transition '" + t.name + "' takes " + std::to_string(io.first) +
                                    " token(s) from node slot " + slotName(key.second) + " but puts out " +
                                    std::to_string(io.second) +
                                    "; node tokens keep their identity, so the two must match");
    }
  }

  // ---- emit the checked, flattened net ----

  /// The builder's index of `script`, added once however many instances share it.
  std::int32_t scriptIndex(const ScriptSpec& script) {
    auto [it, fresh] = script_ids_.try_emplace(&script, -1);
    if (fresh) it->second = builder_.addScript(script);
    return it->second;
  }

  void emit() {
    if (!spec_.globals.empty()) builder_.setGlobalsScript(scriptIndex(spec_.globals));
    for (PlaceId p = 0; p < places_.size(); ++p) {
      const auto& fp = places_[p];
      builder_.addPlace(fp.name, fp.spec->loc);
      std::uint32_t used = 0;
      for (const auto& d : fp.spec->kinds) used |= 1u << d.slot;
      for (const auto& t : fp.spec->tokens) used |= 1u << t.slot;
      for (const auto& n : fp.spec->nodes) used |= 1u << n.slot;
      for (const auto& c : fp.spec->capacity) used |= 1u << c.slot;
      for (const auto& sc : fp.spec->scripts) used |= 1u << sc.slot;
      for (const auto& b : fp.spec->sensors) used |= 1u << b.slot;
      for (int s = 0; s < kSlotCount; ++s) {
        if (!(used & (1u << s))) continue;
        const auto slot = static_cast<SlotId>(s);
        builder_.setSlot(p, slot, kind_of_(placeVertex(p, slot)), capacityFor(p, slot), initialFor(p, slot));
        for (const auto& n : fp.spec->nodes) {
          if (n.slot != slot) continue;
          std::vector<std::string> qualified;
          for (const auto& node : n.nodes) qualified.push_back(fp.node_prefix + node);
          builder_.setNodes(p, slot, qualified);
        }
        for (const auto& b : fp.spec->sensors) {
          if (b.slot == slot) builder_.setSensor(p, slot, fp.node_prefix + b.path);
        }
        for (const auto& sc : fp.spec->scripts) {
          if (sc.slot != slot) continue;
          for (const ScriptKind k : kSlotScripts) {
            if (!scriptOf(sc, k).empty()) builder_.setSlotScript(p, slot, k, scriptIndex(scriptOf(sc, k)));
          }
        }
      }
    }
    for (const auto& ft : transitions_) {
      const auto& s = *ft.spec;
      const auto t = builder_.addTransition(ft.name, s.duration, s.priority, s.probability, s.loc);
      for (const ScriptKind k : kTransitionScripts) {
        if (!scriptOf(s, k).empty()) builder_.setTransitionScript(t, k, scriptIndex(scriptOf(s, k)));
      }
    }
    for (const auto& a : arcs_) {
      if (!a.output) {
        for (const auto& c : a.spec->conditions) builder_.addCondition(a.place, a.transition, c.slot, scriptIndex(c.expression));
      }
      for (const auto& w : weightsOf(*a.spec)) {
        const SlotKind kind = kind_of_(placeVertex(a.place, w.slot));
        if (a.output) {
          builder_.addOutput(a.transition, a.place, w.slot, static_cast<std::int32_t>(w.value));
        } else {
          builder_.addInput(a.place, a.transition, w.slot, static_cast<std::int32_t>(w.value), a.spec->kind);
          for (const auto& pred : a.spec->predicates) {
            if (pred.slot == w.slot) builder_.setLastPredicate(scriptIndex(pred.expression));
          }
        }
        // slots made by arcs take the kind of their component
        const auto place = a.place;
        builder_.setSlot(place, w.slot, kind, capacityFor(place, w.slot), initialFor(place, w.slot));
      }
    }
  }

  std::int64_t capacityFor(PlaceId p, SlotId slot) const {
    for (const auto& c : places_[p].spec->capacity) {
      if (c.slot == slot) return c.value;
    }
    return kUnbounded;
  }
  std::int64_t initialFor(PlaceId p, SlotId slot) const {
    std::int64_t n = 0;
    for (const auto& t : places_[p].spec->tokens) n += t.slot == slot ? t.value : 0;
    for (const auto& t : places_[p].spec->nodes) n += t.slot == slot ? static_cast<std::int64_t>(t.nodes.size()) : 0;
    return n;
  }

  const NetSpec& spec_;
  Diagnostics& diags_;
  std::unordered_map<std::string, const PageSpec*> types_;
  // the page being checked: what each name names
  struct Named {
    const SourceLoc* loc;               // where it is declared
    std::optional<Local::What> end;     // a place or transition: what an arc reaches
    const InstanceSpec* instance;       // an instance
  };
  std::unordered_map<std::string_view, Named> names_;
  std::vector<FlatPlace> places_;
  std::vector<FlatTransition> transitions_;
  std::vector<FlatArc> arcs_;
  std::vector<std::uint32_t> parent_;
  std::function<SlotKind(std::uint32_t)> kind_of_;
  std::unordered_map<const ScriptSpec*, std::int32_t> script_ids_;
  NetBuilder builder_;
};

}  // namespace

std::shared_ptr<const Net> compile(const NetSpec& spec, core::Diagnostics& diags) {
  return Compiler(spec, diags).run();
}

}  // namespace gdpn::net

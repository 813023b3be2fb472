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

#include "gdpn/core/memory.h"
#include "gdpn/core/name_table.h"
#include "gdpn/core/text.h"
#include "gdpn/net/builder.h"
#include "gdpn/net/inscription.h"

namespace gdpn::net {
namespace {

using core::Diagnostics;

/// One end of an arc, resolved on its page.
struct End {
  enum class What : std::uint8_t { None, Place, Transition, Link };
  What what = What::None;     // None: the name reaches nothing (reported)
  std::uint32_t index = 0;     // page-local place or transition; for a link, the reference's index in its type
  std::uint32_t instance = 0;  // for a link: the page-local instance
};

/// What checking a page found, kept to instantiate the page as often as it is used without
/// looking a name up again.
struct PageIndex {
  std::vector<std::pair<End, End>> arcs;        // per arc: from, to
  std::vector<const PageSpec*> instance_types;  // per instance; nullptr when its type is unknown
  std::vector<std::uint32_t> reference_places;  // per reference: the page-local place it publishes
};

constexpr std::uint32_t kNone = 0xffffffffu;

/// One (construct, slot) vertex of the slot-kind graph, with the declaration that fixed it.
struct KindSource {
  SlotKind kind = SlotKind::Control;
  const SourceLoc* loc = nullptr;  // in the spec
  PlaceId place{0};               // the flat place that declared it
};

class Compiler {
 public:
  Compiler(const NetSpec& spec, Diagnostics& diags) : spec_(spec), diags_(diags) {}

  std::shared_ptr<const Net> run() {
    for (const auto* pages : {&spec_.pages, &spec_.page_types}) {
      for (const auto& page : *pages) {
        for (const auto& pl : page.places) spec_has_fluid_ = spec_has_fluid_ || pl.continuous();
        for (const auto& tr : page.transitions) spec_has_fluid_ = spec_has_fluid_ || tr.continuous();
      }
    }
    indexPageTypes();
    checkUnique(spec_.pages, "page");
    for (const auto& page : spec_.pages) checkPage(page, false);
    for (const auto& type : spec_.page_types) checkPage(type, true);
    checkFusions();
    if (diags_.hasErrors()) return nullptr;
    reserveFlat();
    for (const auto& page : spec_.pages) {
      std::vector<const PageSpec*> stack;
      instantiate(page, kNoScope, page.name, "", stack);
    }
    if (diags_.hasErrors()) return nullptr;
    fuse();
    checkFusedArcs();
    if (diags_.hasErrors()) return nullptr;
    splitFluid();
    if (diags_.hasErrors()) return nullptr;
    resolveKinds();
    checkBalance();
    checkPredicates();
    checkHandlers();
    if (diags_.hasErrors()) return nullptr;
    checkColours();
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
      case Duration::Law::Immediate:
        break;
    }
  }

  void checkPage(const PageSpec& page, bool is_type) {
    checkName(page.name, page.loc, is_type ? "page type" : "page");
    PageIndex& index = indexes_[&page];
    const auto n_places = static_cast<std::uint32_t>(page.places.size());
    const auto n_named = n_places + static_cast<std::uint32_t>(page.transitions.size());
    // places, transitions and instances share the page's namespace (ids in that order); the
    // first of a name is what arcs that name reach
    const NameOf name_of{page};
    names_.clear();
    names_.insertAll(n_named + static_cast<std::uint32_t>(page.instances.size()), name_of,
                     [&](std::uint32_t id, std::uint32_t first) {
                       diags_.error(name_of.loc(id), "name '" + std::string(name_of(id)) +
                                                         "' is used twice on page '" + page.name + "'");
                       diags_.note(name_of.loc(first), "first used here");
                     });
    for (std::uint32_t i = 0; i < n_places; ++i) {
      checkName(page.places[i].name, page.places[i].loc, "place");
      checkPlaceValues(page.places[i]);
    }
    for (std::uint32_t i = 0; i < page.transitions.size(); ++i) {
      const auto& t = page.transitions[i];
      checkName(t.name, t.loc, "transition");
      checkDuration(t.duration, t.name);
      if (!(t.probability > 0.0 && t.probability <= 1.0)) {
        diags_.error(t.probability_loc, "probability of transition '" + t.name +
                                            "' must lie in (0, 1], got " + core::formatDouble(t.probability));
      }
      if (t.servers != kUnlimitedServers && !(t.servers >= 1 && t.servers <= kMostServers)) {
        diags_.error(t.servers_loc, "servers of transition '" + t.name + "' must be a whole number from 1 to " +
                                        std::to_string(kMostServers) + " or 'unlimited', got " +
                                        std::to_string(t.servers));
      }
    }
    for (std::uint32_t i = 0; i < page.instances.size(); ++i) {
      const auto& inst = page.instances[i];
      checkName(inst.name, inst.loc, "instance");
      const auto type = types_.find(inst.type);
      index.instance_types.push_back(type == types_.end() ? nullptr : type->second);
      if (type == types_.end()) {
        std::vector<std::string> known;
        for (const auto& [name, t] : types_) known.push_back(name);
        std::sort(known.begin(), known.end());
        diags_.error(inst.type_loc, "unknown page type '" + inst.type + "'" + core::didYouMean(inst.type, known));
      }
    }
    for (const auto& r : page.references) {
      const auto id = names_.find(r.place, name_of);
      index.reference_places.push_back(id && *id < n_places ? *id : kNone);
      if (!id || *id >= n_places) {
        diags_.error(r.loc, "reference '" + r.place + "' names no place of page type '" + page.name + "'" +
                                core::didYouMean(r.place, placeNames(page)));
      }
    }
    index.arcs.reserve(page.arcs.size());
    std::vector<bool> has_input(page.transitions.size(), false);  // one pass over the arcs
    std::vector<bool> takes(page.transitions.size(), false);      // a normal input arc
    constexpr std::size_t kAhead = 8;  // arcs whose ends are fetched ahead (see NameTable::prefetch)
    for (std::size_t i = 0; i < page.arcs.size(); ++i) {
      if (i + kAhead < page.arcs.size()) {
        names_.prefetch(page.arcs[i + kAhead].from);
        names_.prefetch(page.arcs[i + kAhead].to);
      }
      const auto& a = page.arcs[i];
      index.arcs.push_back(checkArc(page, a, name_of));
      if (index.arcs.back().second.what == End::What::Transition) {
        has_input[index.arcs.back().second.index] = true;
        if (a.kind == ArcKind::Normal) takes[index.arcs.back().second.index] = true;
      }
    }
    for (std::uint32_t i = 0; i < page.transitions.size(); ++i) {
      if (!takes[i] && page.transitions[i].servers == kUnlimitedServers) {
        diags_.error(page.transitions[i].servers_loc,
                     "transition '" + page.transitions[i].name +
                         "' has unlimited servers but takes no tokens: it would start without end in one "
                         "step (give it a number of servers, or an input arc that takes)");
      }
      if (!has_input[i]) {
        diags_.warning(page.transitions[i].loc, "transition '" + page.transitions[i].name +
                                                    "' has no input arcs: it starts again in every step it is "
                                                    "not occurring");
      }
    }
    checkParallelArcs(page, index);
  }

  /// The name and declaration of each id of a page's namespace (see checkPage).
  struct NameOf {
    const PageSpec& page;
    std::string_view operator()(std::uint32_t id) const { return item(id).first; }
    const SourceLoc& loc(std::uint32_t id) const { return *item(id).second; }
    std::pair<std::string_view, const SourceLoc*> item(std::uint32_t id) const {
      if (id < page.places.size()) return {page.places[id].name, &page.places[id].loc};
      id -= static_cast<std::uint32_t>(page.places.size());
      if (id < page.transitions.size()) return {page.transitions[id].name, &page.transitions[id].loc};
      id -= static_cast<std::uint32_t>(page.transitions.size());
      return {page.instances[id].name, &page.instances[id].loc};
    }
  };

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
  End endOf(const PageSpec& page, const std::string& name, const SourceLoc& loc, const NameOf& name_of) {
    const auto n_places = static_cast<std::uint32_t>(page.places.size());
    const auto n_named = n_places + static_cast<std::uint32_t>(page.transitions.size());
    if (const auto id = names_.find(name, name_of); id && *id < n_named) {
      return *id < n_places ? End{End::What::Place, *id, 0} : End{End::What::Transition, *id - n_places, 0};
    }
    const auto slash = name.find('/');
    if (slash != std::string::npos) {
      const std::string_view inst = std::string_view(name).substr(0, slash);
      const std::string_view ref = std::string_view(name).substr(slash + 1);
      if (const auto id = names_.find(inst, name_of); id && *id >= n_named) {
        const InstanceSpec& i = page.instances[*id - n_named];
        auto type = types_.find(i.type);
        if (type == types_.end()) return {};  // reported with the instance
        std::vector<std::string> refs;
        const auto& references = type->second->references;
        for (std::uint32_t k = 0; k < references.size(); ++k) {
          if (references[k].place == ref) return {End::What::Link, k, *id - n_named};
          refs.push_back(references[k].place);
        }
        diags_.error(loc, "instance '" + std::string(inst) + "' of page type '" + i.type + "' has no reference '" +
                              std::string(ref) + "'" + core::didYouMean(std::string(ref), refs));
        return {};
      }
    }
    std::vector<std::string> known = placeNames(page);
    for (const auto& t : page.transitions) known.push_back(t.name);
    diags_.error(loc, "'" + name + "' names no place, transition or link on page '" + page.name + "'" +
                          core::didYouMean(name, known));
    return {};
  }

  std::pair<End, End> checkArc(const PageSpec& page, const ArcSpec& a, const NameOf& name_of) {
    const End from = endOf(page, a.from, a.from_loc, name_of);
    const End to = endOf(page, a.to, a.to_loc, name_of);
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
    if (from.what == End::What::None || to.what == End::What::None) return {from, to};
    const bool from_t = from.what == End::What::Transition;
    if (from_t && !a.predicates.empty()) {
      diags_.error(a.predicates[0].expression.loc, "a predicate belongs on an input arc (place to transition)");
    }
    const bool to_t = to.what == End::What::Transition;
    if (from_t == to_t) {
      diags_.error(a.loc, std::string("an arc joins a place and a transition, but '") + a.from + "' and '" +
                              a.to + "' are both " + (from_t ? "transitions" : "places"));
      return {};
    }
    if (from_t && a.kind != ArcKind::Normal) {
      diags_.error(a.loc, std::string(a.kind == ArcKind::Inhibitor ? "an " : "a ") + arcKindName(a.kind) +
                              " arc must run from a place to a transition");
    }
    return {from, to};
  }

  /// One arc that moves tokens each way between a place slot and a transition: two would each
  /// find the tokens (two outputs: the room) that only their sum needs. Checked on the page,
  /// once however many instances it has: a transition and its arcs always share a page.
  void checkParallelArcs(const PageSpec& page, const PageIndex& index) {
    struct Use {
      std::uint64_t place;  // page-local place, or (instance + 1) << 32 | reference
      std::uint32_t arc;
      SlotId slot;
      bool output;
      auto key() const { return std::tuple(output, slot, place, arc); }
    };
    std::vector<std::uint32_t> begin(page.transitions.size() + 1, 0);
    std::vector<std::pair<std::uint32_t, Use>> uses;  // transition, use
    for (std::uint32_t i = 0; i < page.arcs.size(); ++i) {
      const End& from = index.arcs[i].first;  // not a structured binding: the lambda below takes it
      const End& to = index.arcs[i].second;
      if (from.what == End::What::None || to.what == End::What::None) continue;
      const bool output = from.what == End::What::Transition;
      const auto& a = page.arcs[i];
      if (!output && a.kind != ArcKind::Normal) continue;
      const End& place = output ? to : from;
      const std::uint64_t key = place.what == End::What::Place
                                    ? place.index
                                    : (std::uint64_t{place.instance} + 1) << 32 | place.index;
      forEachSlotMoved(a, [&](SlotId slot, std::int64_t, const SourceLoc&) {
        uses.push_back({(output ? from : to).index, Use{key, i, slot, output}});
        ++begin[uses.back().first + 1];
      });
    }
    if (uses.size() < 2) return;
    // group by transition (counting sort), then sort each group, which is small
    for (std::size_t t = 0; t + 1 < begin.size(); ++t) begin[t + 1] += begin[t];
    std::vector<Use> grouped(uses.size());
    std::vector<std::uint32_t> fill(begin.begin(), begin.end() - 1);
    for (const auto& [t, use] : uses) grouped[fill[t]++] = use;
    std::vector<std::tuple<std::uint32_t, std::uint32_t, SlotId>> found;  // second arc, first arc, slot
    for (std::size_t t = 0; t + 1 < begin.size(); ++t) {
      const auto first = grouped.begin() + begin[t], last = grouped.begin() + begin[t + 1];
      if (last - first < 2) continue;
      auto same = [](const Use& x, const Use& y) { return x.output == y.output && x.slot == y.slot && x.place == y.place; };
      if (last - first <= 8) {  // the usual transition: a few arcs, compared pairwise in arc order
        for (auto u = first + 1; u != last; ++u) {
          const auto head = std::find_if(first, u, [&](const Use& x) { return same(x, *u); });
          if (head != u) found.emplace_back(u->arc, head->arc, u->slot);
        }
        continue;
      }
      std::sort(first, last, [](const Use& x, const Use& y) { return x.key() < y.key(); });
      for (auto u = first + 1, head = first; u != last; ++u) {
        if (same(*u, *head)) found.emplace_back(u->arc, head->arc, u->slot);
        else head = u;
      }
    }
    std::sort(found.begin(), found.end());
    for (const auto& [second, first, slot] : found) {
      const auto& a = page.arcs[second];
      diags_.error(a.loc, "a second arc from '" + page.name + "/" + a.from + "' to '" + page.name + "/" + a.to +
                              "' on slot " + slotName(slot) + ": give one arc the sum of their " +
                              (a.inscriptions.empty() ? "weights" : "inscriptions (x ++ y)"));
      diags_.note(page.arcs[first].loc, "the first arc is here");
    }
  }

  // ---- fusion sets: checked on the pages that hold their members ----

  /// Each member names a declared set; an `instance` set's members share one page or page
  /// type; one member declares what the set's place holds, the others name the set alone
  /// (or declare exactly the same).
  void checkFusions() {
    checkUnique(spec_.fusions, "fusion set");
    std::vector<std::string> known;
    for (std::uint32_t i = 0; i < spec_.fusions.size(); ++i) {
      const auto& f = spec_.fusions[i];
      checkName(f.name, f.loc, "fusion set");
      fusion_index_.try_emplace(f.name, i);
      known.push_back(f.name);
    }
    struct Seen {
      const PlaceSpec* first = nullptr;     // its first member
      const PageSpec* page = nullptr;       // the page that holds it
      const PlaceSpec* declarer = nullptr;  // its first member that declares anything
      const PageSpec* declarer_page = nullptr;
    };
    std::vector<Seen> seen(spec_.fusions.size());
    const auto visit = [&](const PageSpec& page) {
      for (const auto& p : page.places) {
        if (p.fusion.empty()) continue;
        const auto it = fusion_index_.find(p.fusion);
        if (it == fusion_index_.end()) {
          diags_.error(p.fusion_loc, "place '" + page.name + "/" + p.name + "' is a member of fusion set '" + p.fusion +
                                         "', which the model does not declare (under 'fusion')" +
                                         core::didYouMean(p.fusion, known));
          continue;
        }
        member_set_.emplace(&p, it->second);
        const FusionSpec& f = spec_.fusions[it->second];
        Seen& s = seen[it->second];
        if (!s.first) {
          s.first = &p;
          s.page = &page;
        } else if (f.scope == FusionScope::Instance && s.page != &page) {
          diags_.error(p.fusion_loc, "fusion set '" + f.name + "' is one place per instance, so its members lie on one "
                                         "page or page type; '" + page.name + "/" + p.name + "' lies on '" + page.name +
                                         "' but '" + s.page->name + "/" + s.first->name + "' on '" + s.page->name +
                                         "' (make the set global to join places of different pages)");
          diags_.note(s.first->fusion_loc, "the set's first member is here");
        }
        if (!p.declares()) continue;
        if (!s.declarer) {
          s.declarer = &p;
          s.declarer_page = &page;
        } else if (!sameDeclarations(*s.declarer, p)) {
          const std::string first = s.declarer_page->name + "/" + s.declarer->name;
          diags_.error(p.loc, "place '" + page.name + "/" + p.name + "' and place '" + first + "' of fusion set '" +
                                  f.name + "' declare its tokens, capacity, slot kinds, sensors or scripts differently; "
                                  "one member declares them and the others name the set alone");
          diags_.note(s.declarer->loc, "'" + first + "' declares them here");
        }
      }
    };
    for (const auto& page : spec_.pages) visit(page);
    for (const auto& type : spec_.page_types) visit(type);
    for (std::uint32_t i = 0; i < spec_.fusions.size(); ++i) {
      if (!seen[i].first) {
        diags_.warning(spec_.fusions[i].loc, "fusion set '" + spec_.fusions[i].name +
                                                 "' has no members (a place joins it with 'fusion: " +
                                                 spec_.fusions[i].name + "')");
      }
    }
  }

  // ---- instantiation: flatten pages and page types into qualified constructs ----

  struct FlatPlace {
    const PlaceSpec* spec;
    std::uint32_t scope;        // its instantiated page (a scope in builder_.names())
    std::uint32_t local;        // its index in its page's places (and table)
    std::uint32_t node_prefix;  // in node_prefixes_: what qualifies its scene paths ("cellA/")
  };
  struct FlatTransition {
    const TransitionSpec* spec;
    std::uint32_t scope;  // its instantiated page
    std::uint32_t local;  // its index in its page's transitions (and table)
  };

  /// The qualified name of flat place `p` ("line/cellA/buffer"), for messages.
  std::string placeName(PlaceId p) {
    std::string out;
    builder_.names().appendName(out, places_[p].scope, places_[p].spec->name);
    return out;
  }
  /// The qualified name of flat transition `t`, for messages.
  std::string transitionName(TransitionId t) {
    std::string out;
    builder_.names().appendName(out, transitions_[t].scope, transitions_[t].spec->name);
    return out;
  }

  /// The table of `page`'s local names and locations, made once for all its instances.
  std::uint32_t tableOf(const PageSpec& page) {
    auto [it, fresh] = tables_.try_emplace(&page, 0);
    if (!fresh) return it->second;
    auto& names = builder_.names();
    it->second = names.addTable();
    for (const auto& p : page.places) names.addPlace(it->second, p.name, p.loc);
    for (const auto& t : page.transitions) names.addTransition(it->second, t.name, t.loc);
    return it->second;
  }
  struct FlatArc {
    PlaceId place;
    TransitionId transition;
    bool output;
    const ArcSpec* spec;
  };

  /// Flat places, transitions and arcs of `page` with its instances expanded (a cycle counts
  /// nothing: it is reported by instantiate()).
  std::array<std::size_t, 3> flatSize(const PageSpec& page, std::unordered_map<const PageSpec*, std::array<std::size_t, 3>>& memo) {
    if (auto it = memo.find(&page); it != memo.end()) return it->second;
    memo[&page] = {0, 0, 0};  // in progress
    std::array<std::size_t, 3> n{page.places.size(), page.transitions.size(), page.arcs.size()};
    const auto& index = indexes_.at(&page);
    for (const PageSpec* type : index.instance_types) {
      const auto inner = flatSize(*type, memo);
      for (std::size_t k = 0; k < 3; ++k) n[k] += inner[k];
    }
    return memo[&page] = n;
  }

  void reserveFlat() {
    std::unordered_map<const PageSpec*, std::array<std::size_t, 3>> memo;
    std::array<std::size_t, 3> n{0, 0, 0};
    for (const auto& page : spec_.pages) {
      const auto size = flatSize(page, memo);
      for (std::size_t k = 0; k < 3; ++k) n[k] += size[k];
    }
    core::reserveLarge(places_, n[0]);
    core::reserveLarge(transitions_, n[1]);
    core::reserveLarge(arcs_, n[2]);
  }

  /// Expands `page` as a scope called `name` inside `parent` (kNoScope for a top page): its
  /// places first (so an instance's own places are consecutive from the first), then its
  /// instances, its transitions and its arcs.
  void instantiate(const PageSpec& page, std::uint32_t parent, std::string_view name, const std::string& node_prefix,
                   std::vector<const PageSpec*>& stack) {
    const PageIndex& index = indexes_.at(&page);
    const auto base = static_cast<std::uint32_t>(places_.size());
    const auto scope = builder_.names().addScope(parent, name, tableOf(page), base, 0);
    const auto prefix_index = static_cast<std::uint32_t>(node_prefixes_.size());
    if (!page.places.empty()) node_prefixes_.push_back(node_prefix);
    if (spec_has_fluid_) scope_prefix_[scope] = node_prefix;
    for (std::uint32_t k = 0; k < page.places.size(); ++k) places_.push_back({&page.places[k], scope, k, prefix_index});
    std::vector<std::optional<PlaceId>> inner(page.instances.size());  // the first place of each instance
    for (std::size_t k = 0; k < page.instances.size(); ++k) {
      const auto& inst = page.instances[k];
      const PageSpec* type = index.instance_types[k];
      if (std::find(stack.begin(), stack.end(), type) != stack.end()) {
        std::string chain;
        for (const auto* s : stack) chain += s->name + " -> ";
        diags_.error(inst.loc, "page type '" + inst.type + "' contains itself (" + chain + inst.type + ")");
        continue;
      }
      inner[k] = PlaceId{places_.size()};
      stack.push_back(type);
      instantiate(*type, scope, inst.name, node_prefix + inst.name + "/", stack);
      stack.pop_back();
    }
    const auto tbase = static_cast<std::uint32_t>(transitions_.size());
    builder_.names().setFirstTransition(scope, tbase);
    for (std::uint32_t k = 0; k < page.transitions.size(); ++k) transitions_.push_back({&page.transitions[k], scope, k});
    auto placeOf = [&](const End& end) -> std::optional<PlaceId> {
      if (end.what == End::What::Place) return PlaceId{base + end.index};
      if (!inner[end.instance]) return std::nullopt;  // only after a cycle error
      const PageIndex& type = indexes_.at(index.instance_types[end.instance]);
      return PlaceId{*inner[end.instance] + type.reference_places[end.index]};
    };
    for (std::size_t i = 0; i < page.arcs.size(); ++i) {
      const auto& [from, to] = index.arcs[i];
      if (from.what == End::What::None || to.what == End::What::None) continue;  // reported
      const bool output = from.what == End::What::Transition;
      const auto place = placeOf(output ? to : from);
      if (!place) continue;
      arcs_.push_back({*place, TransitionId{tbase + (output ? from : to).index}, output, &page.arcs[i]});
    }
  }

  // ---- fusion: the members of a set (per instance, for an `instance` set) become one place ----

  /// Makes the flat places of each fusion set one: the member that declares what it holds
  /// (else the first) stays, under its name; the arcs of the others move to it. The scopes
  /// keep numbering their places as before, and the names map each number to its place.
  void fuse() {
    if (member_set_.empty()) return;
    const auto n = static_cast<std::uint32_t>(places_.size());
    std::vector<std::uint32_t> group(n, kNone);  // per flat place: its set's place, as the flat place that stays
    std::unordered_map<std::uint64_t, std::uint32_t> kept;  // (set, scope) -> the flat place that stays
    for (std::uint32_t v = 0; v < n; ++v) {
      const auto member = member_set_.find(places_[v].spec);
      if (member == member_set_.end()) continue;
      const bool per_instance = spec_.fusions[member->second].scope == FusionScope::Instance;
      const std::uint64_t key = std::uint64_t{member->second} << 32 | (per_instance ? places_[v].scope : kNone);
      auto [it, fresh] = kept.try_emplace(key, v);
      if (!fresh && !places_[it->second].spec->declares() && places_[v].spec->declares()) it->second = v;
    }
    for (std::uint32_t v = 0; v < n; ++v) {
      const auto member = member_set_.find(places_[v].spec);
      if (member == member_set_.end()) continue;
      const bool per_instance = spec_.fusions[member->second].scope == FusionScope::Instance;
      group[v] = kept.at(std::uint64_t{member->second} << 32 | (per_instance ? places_[v].scope : kNone));
    }
    // the places that stay, in their order; each other member is the place of its set
    std::vector<std::uint32_t> id(n, kNone);
    std::vector<FlatPlace> merged;
    merged.reserve(n);
    for (std::uint32_t v = 0; v < n; ++v) {
      if (group[v] != kNone && group[v] != v) continue;
      id[v] = static_cast<std::uint32_t>(merged.size());
      merged.push_back(places_[v]);
    }
    fused_.assign(merged.size(), false);
    for (std::uint32_t v = 0; v < n; ++v) {
      if (group[v] == kNone || group[v] == v) continue;
      id[v] = id[group[v]];
      fused_[id[v]] = true;
    }
    for (auto& a : arcs_) a.place = PlaceId{id[a.place]};
    places_ = std::move(merged);
    builder_.names().setPlaceIds(std::move(id));
  }

  /// Two arcs between a transition and one fused place on one slot (through two members):
  /// like two arcs to one place, each would find the tokens only their sum needs. Reported
  /// once per pair of arcs, however many instances repeat them.
  void checkFusedArcs() {
    if (fused_.empty()) return;
    std::map<std::tuple<TransitionId, PlaceId, SlotId, bool>, const ArcSpec*> first;
    std::set<std::pair<const ArcSpec*, const ArcSpec*>> told;
    for (const auto& a : arcs_) {
      if (!fused_[a.place] || (!a.output && a.spec->kind != ArcKind::Normal)) continue;
      forEachSlotMoved(*a.spec, [&](SlotId slot, std::int64_t, const SourceLoc&) {
        const auto [it, fresh] = first.try_emplace({a.transition, a.place, slot, a.output}, a.spec);
        if (fresh || !told.emplace(it->second, a.spec).second) return;
        diags_.error(a.spec->loc, "a second arc between transition '" + transitionName(a.transition) +
                                      "' and fusion place '" + placeName(a.place) + "' on slot " + slotName(slot) +
                                      " (through another member of its set): give one arc the sum of their " +
                                      (a.spec->inscriptions.empty() ? "weights" : "inscriptions (x ++ y)"));
        diags_.note(it->second->loc, "the first arc is here");
      });
    }
  }

  // ---- slot kinds: union-find over (place, slot) and (transition, slot), for the slots the
  // net uses (most nets use one or two of the 32) ----

  std::uint32_t placeVertex(PlaceId p, SlotId s) const { return p * slots_used_ + dense_slot_[s]; }
  std::uint32_t transitionVertex(TransitionId t, SlotId s) const {
    return static_cast<std::uint32_t>(places_.size() + t) * slots_used_ + dense_slot_[s];
  }
  std::uint32_t find(std::uint32_t v) {
    while (parent_[v] != v) v = parent_[v] = parent_[parent_[v]];
    return v;
  }
  /// The kind of the component of `vertex`: what its first declaration says, else control.
  SlotKind kindOf(std::uint32_t vertex) { return root_kind_[find(vertex)]; }

  /// Calls `f(slot, tokens, loc)` for each slot arc `a` moves tokens on: its weights, or one
  /// token on the default slot when it names none (a condition alone moves no tokens).
  template <class F>
  static void forEachWeight(const ArcSpec& a, F&& f) {
    if (!a.weights.empty() || !a.conditions.empty() || !a.inscriptions.empty()) {
      for (const auto& w : a.weights) f(w.slot, w.value, w.loc);
    } else {
      f(kDefaultSlot, std::int64_t{1}, a.loc);
    }
  }

  /// forEachWeight, and then each slot the arc's inscriptions move values on (tokens 0: how many
  /// depends on the binding).
  template <class F>
  static void forEachSlotMoved(const ArcSpec& a, F&& f) {
    forEachWeight(a, f);
    for (const auto& i : a.inscriptions) f(i.slot, std::int64_t{0}, i.loc);
  }

  /// Numbers the slots that any arc or place names, densely.
  void numberSlots() {
    std::uint32_t used = 1u << kDefaultSlot;
    auto use = [&](SlotId s) { used |= 1u << s; };
    for (const auto& a : arcs_) {
      for (const auto& w : a.spec->weights) use(w.slot);
      for (const auto& c : a.spec->conditions) use(c.slot);
      for (const auto& p : a.spec->predicates) use(p.slot);
      for (const auto& i : a.spec->inscriptions) use(i.slot);
    }
    const PlaceSpec* last = nullptr;
    for (const auto& fp : places_) {
      if (fp.spec == last) continue;  // instances of one type follow one another
      last = fp.spec;
      for (const auto& d : fp.spec->kinds) use(d.slot);
      for (const auto& t : fp.spec->tokens) use(t.slot);
      for (const auto& n : fp.spec->nodes) use(n.slot);
      for (const auto& c : fp.spec->capacity) use(c.slot);
      for (const auto& sc : fp.spec->scripts) use(sc.slot);
      for (const auto& b : fp.spec->sensors) use(b.slot);
      for (const auto& c : fp.spec->colours) use(c.slot);
    }
    slots_used_ = 0;
    for (int s = 0; s < kSlotCount; ++s) dense_slot_[static_cast<std::size_t>(s)] = (used >> s & 1u) ? slots_used_++ : 0;
  }

  void resolveKinds() {
    numberSlots();
    parent_.resize((places_.size() + transitions_.size()) * slots_used_);
    std::iota(parent_.begin(), parent_.end(), 0u);
    for (const auto& a : arcs_) {
      forEachWeight(*a.spec, [&](SlotId slot, std::int64_t, const SourceLoc&) {
        parent_[find(placeVertex(a.place, slot))] = find(transitionVertex(a.transition, slot));
      });
    }
    // declarations in declaration order: the first one fixes the kind of its component
    root_kind_.assign(parent_.size(), SlotKind::Control);
    std::vector<KindSource> sources;
    std::vector<std::uint32_t> source_of(parent_.size(), kNone);  // per root: its entry in sources
    auto declare = [&](PlaceId p, SlotId slot, SlotKind kind, const SourceLoc& loc) {
      const auto root = find(placeVertex(p, slot));
      if (source_of[root] == kNone) {
        source_of[root] = static_cast<std::uint32_t>(sources.size());
        sources.push_back({kind, &loc, p});
        root_kind_[root] = kind;
        return;
      }
      const KindSource& first = sources[source_of[root]];
      if (first.kind == kind) return;
      const std::string other = placeName(first.place);
      diags_.error(loc, "slot " + slotName(slot) + " is " + slotKindName(kind) + " on place '" + placeName(p) +
                            "' but " + slotKindName(first.kind) + " on place '" + other + "', and arcs join the two");
      diags_.note(*first.loc, "slot " + slotName(slot) + " of '" + other + "' is " + slotKindName(first.kind) + " here");
    };
    for (PlaceId p{0}; p < places_.size(); ++p) {
      const auto& spec = *places_[p].spec;
      for (const auto& d : spec.kinds) declare(p, d.slot, d.kind, d.loc);
      for (const auto& t : spec.tokens) declare(p, t.slot, SlotKind::Control, t.loc);
      for (const auto& n : spec.nodes) declare(p, n.slot, SlotKind::Node, n.loc);
      for (const auto& b : spec.sensors) declare(p, b.slot, SlotKind::Sensor, b.loc);
      for (const auto& c : spec.colours) declare(p, c.slot, SlotKind::Value, c.loc);
    }
    // a sensor slot carries no tokens: nothing may flow through it (one pass over the arcs)
    const bool sensors = std::any_of(sources.begin(), sources.end(), [](const auto& k) { return k.kind == SlotKind::Sensor; });
    for (const auto& a : arcs_) {
      if (!sensors) break;
      forEachWeight(*a.spec, [&](SlotId slot, std::int64_t, const SourceLoc& loc) {
        if (kindOf(placeVertex(a.place, slot)) == SlotKind::Sensor) {
          diags_.error(loc, "slot " + slotName(slot) + " of '" + placeName(a.place) +
                                "' reads a sensor and carries no tokens; give the arc a condition instead");
        }
      });
    }
  }

  void checkPredicates() {
    for (const auto& a : arcs_) {
      for (const auto& c : a.spec->conditions) {
        if (a.output) {
          diags_.error(c.expression.loc, "a condition belongs on an arc from a place to a transition");
        } else if (kindOf(placeVertex(a.place, c.slot)) != SlotKind::Sensor) {
          diags_.error(c.expression.loc, "a condition reads a sensor slot, but slot " + slotName(c.slot) + " of '" +
                                             placeName(a.place) + "' is not one (declare it under 'sensors')");
        }
      }
      for (const auto& pred : a.spec->predicates) {
        if (kindOf(placeVertex(a.place, pred.slot)) != SlotKind::Node) {
          diags_.error(pred.expression.loc, "a predicate selects node tokens, but slot " + slotName(pred.slot) +
                                                " of '" + placeName(a.place) + "' is a control slot");
        }
      }
    }
  }

  /// A sensor handler (on_enter, on_exit, on_sample, on_change) needs a sensor in its slot.
  void checkHandlers() {
    std::set<std::pair<int, int>> told;  // a page type's script is told once, not per instance
    for (PlaceId p{0}; p < places_.size(); ++p) {
      for (const auto& sc : places_[p].spec->scripts) {
        if (kindOf(placeVertex(p, sc.slot)) == SlotKind::Sensor) continue;
        for (const ScriptKind k : kSlotScripts) {
          if (k == ScriptKind::OnDeposit || k == ScriptKind::OnRemove || scriptOf(sc, k).empty()) continue;
          if (!told.emplace(scriptOf(sc, k).loc.line, scriptOf(sc, k).loc.column).second) continue;
          diags_.error(scriptOf(sc, k).loc, std::string(info(k).key) + " of place '" + placeName(p) +
                                                "' is a sensor handler, but its slot " + slotName(sc.slot) +
                                                " holds no sensor (declare one under 'sensors')");
        }
      }
    }
  }

  void checkBalance() {
    // per transition and node slot: tokens taken in must equal tokens put out
    std::map<std::pair<TransitionId, SlotId>, std::pair<std::int64_t, std::int64_t>> flow;
    for (const auto& a : arcs_) {
      if (!a.output && a.spec->kind != ArcKind::Normal) continue;
      forEachWeight(*a.spec, [&](SlotId slot, std::int64_t value, const SourceLoc&) {
        if (kindOf(transitionVertex(a.transition, slot)) != SlotKind::Node) return;
        auto& [in, out] = flow[{a.transition, slot}];
        (a.output ? out : in) += value;
      });
    }
    for (const auto& [key, io] : flow) {
      if (io.first == io.second) continue;
      const auto& t = transitions_[key.first];
      diags_.error(t.spec->loc, "transition '" + transitionName(key.first) + "' takes " + std::to_string(io.first) +
                                    " token(s) from node slot " + slotName(key.second) + " but puts out " +
                                    std::to_string(io.second) +
                                    "; node tokens keep their identity, so the two must match");
    }
  }


  // ---- hybrid nets: the continuous places and transitions, taken out of the discrete net ----

  /// Reports `message` at `loc` once, however many instances repeat the construct.
  void errorOnce(const SourceLoc& loc, const std::string& message) {
    if (told_fluid_.emplace(loc.file, loc.line, loc.column, message).second) diags_.error(loc, message);
  }

  /// Checks the continuous places and transitions, takes every arc with a continuous place out
  /// of arcs_ (they take no part in slot kinds), and builds fluid_: its places, flows, arcs,
  /// thresholds and the terms of discrete transitions on continuous places.
  void splitFluid() {
    if (!spec_has_fluid_) return;
    fluid_of_place_.assign(places_.size(), -1);
    for (PlaceId p{0}; p < places_.size(); ++p) {
      const PlaceSpec& ps = *places_[p].spec;
      if (!ps.continuous()) continue;
      const FluidSpec& fs = *ps.fluid;
      const std::string what = "continuous place '" + ps.name + "'";
      if (!ps.tokens.empty() || !ps.nodes.empty() || !ps.kinds.empty() || !ps.capacity.empty() || !ps.scripts.empty() ||
          !ps.sensors.empty() || !ps.colours.empty() || !ps.values.empty()) {
        errorOnce(fs.loc, what + " holds an amount, not tokens: it takes 'amount', 'capacity' (a number), 'unit' and "
                                 "'drives', not slots, tokens, node tokens, colours, sensors or scripts");
      }
      if (!(fs.amount >= 0.0) || !std::isfinite(fs.amount)) errorOnce(fs.loc, what + ": its amount must be a number >= 0");
      if (fs.capacity && (!(*fs.capacity > 0.0) || !std::isfinite(*fs.capacity))) {
        errorOnce(fs.loc, what + ": its capacity must be a number > 0");
      } else if (fs.capacity && fs.amount > *fs.capacity) {
        errorOnce(fs.loc, what + ": its amount " + core::formatDouble(fs.amount) + " is more than its capacity " +
                              core::formatDouble(*fs.capacity));
      }
      fluid_of_place_[p] = static_cast<std::int32_t>(fluid_.places.size());
      FluidPlace fp;
      fp.place = p;
      fp.initial = fs.amount;
      fp.capacity = fs.capacity.value_or(kNoBound);
      fp.unit = fs.unit;
      for (auto d : fs.drives) {
        d.node = node_prefixes_[places_[p].node_prefix] + d.node;
        fp.drives.push_back(std::move(d));
      }
      fluid_.places.push_back(std::move(fp));
    }
    fluid_.of_place = fluid_of_place_;
    fluid_.of_transition.assign(transitions_.size(), -1);
    for (TransitionId t{0}; t < transitions_.size(); ++t) {
      const TransitionSpec& ts = *transitions_[t].spec;
      if (!ts.continuous()) continue;
      const std::string what = "continuous transition '" + ts.name + "'";
      if (ts.duration != Duration{} || ts.servers != 1 || ts.probability != 1.0 || ts.priority != 0 || ts.scripted() ||
          ts.conditioned()) {
        errorOnce(ts.flow->loc, what + " flows at its rate: it takes no duration, priority, probability, servers, "
                                       "condition or scripts");
      }
      if (ts.flow->rate.text.empty()) errorOnce(ts.flow->loc, what + " needs a rate ('rate: 0.5', units per second)");
      fluid_.of_transition[t] = static_cast<std::int32_t>(fluid_.flows.size());
      Flow flow;
      flow.transition = t;
      fluid_.flows.push_back(std::move(flow));
    }
    // the arcs: a continuous place's leave arcs_; a continuous transition keeps its tests and
    // inhibitors of discrete places there (they switch it)
    struct Pending {
      PlaceId place;
      TransitionId transition;
      bool output;
      const ArcSpec* spec;
    };
    std::vector<Pending> flow_arcs;
    std::vector<FluidTerm> terms;
    std::vector<PlaceId> term_places;
    std::vector<FlatArc> kept;
    for (const auto& a : arcs_) {
      const bool cp = fluid_of_place_[a.place] >= 0;
      const bool ct = fluid_.of_transition[a.transition] >= 0;
      const std::string arc = "arc '" + a.spec->from + "' -> '" + a.spec->to + "'";
      if (!cp && !ct) {
        kept.push_back(a);
        continue;
      }
      if (!a.spec->inscriptions.empty() || !a.spec->predicates.empty() || !a.spec->conditions.empty()) {
        errorOnce(a.spec->loc, arc + " joins a continuous place or transition: it takes a weight, not inscriptions, "
                                     "predicates or conditions");
        continue;
      }
      double w = 1.0;
      if (a.spec->amount) {
        w = *a.spec->amount;
      } else {
        for (const auto& sc : a.spec->weights) w = static_cast<double>(sc.value);
      }
      if (cp && (a.spec->weights.size() > 1 || (a.spec->weights.size() == 1 && a.spec->weights[0].slot != kDefaultSlot))) {
        errorOnce(a.spec->loc, arc + ": a continuous place has no slots; give the arc one weight ('weight: 2.5')");
        continue;
      }
      if (!(w > 0.0) || !std::isfinite(w)) {
        errorOnce(a.spec->loc, arc + ": its weight must be a number > 0");
        continue;
      }
      if (!cp) {
        // a discrete place and a continuous transition: only tests and inhibitors switch a flow
        if (a.output || a.spec->kind == ArcKind::Normal) {
          errorOnce(a.spec->loc, arc + ": a continuous transition neither takes nor puts tokens; switch it with a "
                                       "test or an inhibitor arc ('kind: test')");
          continue;
        }
        if (a.spec->amount && *a.spec->amount != std::floor(*a.spec->amount)) {
          errorOnce(a.spec->loc, arc + ": a discrete place's weight is a whole number");
          continue;
        }
        kept.push_back(a);
        continue;
      }
      if (ct) {
        flow_arcs.push_back({a.place, a.transition, a.output, a.spec});
        continue;
      }
      FluidTerm term;
      term.transition = a.transition;
      term.place = static_cast<std::uint32_t>(fluid_of_place_[a.place]);
      term.weight = w;
      term.test = a.output ? LevelTest::Room
                  : a.spec->kind == ArcKind::Inhibitor ? LevelTest::Below
                                                         : LevelTest::AtLeast;
      term.moves = a.output || a.spec->kind == ArcKind::Normal;
      terms.push_back(term);
      term_places.push_back(a.place);
    }
    arcs_ = std::move(kept);
    // terms grouped by place (stable: in arc order within a place)
    std::vector<std::uint32_t> order(terms.size());
    std::iota(order.begin(), order.end(), 0u);
    std::stable_sort(order.begin(), order.end(), [&](std::uint32_t x, std::uint32_t y) { return terms[x].place < terms[y].place; });
    for (const auto k : order) {
      fluid_.terms.push_back(terms[k]);
      fluid_term_places_.push_back(term_places[k]);
    }
    for (std::uint32_t k = 0; k < fluid_.terms.size(); ++k) {
      auto& fp = fluid_.places[fluid_.terms[k].place];
      if (fp.terms_end == 0) fp.terms_begin = k;
      fp.terms_end = k + 1;
    }
    // each flow's arcs: inputs, outputs, tests, inhibitors
    std::stable_sort(flow_arcs.begin(), flow_arcs.end(), [](const Pending& x, const Pending& y) { return x.transition < y.transition; });
    std::size_t i = 0;
    for (auto& flow : fluid_.flows) {
      std::size_t end = i;
      while (end < flow_arcs.size() && flow_arcs[end].transition == flow.transition) ++end;
      auto weightOf = [](const ArcSpec& arc) {
        double w = 1.0;
        if (arc.amount) w = *arc.amount;
        else for (const auto& sc : arc.weights) w = static_cast<double>(sc.value);
        return w;
      };
      auto take = [&](std::vector<FlowArc>& into, auto pick) {
        for (auto k = i; k < end; ++k) {
          if (!pick(flow_arcs[k])) continue;
          into.push_back({static_cast<std::uint32_t>(fluid_of_place_[flow_arcs[k].place]), weightOf(*flow_arcs[k].spec)});
        }
        return static_cast<std::uint32_t>(into.size());
      };
      flow.inputs_begin = static_cast<std::uint32_t>(fluid_.arcs.size());
      flow.outputs_begin = take(fluid_.arcs, [](const Pending& a) { return !a.output && a.spec->kind == ArcKind::Normal; });
      flow.outputs_end = take(fluid_.arcs, [](const Pending& a) { return a.output; });
      flow.tests_begin = static_cast<std::uint32_t>(fluid_.thresholds.size());
      flow.inhibitors_begin = take(fluid_.thresholds, [](const Pending& a) { return !a.output && a.spec->kind == ArcKind::Test; });
      flow.thresholds_end = take(fluid_.thresholds, [](const Pending& a) { return !a.output && a.spec->kind == ArcKind::Inhibitor; });
      i = end;
    }
    // levels: 0, the capacity and every threshold
    for (auto& fp : fluid_.places) {
      fp.levels.push_back(0.0);
      if (fp.capacity != kNoBound) fp.levels.push_back(fp.capacity);
    }
    for (const auto& term : fluid_.terms) {
      if (term.test != LevelTest::Room) fluid_.places[term.place].levels.push_back(term.weight);
    }
    for (const auto& th : fluid_.thresholds) fluid_.places[th.place].levels.push_back(th.weight);
    for (auto& fp : fluid_.places) {
      std::sort(fp.levels.begin(), fp.levels.end());
      fp.levels.erase(std::unique(fp.levels.begin(), fp.levels.end()), fp.levels.end());
      std::erase_if(fp.levels, [&](double l) { return l > fp.capacity; });
    }
    compileRates();
  }

  /// Compiles each flow's rate: names are the continuous places of its page (their amounts),
  /// its reads, then the model's parameters (constants).
  void compileRates() {
    std::map<std::pair<std::uint32_t, std::string_view>, std::uint32_t> place_of;  // (scope, name) -> fluid place
    for (std::uint32_t k = 0; k < fluid_.places.size(); ++k) {
      const auto& flat = places_[fluid_.places[k].place];
      place_of.emplace(std::make_pair(flat.scope, std::string_view(flat.spec->name)), k);
    }
    const auto places = static_cast<std::uint32_t>(fluid_.places.size());
    struct Constant {
      std::uint32_t flow;
      double value;
    };
    std::vector<Constant> constants;
    for (std::uint32_t k = 0; k < fluid_.flows.size(); ++k) {
      auto& flow = fluid_.flows[k];
      const auto& ft = transitions_[flow.transition];
      const FlowSpec& fs = *ft.spec->flow;
      if (fs.rate.text.empty()) continue;
      const auto reads_begin = static_cast<std::uint32_t>(fluid_.reads.size());
      std::vector<std::string> known;
      for (const auto& [key, index] : place_of) {
        if (key.first == ft.scope) known.emplace_back(key.second);
      }
      for (const auto& r : fs.reads) {
        known.push_back(r.name);
        const auto prefix = scope_prefix_.find(ft.scope);
        fluid_.reads.push_back({(prefix == scope_prefix_.end() ? std::string() : prefix->second) + r.node, r.of, r.loc,
                                flow.transition});
      }
      for (const auto& [name, value] : fs.params) known.push_back(name);
      std::vector<std::pair<std::uint32_t, double>> wanted;  // (placeholder slot, value) of the parameters used
      const auto resolve = [&](std::string_view name) -> std::optional<std::uint32_t> {
        if (auto it = place_of.find({ft.scope, name}); it != place_of.end()) return it->second;
        for (std::size_t r = 0; r < fs.reads.size(); ++r) {
          if (fs.reads[r].name == name) return static_cast<std::uint32_t>(places + reads_begin + r);
        }
        for (const auto& [pname, value] : fs.params) {
          if (pname != name) continue;
          // a constant: numbered after every read, fixed below once all reads are known
          constants.push_back({k, value});
          return kConstantSlot + static_cast<std::uint32_t>(constants.size() - 1);
        }
        return std::nullopt;
      };
      core::ExpressionError error;
      auto program = core::compileExpression(fs.rate.text, resolve, error, known);
      if (!program) {
        SourceLoc in_text{fs.rate.loc.file, 1, static_cast<int>(error.column) + 1};
        errorOnce(fs.rate.where(in_text), "rate of continuous transition '" + ft.spec->name + "': " + error.message +
                                              (error.message.rfind("no name", 0) == 0
                                                   ? " (a rate names the continuous places of its page, its 'reads' "
                                                     "and the model's parameters)"
                                                   : ""));
        continue;
      }
      flow.rate = std::move(*program);
      flow.stateful = !flow.rate.reads.empty() && flow.rate.reads.front() < places;
    }
    // the parameters' constants after the reads
    const auto first_constant = places + static_cast<std::uint32_t>(fluid_.reads.size());
    for (auto& flow : fluid_.flows) {
      for (auto& op : flow.rate.ops) {
        if (op.op == core::Program::Op::Load && op.arg >= kConstantSlot) op.arg = first_constant + (op.arg - kConstantSlot);
      }
      for (auto& r : flow.rate.reads) {
        if (r >= kConstantSlot) r = first_constant + (r - kConstantSlot);
      }
    }
    for (const auto& c : constants) fluid_.constants.push_back(c.value);
  }
  static constexpr std::uint32_t kConstantSlot = 0x40000000u;

  // ---- emit the checked, flattened net ----

  /// The builder's index of `script`, added once however many instances share it.
  std::int32_t scriptIndex(const ScriptSpec& script) {
    auto [it, fresh] = script_ids_.try_emplace(&script, -1);
    if (fresh) it->second = builder_.addScript(script);
    return it->second;
  }

  void emit() {
    builder_.reserve(places_.size(), transitions_.size(), arcs_.size());
    if (!spec_.globals.empty()) builder_.setGlobalsScript(scriptIndex(spec_.globals));
    for (PlaceId p{0}; p < places_.size(); ++p) {
      auto& fp = places_[p];
      builder_.addScopedPlace(fp.scope, fp.local);
      if (!fluid_of_place_.empty() && fluid_of_place_[p] >= 0) {
        builder_.setSlot(p, kDefaultSlot, SlotKind::Continuous, kUnbounded, 0);
        continue;
      }
      std::uint32_t used = 0;
      for (const auto& d : fp.spec->kinds) used |= 1u << d.slot;
      for (const auto& t : fp.spec->tokens) used |= 1u << t.slot;
      for (const auto& n : fp.spec->nodes) used |= 1u << n.slot;
      for (const auto& c : fp.spec->capacity) used |= 1u << c.slot;
      for (const auto& sc : fp.spec->scripts) used |= 1u << sc.slot;
      for (const auto& b : fp.spec->sensors) used |= 1u << b.slot;
      for (const auto& c : fp.spec->colours) used |= 1u << c.slot;
      for (int s = 0; s < kSlotCount; ++s) {
        if (!(used & (1u << s))) continue;
        const auto slot = static_cast<SlotId>(s);
        builder_.setSlot(p, slot, kindOf(placeVertex(p, slot)), capacityFor(p, slot), initialFor(p, slot));
        if (const auto set = valueSet(p, slot)) builder_.setValues(p, slot, *set, initialValues(p, slot));
        for (const auto& n : fp.spec->nodes) {
          if (n.slot != slot) continue;
          std::vector<std::string> qualified;
          for (const auto& node : n.nodes) qualified.push_back(node_prefixes_[fp.node_prefix] + node);
          builder_.setNodes(p, slot, qualified);
        }
        for (const auto& b : fp.spec->sensors) {
          if (b.slot == slot) builder_.setSensor(p, slot, node_prefixes_[fp.node_prefix] + b.path);
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
      const auto t = builder_.addScopedTransition(ft.scope, ft.local, s.duration, s.priority, s.probability);
      if (s.servers != 1) builder_.setServers(t, static_cast<std::uint32_t>(s.servers));
      for (const ScriptKind k : kTransitionScripts) {
        if (!scriptOf(s, k).empty()) builder_.setTransitionScript(t, k, scriptIndex(scriptOf(s, k)));
      }
    }
    // per transition, the terms added for it so far: a coloured arc's term is known by its rank
    std::vector<std::uint32_t> added(transitions_.size(), 0);
    std::vector<std::vector<std::uint32_t>> colour_arcs(colouring_.transitions.size());
    std::size_t next_inscription = 0;  // in arc_exprs_, filled in the same order by checkColours()
    for (const auto& a : arcs_) {
      if (!a.output) {
        for (const auto& c : a.spec->conditions) {
          builder_.addCondition(a.place, a.transition, c.slot, scriptIndex(c.expression));
          ++added[a.transition];
        }
      }
      forEachWeight(*a.spec, [&](SlotId slot, std::int64_t value, const SourceLoc&) {
        const SlotKind kind = kindOf(placeVertex(a.place, slot));
        if (a.output) {
          builder_.addOutput(a.transition, a.place, slot, static_cast<std::int32_t>(value));
        } else {
          builder_.addInput(a.place, a.transition, slot, static_cast<std::int32_t>(value), a.spec->kind);
          for (const auto& pred : a.spec->predicates) {
            if (pred.slot == slot) builder_.setLastPredicate(scriptIndex(pred.expression));
          }
        }
        ++added[a.transition];
        // slots made by arcs take the kind of their component
        builder_.setSlot(a.place, slot, kind, capacityFor(a.place, slot), initialFor(a.place, slot));
      });
      for (const auto& ins : a.spec->inscriptions) {
        // the counts the kernel checks first: an input's, the least its inscription takes or
        // needs; an output's, what it puts where every inscription of the transition moves a
        // fixed number (else 0: the binding's counts decide the room, rule 4, as a self-loop
        // taking more than the least would otherwise find none); an inhibitor's, none (a test
        // of 0 tokens: its values decide)
        const std::size_t k = next_inscription++;
        const bool inhibits = a.spec->kind == ArcKind::Inhibitor && !a.output;
        const std::int64_t count = inhibits ? 0
                                   : a.output && !fixed_[a.transition] ? 0
                                                                       : least_[k];
        const auto weight = static_cast<std::int32_t>(std::min<std::int64_t>(count, kMaxWeight));
        if (a.output) builder_.addOutput(a.transition, a.place, ins.slot, weight);
        else builder_.addInput(a.place, a.transition, ins.slot, weight, inhibits ? ArcKind::Test : a.spec->kind);
        colour_arcs[static_cast<std::size_t>(colouring_.of_transition[a.transition])].push_back(added[a.transition]++);
      }
    }
    if (coloured_) builder_.setColouring(std::move(colouring_), std::move(colour_arcs));
    if (spec_has_fluid_) {
      std::vector<std::uint32_t> fluid_arcs;
      for (std::size_t k = 0; k < fluid_.terms.size(); ++k) {
        fluid_arcs.push_back(builder_.addFluidTerm(fluid_term_places_[k], fluid_.terms[k].transition));
      }
      builder_.setFluid(std::move(fluid_), std::move(fluid_arcs));
    }
  }

  /// The fewest tokens the multiset `e` (checked) can hold under any binding, and whether
  /// it always holds that many (`fixed`).
  std::int64_t leastSize(const Expr& e, bool* fixed = nullptr) const {
    bool own = true;
    bool& exact = fixed ? *fixed : own;
    using Op = Expr::Op;
    switch (e.op) {
      case Op::Sum: return leastSize(e.args[0], &exact) + leastSize(e.args[1], &exact);
      case Op::Times:
        if (e.args[0].op == Op::Const) return std::max<std::int64_t>(0, e.args[0].value.i) * leastSize(e.args[1], &exact);
        exact = false;
        return 0;
      case Op::If: {
        const auto a = leastSize(e.args[1], &exact), b = leastSize(e.args[2], &exact);
        exact = exact && a == b;
        return std::min(a, b);
      }
      case Op::Empty: return 0;
      case Op::All: {
        const auto size = colouring_.colours.at(e.type).size;
        exact = exact && size.has_value();
        return size.value_or(0);
      }
      case Op::Tuple: {
        std::int64_t n = 1;
        for (const auto& a : e.args) n *= a.multiset ? leastSize(a, &exact) : 1;
        return n;
      }
      case Op::Const: case Op::Name: case Op::Var: case Op::Record: case Op::Field: case Op::Neg: case Op::Not:
      case Op::Add: case Op::Sub: case Op::Mul: case Op::Div: case Op::Mod: case Op::Eq: case Op::Ne: case Op::Lt:
      case Op::Le: case Op::Gt: case Op::Ge: case Op::And: case Op::Or: case Op::Succ: case Op::Pred:
        return 1;
    }
    return 0;
  }

  // ---- value tokens: colour sets, variables, value slots and inscriptions ----

  /// The set of value slot `slot` of flat place `p`, if it is one.
  std::optional<ColourId> valueSet(PlaceId p, SlotId slot) const {
    if (!coloured_) return std::nullopt;
    const auto it = slot_sets_.find({p, slot});
    return it == slot_sets_.end() ? std::nullopt : std::optional<ColourId>(it->second);
  }

  /// The initial values of value slot `slot` of flat place `p` (evaluated by checkColours()).
  Multiset initialValues(PlaceId p, SlotId slot) const {
    const auto it = initial_.find({p, slot});
    return it == initial_.end() ? Multiset{} : it->second;
  }

  /// `text` parsed once, however many instances share it (nullopt after a reported mistake).
  const std::optional<Expr>& parsed(const SlotText& text) {
    auto [it, fresh] = parsed_.try_emplace(&text);
    if (fresh) {
      core::Diagnostics found;
      it->second = parseInscription(text, found);
      tell(found);
    }
    return it->second;
  }

  /// Passes on what `found` says (a page type's mistake is said once: Diagnostics drops repeats).
  void tell(const core::Diagnostics& found) { diags_.append(found); }

  void checkColours() {
    bool any = !spec_.colours.empty() || !spec_.variables.empty();
    for (const auto& fp : places_) any = any || !fp.spec->colours.empty() || !fp.spec->values.empty();
    for (const auto& ft : transitions_) any = any || ft.spec->conditioned();
    for (const auto& a : arcs_) any = any || !a.spec->inscriptions.empty();
    if (!any) return;
    coloured_ = true;
    Colours& colours = colouring_.colours;
    colours.declare(spec_.colours, diags_);
    InscriptionScope scope;
    scope.colours = &colours;
    std::set<std::string> seen;
    for (const auto& v : spec_.variables) {
      const auto set = colours.find(v.colour);
      if (!seen.insert(v.name).second) {
        diags_.error(v.loc, "variable '" + v.name + "' is declared twice");
      } else if (colours.find(v.name) || colours.constant(v.name)) {
        diags_.error(v.loc, "variable '" + v.name + "' has the name of a colour set or a constant");
      } else if (!set) {
        diags_.error(v.loc, "variable '" + v.name + "' is of colour set '" + v.colour + "', which is not declared");
      } else {
        scope.variable_names.push_back(v.name);
        scope.variable_sets.push_back(*set);
      }
    }
    colouring_.variables = scope.variable_names;
    colouring_.variable_sets = scope.variable_sets;
    if (diags_.hasErrors()) return;

    // value slots: their sets and initial values
    for (PlaceId p{0}; p < places_.size(); ++p) {
      const auto& spec = *places_[p].spec;
      for (const auto& c : spec.colours) {
        const auto set = colours.find(c.text);
        if (!set) {
          core::Diagnostics found;
          found.error(c.loc, "colour set '" + c.text + "' is not declared");
          tell(found);
          continue;
        }
        slot_sets_[{p, c.slot}] = *set;
      }
      for (const auto& v : spec.values) {
        core::Diagnostics found;
        const auto set = valueSet(p, v.slot);
        if (!set) {
          found.error(v.loc, "initial values need a colour set: give place '" + placeName(p) + "' a colour for slot " +
                                 slotName(v.slot));
        } else if (const auto& parsed_values = parsed(v)) {
          Expr e = *parsed_values;
          std::vector<std::uint32_t> used;
          if (checkInscription(e, *set, Expect::Tokens, scope, used, found) && !used.empty()) {
            found.error(v.loc, "initial values cannot name variables ('" + scope.variable_names[used[0]] + "')");
          } else if (!found.hasErrors() && !evaluateInto(e, {}, colours, *set, initial_[{p, v.slot}])) {
            found.error(v.loc, "the initial values have no value in colour set '" + colours.at(*set).name +
                                   "' (a number outside its range?)");
          }
        }
        tell(found);
      }
    }
    // a slot declared to hold values must say which
    for (PlaceId p{0}; p < places_.size(); ++p) {
      for (const auto& d : places_[p].spec->kinds) {
        if (d.kind != SlotKind::Value || valueSet(p, d.slot)) continue;
        core::Diagnostics found;
        found.error(d.loc, "slot " + slotName(d.slot) + " of place '" + placeName(p) +
                               "' holds values but has no colour set: give the place a 'colour'");
        tell(found);
      }
    }

    // per transition: its arcs' inscriptions and its condition, checked together (one list of
    // the variables they use), in the order emit() adds their terms
    colouring_.of_transition.assign(transitions_.size(), -1);
    std::vector<std::vector<std::uint32_t>> used(transitions_.size());
    auto entry = [&](TransitionId t) -> TransitionInscriptions& {
      auto& c = colouring_.of_transition[t];
      if (c < 0) {
        c = static_cast<std::int32_t>(colouring_.transitions.size());
        colouring_.transitions.emplace_back();
        colouring_.transition_ids.push_back(t);
      }
      return colouring_.transitions[static_cast<std::size_t>(c)];
    };
    for (const auto& a : arcs_) {
      for (const auto& w : a.spec->weights) {
        if (valueSet(a.place, w.slot)) {
          core::Diagnostics found;
          found.error(w.loc, "slot " + slotName(w.slot) + " of '" + placeName(a.place) +
                                 "' holds values: give the arc an 'inscription' rather than a weight");
          tell(found);
        }
      }
      if (a.spec->weights.empty() && a.spec->conditions.empty() && a.spec->inscriptions.empty() &&
          valueSet(a.place, kDefaultSlot)) {
        core::Diagnostics found;
        found.error(a.spec->loc, "place '" + placeName(a.place) + "' holds values (colour set '" +
                                     colours.at(*valueSet(a.place, kDefaultSlot)).name +
                                     "'): the arc needs an 'inscription' saying which");
        tell(found);
      }
      for (const auto& ins : a.spec->inscriptions) {
        auto& t = entry(a.transition);
        core::Diagnostics found;
        const auto set = valueSet(a.place, ins.slot);
        ArcInscription arc;
        arc.role = a.output ? ArcRole::Put
                   : a.spec->kind == ArcKind::Test      ? ArcRole::Test
                   : a.spec->kind == ArcKind::Inhibitor ? ArcRole::Inhibit
                                                        : ArcRole::Take;
        if (!set) {
          found.error(ins.loc, "an inscription needs a place slot that holds values, but slot " + slotName(ins.slot) +
                                   " of '" + placeName(a.place) + "' has no colour set");
        } else if (const auto& e = parsed(ins)) {
          arc.expr = *e;
          arc.set = *set;
          checkInscription(arc.expr, *set, Expect::Tokens, scope, used[a.transition], found);
        }
        tell(found);
        t.arcs.push_back(std::move(arc));
        arc_exprs_.push_back(&t.arcs.back().expr);
      }
    }
    for (TransitionId t{0}; t < transitions_.size(); ++t) {
      const auto& when = transitions_[t].spec->when;
      if (when.text.empty()) continue;
      auto& ti = entry(t);
      core::Diagnostics found;
      if (const auto& e = parsed(when)) {
        ti.when = *e;
        checkInscription(*ti.when, Colours::kBool, Expect::Condition, scope, used[t], found);
      }
      tell(found);
    }
    // arc_exprs_ points into vectors that moved as they grew: point again, in the same order
    arc_exprs_.clear();
    std::vector<std::size_t> next(colouring_.transitions.size(), 0);
    for (const auto& a : arcs_) {
      for (std::size_t k = 0; k < a.spec->inscriptions.size(); ++k) {
        const auto c = static_cast<std::size_t>(colouring_.of_transition[a.transition]);
        arc_exprs_.push_back(&colouring_.transitions[c].arcs[next[c]++].expr);
      }
    }
    // what each inscription moves at least, whether always that, per transition whether all
    // its inscriptions move fixed numbers; and a transition of unlimited servers must take
    // something in every binding
    fixed_.assign(transitions_.size(), true);
    std::vector<bool> takes(transitions_.size(), false);
    for (const auto& a : arcs_) {
      if (!a.output && a.spec->kind == ArcKind::Normal && a.spec->inscriptions.empty()) takes[a.transition] = true;
    }
    std::size_t k = 0;
    for (const auto& a : arcs_) {
      for (std::size_t i = 0; i < a.spec->inscriptions.size(); ++i, ++k) {
        bool fixed = true;
        least_.push_back(diags_.hasErrors() ? 0 : leastSize(*arc_exprs_[k], &fixed));
        const bool inhibits = a.spec->kind == ArcKind::Inhibitor && !a.output;
        if (inhibits) continue;
        fixed_[a.transition] = fixed_[a.transition] && fixed;
        colouring_.counts_exact = colouring_.counts_exact && fixed;
        if (!a.output && a.spec->kind == ArcKind::Normal && least_.back() > 0) takes[a.transition] = true;
      }
    }
    for (TransitionId t{0}; t < transitions_.size(); ++t) {
      const auto& spec = *transitions_[t].spec;
      if (spec.servers != kUnlimitedServers || takes[t] || colouring_.of_transition[t] < 0) continue;
      core::Diagnostics found;
      found.error(spec.servers_loc, "transition '" + transitionName(t) +
                                        "' has unlimited servers, but some binding takes no tokens (its inscriptions "
                                        "can take none): it would start without end in one step");
      tell(found);
    }
    for (std::size_t c = 0; c < colouring_.transitions.size(); ++c) {
      const TransitionId t = colouring_.transition_ids[c];
      auto& ti = colouring_.transitions[c];
      for (const auto v : used[t]) {
        ti.variables.push_back(scope.variable_names[v]);
        ti.sets.push_back(scope.variable_sets[v]);
      }
      if (diags_.hasErrors()) continue;
      if (auto why = unboundVariable(ti, colours); !why.empty()) {
        core::Diagnostics found;
        found.error(transitions_[t].spec->loc, "transition '" + transitionName(t) + "': " + why);
        tell(found);
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
  core::NameTable names_;  // the page being checked: its namespace (see checkPage)
  std::unordered_map<const PageSpec*, PageIndex> indexes_;
  std::vector<FlatPlace> places_;
  std::vector<std::string> node_prefixes_;  // one per instantiated page that has places
  std::vector<FlatTransition> transitions_;
  std::vector<FlatArc> arcs_;
  std::array<std::uint32_t, kSlotCount> dense_slot_{};  // slot -> its number among the used ones
  std::uint32_t slots_used_ = 1;
  std::vector<std::uint32_t> parent_;
  std::vector<SlotKind> root_kind_;
  std::unordered_map<const ScriptSpec*, std::int32_t> script_ids_;
  std::unordered_map<const PageSpec*, std::uint32_t> tables_;  // each page's table in builder_.names()
  std::unordered_map<std::string, std::uint32_t> fusion_index_;       // a fusion set's name -> its index
  std::unordered_map<const PlaceSpec*, std::uint32_t> member_set_;    // a member place -> its set's index
  std::vector<bool> fused_;  // per flat place after fuse(): whether other members joined it
  NetBuilder builder_;
  // hybrid nets (splitFluid)
  bool spec_has_fluid_ = false;                       // some place or transition is continuous
  Fluid fluid_;
  std::vector<std::int32_t> fluid_of_place_;           // per flat place: its fluid place, -1 for a discrete one
  std::vector<PlaceId> fluid_term_places_;             // per fluid term: its flat place
  std::unordered_map<std::uint32_t, std::string> scope_prefix_;  // what qualifies a scope's scene paths
  std::set<std::tuple<std::string, int, int, std::string>> told_fluid_;
  // value tokens (checkColours)
  bool coloured_ = false;
  Colouring colouring_;
  std::map<std::pair<std::uint32_t, SlotId>, ColourId> slot_sets_;  // (flat place, slot) -> its set
  std::unordered_map<const SlotText*, std::optional<Expr>> parsed_;
  std::vector<const Expr*> arc_exprs_;  // the checked inscriptions, in the order emit() adds their terms
  std::vector<std::int64_t> least_;      // per inscription (same order): the fewest tokens it moves
  std::vector<bool> fixed_;              // per transition: every inscription of it moves a fixed number
  std::map<std::pair<std::uint32_t, SlotId>, Multiset> initial_;  // (flat place, slot) -> its initial values
};

}  // namespace

std::shared_ptr<const Net> compile(const NetSpec& spec, core::Diagnostics& diags) {
  return Compiler(spec, diags).run();
}

}  // namespace gdpn::net

// Unfolding a coloured net into a place/transition net (unfold.h).

#include "gdpn/net/unfold.h"

#include <algorithm>
#include <cctype>
#include <map>
#include <set>
#include <string>
#include <tuple>

#include "detail/pnml_tool.h"
#include "gdpn/net/inscription.h"

namespace gdpn::net {
namespace {

/// An identifier made of value text `text` ("(1, p2)" -> "1_p2"): letters, digits and single
/// '_' between them.
std::string identOf(const std::string& text) {
  std::string out;
  for (const char c : text) {
    if (std::isalnum(static_cast<unsigned char>(c))) out += c;
    else if (!out.empty() && out.back() != '_') out += '_';
  }
  while (!out.empty() && out.back() == '_') out.pop_back();
  return out.empty() ? "v" : out;
}

/// A value slot of a place, unfolded: its set, and per value of it the place made for it.
struct ValueSlot {
  SlotId slot = kDefaultSlot;
  ColourId set = Colours::kDot;
  std::vector<Value> values;
  std::vector<std::string> places;  // per value, the unfolded place's name
};

/// A place of a page with value slots.
struct ColouredPlace {
  std::vector<ValueSlot> slots;
  bool kept = false;  // the place itself stays for its other slots
};

class Unfolder {
 public:
  Unfolder(const NetSpec& spec, core::Diagnostics& diags, std::size_t most)
      : spec_(spec), diags_(diags), most_(most) {}

  std::optional<Unfolding> run() {
    if (!colours_.declare(spec_.colours, diags_)) return std::nullopt;
    scope_.colours = &colours_;
    for (const auto& v : spec_.variables) {
      const auto set = colours_.find(v.colour);
      if (!set) {
        diags_.error(v.loc, "variable '" + v.name + "' is of colour set '" + v.colour + "', which is not declared");
        continue;
      }
      scope_.variable_names.push_back(v.name);
      scope_.variable_sets.push_back(*set);
    }
    Unfolding out;
    out.net = spec_;
    out.net.colours.clear();
    out.net.variables.clear();
    for (const auto& page : spec_.page_types) {
      if (pageColoured(page)) diags_.error(page.loc, "page type '" + page.name + "' has value slots or inscriptions: "
                                                     "unfolding coloured page types is not supported yet");
    }
    if (diags_.hasErrors()) return std::nullopt;
    for (auto& page : out.net.pages) unfoldPage(page, out.names);
    if (diags_.hasErrors()) return std::nullopt;
    return out;
  }

  static bool pageColoured(const PageSpec& page) {
    for (const auto& p : page.places) {
      if (!p.colours.empty() || !p.values.empty()) return true;
    }
    for (const auto& t : page.transitions) {
      if (t.conditioned()) return true;
    }
    for (const auto& a : page.arcs) {
      if (!a.inscriptions.empty()) return true;
    }
    return false;
  }

 private:
  /// A name on the page no construct has: `base`, or it with '_' appended.
  std::string fresh(std::string base, std::set<std::string>& used) {
    while (used.count(base)) base += "_";
    used.insert(base);
    return base;
  }

  /// `t` parsed and checked; where it is not, a note quotes it (a PNML term's text is not in
  /// the file as such: its line is the label's).
  std::optional<Expr> checked(const SlotText& t, ColourId set, Expect what, std::vector<std::uint32_t>& used) {
    auto e = parseInscription(t, diags_);
    if (e && checkInscription(*e, set, what, scope_, used, diags_)) return e;
    diags_.note(t.loc, "in the inscription '" + t.text + "'");
    return std::nullopt;
  }

  void unfoldPage(PageSpec& page, NameExpansion& names) {
    if (!pageColoured(page)) return;
    const std::string prefix = page.name + "/";
    std::set<std::string> place_names, transition_names;
    for (const auto& p : page.places) place_names.insert(p.name);
    for (const auto& t : page.transitions) transition_names.insert(t.name);

    // which places arcs reach other than through inscriptions: those keep their own place
    std::set<std::string> plain_ends;
    for (const auto& a : page.arcs) {
      if (!a.weights.empty() || !a.predicates.empty() || !a.conditions.empty()) {
        plain_ends.insert(a.from);
        plain_ends.insert(a.to);
      }
    }
    // an arc with neither inscriptions nor weights acts on a0: not a value slot
    std::set<std::string> value_a0;
    for (const auto& p : page.places) {
      for (const auto& c : p.colours) {
        if (c.slot == kDefaultSlot) value_a0.insert(p.name);
      }
    }
    for (const auto& a : page.arcs) {
      if (!a.inscriptions.empty() || !a.weights.empty()) continue;
      const std::string& place = value_a0.count(a.from) ? a.from : a.to;
      if (!value_a0.count(place)) continue;
      diags_.error(a.loc, "the arc between '" + a.from + "' and '" + a.to + "' reaches value slot a0 of place '" +
                              place + "' and has no inscription");
    }

    // ---- places
    std::map<std::string, ColouredPlace> coloured;
    std::vector<PlaceSpec> places;
    for (auto& p : page.places) {
      if (p.colours.empty()) {
        if (!p.values.empty()) diags_.error(p.values[0].loc, "place '" + p.name + "' has values but no colour set");
        places.push_back(std::move(p));
        continue;
      }
      ColouredPlace cp;
      std::vector<PlaceSpec> made;
      for (const auto& c : p.colours) {
        ValueSlot vs;
        vs.slot = c.slot;
        const auto set = colours_.find(c.text);
        if (!set) {
          diags_.error(c.loc, "colour set '" + c.text + "' is not declared");
          continue;
        }
        vs.set = *set;
        if (!colours_.at(*set).size) {
          diags_.error(c.loc, "place '" + p.name + "' holds values of '" + c.text +
                                  "', which is not finite: it cannot be unfolded");
          continue;
        }
        if (static_cast<std::uint64_t>(*colours_.at(*set).size) > std::max(most_, kMostUnfoldedBindings)) {
          diags_.error(c.loc, "place '" + p.name + "' holds values of '" + c.text + "', " +
                                  std::to_string(*colours_.at(*set).size) + " of them: unfolding it would make more than " +
                                  std::to_string(std::max(most_, kMostUnfoldedBindings)) +
                                  " places (`gdpn analyze` searches it without unfolding)");
          continue;
        }
        vs.values = colours_.values(*set);
        Multiset initial;
        for (const auto& v : p.values) {
          if (v.slot != c.slot) continue;
          std::vector<std::uint32_t> used;
          auto e = checked(v, *set, Expect::Tokens, used);
          if (!e) continue;
          if (!used.empty()) {
            diags_.error(v.loc, "an initial marking names no variables");
            continue;
          }
          if (!evaluateInto(*e, {}, colours_, *set, initial)) {
            diags_.error(v.loc, "the initial marking of place '" + p.name + "' has no value");
          }
        }
        for (const auto& value : vs.values) {
          std::string base = p.name + "_" + (p.colours.size() > 1 ? slotName(c.slot) + "_" : std::string()) +
                             identOf(colours_.text(*set, value));
          PlaceSpec u;
          u.name = fresh(base, place_names);
          u.loc = p.loc;
          u.description = detail::isIdNote(p.description) ? std::string() : p.description;
          u.position = p.position;
          if (const auto at = initial.find(value); at != initial.end()) {
            u.tokens.push_back({kDefaultSlot, at->second, p.loc, {}});
          }
          vs.places.push_back(u.name);
          made.push_back(std::move(u));
        }
        cp.slots.push_back(std::move(vs));
      }
      // the place itself stays where it has other slots, or an arc reaches it so
      PlaceSpec rest = p;
      rest.colours.clear();
      rest.values.clear();
      std::erase_if(rest.kinds, [&](const SlotDecl& d) {
        return std::any_of(p.colours.begin(), p.colours.end(), [&](const SlotText& c) { return c.slot == d.slot; });
      });
      for (const auto& cap : p.capacity) {
        if (std::any_of(p.colours.begin(), p.colours.end(), [&](const SlotText& c) { return c.slot == cap.slot; })) {
          diags_.error(cap.loc, "place '" + p.name + "' has a capacity on value slot " + slotName(cap.slot) +
                                    ", which unfolding does not carry over yet");
        }
      }
      cp.kept = rest.declares() || plain_ends.count(p.name) > 0;
      auto& list = names.places[prefix + p.name];
      if (cp.kept) {
        list.push_back(prefix + p.name);
        places.push_back(std::move(rest));
      }
      for (auto& u : made) {
        list.push_back(prefix + u.name);
        places.push_back(std::move(u));
      }
      coloured[p.name] = std::move(cp);
    }
    page.places = std::move(places);

    // ---- transitions and their arcs
    std::vector<TransitionSpec> transitions;
    std::vector<ArcSpec> arcs;
    std::set<std::string> coloured_transitions;
    for (const auto& t : page.transitions) {
      bool is_coloured = t.conditioned();
      for (const auto& a : page.arcs) {
        if ((a.from == t.name || a.to == t.name) && !a.inscriptions.empty()) is_coloured = true;
      }
      if (is_coloured) coloured_transitions.insert(t.name);
    }
    for (auto& t : page.transitions) {
      if (!coloured_transitions.count(t.name)) {
        transitions.push_back(std::move(t));
        continue;
      }
      unfoldTransition(page, t, coloured, transition_names, transitions, arcs, names.transitions[prefix + t.name],
                       prefix);
    }
    for (const auto& a : page.arcs) {
      if (!coloured_transitions.count(a.from) && !coloured_transitions.count(a.to)) arcs.push_back(a);
    }
    page.transitions = std::move(transitions);
    page.arcs = std::move(arcs);
  }

  void unfoldTransition(const PageSpec& page, const TransitionSpec& t, const std::map<std::string, ColouredPlace>& coloured,
                        std::set<std::string>& transition_names, std::vector<TransitionSpec>& transitions,
                        std::vector<ArcSpec>& arcs, std::vector<std::string>& expansion, const std::string& prefix) {
    transition_names.erase(t.name);  // its copies may take its name
    TransitionInscriptions ti;
    std::vector<std::uint32_t> used;
    // per arc of t (in page order): its index in page.arcs, and per inscription the slot it acts on
    struct Inscribed {
      std::size_t arc;
      const ValueSlot* slot;
    };
    std::vector<Inscribed> inscribed;
    std::vector<std::size_t> plain;  // arcs of t with no inscription
    bool ok = true;
    for (std::size_t i = 0; i < page.arcs.size(); ++i) {
      const ArcSpec& a = page.arcs[i];
      if (a.from != t.name && a.to != t.name) continue;
      if (a.inscriptions.empty()) {
        plain.push_back(i);
        continue;
      }
      const bool input = a.to == t.name;
      const std::string& place = input ? a.from : a.to;
      const auto cp = coloured.find(place);
      if (cp == coloured.end()) {
        diags_.error(a.loc, "the arc's inscription needs a place with a value slot; '" + place + "' has none" +
                                (place.find('/') != std::string::npos ? " on this page (links are not unfolded yet)" : ""));
        ok = false;
        continue;
      }
      for (const auto& text : a.inscriptions) {
        const auto vs = std::find_if(cp->second.slots.begin(), cp->second.slots.end(),
                                     [&](const ValueSlot& s) { return s.slot == text.slot; });
        if (vs == cp->second.slots.end()) {
          diags_.error(text.loc, "slot " + slotName(text.slot) + " of place '" + place + "' is not a value slot");
          ok = false;
          continue;
        }
        auto e = checked(text, vs->set, Expect::Tokens, used);
        if (!e) {
          ok = false;
          continue;
        }
        ArcInscription ai;
        ai.set = vs->set;
        ai.expr = std::move(*e);
        ai.role = !input ? ArcRole::Put
                  : a.kind == ArcKind::Test ? ArcRole::Test
                  : a.kind == ArcKind::Inhibitor ? ArcRole::Inhibit
                                                 : ArcRole::Take;
        ti.arcs.push_back(std::move(ai));
        inscribed.push_back({i, &*vs});
      }
    }
    if (t.conditioned()) {
      if (auto e = checked(t.when, Colours::kBool, Expect::Condition, used)) ti.when = std::move(*e);
      else ok = false;
    }
    if (!ok) return;
    for (const std::uint32_t v : used) {
      ti.variables.push_back(scope_.variable_names[v]);
      ti.sets.push_back(scope_.variable_sets[v]);
    }
    std::string why;
    const auto bindings = allBindings(ti, colours_, most_, why);
    if (!bindings) {
      diags_.error(t.loc, "transition '" + t.name + "' cannot be unfolded: " + why);
      return;
    }
    for (const auto& b : *bindings) {
      TransitionSpec u = t;
      std::string base = t.name;
      for (std::size_t k = 0; k < b.binding.size(); ++k) base += "_" + identOf(colours_.text(ti.sets[k], b.binding[k]));
      u.name = fresh(base, transition_names);
      u.when = {};
      if (detail::isIdNote(u.description)) u.description.clear();
      expansion.push_back(prefix + u.name);
      // arcs: (from, to, kind) -> weight on a0 for unfolded places; others copied
      std::vector<ArcSpec> made;
      std::map<std::tuple<std::string, std::string, ArcKind>, std::size_t> merged;
      auto add = [&](const ArcSpec& like, const std::string& from, const std::string& to, std::int64_t n) {
        const auto key = std::make_tuple(from, to, like.kind);
        if (const auto at = merged.find(key); at != merged.end()) {
          made[at->second].weights[0].value += n;
          return;
        }
        ArcSpec a;
        a.from = from, a.to = to, a.kind = like.kind, a.loc = like.loc, a.from_loc = like.from_loc, a.to_loc = like.to_loc;
        a.weights.push_back({kDefaultSlot, n, like.loc, {}});
        merged[key] = made.size();
        made.push_back(std::move(a));
      };
      for (std::size_t k = 0; k < inscribed.size(); ++k) {
        const ArcSpec& a = page.arcs[inscribed[k].arc];
        const bool input = a.to == t.name;
        if (ti.arcs[k].role == ArcRole::Inhibit && b.arcs[k].size() > 1) {
          // it inhibits only while the place holds all of it; unfolded, each value would alone
          diags_.error(a.loc, "the inhibitor arc from '" + a.from + "' inhibits with several values at once (" +
                                  colours_.text(inscribed[k].slot->set, b.arcs[k]) +
                                  "), which place/transition arcs cannot say: it cannot be unfolded");
          return;
        }
        for (const auto& [value, n] : b.arcs[k]) {
          const auto& vals = inscribed[k].slot->values;
          const auto at = std::lower_bound(vals.begin(), vals.end(), value);
          if (at == vals.end() || !(*at == value) || n <= 0) continue;
          const std::string& place = inscribed[k].slot->places[static_cast<std::size_t>(at - vals.begin())];
          add(a, input ? place : u.name, input ? u.name : place, n);
        }
      }
      // the arcs' other slots (weights written beside the inscriptions), and arcs without any
      std::set<std::size_t> done;
      for (const auto& ins : inscribed) {
        if (!done.insert(ins.arc).second) continue;
        ArcSpec a = page.arcs[ins.arc];
        if (a.weights.empty() && a.predicates.empty() && a.conditions.empty()) continue;
        a.inscriptions.clear();
        (a.from == t.name ? a.from : a.to) = u.name;
        made.push_back(std::move(a));
      }
      for (const std::size_t i : plain) {
        ArcSpec a = page.arcs[i];
        (a.from == t.name ? a.from : a.to) = u.name;
        made.push_back(std::move(a));
      }
      transitions.push_back(std::move(u));
      for (auto& a : made) arcs.push_back(std::move(a));
    }
  }

  const NetSpec& spec_;
  core::Diagnostics& diags_;
  std::size_t most_;
  Colours colours_;
  InscriptionScope scope_;
};

}  // namespace

bool coloured(const NetSpec& spec) {
  if (!spec.colours.empty() || !spec.variables.empty()) return true;
  for (const auto* pages : {&spec.pages, &spec.page_types}) {
    for (const auto& page : *pages) {
      if (Unfolder::pageColoured(page)) return true;
    }
  }
  return false;
}

std::optional<Unfolding> unfold(const NetSpec& spec, core::Diagnostics& diags, std::size_t most_bindings) {
  return Unfolder(spec, diags, most_bindings).run();
}

}  // namespace gdpn::net

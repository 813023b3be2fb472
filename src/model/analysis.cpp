#include "gdpn/model/analysis.h"

#include <map>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <limits>
#include <sstream>
#include <string_view>
#include <tuple>

#include "gdpn/core/text.h"
#include "gdpn/net/coloured_search.h"
#include "gdpn/net/kernel.h"

namespace gdpn::model {

std::vector<double> effectiveDurations(const net::Net& net, double dt) {
  std::vector<double> out;
  for (const auto& t : net.transitions()) {
    const double mean = net::meanSeconds(t.duration);
    if (t.duration.law == net::Duration::Law::Immediate) {
      out.push_back(0.0);
    } else if (dt > 0.0 && t.duration.fixed()) {
      out.push_back(static_cast<double>(net::durationSteps(mean, dt)) * dt);
    } else {
      out.push_back(mean);
    }
  }
  return out;
}

bool timed(const net::Net& net) {
  for (const auto& t : net.transitions()) {
    if (net::meanSeconds(t.duration) > 0.0) return true;
  }
  return false;
}

std::string invariantText(const net::Net& net, const net::Invariant& y) {
  std::string s;
  for (const auto& [k, w] : y.weights) {
    if (!s.empty()) s += " + ";
    if (w != 1) s += std::to_string(w) + "*";
    s += net::placeSlotName(net, net::PlaceSlotId{k});
  }
  return s;
}

std::vector<DistinctCycle> distinctCycles(const std::vector<net::CycleBound>& bounds) {
  std::vector<DistinctCycle> out;
  // alike: the same transitions, tokens and seconds (compared where they lie)
  auto less = [](const net::CycleBound* a, const net::CycleBound* b) {
    return std::tie(a->transitions, a->tokens, a->seconds) < std::tie(b->transitions, b->tokens, b->seconds);
  };
  std::map<const net::CycleBound*, std::size_t, decltype(less)> seen(less);
  for (const auto& b : bounds) {
    const auto [it, added] = seen.try_emplace(&b, out.size());
    if (added) {
      out.push_back({b, 0});
    } else {
      ++out[it->second].alike;
    }
  }
  return out;
}

std::vector<std::string> invariantWords(std::string_view text, std::size_t most, std::string_view where) {
  std::vector<std::string> terms;
  for (std::string_view term : core::words(text)) {
    if (term != "+") terms.emplace_back(term);
  }
  for (std::size_t i = 0; i + 1 < terms.size(); ++i) terms[i] += " +";
  if (terms.size() > most) {
    const std::size_t more = terms.size() - most;
    terms.resize(most);
    const std::string rest = "... and " + std::to_string(more) + " more (" + std::string(where) + " has all)";
    for (std::string_view x : core::words(rest)) terms.emplace_back(x);
  }
  return terms;
}

Analysis analyze(const net::Net& net, std::string path, const AnalysisOptions& options) {
  Analysis a;
  a.path = std::move(path);
  // one deadline for all phases; the state space's limits bound the invariants too
  net::ExploreOptions explore = options.explore;
  if (options.time_limit_s > 0.0) {
    explore.deadline = net::deadlineAfter(options.time_limit_s);
  }
  net::InvariantOptions limits;
  limits.max_candidates = static_cast<std::size_t>(std::min<std::uint64_t>(limits.max_candidates, explore.max_states));
  limits.max_bytes = explore.max_bytes;
  limits.deadline = explore.deadline;
  auto phase = [&](const char* name) {
    if (options.progress) limits.progress = [&options, name](const net::InvariantProgress& p) { options.progress(name, p); };
  };
  phase("invariants");
  // a coloured net searched as it is: its arcs' counts are the least they move, which says
  // nothing of its invariants where some move more under some binding
  if (!net.colouring() || net.countsExact()) a.invariants = net::invariants(net, limits);
  phase("cycle times");
  if (timed(net) && net.countsExact()) a.cycles = net::cycleBounds(net, a.invariants, effectiveDurations(net, options.dt), limits, &a.cycles_stop);
  explore.invariants = &a.invariants;  // their bounds size the markings
  a.space = net.colouring() ? net::exploreColoured(net, explore) : net::explore(net, explore);
  if (options.coloured) {
    phase("coloured invariants");
    net::ColouredInvariantOptions coloured;
    coloured.limits = limits;
    a.coloured = colouredInvariantLines(*options.coloured, net::colouredInvariants(*options.coloured, coloured));
  }
  return a;
}

std::vector<std::pair<std::string, net::ExploreStop>> stoppedPhases(const Analysis& a) {
  std::vector<std::pair<std::string, net::ExploreStop>> out;
  if (!a.invariants.answered()) {
    // the list that was cut, by name: the yes-or-no answers beside them are whole (a list cut
    // by the candidates' budget alone, too long to give, leaves no answer open: it is named
    // where the invariants are shown)
    const auto& inv = a.invariants;
    out.emplace_back(!inv.p_complete && !inv.t_complete ? "invariants"
                     : !inv.p_complete                  ? "P-invariants"
                                                        : "T-invariants",
                     inv.stop);
  }
  if (a.cycles_stop != net::ExploreStop::Done) out.emplace_back("cycle times", a.cycles_stop);
  if (!a.space.complete) out.emplace_back("state space", a.space.stop);
  return out;
}

namespace {

std::int64_t tokensOn(const net::Net& net, const net::Invariant& y) {
  std::int64_t n = 0;
  for (const auto& [k, w] : y.weights) n += w * net.placeSlots()[k].initial;
  return n;
}

std::string seconds(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.3f s", v);
  return buf;
}

/// The bound the whole net cannot repeat faster than: the largest that is a bound (not a
/// flow's, not a cycle of immediate transitions); none when the net as a whole cannot repeat
/// (no T-invariant covers every transition: a transition that fires once has no cycle time).
const net::CycleBound* cycleTime(const Analysis& a) {
  if (!a.invariants.consistent) return nullptr;
  const auto it = std::find_if(a.cycles.begin(), a.cycles.end(),
                               [](const net::CycleBound& c) { return !c.flow && !c.immediate; });
  return it == a.cycles.end() ? nullptr : &*it;
}

std::string megabytes(std::uint64_t bytes) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.1f MiB", static_cast<double>(bytes) / (1024.0 * 1024.0));
  return buf;
}

}  // namespace

std::vector<std::string> untimedCaveats(const net::Net& net) {
  std::vector<std::string> out;
  const auto& index = net.scriptIndex();
  auto names = [](const std::vector<std::string>& list) {
    std::string text;
    for (std::size_t i = 0; i < list.size() && i < 3; ++i) text += (i ? ", " : "") + std::string(list[i]);
    if (list.size() > 3) text += " and " + std::to_string(list.size() - 3) + " more";
    return text;
  };
  using core::counted;
  std::vector<std::string> guarded, scripted, handled;
  for (net::TransitionId t{0}; t < index.transitions.size(); ++t) {
    const auto& s = index.transitions[t];
    if (s[0] >= 0) guarded.push_back(net.transitionName(t));
    if (s[1] >= 0 || s[2] >= 0 || s[3] >= 0) scripted.push_back(net.transitionName(t));
  }
  for (net::PlaceSlotId k{0}; k < index.slots.size(); ++k) {
    const auto& s = index.slots[k];
    const auto name = net.placeName(net.placeSlots()[k].place);
    if (std::any_of(s.begin(), s.end(), [](std::int32_t x) { return x >= 0; }) &&
        (handled.empty() || handled.back() != name)) {
      handled.push_back(name);
    }
  }
  std::size_t conditions = 0, predicates = 0;
  for (const net::Term& term : net.terms()) {
    conditions += term.kind == net::TermKind::Condition;
    predicates += term.predicate;
  }
  if (!guarded.empty()) {
    out.push_back("the guards of " + counted(guarded.size(), "transition") + " (" + names(guarded) +
                  ") are taken to hold: the analysis may show firings the run never makes");
  }
  if (conditions != 0 || predicates != 0) {
    out.push_back(counted(conditions, "sensor condition") + " and " + counted(predicates, "token predicate") +
                  " on arcs are taken to hold: the plant is not simulated");
  }
  if (!scripted.empty() || !handled.empty() || net.globalsScript() >= 0) {
    std::string what;
    if (!scripted.empty()) what += "the firing scripts of " + counted(scripted.size(), "transition") + " (" + names(scripted) + ")";
    if (!handled.empty()) {
      what += std::string(what.empty() ? "" : " and ") + "the token and sensor handlers of " +
              counted(handled.size(), "place") + " (" + names(handled) + ")";
    }
    if (what.empty()) what = "the model's globals script";
    out.push_back(what + " are not run: tokens they add or remove (sim.set, add, spawn) are not among the markings "
                         "explored");
  }
  return out;
}

namespace {

/// Appends the member `key`: `value` to the JSON object `o`, whose keys differ from it.
/// (ordered_json's own insertion looks the key up among those before it: a model of 10^5
/// instances, 3 * 10^5 places, took two minutes for its bounds.)
void appendMember(nlohmann::ordered_json& o, std::string key, nlohmann::ordered_json value) {
  o.get_ref<nlohmann::ordered_json::object_t&>().emplace_back(std::move(key), std::move(value));
}

}  // namespace

ColouredInvariantLines colouredInvariantLines(const net::Net& net, const net::ColouredInvariants& found) {
  ColouredInvariantLines out;
  out.complete = found.complete;
  for (const auto& inv : found.invariants) out.invariants.push_back(net::colouredInvariantText(net, inv));
  out.notes = found.notes;
  return out;
}

std::string analysisJson(const net::Net& net, const Analysis& a) {
  using nlohmann::ordered_json;
  const auto& s = a.space;
  const auto& tr = net.transitions();
  const auto& places = net.places();
  ordered_json j;
  j["net"] = a.path;
  j["left_out"] = a.notes;
  for (auto& line : untimedCaveats(net)) j["left_out"].push_back(std::move(line));
  j["complete"] = s.complete;
  j["partial"] = ordered_json::array();
  for (const auto& [phase, stop] : stoppedPhases(a)) j["partial"].push_back({{"phase", phase}, {"stop", net::stopReason(stop)}});
  j["stop"] = net::stopReason(s.stop);
  j["bounded"] = s.bounded;
  j["states"] = s.states;
  j["edges"] = s.edges;
  j["deadlock"] = s.deadlock;
  j["deadlock_path"] = ordered_json::array();
  for (auto t : s.deadlock_path) j["deadlock_path"].push_back(net.transitionName(t));
  if (!s.deadlock_bindings.empty()) j["deadlock_bindings"] = s.deadlock_bindings;
  if (!s.dead_marking.empty()) j["dead_marking"] = s.dead_marking;
  j["dead_markings"] = s.dead_markings;
  j["more_dead_paths"] = ordered_json::array();
  for (const auto& path : s.more_dead_paths) {
    ordered_json names = ordered_json::array();
    for (auto t : path) names.push_back(net.transitionName(t));
    j["more_dead_paths"].push_back(names);
  }
  j["max_tokens_place"] = s.max_place;
  j["max_tokens_marking"] = s.max_marking;
  j["one_safe"] = s.one_safe;
  j["quasi_live"] = s.quasi_live;
  j["live"] = s.decided ? ordered_json(s.live) : ordered_json(nullptr);
  j["reversible"] = s.decided ? ordered_json(s.reversible) : ordered_json(nullptr);
  j["dead_transitions"] = ordered_json::array();
  for (net::TransitionId t{0}; t < tr.size(); ++t) {
    if (!s.fired[t]) j["dead_transitions"].push_back(net.transitionName(t));
  }
  j["unbounded_places"] = ordered_json::array();
  for (auto p : s.unbounded_places) j["unbounded_places"].push_back(net.placeName(p));
  j["constant_places"] = ordered_json::array();
  for (auto p : s.constant_places) j["constant_places"].push_back(net.placeName(p));
  ordered_json bounds = ordered_json::object();
  bounds.get_ref<ordered_json::object_t&>().reserve(places.size());
  for (net::PlaceId p{0}; p < places.size(); ++p) {
    appendMember(bounds, net.placeName(p), s.place_bound[p] == net::kOmega ? ordered_json("omega") : ordered_json(s.place_bound[p]));
  }
  j["bounds"] = std::move(bounds);
  j["peak_bytes"] = s.peak_bytes;

  const auto& inv = a.invariants;
  ordered_json ij;
  ij["complete"] = inv.complete;
  ij["p_complete"] = inv.p_complete;
  ij["t_complete"] = inv.t_complete;
  ij["stop"] = net::stopReason(inv.stop);
  ij["answered"] = inv.answered();  // the yes-or-no answers whole, a list perhaps too long to give
  ij["conservative"] = inv.conservative;
  ij["structurally_bounded"] = inv.structurally_bounded;
  ij["consistent"] = inv.consistent;
  ij["p"] = ordered_json::array();
  for (const auto& y : inv.p) {
    ordered_json w = ordered_json::object();
    for (const auto& [k, v] : y.weights) appendMember(w, net::placeSlotName(net, net::PlaceSlotId{k}), v);
    ij["p"].push_back({{"weights", w}, {"tokens", tokensOn(net, y)}});
  }
  ij["t"] = ordered_json::array();
  for (const auto& x : inv.t) {
    ordered_json w = ordered_json::object();
    for (const auto& [k, v] : x.weights) appendMember(w, net.transitionName(net::TransitionId{k}), v);
    ij["t"].push_back(w);
  }
  j["invariants"] = ij;
  if (a.coloured) {
    j["coloured_invariants"] = {{"complete", a.coloured->complete},
                                {"invariants", a.coloured->invariants},
                                {"notes", a.coloured->notes}};
  }
  j["cycle_times"] = ordered_json::array();
  for (const auto& c : a.cycles) {
    ordered_json names = ordered_json::array();
    for (auto t : c.transitions) names.push_back(net.transitionName(t));
    j["cycle_times"].push_back({{"invariant", invariantText(net, inv.p[c.invariant])},
                                {"transitions", names},
                                {"tokens", c.tokens},
                                {"circuit", c.circuit},
                                {"flow", c.flow},
                                {"immediate", c.immediate},
                                {"seconds", c.flow || c.immediate ? ordered_json(nullptr) : ordered_json(c.seconds)}});
  }
  const auto* first = cycleTime(a);
  j["cycle_time"] = first ? ordered_json(first->seconds) : ordered_json(nullptr);
  return j.dump(2) + "\n";
}

std::vector<std::pair<std::string, std::int64_t>> markedPlaces(const net::Net& net,
                                                                const std::vector<std::int64_t>& marking) {
  std::vector<std::pair<std::string, std::int64_t>> out;
  for (net::PlaceId pid{0}; pid < net.places().size(); ++pid) {
    const net::Place& p = net.places()[pid];
    std::int64_t n = 0;
    for (auto k = p.slots_begin; k < p.slots_end; ++k) n += marking[k];
    if (n != 0) out.emplace_back(net.placeName(pid), n);
  }
  return out;
}

namespace {


/// What the untimed analysis leaves out, as notes wrapped at 100 columns.
void printCaveats(std::ostream& out, const net::Net& net, const std::vector<std::string>& notes) {
  std::vector<std::string> lines = notes;
  for (auto& line : untimedCaveats(net)) lines.push_back(std::move(line));
  for (const std::string& line : lines) {
    out << "note:";
    core::writeWrapped(out, 5, core::words(line), 6);
    out << "\n";
  }
}

}  // namespace

void printAnalysis(std::ostream& out, const net::Net& net, const Analysis& a) {
  const auto& s = a.space;
  const auto& tr = net.transitions();
  auto yes = [](bool b) { return b ? "yes" : "no"; };
  auto decided = [&](bool b) { return s.decided ? yes(b) : "unknown (the graph is partial or unbounded)"; };
  for (const auto& [phase, stop] : stoppedPhases(a)) out << "stopped early: " << phase << " (" << net::stopReason(stop) << ")\n";
  printCaveats(out, net, a.notes);
  {
    // the figures wrapped at 100 columns after the path
    std::ostringstream figures;
    figures << core::counted(s.states, "state") << ", " << core::counted(s.edges, "edge") << (s.bounded ? "" : " of a coverability graph") << " ("
            << (s.bounded ? "" : "the net is unbounded; ") << net::stopReason(s.stop) << "; the search held "
            << megabytes(s.peak_bytes) << ")";
    out << a.path << ":";
    core::writeWrapped(out, a.path.size() + 1, core::words(figures.str()), 2);
    out << "\n";
  }
  // lists of names wrap at 100 columns, under the first value
  constexpr std::size_t kValue = 19;
  out << "  deadlock:        " << (s.deadlock ? "yes" : s.complete ? "no" : "none found");
  if (s.deadlock && !s.deadlock_path.empty()) {
    const std::string head =
        " after " + std::to_string(s.deadlock_path.size()) + (s.deadlock_path.size() == 1 ? " firing:" : " firings:");
    out << head;
    std::vector<std::string> names;
    for (std::size_t i = 0; i < s.deadlock_path.size(); ++i) {
      names.emplace_back(net.transitionName(s.deadlock_path[i]));
      // a binding as CPN Tools writes one: t<x=1, y=p2>
      if (i < s.deadlock_bindings.size() && !s.deadlock_bindings[i].empty()) {
        names.back() += "<" + s.deadlock_bindings[i] + ">";
      }
    }
    core::writeWrapped(out, kValue + 3 + head.size(), names, kValue);
  } else if (s.deadlock && s.complete && s.bounded) {
    out << " (the initial marking is dead)";
  }
  constexpr std::size_t kShownNames = 20;
  // a dead marking itself: its path fired from the initial marking
  auto deadMarking = [&](const std::vector<net::TransitionId>& path) {
    std::vector<std::int64_t> m;
    for (const auto& ps : net.placeSlots()) m.push_back(ps.initial);
    for (auto t : path) {
      for (const auto& term : net.termsOf(t)) {
        if (term.kind == net::TermKind::Input) m[term.place_slot] -= term.weight;
        if (term.kind == net::TermKind::Output) m[term.place_slot] += term.weight;
      }
    }
    std::vector<std::string> marked;
    for (const auto& [place, n] : markedPlaces(net, m)) marked.push_back(std::string(place) + " = " + std::to_string(n));
    if (marked.empty()) marked.emplace_back("no tokens");
    out << "\n  dead marking:   ";
    core::writeWrapped(out, kValue - 1, marked, kValue, kShownNames);
  };
  if (!s.dead_marking.empty()) {
    out << "\n  dead marking:   ";
    core::writeWrapped(out, kValue - 1, s.dead_marking, kValue, kShownNames);
  } else if (s.deadlock && (!s.deadlock_path.empty() || (s.complete && s.bounded))) {
    deadMarking(s.deadlock_path);
  }
  // the next ones the search met, each with its path
  for (const auto& path : s.more_dead_paths) {
    if (path.empty() || !s.bounded) continue;
    const std::string head = "after " + std::to_string(path.size()) + (path.size() == 1 ? " firing:" : " firings:");
    out << "\n  also dead:       " << head;
    std::vector<std::string> names;
    for (auto t : path) names.emplace_back(net.transitionName(t));
    core::writeWrapped(out, kValue + head.size(), names, kValue, kShownNames);
    deadMarking(path);
  }
  if (s.dead_markings > 1 + s.more_dead_paths.size()) {
    out << "\n  dead markings:   " << s.dead_markings << (s.complete ? "" : " found") << " in all";
  }
  out << "\n  bounds:          max " << s.max_place << " in one place, " << s.max_marking
      << " in one marking; one-safe: " << yes(s.one_safe) << "\n";
  if (s.complete && s.bounded && !s.place_bound.empty()) {
    // each place's bound, places of equal bound together
    std::map<std::int64_t, std::vector<std::string>> by_bound;
    for (net::PlaceId p{0}; p < s.place_bound.size(); ++p) by_bound[s.place_bound[p]].emplace_back(net.placeName(p));
    for (auto it = by_bound.rbegin(); it != by_bound.rend(); ++it) {
      const std::string head = std::string(kValue, ' ') + "at most " + std::to_string(it->first) + ":";
      out << head;
      core::writeWrapped(out, head.size(), it->second, kValue + 2, kShownNames);
      out << "\n";
    }
  }
  if (!s.bounded) {
    out << "  unbounded:      ";
    std::vector<std::string> names;
    for (auto p : s.unbounded_places) names.emplace_back(net.placeName(p));
    core::writeWrapped(out, kValue - 1, names, kValue, kShownNames);
    out << "\n";
  }
  out << "  quasi-live:      " << yes(s.quasi_live);
  if (!s.quasi_live) {
    std::vector<std::string> names;
    for (net::TransitionId t{0}; t < tr.size(); ++t) {
      if (!s.fired[t]) names.emplace_back(net.transitionName(t));
    }
    const std::string head = s.complete ? "dead (" : "not fired yet (";
    out << ", " << head << names.size() << "):";
    core::writeWrapped(out, kValue + 2 + 2 + head.size() + std::to_string(names.size()).size() + 2, names, kValue, kShownNames);
  }
  out << "\n  live:            " << decided(s.live) << "\n  reversible:      " << decided(s.reversible)
      << "\n  constant places: " << s.constant_places.size();
  if (!s.constant_places.empty()) {
    std::vector<std::string> names;
    for (auto p : s.constant_places) names.emplace_back(net.placeName(p));
    out << ":";
    core::writeWrapped(out, kValue + std::to_string(s.constant_places.size()).size() + 1, names, kValue, kShownNames);
  }
  out << "\n";

  constexpr std::size_t kShown = 20, kMostPlaces = 8;
  const auto& inv = a.invariants;
  const char* cut = inv.p_complete == inv.t_complete ? "" : inv.p_complete ? "T-invariants " : "P-invariants ";
  std::string why;
  if (!inv.complete) why = std::string(" (") + cut + (inv.answered() ? "listed in part: too many to list" : net::stopReason(inv.stop)) + ")";
  out << "invariants" << why << ":\n";
  if (net.colouring() && !net.countsExact()) {
    out << "  of the counts: none sought, as what some arcs move depends on the binding\n";
  } else {
    out << "  conservative: " << yes(inv.conservative) << "; structurally bounded: " << yes(inv.structurally_bounded)
        << "; covered by T-invariants: " << yes(inv.consistent) << "\n";
    out << "  P-invariants (" << inv.p.size() << (inv.p_complete ? "" : " found; the list was cut short") << "):"
        << (inv.p.empty() && inv.p_complete ? " none" : "") << "\n";
    // each wrapped at 100 columns, cut after kMostPlaces places (--json has them whole)
    for (std::size_t i = 0; i < inv.p.size() && i < kShown; ++i) {
      auto terms = invariantWords(invariantText(net, inv.p[i]), kMostPlaces, "--json");
      terms.push_back("= " + std::to_string(tokensOn(net, inv.p[i])));
      out << "   ";
      core::writeWrapped(out, 3, terms, 6);
      out << "\n";
    }
    if (inv.p.size() > kShown) out << "    ... and " << inv.p.size() - kShown << " more (--json lists all)\n";
    out << "  T-invariants (" << inv.t.size() << (inv.t_complete ? "" : " found; the list was cut short") << "):"
        << (inv.t.empty() && inv.t_complete ? " none" : "") << "\n";
    for (std::size_t i = 0; i < inv.t.size() && i < kShown; ++i) {
      std::vector<std::string> names;
      for (const auto& [k, w] : inv.t[i].weights) names.push_back((w != 1 ? std::to_string(w) + "*" : "") + net.transitionName(net::TransitionId{k}));
      out << "   ";
      core::writeWrapped(out, 3, names, 6, kShownNames);
      out << "\n";
    }
    if (inv.t.size() > kShown) out << "    ... and " << inv.t.size() - kShown << " more (--json lists all)\n";
  }
  if (const auto& c = a.coloured) {
    // the coloured net's own, in its places' names, each wrapped under its start
    out << "  coloured P-invariants, found without unfolding (" << c->invariants.size() << ")"
        << (c->complete ? "" : " (partial)") << ":" << (c->invariants.empty() ? " none" : "") << "\n";
    for (std::size_t i = 0; i < c->invariants.size() && i < kShown; ++i) {
      out << "   ";
      core::writeWrapped(out, 3, core::words(c->invariants[i]), 6);
      out << "\n";
    }
    if (c->invariants.size() > kShown) out << "    ... and " << c->invariants.size() - kShown << " more (--json lists all)\n";
    constexpr std::size_t kNotes = 3;
    for (std::size_t i = 0; i < c->notes.size() && i < kNotes; ++i) {
      out << "    note:";
      core::writeWrapped(out, 9, core::words(c->notes[i]), 10);
      out << "\n";
    }
    if (c->notes.size() > kNotes) out << "    ... and " << c->notes.size() - kNotes << " more notes (--json lists all)\n";
  }
  if (!a.cycles.empty()) {
    out << "cycle times (one token's longest circuit, else durations summed over tokens; alike ones once):\n";
    bool flow = false, immediate = false;
    for (const auto& [c, alike] : distinctCycles(a.cycles)) {
      // the bound, then the places and the circuit wrapped under them
      std::string head = c.flow ? std::string("flow") : c.immediate ? std::string("-") : seconds(c.seconds);
      head = std::string(head.size() < 8 ? 10 - head.size() : 2, ' ') + head + " ";  // right-aligned
      out << head;
      auto terms = invariantWords(invariantText(net, inv.p[c.invariant]), kMostPlaces, "--json");
      terms.push_back("(" + std::to_string(c.tokens) + (c.tokens == 1 ? " token" : " tokens") + (c.circuit ? ";" : ")"));
      if (c.circuit) {
        terms.emplace_back("circuit");
        for (std::size_t i = 0; i < c.transitions.size(); ++i) {
          terms.push_back(net.transitionName(c.transitions[i]) + (i + 1 < c.transitions.size() ? " ->" : ")"));
        }
      }
      if (alike > 0) terms.push_back("(+" + std::to_string(alike) + " alike)");
      flow = flow || c.flow;
      immediate = immediate || c.immediate;
      core::writeWrapped(out, head.size(), terms, 12);
      out << "\n";
    }
    if (flow) out << "  flow: tokens that take alternative paths (a flow, not a cycle): no bound\n";
    if (immediate) out << "  -: its transitions take no time: what they wait for sets its pace, no bound\n";
    if (const auto* first = cycleTime(a)) {
      out << "  the net's cycle time is at least " << seconds(first->seconds) << "\n";
    } else if (!a.invariants.consistent) {
      out << "  the net as a whole does not repeat (no T-invariant covers every transition): no cycle time\n";
    }
  }
}

}  // namespace gdpn::model

namespace gdpn::model {
namespace {

std::string verdictWord(const net::QueryAnswer& a) {
  switch (a.verdict) {
    case net::Verdict::True: return "true";
    case net::Verdict::False: return "false";
    case net::Verdict::Value: return std::to_string(a.value);
    case net::Verdict::Unknown: break;
  }
  return "unknown";
}

}  // namespace

/// The means an answer names (its technique, in the contest's words) in words for people:
/// "simplified by the state equation, a guided search over stubborn sets".
std::string methodText(const std::string& technique) {
  static const std::vector<std::pair<std::string_view, std::string_view>> kWords = {
      {"QUERY_SIMPLIFICATION", "simplified by the state equation"},
      {"INITIAL_STATE", "at the initial marking"},
      {"BREADTH_FIRST_SEARCH", "a breadth-first search"},
      {"BEST_FIRST_SEARCH", "a search guided towards it"},
      {"CTL_LOCAL", "local searches"},
      {"CTL_FIXED_POINTS", "fixed points on the whole graph"},
      {"LTL_TABLEAU", "an automaton's product"},
      {"ON_THE_FLY", "on the fly"},
      {"STUBBORN_SETS", "over stubborn sets"},
  };
  std::string out;
  std::string_view rest = technique;
  bool bound = false;  // STATE_EQUATION after a simplification says nothing new
  while (!rest.empty()) {
    const auto space = rest.find(' ');
    const std::string_view word = rest.substr(0, space);
    rest = space == std::string_view::npos ? std::string_view{} : rest.substr(space + 1);
    std::string_view phrase;
    if (word == "STATE_EQUATION") {
      if (!bound) phrase = "the state equation's bound";
    } else {
      for (const auto& [w, p] : kWords) {
        if (w == word) phrase = p;
      }
    }
    bound = bound || word == "QUERY_SIMPLIFICATION" || word == "STATE_EQUATION";
    if (phrase.empty()) continue;
    const bool joined = phrase == "on the fly" || phrase == "over stubborn sets";
    out += out.empty() ? "" : (joined ? " " : ", ");
    out += phrase;
  }
  return out;
}

void printQueries(std::ostream& out, const net::Net& net, const std::vector<QueryResult>& results,
                  const net::NameExpansion* expansion, const std::vector<std::string>& notes) {
  printCaveats(out, net, notes);
  for (std::size_t i = 0; i < results.size(); ++i) {
    const auto& [text, formula, a, id] = results[i];
    if (!id.empty()) {
      std::string word = verdictWord(a);
      for (char& c : word) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
      if (a.verdict == net::Verdict::Unknown) {
        out << "FORMULA " << id << " CANNOT_COMPUTE (" << (a.unsupported.empty() ? net::stopReason(a.stop) : a.unsupported) << ")\n";
      } else {
        out << "FORMULA " << id << " " << word << " TECHNIQUES " << a.technique << "\n";
      }
      continue;
    }
    const std::string head = "query " + std::to_string(i + 1) + ":";
    out << head;
    core::writeWrapped(out, head.size(), std::vector<std::string>{net::formulaText(net, formula, expansion)}, 2);
    out << "\n  " << verdictWord(a);
    if (a.verdict == net::Verdict::Unknown) {
      out << ": " << (a.unsupported.empty() ? net::stopReason(a.stop) : a.unsupported);
      if (a.unsupported.empty()) out << " (" << a.states << " markings explored)";
      out << "\n";
      continue;
    }
    if (a.technique == "STATE_EQUATION") {
      out << " (by the state equation: no solution of it holds the formula; no marking explored)\n";
    } else {
      const std::string method = methodText(a.technique);
      out << " (" << a.states << (a.states == 1 ? " marking" : " markings") << " explored"
          << (method.empty() ? "" : "; " + method) << ")\n";
    }
    if (!a.has_marking) continue;
    const std::string lead = std::string("  shown by ") +
                             (a.path.empty() ? "the initial marking" : "the marking after " + std::to_string(a.path.size()) +
                                                                          (a.path.size() == 1 ? " firing:" : " firings:"));
    out << lead;
    std::vector<std::string> names;
    for (auto t : a.path) names.push_back(net.transitionName(t));
    core::writeWrapped(out, lead.size(), names, 4);
    std::vector<std::string> marked;
    for (const auto& [place, n] : markedPlaces(net, a.marking)) marked.push_back(std::string(place) + " = " + std::to_string(n));
    if (marked.empty()) marked.push_back("none");
    const std::string what = "  tokens there:";
    out << "\n" << what;
    core::writeWrapped(out, what.size(), marked, 4);
    out << "\n";
    if (!a.lasso) continue;
    if (a.cycle.empty()) {
      out << "  and stays there forever: the marking is dead\n";
      continue;
    }
    const std::string loop = "  then forever, " + std::to_string(a.cycle.size()) + (a.cycle.size() == 1 ? " firing:" : " firings:");
    out << loop;
    std::vector<std::string> cycle;
    for (auto t : a.cycle) cycle.push_back(net.transitionName(t));
    core::writeWrapped(out, loop.size(), cycle, 4);
    out << "\n";
  }
}

namespace {

/// One answer as JSON: the query, the answer, and the firing sequence and marking that show it.
nlohmann::ordered_json queryObject(const net::Net& net, const QueryResult& r, const net::NameExpansion* expansion) {
  using nlohmann::ordered_json;
  const auto& [text, formula, a, id] = r;
  ordered_json q;
  if (!id.empty()) q["id"] = id;
  q["query"] = text;
  q["formula"] = net::formulaText(net, formula, expansion);
  if (a.verdict == net::Verdict::Value) {
    q["answer"] = a.value;
  } else {
    q["answer"] = verdictWord(a);
  }
  if (a.verdict == net::Verdict::Unknown) q["why"] = a.unsupported.empty() ? net::stopReason(a.stop) : a.unsupported;
  q["states"] = a.states;
  q["technique"] = a.technique;
  if (a.has_marking) {
    auto names = [&](const std::vector<net::TransitionId>& ts) {
      ordered_json list = ordered_json::array();
      for (auto t : ts) list.push_back(net.transitionName(t));
      return list;
    };
    q["path"] = names(a.path);
    if (a.lasso) q["cycle"] = names(a.cycle);
    ordered_json m = ordered_json::object();
    for (const auto& [place, n] : markedPlaces(net, a.marking)) m[std::string(place)] = n;
    q["marking"] = m;
  }
  return q;
}

}  // namespace

std::string queriesJson(const net::Net& net, const std::vector<QueryResult>& results,
                        const net::NameExpansion* expansion) {
  nlohmann::ordered_json j = nlohmann::ordered_json::array();
  for (const auto& r : results) j.push_back(queryObject(net, r, expansion));
  return nlohmann::ordered_json{{"queries", j}}.dump(2) + "\n";
}

std::string witnessJson(const net::Net& net, const QueryResult& result, const std::string& model_file) {
  nlohmann::ordered_json j{{"model", model_file}};
  j.update(queryObject(net, result, nullptr));
  return j.dump(2) + "\n";
}

}  // namespace gdpn::model

#include "gdpn/model/report.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>
#include <utility>

#include "gdpn/core/text.h"
#include "gdpn/model/analysis.h"

namespace gdpn::model {

namespace {

/// The invariants and cycle bounds of `sim`'s net, within `cycle_seconds` of wall-clock time.
std::unique_ptr<CyclePlan> planCycles(const Simulation& sim, double cycle_seconds) {
  const auto& net = sim.net();
  auto plan = std::make_unique<CyclePlan>();
  net::InvariantOptions budget;
  budget.deadline = net::deadlineAfter(std::max(0.0, cycle_seconds));
  plan->invariants = net::invariants(net, budget);
  plan->stop = plan->invariants.stop;
  net::ExploreStop bounds_stop = net::ExploreStop::Done;
  plan->bounds = net::cycleBounds(net, plan->invariants, effectiveDurations(net, sim.kernel().dt()), budget, &bounds_stop);
  if (plan->stop == net::ExploreStop::Done) plan->stop = bounds_stop;
  return plan;
}

}  // namespace

void watchRoundTrips(Simulation& sim, double cycle_seconds) {
  const auto& net = sim.net();
  if (!timed(net) || !net.countsExact()) return;
  auto plan = planCycles(sim, cycle_seconds);
  std::vector<std::vector<net::TransitionId>> takers_of;  // per place slot, made when first needed
  // one watch per cycle the report lists (alike ones share its circuits)
  for (const auto& [b, alike] : distinctCycles(plan->bounds)) {
    if (!b.alternatives) continue;
    // the token's home: the place slot that holds it at the start
    const auto& weights = plan->invariants.p[b.invariant].weights;
    const auto home = std::find_if(weights.begin(), weights.end(), [&](const auto& kw) {
      return net.placeSlots()[kw.first].initial > 0;
    });
    if (home == weights.end()) continue;
    // every transition that takes from the invariant (b.transitions holds the longest circuit's)
    if (takers_of.empty()) {
      takers_of.resize(net.placeSlots().size());
      for (net::TransitionId t{0}; t < net.transitions().size(); ++t) {
        for (const auto& term : net.termsOf(t)) {
          if (term.kind == net::TermKind::Input) takers_of[term.place_slot].push_back(t);
        }
      }
    }
    std::vector<net::TransitionId> takers;
    for (const auto& [k, w] : weights) takers.insert(takers.end(), takers_of[k].begin(), takers_of[k].end());
    std::sort(takers.begin(), takers.end());
    takers.erase(std::unique(takers.begin(), takers.end()), takers.end());
    if (!plan->trips) plan->trips = std::make_unique<net::RoundTrips>(net.transitions().size());
    plan->watch_of[b.invariant] = plan->trips->watch(net, net::PlaceSlotId{home->first}, takers);
  }
  sim.keepCycles(std::move(plan));
}

Report makeReport(Simulation& sim, const RunOutcome& outcome, double cycle_seconds) {
  Report r;
  r.model = sim.model().path;
  r.seed = sim.seed();
  r.params = sim.model().params;
  r.dt = sim.kernel().dt();
  r.outcome = outcome;
  const auto& net = sim.net();
  const auto& stats = sim.stats();
  const double dt = r.dt;
  const auto steps = static_cast<double>(outcome.steps);
  // a line per construct: their number known, no room left over (100,000 instances make
  // hundreds of thousands of lines)
  r.transitions.reserve(net.transitions().size());
  r.places.reserve(net.places().size());
  for (net::TransitionId t{0}; t < net.transitions().size(); ++t) {
    const auto& s = stats.transitions()[t];
    TransitionFigures f;
    f.name = net.transitionName(t);
    f.occurrences = s.starts;
    f.cycles = s.cycles();
    if (f.cycles > 0) {
      f.mean_cycle = static_cast<double>(s.cycle_sum) * dt / static_cast<double>(f.cycles);
      f.min_cycle = static_cast<double>(s.cycle_min) * dt;
      f.max_cycle = static_cast<double>(s.cycle_max) * dt;
    }
    // the occurrences at once, averaged; and that as a share of its servers (none when unlimited)
    f.servers = net.transitions()[t].servers;
    f.mean_busy = steps > 0 ? static_cast<double>(s.busy) / steps : 0.0;
    f.continuous = net.continuous(t);
    f.utilisation = f.servers == net::kUnlimitedServers ? std::numeric_limits<double>::quiet_NaN()
                                                        : f.mean_busy / static_cast<double>(f.servers);
    r.transitions.push_back(std::move(f));
  }
  for (net::PlaceId p{0}; p < net.places().size(); ++p) {
    const auto& s = stats.places()[p];
    PlaceFigures f;
    f.name = net.placeName(p);
    f.mean_tokens = steps > 0 ? static_cast<double>(s.area) / steps : static_cast<double>(s.tokens);
    f.max_tokens = s.max;
    f.final_tokens = s.tokens;
    f.throughput = outcome.time > 0 ? static_cast<double>(s.deposited) / outcome.time : 0.0;
    f.continuous = net.continuousPlace(p);
    const auto& place = net.places()[p];
    f.sensors_only = place.slots_begin < place.slots_end;
    for (net::PlaceSlotId ps{place.slots_begin}; ps < place.slots_end; ++ps) {
      f.sensors_only = f.sensors_only && net.placeSlots()[ps].kind == net::SlotKind::Sensor;
      const net::Colouring* c = net.colouring();
      if (!c || !c->setOf(ps)) continue;
      const auto slot = net.placeSlots()[ps].slot;
      f.final_values += (f.final_values.empty() ? "" : "; ") +
                        (slot == net::kDefaultSlot ? std::string() : net::slotName(slot) + ": ") +
                        c->colours.text(*c->setOf(ps), sim.kernel().values(ps));
    }
    r.places.push_back(std::move(f));
  }
  // the continuous part: the amounts' extremes and mean, the flows' amounts and time flowing
  if (const net::Fluid* fluid = net.fluid()) {
    const net::FluidTally& tally = *sim.kernel().fluidTally();
    r.amounts.reserve(fluid->places.size());
    for (std::size_t k = 0; k < fluid->places.size(); ++k) {
      const net::FluidPlace& fp = fluid->places[k];
      AmountFigures f;
      f.name = net.placeName(fp.place);
      f.unit = fp.unit;
      f.final_amount = sim.kernel().amount(fp.place);
      // a jump after the last step's flows counts too
      f.lowest = std::min(tally.lowest[k], f.final_amount);
      f.highest = std::max(tally.highest[k], f.final_amount);
      f.mean = tally.time > 0 ? tally.area[k] / tally.time : f.final_amount;
      r.amounts.push_back(std::move(f));
    }
    r.flows.reserve(fluid->flows.size());
    for (std::size_t k = 0; k < fluid->flows.size(); ++k) {
      const net::Flow& flow = fluid->flows[k];
      FlowFigures f;
      f.name = net.transitionName(flow.transition);
      f.moved = tally.moved[k];
      f.flowing = tally.time > 0 ? std::min(1.0, tally.flowing[k] / tally.time) : 0.0;
      if (flow.inputs_begin < flow.outputs_end && fluid->arcs[flow.inputs_begin].weight == 1.0) {
        f.unit = fluid->places[fluid->arcs[flow.inputs_begin].place].unit;
      }
      r.flows.push_back(std::move(f));
    }
  }
  // the bounds from the invariants, beside the cycles measured: where measured exceeds the
  // bound, the net waited on something else (the plant, a guard, a shared resource)
  if (timed(net) && net.countsExact()) {
    // the cycles worked out before the run when its round trips were watched, else now
    std::unique_ptr<CyclePlan> own;
    const CyclePlan* plan = sim.cycles();
    if (plan == nullptr) plan = (own = planCycles(sim, cycle_seconds)).get();
    const auto& invariants = plan->invariants;
    r.cycles_stop = plan->stop;
    const auto seconds = effectiveDurations(net, dt);
    // one line per set of transitions (slots of one place moving together make one cycle each)
    const auto distinct = distinctCycles(plan->bounds);
    r.cycles.reserve(distinct.size());
    for (const auto& [c, alike] : distinct) {
      CycleFigures f;
      f.invariant = invariantText(net, invariants.p[c.invariant]);
      f.tokens = c.tokens;
      f.flow = c.flow;
      // no bound for a flow, nor for transitions that take no time (their pace is what they
      // wait for: a bound of a step or two would mislead)
      if (!c.flow && !c.immediate) f.bound = c.seconds;
      f.alike = alike;
      // a flow's transitions do not repeat together: nothing measured to set beside a bound.
      // Else the intervals between successive starts of its transitions, pooled: each fires
      // once a round, so every interval is a round's length (a transition with fewer
      // intervals measured, one started late, weighs less, rather than its mean alone
      // standing for the cycle)
      if (!c.flow && !c.alternatives) {
        std::int64_t rounds = 0, round_steps = 0;
        for (auto t : c.transitions) {
          const auto& s = stats.transitions()[t];
          rounds += s.cycles();
          round_steps += s.cycle_sum;
        }
        if (rounds > 0) f.measured = static_cast<double>(round_steps) * dt / static_cast<double>(rounds);
      }
      // each circuit the token took, most taken first
      if (const auto w = plan->watch_of.find(c.invariant); w != plan->watch_of.end()) {
        for (const auto& taken : plan->trips->circuits(w->second)) {
          CircuitFigures k;
          k.trips = taken.trips;
          k.measured = static_cast<double>(taken.steps) * dt / static_cast<double>(taken.trips);
          for (auto t : taken.transitions) {
            k.transitions.push_back(net.transitionName(t));
            k.bound += seconds[t];
          }
          f.circuits.push_back(std::move(k));
        }
        std::stable_sort(f.circuits.begin(), f.circuits.end(),
                         [](const CircuitFigures& a, const CircuitFigures& b) { return a.trips > b.trips; });
        f.other_trips = plan->trips->overlong(w->second);
        // one token choosing among circuits: a round is a trip. Measured: its trips' mean;
        // bound: what the circuits it took need, averaged over its trips (so that measured
        // minus bound is the time it lay idle); the longest circuit's when it took none
        std::int64_t trips = 0;
        double took = 0.0, needed = 0.0;
        for (const auto& k : f.circuits) {
          trips += k.trips;
          took += k.measured * static_cast<double>(k.trips);
          needed += k.bound * static_cast<double>(k.trips);
        }
        if (trips > 0) {
          f.measured = took / static_cast<double>(trips);
          if (f.bound) f.bound = needed / static_cast<double>(trips);
        }
      }
      r.cycles.push_back(std::move(f));
    }
  }
  r.figures = sim.modelFigures(r.figures_error);
  return r;
}

namespace {

/// The text of a JSON document as `ordered_json::dump(2)` writes it, written piece by piece
/// to a stream: the large arrays one element at a time, so that neither a tree of the whole
/// report nor its text is held (at 100,000 instances the text alone is 135 MB).
class JsonText {
 public:
  explicit JsonText(std::ostream& out) : out_(out) { out_ << "{\n"; }
  /// A member whose value is small enough to build whole.
  void member(const std::string& key, const nlohmann::ordered_json& value) {
    open(key);
    indented(value.dump(2), 2);
  }
  /// A member holding an array: `element(i)` makes element i of `count`.
  template <class Element>
  void array(const std::string& key, std::size_t count, Element&& element) {
    open(key);
    if (count == 0) {
      out_ << "[]";
      return;
    }
    out_ << "[\n";
    for (std::size_t i = 0; i < count; ++i) {
      out_ << "    ";
      indented(element(i).dump(2), 4);
      out_ << (i + 1 < count ? ",\n" : "\n");
    }
    out_ << "  ]";
  }
  void close() { out_ << "\n}\n"; }

 private:
  void open(const std::string& key) {
    if (!first_) out_ << ",\n";
    first_ = false;
    out_ << "  " << nlohmann::ordered_json(key).dump() << ": ";
  }
  /// `text` with `by` more spaces after each line break (strings in it never hold one).
  void indented(const std::string& text, std::size_t by) {
    piece_.clear();
    for (const char c : text) {
      piece_ += c;
      if (c == '\n') piece_.append(by, ' ');
    }
    out_ << piece_;
  }
  std::ostream& out_;
  std::string piece_;
  bool first_ = true;
};

}  // namespace

namespace {

/// The parameters as the run had them: {name: value}, a whole one as a whole number.
nlohmann::ordered_json paramsJson(const std::vector<Param>& params) {
  // what the run had: a run is made again from its report with these as --param
  nlohmann::ordered_json out = nlohmann::ordered_json::object();
  for (const auto& p : params) {
    if (p.integer) out[p.name] = static_cast<std::int64_t>(p.value);
    else out[p.name] = p.value;
  }
  return out;
}

}  // namespace

std::string reportJson(const Report& report) {
  std::ostringstream out;
  writeReportJson(out, report);
  return std::move(out).str();
}

void writeReportJson(std::ostream& out, const Report& report) {
  using nlohmann::ordered_json;
  JsonText j(out);
  j.member("model", report.model);
  j.member("seed", report.seed);
  if (!report.params.empty()) j.member("params", paramsJson(report.params));
  j.member("dt", report.dt);
  j.member("steps", report.outcome.steps);
  j.member("time", report.outcome.time);
  j.member("stopped", stopReasonName(report.outcome.reason));
  if (!report.outcome.message.empty()) j.member("message", report.outcome.message);
  j.array("transitions", report.transitions.size(), [&](std::size_t i) {
    const auto& t = report.transitions[i];
    ordered_json line{{"name", t.name},
                      {"occurrences", t.occurrences},
                      {"cycles", t.cycles},
                      {"mean_cycle", t.mean_cycle},
                      {"min_cycle", t.min_cycle},
                      {"max_cycle", t.max_cycle},
                      {"utilisation", std::isnan(t.utilisation) ? ordered_json(nullptr) : ordered_json(t.utilisation)}};
    if (t.continuous) line["continuous"] = true;
    if (t.servers != 1) {
      line["servers"] = t.servers == net::kUnlimitedServers ? ordered_json("unlimited") : ordered_json(t.servers);
      line["mean_busy"] = t.mean_busy;
    }
    return line;
  });
  j.array("places", report.places.size(), [&](std::size_t i) {
    const auto& p = report.places[i];
    ordered_json line{{"name", p.name},
                      {"mean_tokens", p.mean_tokens},
                      {"max_tokens", p.max_tokens},
                      {"final_tokens", p.final_tokens},
                      {"throughput", p.throughput},
                      {"sensors_only", p.sensors_only}};
    if (!p.final_values.empty()) line["final_values"] = p.final_values;
    if (p.continuous) line["continuous"] = true;
    return line;
  });
  if (!report.amounts.empty()) {
    j.array("amounts", report.amounts.size(), [&](std::size_t i) {
      const auto& a = report.amounts[i];
      return ordered_json{{"name", a.name},     {"unit", a.unit},       {"final", a.final_amount},
                          {"lowest", a.lowest}, {"highest", a.highest}, {"mean", a.mean}};
    });
  }
  if (!report.flows.empty()) {
    j.array("flows", report.flows.size(), [&](std::size_t i) {
      const auto& f = report.flows[i];
      return ordered_json{{"name", f.name}, {"moved", f.moved}, {"unit", f.unit}, {"flowing", f.flowing}};
    });
  }
  j.array("cycles", report.cycles.size(), [&](std::size_t i) {
    const auto& c = report.cycles[i];
    ordered_json cycle{{"invariant", c.invariant},
                       {"tokens", c.tokens},
                       {"flow", c.flow},
                       {"bound", c.bound ? ordered_json(*c.bound) : ordered_json(nullptr)},
                       {"measured", c.measured ? ordered_json(*c.measured) : ordered_json(nullptr)},
                       {"alike", c.alike}};
    if (!c.circuits.empty() || c.other_trips > 0) {
      auto& circuits = cycle["circuits"] = ordered_json::array();
      for (const auto& k : c.circuits) {
        circuits.push_back({{"transitions", k.transitions}, {"trips", k.trips}, {"bound", k.bound},
                            {"measured", k.measured}});
      }
      cycle["other_trips"] = c.other_trips;
    }
    return cycle;
  });
  j.member("cycles_complete", report.cycles_stop == net::ExploreStop::Done);
  // a number as a number (its unit beside, under figure_units), text as text
  ordered_json figures = ordered_json::object(), units = ordered_json::object();
  for (const auto& f : report.figures) {
    if (f.value && f.integer) figures[f.label] = static_cast<std::int64_t>(*f.value);
    else if (f.value) figures[f.label] = *f.value;
    else figures[f.label] = f.text;
    if (!f.unit.empty()) units[f.label] = f.unit;
  }
  j.member("figures", figures);
  if (!units.empty()) j.member("figure_units", units);
  if (!report.figures_error.empty()) j.member("figures_error", report.figures_error);
  j.close();
}

namespace {

std::string fixed(double v, int decimals) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
  return buf;
}

/// A step length in seconds as a person reads it: "0.01"; "1/60" for a step of a whole rate
/// that no short decimal writes (not 0.016666666666666666); else four significant digits.
std::string stepText(double dt) {
  std::string shortest = core::formatDouble(dt);
  if (shortest.size() <= 8) return shortest;
  const double rate = std::round(1.0 / dt);
  if (rate >= 1.0 && rate < 1e9 && std::abs(1.0 / rate - dt) <= 1e-12 * dt) {
    return "1/" + std::to_string(static_cast<long long>(rate));
  }
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.4g", dt);
  return buf;
}

std::string pad(const std::string& s, std::size_t width, bool right) {
  if (s.size() >= width) return s;
  const std::string fill(width - s.size(), ' ');
  return right ? fill + s : s + fill;
}

/// An amount as a person reads it: four significant digits at most, no trailing zeros ("0.525",
/// "12.5", "40"); whole above 10,000.
std::string amountText(double v) {
  if (std::abs(v) >= 1e4) return fixed(v, 0);
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.4g", v);
  std::string text = buf;
  return text == "-0" ? "0" : text;
}

/// The continuous places' and transitions' lines, kMostRows of each at most.
void printAmounts(std::ostream& out, const Report& report) {
  const auto more = [&out](std::size_t n, const char* what) {
    if (n > 0) out << "  ... and " << n << " more " << what << " (--report has them)\n";
  };
  if (!report.amounts.empty()) out << "\ncontinuous places:\n";
  for (std::size_t i = 0; i < std::min(report.amounts.size(), kMostRows); ++i) {
    const auto& a = report.amounts[i];
    const std::string u = a.unit.empty() ? "" : " " + a.unit;
    out << "  " << a.name << ": " << amountText(a.final_amount) << u << " at the end (" << amountText(a.lowest)
        << " to " << amountText(a.highest) << u << ", mean " << amountText(a.mean) << u << ")\n";
  }
  more(report.amounts.size() - std::min(report.amounts.size(), kMostRows), "continuous places");
  if (!report.flows.empty()) out << "\ncontinuous transitions:\n";
  for (std::size_t i = 0; i < std::min(report.flows.size(), kMostRows); ++i) {
    const auto& f = report.flows[i];
    out << "  " << f.name << ": moved " << amountText(f.moved) << (f.unit.empty() ? "" : " " + f.unit) << ", flowing "
        << fixed(100.0 * f.flowing, 1) << " % of the time\n";
  }
  more(report.flows.size() - std::min(report.flows.size(), kMostRows), "continuous transitions");
}

}  // namespace

void printSummary(std::ostream& out, const Report& report) {
  // the run on one line, why it stopped (when not at its end) on the next, wrapped at 100 columns
  out << core::escapeInvalidUtf8(report.model) << ": " << report.outcome.steps << " steps of " << stepText(report.dt)
      << " s, t = " << fixed(report.outcome.time, 3) << " s, seed " << report.seed << "\n";
  std::string stopped;
  if (report.outcome.reason == StopReason::Dead) stopped = "stopped: the net is dead (nothing enabled or occurring)";
  if (report.outcome.reason == StopReason::Interrupted) stopped = "stopped: interrupted";
  if (report.outcome.reason == StopReason::Stopped) stopped = "stopped by a script: " + report.outcome.message;
  if (report.outcome.reason == StopReason::ScriptError) stopped = "stopped: a script failed";
  if (!stopped.empty()) {
    const auto words = core::words(stopped);
    out << words.front();
    core::writeWrapped(out, words.front().size(), std::vector<std::string_view>(words.begin() + 1, words.end()), 2);
    out << "\n";
  }
  if (!report.params.empty()) {
    // the parameters as the run had them, wrapped at 100 columns
    std::vector<std::string> items;
    for (std::size_t i = 0; i < report.params.size(); ++i) {
      const auto& p = report.params[i];
      items.push_back(p.name + " = " + core::formatDouble(p.value) + (p.unit.empty() ? "" : " " + p.unit) +
                      (i + 1 < report.params.size() ? "," : ""));
    }
    std::vector<std::string_view> words;
    for (const auto& item : items) {
      for (auto w : core::words(item)) words.push_back(w);
    }
    out << "parameters:";
    core::writeWrapped(out, 11, words, 2);
    out << "\n";
  }
  out << "\n";

  // places that only read sensors and never held a token say nothing here (--report has them)
  // continuous places and transitions have lines of their own (below the places)
  auto listed = [](const PlaceFigures& p) { return !p.continuous && (!p.sensors_only || p.max_tokens > 0); };
  std::vector<const TransitionFigures*> shown;
  for (const auto& t : report.transitions) {
    if (!t.continuous) shown.push_back(&t);
  }
  // each table shows its first kMostRows lines and says how many more the JSON report has (a
  // model of 100,000 instances would print 700,000 lines)
  const std::size_t transitions = std::min(shown.size(), kMostRows);
  std::vector<const PlaceFigures*> places;
  std::size_t w = 10, unlisted = 0, more_places = 0;
  for (std::size_t i = 0; i < transitions; ++i) w = std::max(w, shown[i]->name.size());
  for (const auto& p : report.places) {
    if (p.continuous) continue;
    if (!listed(p)) {
      ++unlisted;
    } else if (places.size() == kMostRows) {
      ++more_places;
    } else {
      places.push_back(&p);
      w = std::max(w, p.name.size());
    }
  }
  w += 2;
  auto more = [&out](std::size_t n, const char* what) {
    if (n > 0) out << "... and " << n << " more " << what << (n == 1 ? " (--report has it)\n" : "s (--report has them)\n");
  };

  // with servers, how many occurrences ran at once on average, and of how many servers
  const bool servers = std::any_of(report.transitions.begin(), report.transitions.end(),
                                   [](const TransitionFigures& t) { return t.servers != 1; });
  out << pad("transition", w, false) << pad("occurrences", 12, true) << pad("mean cycle [s]", 16, true)
      << pad("max cycle [s]", 15, true) << pad("utilisation", 13, true);
  if (servers) out << pad("at once", 9, true) << pad("servers", 9, true);
  out << "\n";
  for (std::size_t i = 0; i < transitions; ++i) {
    const auto& t = *shown[i];
    const bool cyc = t.cycles > 0;
    out << pad(t.name, w, false) << pad(std::to_string(t.occurrences), 12, true)
        << pad(cyc ? fixed(t.mean_cycle, 3) : "-", 16, true) << pad(cyc ? fixed(t.max_cycle, 3) : "-", 15, true)
        << pad(std::isnan(t.utilisation) ? "-" : fixed(100.0 * t.utilisation, 1) + " %", 13, true);
    if (servers) {
      out << pad(fixed(t.mean_busy, 2), 9, true)
          << pad(t.servers == net::kUnlimitedServers ? "any" : std::to_string(t.servers), 9, true);
    }
    out << "\n";
  }
  more(shown.size() - transitions, "transition");
  out << "\n"
      << pad("place", w, false) << pad("mean tokens", 12, true) << pad("max tokens", 16, true)
      << pad("final", 15, true) << pad("thru [1/s]", 13, true) << "\n";
  for (const PlaceFigures* p : places) {
    out << pad(p->name, w, false) << pad(fixed(p->mean_tokens, 3), 12, true)
        << pad(std::to_string(p->max_tokens), 16, true) << pad(std::to_string(p->final_tokens), 15, true)
        << pad(fixed(p->throughput, 3), 13, true) << "\n";
  }
  more(more_places, "place");
  // value places: what they hold at the end, wrapped at 100 columns between values, at most
  // four lines a place
  bool values_head = false;
  for (const PlaceFigures* p : places) {
    if (p->final_values.empty()) continue;
    if (!std::exchange(values_head, true)) out << "\nvalues at the end:\n";
    std::string line = "  " + p->name + ":";
    const std::string indent(4, ' ');
    int lines = 1;
    std::size_t from = 0;
    while (from < p->final_values.size()) {
      auto next = p->final_values.find(" ++ ", from);
      const std::string value =
          p->final_values.substr(from, next == std::string::npos ? std::string::npos : next + 3 - from);
      from = next == std::string::npos ? p->final_values.size() : next + 4;
      if (line.size() + 1 + value.size() > 100 && line.size() > indent.size()) {
        if (++lines > 4) {
          line += " ... (--report has all)";
          break;
        }
        out << line << "\n";
        line = indent;
      }
      line += (line == indent ? "" : " ") + value;
    }
    out << line << "\n";
  }
  printAmounts(out, report);
  if (unlisted > 0) {
    out << "(" << unlisted << (unlisted == 1 ? " place that only reads" : " places that only read")
        << " sensors, never holding a token, not listed; --report has them)\n";
  }
  if (!report.cycles.empty()) {
    // the figures first, in aligned columns; the invariant last, wrapped at 100 columns under
    // its heading and cut after a few lines (--report has it whole)
    constexpr std::size_t kFigures = 46, kMostPlaces = 6;
    out << "\n"
        << pad("tokens", 8, true) << pad("bound [s]", 12, true) << pad("measured [s]", 14, true)
        << pad("idle [s]", 12, true) << "  cycle (P-invariant)\n";
    bool alike = false, flow = false, circuits = false, immediate = false;
    const std::size_t cycles = std::min(report.cycles.size(), kMostRows);
    for (std::size_t n = 0; n < cycles; ++n) {
      const auto& c = report.cycles[n];
      out << pad(std::to_string(c.tokens), 8, true)
          << pad(c.flow ? "flow" : c.bound ? fixed(*c.bound, 3) : "-", 12, true)
          << pad(c.measured ? fixed(*c.measured, 3) : "-", 14, true)
          << pad(c.measured && c.bound ? fixed(*c.measured - *c.bound, 3) : "-", 12, true) << " ";
      immediate = immediate || (!c.flow && !c.bound);
      // its places (with their weights) as words, " + " between them
      auto terms = invariantWords(c.invariant, kMostPlaces, "--report");
      if (c.alike > 0) terms.push_back("(+" + std::to_string(c.alike) + " alike)");
      alike = alike || c.alike > 0;
      flow = flow || c.flow;
      core::writeWrapped(out, kFigures + 1, terms, kFigures + 2);
      out << "\n";
      // the circuits its token took, each measured: times taken, then its transitions by their
      // own names (the page's path is the cycle's)
      for (const auto& k : c.circuits) {
        std::vector<std::string> words{std::to_string(k.trips) + (k.trips == 1 ? " trip:" : " trips:")};
        for (std::size_t i = 0; i < k.transitions.size(); ++i) {
          const auto& name = k.transitions[i];
          words.push_back(name.substr(name.rfind('/') + 1) + (i + 1 < k.transitions.size() ? "," : ""));
        }
        out << pad("", 8, true) << pad(fixed(k.bound, 3), 12, true) << pad(fixed(k.measured, 3), 14, true)
            << pad(fixed(k.measured - k.bound, 3), 12, true) << "   ";
        core::writeWrapped(out, kFigures + 3, std::vector<std::string_view>(words.begin(), words.end()), kFigures + 4);
        out << "\n";
      }
      if (c.other_trips > 0) out << pad("", kFigures + 3, false) << c.other_trips << " more trips on other circuits\n";
      circuits = circuits || !c.circuits.empty();
    }
    more(report.cycles.size() - cycles, "cycle");
    out << "bound: the least time a round of the cycle takes by its durations; measured: the mean\n"
           "round; idle: their difference, the time its tokens lay in its places each round (waiting\n"
           "for the plant, a guard, another cycle, or to be needed)\n";
    if (immediate) out << "-: its transitions take no time: what they wait for sets its pace, no bound\n";
    if (circuits) {
      out << "indented under a cycle: each circuit its token took (a choice made on the way), measured\n"
             "from a trip's start to the next trip's; its bound is its own durations summed\n";
    }
    if (flow) {
      out << "flow: tokens that take alternative paths through the net (a box passing a station or\n"
             "entering it) flow rather than cycle: no bound, and no one cycle to measure\n";
    }
    if (alike) {
      out << "(+N alike): N more invariants with the same transitions, tokens and bound, not listed (the same\n"
             "cycle through the other slots of its places, or the same places with other weights)\n";
    }
  }
  if (report.cycles_stop != net::ExploreStop::Done) {
    out << "\ncycle bounds cut short ("
        << (report.cycles_stop == net::ExploreStop::TimeLimit ? "their time budget ran out"
                                                              : std::string(net::stopReason(report.cycles_stop)))
        << "): " << (report.cycles.empty() ? "none found" : "the ones found are listed") << "\n";
  }
  if (!report.figures.empty() || !report.figures_error.empty()) {
    out << "\nthe model's figures:\n";
    std::size_t fw = 0;
    for (const auto& f : report.figures) fw = std::max(fw, f.label.size());
    for (const auto& f : report.figures) {
      // the value wrapped at 100 columns, under itself
      out << "  " << pad(f.label + ":", fw + 1, false);
      core::writeWrapped(out, fw + 3, core::words(f.text), fw + 4);
      out << "\n";
    }
    if (!report.figures_error.empty()) out << "  " << report.figures_error << "\n";
  }
}

}  // namespace gdpn::model

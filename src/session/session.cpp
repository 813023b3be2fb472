#include "gdpn/session/session.h"

#include <algorithm>
#include <filesystem>
#include <sstream>

#include "gdpn/core/text.h"
#include "gdpn/net/observer.h"
#include "gdpn/net/timeline.h"

namespace gdpn::session {

const char* compareName(Compare compare) {
  switch (compare) {
    case Compare::Less: return "<";
    case Compare::LessEqual: return "<=";
    case Compare::Equal: return "==";
    case Compare::NotEqual: return "!=";
    case Compare::GreaterEqual: return ">=";
    case Compare::Greater: return ">";
  }
  return "?";
}

std::optional<Compare> parseCompare(std::string_view text) {
  for (const Compare c : {Compare::Less, Compare::LessEqual, Compare::Equal, Compare::NotEqual, Compare::GreaterEqual,
                          Compare::Greater}) {
    if (text == compareName(c)) return c;
  }
  return std::nullopt;
}

Breakpoint Breakpoint::starts(std::string transition) {
  Breakpoint b;
  b.kind = BreakKind::Starts;
  b.target = std::move(transition);
  return b;
}

Breakpoint Breakpoint::completes(std::string transition) {
  Breakpoint b = starts(std::move(transition));
  b.kind = BreakKind::Completes;
  return b;
}

Breakpoint Breakpoint::marking(std::string place, Compare how, std::int64_t value) {
  Breakpoint b;
  b.kind = BreakKind::Marking;
  b.target = std::move(place);
  b.compare = how;
  b.value = value;
  return b;
}

Breakpoint Breakpoint::level(std::string place, Compare how, double value) {
  Breakpoint b = marking(std::move(place), how, 0);
  b.real = value;
  return b;
}

Breakpoint Breakpoint::predicate(std::string expression) {
  Breakpoint b;
  b.kind = BreakKind::Predicate;
  b.expression = std::move(expression);
  return b;
}

std::string Breakpoint::describe() const {
  switch (kind) {
    case BreakKind::Starts: return "starts " + target;
    case BreakKind::Completes: return "completes " + target;
    case BreakKind::Marking:
      return target + " " + compareName(compare) + " " + (real ? core::formatDouble(*real) : std::to_string(value));
    case BreakKind::Predicate: return expression.empty() ? "a test of the caller's" : expression;
  }
  return {};
}

namespace {

template <typename Number>
bool compare(Number a, Compare how, Number b) {
  switch (how) {
    case Compare::Less: return a < b;
    case Compare::LessEqual: return a <= b;
    case Compare::Equal: return a == b;
    case Compare::NotEqual: return a != b;
    case Compare::GreaterEqual: return a >= b;
    case Compare::Greater: return a > b;
  }
  return false;
}

}  // namespace

/// Notes which transitions started and completed in the current step.
class Session::Watcher final : public net::NetObserver {
 public:
  void onStart(net::TransitionId t, std::int64_t) override { started.push_back(t); }
  void onComplete(net::TransitionId t, std::int64_t, std::int64_t) override { completed.push_back(t); }
  void clear() {
    started.clear();
    completed.clear();
  }
  std::vector<net::TransitionId> started, completed;
};

Session::~Session() = default;

std::unique_ptr<Session> Session::create(model::Model model, core::Diagnostics& diags, SessionOptions options) {
  std::unique_ptr<Session> s(new Session());
  s->options_ = options;
  auto sim = s->make(model, diags);
  if (!sim) return nullptr;
  s->model_ = std::move(model);
  s->adopt(std::move(sim));
  return s;
}

std::unique_ptr<model::Simulation> Session::make(const model::Model& model, core::Diagnostics& diags) {
  auto sim = model::Simulation::create(model, diags, options_.seed, options_.script_limits, options_.run.echo_log);
  if (sim && options_.imager && sim->hasCameras()) {
    if (!imager_) imager_ = options_.imager(std::filesystem::path(model.path).parent_path().string());
    sim->setImager(imager_);
  }
  return sim;
}

void Session::adopt(std::unique_ptr<model::Simulation> sim) {
  if (watcher_ && sim_) sim_->kernel().removeObserver(watcher_.get());
  if (timeline_ && sim_) sim_->kernel().removeObserver(timeline_.get());
  sim_ = std::move(sim);
  hit_.reset();
  if (trace_out_) sim_->traceTo(*trace_out_);
  if (!input_.empty()) sim_->setInput(input_);
  // what the run collects from its start: the report's figures and circuits, a timeline
  if (options_.run.report) {
    model::watchRoundTrips(*sim_, options_.run.cycle_seconds);
  } else {
    sim_->dropStatistics();
  }
  timeline_.reset();
  if (options_.run.timeline) {
    timeline_ = std::make_unique<net::Timeline>(sim_->net());
    sim_->kernel().addObserver(timeline_.get());
    sim_->recordLevels();  // the continuous places' levels, plotted beside the tokens
  }
  if (witness_) {
    auto sequence = witness_->path;
    sequence.insert(sequence.end(), witness_->cycle.begin(), witness_->cycle.end());
    sim_->replay(std::move(sequence));
  }
  // breakpoints whose transition or place the net lacks (after an edit) are dropped
  targets_.clear();
  for (auto it = breakpoints_.begin(); it != breakpoints_.end();) {
    const auto target = targetOf(it->second);
    const bool named = it->second.kind != BreakKind::Predicate;
    if (named && !target) {
      it = breakpoints_.erase(it);
      continue;
    }
    targets_.push_back(target);
    ++it;
  }
  watcher_.reset();
  watch();
}

void Session::watch() {
  const bool needed = std::any_of(breakpoints_.begin(), breakpoints_.end(), [](const auto& b) {
    return b.second.kind == BreakKind::Starts || b.second.kind == BreakKind::Completes;
  });
  if (needed && !watcher_) {
    watcher_ = std::make_unique<Watcher>();
    sim_->kernel().addObserver(watcher_.get());
  } else if (!needed && watcher_) {
    sim_->kernel().removeObserver(watcher_.get());
    watcher_.reset();
  }
}

std::optional<std::uint32_t> Session::targetOf(const Breakpoint& bp) const {
  auto index = [](const auto& id) { return id ? std::optional<std::uint32_t>(id->index()) : std::nullopt; };
  switch (bp.kind) {
    case BreakKind::Starts:
    case BreakKind::Completes: return index(sim_->net().findTransition(bp.target));
    case BreakKind::Marking: return index(sim_->net().findPlace(bp.target));
    case BreakKind::Predicate: return std::nullopt;
  }
  return std::nullopt;
}

bool Session::reset(core::Diagnostics& diags, std::optional<std::uint64_t> seed) {
  const auto previous = options_.seed;
  if (seed) options_.seed = seed;
  core::Diagnostics own;
  auto sim = make(model_, own);
  diags.append(own);
  if (!sim) {
    options_.seed = previous;
    return false;
  }
  adopt(std::move(sim));
  return true;
}

bool Session::rebuild(const model::Model& model, core::Diagnostics& diags) {
  // the edit is judged on its own, whatever `diags` held before
  core::Diagnostics own;
  auto sim = make(model, own);
  diags.append(own);
  if (!sim) return false;
  model_ = model;
  witness_.reset();  // its transitions were the old net's
  adopt(std::move(sim));
  return true;
}

model::Report Session::report(const model::RunOutcome& outcome) {
  GDPN_ASSERT(options_.run.report, "a report of a session whose RunRequest collects none");
  return model::makeReport(*sim_, outcome, options_.run.cycle_seconds);
}

bool Session::replay(const std::string& path, core::Diagnostics& diags) {
  auto witness = model::loadWitness(sim_->net(), path, diags);
  if (!witness) return false;
  auto sequence = witness->path;
  sequence.insert(sequence.end(), witness->cycle.begin(), witness->cycle.end());
  sim_->replay(std::move(sequence));
  witness_ = std::move(witness);
  return true;
}

std::optional<ReplayVerdict> Session::replayVerdict() const {
  if (!witness_) return std::nullopt;
  const model::Witness& w = *witness_;
  const std::size_t total = w.path.size() + w.cycle.size();
  const std::string loop = w.lasso ? " (its cycle once)" : "";
  const std::string all = total == 1 ? "the 1 firing" : "all " + std::to_string(total) + " firings";
  std::ostringstream out;
  ReplayVerdict verdict;
  if (sim_->replayed() < total) {
    out << "replay stopped after " << sim_->replayed() << " of " << total << " firings" << loop << " at t = "
        << sim_->kernel().now() << " s: " << (sim_->replayBlocked().empty() ? "the run ended first" : sim_->replayBlocked());
  } else if (sim_->kernel().occurringCount() != 0) {
    out << "replay: " << all << " started" << loop << ", but " << sim_->kernel().occurringCount()
        << " still occur at t = " << sim_->kernel().now() << " s (a later --until lets them complete)";
  } else if (const std::string differs = model::witnessMismatch(sim_->net(), sim_->kernel(), w); !differs.empty()) {
    out << "replay: " << all << " done" << loop << ", but the marking is not the witness': " << differs;
  } else {
    verdict.done = true;
    out << "replay: " << all << " done" << loop << " by t = " << sim_->kernel().now() << " s; the marking is the witness'"
        << (w.query.empty() ? "" : " (" + w.query + ")");
  }
  verdict.message = out.str();
  return verdict;
}

void Session::traceTo(std::ostream& out) {
  trace_out_ = &out;
  if (!sim_->started()) sim_->traceTo(out);
}

void Session::setInput(std::vector<sensors::InputEvent> events) {
  input_ = events;
  sim_->setInput(std::move(events));
}

void Session::step() {
  if (watcher_) watcher_->clear();
  sim_->step();
}

void Session::stepPlant() {
  if (!sim_->started()) sim_->start();
  sim_->stepPlant();
}

void Session::push(sensors::InputEvent event) { sim_->push(std::move(event)); }

namespace {

/// "no place 'main/pp' in the net (did you mean 'main/p'?)": the net's places or transitions
/// as the candidates.
std::string noSuch(const net::Net& net, bool place, const std::string& name) {
  std::vector<std::string> names;
  if (place) {
    for (const auto p : net.placeIds()) names.push_back(net.placeName(p));
  } else {
    for (const auto t : net.transitionIds()) names.push_back(net.transitionName(t));
  }
  return std::string("no ") + (place ? "place" : "transition") + " '" + name + "' in the net" + core::didYouMean(name, names);
}

}  // namespace

std::string Session::fire(const std::string& transition) {
  const auto t = sim_->net().findTransition(transition);
  if (!t) return noSuch(sim_->net(), false, transition);
  if (!sim_->started()) sim_->start();
  if (watcher_) watcher_->clear();
  return sim_->kernel().fire(*t);
}

std::string Session::fire(const std::string& transition, const net::Binding& binding) {
  const auto t = sim_->net().findTransition(transition);
  if (!t) return noSuch(sim_->net(), false, transition);
  if (watcher_) watcher_->clear();
  // at time 0 the chosen binding starts before the first firing phase chooses for the rest
  if (!sim_->started()) {
    std::string why;
    sim_->start([&] { why = sim_->kernel().fire(*t, binding); });
    return why;
  }
  return sim_->kernel().fire(*t, binding);
}

std::optional<int> Session::addBreakpoint(Breakpoint breakpoint, std::string& why) {
  const auto target = targetOf(breakpoint);
  switch (breakpoint.kind) {
    case BreakKind::Starts:
    case BreakKind::Completes:
      if (!target) {
        why = noSuch(sim_->net(), false, breakpoint.target);
        return std::nullopt;
      }
      break;
    case BreakKind::Marking:
      if (!target) {
        why = noSuch(sim_->net(), true, breakpoint.target);
        return std::nullopt;
      }
      break;
    case BreakKind::Predicate:
      if (!breakpoint.test && breakpoint.expression.find_first_not_of(" \t\n") == std::string::npos) {
        why = "a predicate breakpoint needs an expression";
        return std::nullopt;
      }
      break;
  }
  const int id = next_id_++;
  breakpoints_.emplace_back(id, std::move(breakpoint));
  targets_.push_back(target);
  watch();
  return id;
}

bool Session::removeBreakpoint(int id) {
  const auto it = std::find_if(breakpoints_.begin(), breakpoints_.end(), [&](const auto& b) { return b.first == id; });
  if (it == breakpoints_.end()) return false;
  targets_.erase(targets_.begin() + (it - breakpoints_.begin()));
  breakpoints_.erase(it);
  watch();
  return true;
}

bool Session::enableBreakpoint(int id, bool enabled) {
  for (auto& [key, bp] : breakpoints_) {
    if (key != id) continue;
    bp.enabled = enabled;
    return true;
  }
  return false;
}

std::optional<int> Session::holding() {
  for (std::size_t i = 0; i < breakpoints_.size(); ++i) {
    const auto& [id, bp] = breakpoints_[i];
    if (!bp.enabled) continue;
    switch (bp.kind) {
      case BreakKind::Starts:
      case BreakKind::Completes: {
        const net::TransitionId t{*targets_[i]};
        const auto& seen = bp.kind == BreakKind::Starts ? watcher_->started : watcher_->completed;
        if (std::find(seen.begin(), seen.end(), t) != seen.end()) return id;
        break;
      }
      case BreakKind::Marking: {
        const net::PlaceId p{*targets_[i]};
        // a continuous place's amount, else the tokens; as real numbers where either is one
        const net::Kernel& k = sim_->kernel();
        const bool amount = sim_->net().continuousPlace(p);
        if (amount || bp.real) {
          const double x = amount ? k.amount(p) : static_cast<double>(k.placeTokens(p));
          if (compare(x, bp.compare, bp.real.value_or(static_cast<double>(bp.value)))) return id;
        } else if (compare(k.placeTokens(p), bp.compare, bp.value)) {
          return id;
        }
        break;
      }
      case BreakKind::Predicate: {
        std::string error;
        std::optional<bool> holds;
        if (bp.expression.empty() && bp.test) {
          try {
            holds = bp.test();
          } catch (const std::exception& e) {
            error = e.what();
          }
        } else {
          holds = sim_->evaluate(bp.expression, error);
        }
        // a predicate that fails stops the run too: the user learns why at once
        if (!holds) predicate_error_ = "breakpoint " + std::to_string(id) + " (" + bp.describe() + ") failed: " + error;
        if (!holds || *holds) return id;
        break;
      }
    }
  }
  return std::nullopt;
}

model::RunOutcome Session::run(const model::RunLimits& limits, const model::ProgressFn& progress,
                               const std::atomic<bool>* interrupt) {
  hit_.reset();
  predicate_error_.clear();
  if (breakpoints_.empty()) return sim_->run(limits, progress, interrupt);
  // with breakpoints: each step is checked after it, and one that holds ends the run there
  sim_->setStopCheck([this] {
    hit_ = holding();
    if (watcher_) watcher_->clear();
    return hit_.has_value();
  });
  if (watcher_) watcher_->clear();
  model::RunOutcome outcome = sim_->run(limits, progress, interrupt);
  sim_->setStopCheck({});
  if (!predicate_error_.empty()) {
    outcome.reason = model::StopReason::ScriptError;
    outcome.message = predicate_error_;
  } else if (hit_) {
    const auto it = std::find_if(breakpoints_.begin(), breakpoints_.end(), [&](const auto& b) { return b.first == *hit_; });
    outcome.message = "breakpoint " + std::to_string(*hit_) + ": " + it->second.describe();
  }
  return outcome;
}

}  // namespace gdpn::session

// The kernel's continuous part (hybrid nets, semantics: *Hybrid nets*): amounts, the jumps of
// discrete transitions, and the terms on continuous places that the amounts decide.

#include <algorithm>
#include <cmath>

#include "gdpn/core/text.h"
#include "gdpn/net/kernel.h"

namespace gdpn::net {

void Kernel::fluidInit() {
  fluid_ = net_->fluid();
  if (!fluid_) return;
  const Fluid& f = *fluid_;
  FluidRun run{{}, std::vector<double>(f.places.size(), 0.0), std::vector<double>(f.reads.size(), 0.0),
               std::vector<std::uint8_t>(f.flows.size(), 0), FluidSolver(f), {}, {}};
  for (const auto& p : f.places) run.x.push_back(p.initial);
  fluid_run_.emplace(std::move(run));
  // a continuous transition never fires: one term that never holds
  for (const auto& flow : f.flows) ++tr_[flow.transition].unsat;
  // the terms on continuous places, as the initial amounts decide them (Condition terms
  // start out not holding)
  for (std::uint32_t k = 0; k < f.terms.size(); ++k) {
    if (!fluidTermHolds(k)) continue;
    cond_[f.terms[k].term] = 1;
    --tr_[f.terms[k].transition].unsat;
  }
}

bool Kernel::fluidTermHolds(std::uint32_t k) const {
  const FluidTerm& term = fluid_->terms[k];
  return levelHolds(term, fluid_run_->x[term.place], fluid_run_->reserved[term.place], fluid_->places[term.place].capacity);
}

void Kernel::fluidRefresh(std::uint32_t place) {
  const FluidPlace& fp = fluid_->places[place];
  for (auto k = fp.terms_begin; k < fp.terms_end; ++k) setCondition(fluid_->terms[k].term, fluidTermHolds(k));
}

void Kernel::fluidBegin(TransitionId t) {
  const TransitionState& tr = tr_[t];
  for (auto i = tr.inputs_end; i < tr.conditions_end; ++i) {
    const auto k = fluid_->of_term[i];
    if (k < 0) continue;
    const FluidTerm& term = fluid_->terms[static_cast<std::size_t>(k)];
    if (!term.moves) continue;
    if (term.test == LevelTest::AtLeast) {
      double& x = fluid_run_->x[term.place];
      x = std::max(0.0, x - term.weight);
      for (auto* o : observers_) o->onAmount(fluid_->places[term.place].place, term.weight, false, x, steps());
    } else {
      fluid_run_->reserved[term.place] += term.weight;
    }
    fluidRefresh(term.place);
  }
}

void Kernel::fluidFinish(TransitionId t) {
  const TransitionState& tr = tr_[t];
  for (auto i = tr.inputs_end; i < tr.conditions_end; ++i) {
    const auto k = fluid_->of_term[i];
    if (k < 0) continue;
    const FluidTerm& term = fluid_->terms[static_cast<std::size_t>(k)];
    if (!term.moves || term.test != LevelTest::Room) continue;
    double& reserved = fluid_run_->reserved[term.place];
    reserved = std::max(0.0, reserved - term.weight);
    double& x = fluid_run_->x[term.place];
    x = std::min(x + term.weight, fluid_->places[term.place].capacity);
    for (auto* o : observers_) o->onAmount(fluid_->places[term.place].place, term.weight, true, x, steps());
    fluidRefresh(term.place);
  }
}

void Kernel::fluidRates() {
  FluidRun& run = *fluid_run_;
  for (std::size_t k = 0; k < fluid_->flows.size(); ++k) run.on[k] = tr_[fluid_->flows[k].transition].unsat == 1;
  run.solver.rates(run.x, run.on, run.inputs, run.reserved);
}

void Kernel::advanceFluid() {
  if (!fluid_) return;
  FluidRun& run = *fluid_run_;
  for (std::size_t k = 0; k < fluid_->flows.size(); ++k) run.on[k] = tr_[fluid_->flows[k].transition].unsat == 1;
  run.crossed.clear();
  run.before = run.x;
  const std::vector<double>& before = run.before;
  const double t0 = static_cast<double>(steps() - 1) * dt_;
  run.solver.advance(run.x, run.on, run.inputs, run.reserved, t0, dt_, run.crossed);
  for (const Crossing& c : run.crossed) {
    for (auto* o : observers_) o->onCross(fluid_->places[c.place].place, c.level, c.time, c.rising, steps());
  }
  for (std::uint32_t p = 0; p < run.x.size(); ++p) {
    if (run.x[p] != before[p]) fluidRefresh(p);
  }
}

double Kernel::amount(PlaceId p) const {
  if (!fluid_ || fluid_->of_place[p] < 0) return 0.0;
  return fluid_run_->x[static_cast<std::size_t>(fluid_->of_place[p])];
}

double Kernel::amountReserved(PlaceId p) const {
  if (!fluid_ || fluid_->of_place[p] < 0) return 0.0;
  return fluid_run_->reserved[static_cast<std::size_t>(fluid_->of_place[p])];
}

std::string Kernel::setAmount(PlaceId p, double value) {
  if (!fluid_ || fluid_->of_place[p] < 0) return "'" + net_->placeName(p) + "' is not a continuous place";
  const auto k = static_cast<std::uint32_t>(fluid_->of_place[p]);
  const FluidPlace& fp = fluid_->places[k];
  if (!std::isfinite(value) || value < 0.0) return "an amount is a number >= 0, not " + core::formatDouble(value);
  if (fp.capacity != kNoBound && value + fluid_run_->reserved[k] > fp.capacity) {
    return "'" + net_->placeName(p) + "' holds at most " + core::formatDouble(fp.capacity - fluid_run_->reserved[k]) +
           (fp.unit.empty() ? "" : " " + fp.unit) + " now (its capacity less the room promised)";
  }
  double& x = fluid_run_->x[k];
  if (value == x) return "";
  const double moved = std::abs(value - x);
  const bool up = value > x;
  x = value;
  for (auto* o : observers_) o->onAmount(p, moved, up, x, steps());
  fluidRefresh(k);
  return "";
}

void Kernel::setFluidInput(std::size_t i, double value) {
  if (fluid_ && i < fluid_run_->inputs.size()) fluid_run_->inputs[i] = value;
}

double Kernel::flowRate(TransitionId t) const {
  if (!fluid_ || fluid_->of_transition[t] < 0) return 0.0;
  return fluid_run_->solver.flowRates()[static_cast<std::size_t>(fluid_->of_transition[t])];
}

double Kernel::nominalRate(TransitionId t) const {
  if (!fluid_ || fluid_->of_transition[t] < 0) return 0.0;
  return fluid_run_->solver.nominalRates()[static_cast<std::size_t>(fluid_->of_transition[t])];
}

bool Kernel::flowing() const { return fluid_ && fluid_run_->solver.flowing(); }

}  // namespace gdpn::net

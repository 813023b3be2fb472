#include "gdpn/model/simulation.h"

#include <cmath>

#include "gdpn/net/compile.h"

namespace gdpn::model {

const char* stopReasonName(StopReason reason) {
  switch (reason) {
    case StopReason::Until: return "until";
    case StopReason::Dead: return "dead";
    case StopReason::Interrupted: return "interrupted";
  }
  return "?";
}

std::unique_ptr<Simulation> Simulation::create(const Model& model, core::Diagnostics& diags,
                                               std::optional<std::uint64_t> seed) {
  auto net = net::compile(model.net, diags);
  if (!net) return nullptr;
  std::unique_ptr<Simulation> sim(new Simulation());
  sim->model_ = model;
  sim->net_ = std::move(net);
  sim->seed_ = seed.value_or(model.settings.seed);
  sim->kernel_ = std::make_unique<net::Kernel>(sim->net_, net::KernelSettings{model.settings.dt, sim->seed_});
  sim->stats_ = std::make_unique<net::StatsCollector>(*sim->net_);
  sim->kernel_->addObserver(sim->stats_.get());
  return sim;
}

std::string Simulation::nodeName(net::NodeRef ref) const {
  const auto names = net_->nodeNames();
  return ref < names.size() ? names[ref] : "#" + std::to_string(ref);
}

void Simulation::traceTo(std::ostream& out) {
  trace_ = std::make_unique<net::TraceWriter>(out, *net_, kernel_->dt(),
                                              [this](net::NodeRef r) { return nodeName(r); });
  kernel_->addObserver(trace_.get());
}

void Simulation::start() {
  if (started_) return;
  started_ = true;
  kernel_->start();
}

void Simulation::step() {
  if (!started_) start();
  // phases 1 and 2 (world, sensors) arrive with the plant
  kernel_->beginStep();
  kernel_->completeOccurrences();
  kernel_->fireEnabled();
}

RunOutcome Simulation::run(const RunLimits& limits, const ProgressFn& progress,
                           const std::atomic<bool>* interrupt) {
  start();
  std::int64_t target = -1;
  if (limits.steps) {
    target = *limits.steps;
  } else if (const auto until = limits.until ? limits.until : model_.settings.until) {
    // an end time within a billionth of a step counts as that step
    const double x = *until / kernel_->dt();
    target = static_cast<std::int64_t>(std::ceil(x - 1e-9 * std::max(1.0, x)));
  }
  RunOutcome outcome;
  outcome.reason = StopReason::Until;
  const std::int64_t first = kernel_->steps();
  const std::int64_t total = target >= 0 ? target - first : 0;
  while (target < 0 || kernel_->steps() < target) {
    if (kernel_->dead()) {
      outcome.reason = StopReason::Dead;
      break;
    }
    if (interrupt && interrupt->load(std::memory_order_relaxed)) {
      outcome.reason = StopReason::Interrupted;
      break;
    }
    step();
    if (progress && (kernel_->steps() & 4095) == 0) progress(kernel_->steps() - first, total);
  }
  if (progress) progress(kernel_->steps() - first, total);
  stats_->finish(kernel_->steps());
  outcome.steps = kernel_->steps();
  outcome.time = kernel_->now();
  return outcome;
}

}  // namespace gdpn::model

// The continuous part of a hybrid net: the first-order fluid rules, and amounts advanced
// exactly (piecewise-linear) or by CVODE, with every level crossing located.

#include "gdpn/net/fluid.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <tuple>

#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sunnonlinsol/sunnonlinsol_fixedpoint.h>

#include "gdpn/core/diagnostics.h"

namespace gdpn::net {

bool levelHolds(const FluidTerm& term, double x, double reserved, double capacity) {
  switch (term.test) {
    case LevelTest::AtLeast: return x >= term.weight;
    case LevelTest::Below: return x < term.weight;
    case LevelTest::Room: return capacity == kNoBound || x + reserved + term.weight <= capacity;
  }
  return false;
}

namespace {

/// Segments one step may be cut into (crossings): a guard against a rate that chatters.
constexpr int kMostSegments = 100000;
/// Passes of the first-order rules over the empty and full places (they only ever lower rates).
constexpr int kMostPasses = 100;
/// CVODE's tolerances: relative, and absolute in the places' units.
constexpr double kRelTol = 1e-10;
constexpr double kAbsTol = 1e-12;

}  // namespace

/// CVODE's memory for one solver: made when a step first needs it.
struct FluidSolver::Cvode {
  SUNContext ctx = nullptr;
  N_Vector y = nullptr;
  void* mem = nullptr;
  SUNNonlinearSolver nls = nullptr;
  std::vector<std::pair<std::uint32_t, double>> roots;  // per root function: (place, level)
  std::vector<int> found;
  bool initialised = false;
  // where the last run stopped at its stop time (NaN: at a root, or it failed), and what its
  // right-hand side read then (the flows running, the reads, the room): while none of it
  // changes, the next step goes on from there without a restart, keeping CVODE's order and
  // step size
  double end = std::numeric_limits<double>::quiet_NaN();
  std::vector<std::uint8_t> active;
  std::vector<double> inputs, full;

  explicit Cvode(std::size_t n) {
    GDPN_ASSERT(SUNContext_Create(nullptr, &ctx) == 0, "CVODE: no context");
    y = N_VNew_Serial(static_cast<sunindextype>(std::max<std::size_t>(n, 1)), ctx);
    // Adams with fixed-point iteration: the flows of tanks and batteries are not stiff, and
    // it needs no Jacobian (a thousand places would make a dense one costly)
    mem = CVodeCreate(CV_ADAMS, ctx);
    nls = SUNNonlinSol_FixedPoint(y, 0, ctx);
    GDPN_ASSERT(y && mem && nls, "CVODE: out of memory");
  }
  ~Cvode() {
    if (mem) CVodeFree(&mem);
    if (nls) SUNNonlinSolFree(nls);
    if (y) N_VDestroy(y);
    if (ctx) SUNContext_Free(&ctx);
  }
  Cvode(const Cvode&) = delete;
  Cvode& operator=(const Cvode&) = delete;

  static int rhs(sunrealtype, N_Vector y, N_Vector dy, void* user) {
    static_cast<FluidSolver*>(user)->derivative(N_VGetArrayPointer(y), N_VGetArrayPointer(dy));
    return 0;
  }
  static int root(sunrealtype, N_Vector y, sunrealtype* g, void* user) {
    const auto* self = static_cast<FluidSolver*>(user)->cvode_.get();
    const double* x = N_VGetArrayPointer(y);
    for (std::size_t i = 0; i < self->roots.size(); ++i) g[i] = x[self->roots[i].first] - self->roots[i].second;
    return 0;
  }
  static void quiet(int, const char*, const char*, char*, void*) {}
};

FluidSolver::FluidSolver(const Fluid& fluid) : fluid_(&fluid) {
  const std::size_t places = fluid.places.size();
  values_.assign(places + fluid.reads.size(), 0.0);
  values_.insert(values_.end(), fluid.constants.begin(), fluid.constants.end());
  v_.assign(fluid.flows.size(), 0.0);
  f_.assign(fluid.flows.size(), 0.0);
  active_.assign(fluid.flows.size(), 0);
  side_.assign(places, 0);
  side_level_.assign(places, 0.0);
  full_.assign(places, kNoBound);
  feeds_.resize(places);
  draws_.resize(places);
  for (std::uint32_t k = 0; k < fluid.flows.size(); ++k) {
    const Flow& flow = fluid.flows[k];
    for (auto a = flow.inputs_begin; a < flow.outputs_begin; ++a) draws_[fluid.arcs[a].place].push_back({k, fluid.arcs[a].weight});
    for (auto a = flow.outputs_begin; a < flow.outputs_end; ++a) feeds_[fluid.arcs[a].place].push_back({k, fluid.arcs[a].weight});
  }
  tally_.lowest.assign(places, kNoBound);
  tally_.highest.assign(places, -kNoBound);
  tally_.area.assign(places, 0.0);
  tally_.moved.assign(fluid.flows.size(), 0.0);
  tally_.flowing.assign(fluid.flows.size(), 0.0);
}

FluidSolver::~FluidSolver() = default;

FluidSolver::FluidSolver(const FluidSolver& other)
    : fluid_(other.fluid_), values_(other.values_), v_(other.v_), f_(other.f_), active_(other.active_),
      side_(other.side_), side_level_(other.side_level_), full_(other.full_), feeds_(other.feeds_),
      draws_(other.draws_), bounded_(other.bounded_), held_(other.held_), sliding_(other.sliding_), dx_(other.dx_),
      tally_(other.tally_) {}

FluidSolver& FluidSolver::operator=(const FluidSolver& other) {
  if (this == &other) return *this;
  fluid_ = other.fluid_;
  values_ = other.values_;
  v_ = other.v_;
  f_ = other.f_;
  active_ = other.active_;
  side_ = other.side_;
  side_level_ = other.side_level_;
  full_ = other.full_;
  feeds_ = other.feeds_;
  draws_ = other.draws_;
  bounded_ = other.bounded_;
  held_ = other.held_;
  sliding_ = other.sliding_;
  dx_ = other.dx_;
  tally_ = other.tally_;
  cvode_.reset();
  return *this;
}

// whether flow k moves place p: draws from it (`draws`) or feeds it
bool FluidSolver::moves(std::uint32_t k, std::uint32_t p, bool draws) const {
  const auto& list = draws ? draws_[p] : feeds_[p];
  return std::any_of(list.begin(), list.end(), [&](const auto& e) { return e.first == k; });
}

bool FluidSolver::thresholdsHold(std::uint32_t k, const double* x) const {
  const Flow& flow = fluid_->flows[k];
  // At its level exactly, a place counts as on the side it came from (a place the step
  // started there counts as at it). A flow that itself draws the place down to its test's
  // level, or fills it up to its inhibitor's, is on there: the rules hold the place at the
  // level (reduce) rather than let the flow switch on and off without end.
  for (auto i = flow.tests_begin; i < flow.inhibitors_begin; ++i) {
    const FlowArc& a = fluid_->thresholds[i];
    if (x[a.place] > a.weight) continue;
    if (x[a.place] < a.weight) return false;
    const bool from_above = side_[a.place] < 0 && side_level_[a.place] == a.weight;
    if (from_above && !moves(k, a.place, true)) return false;
  }
  for (auto i = flow.inhibitors_begin; i < flow.thresholds_end; ++i) {
    const FlowArc& a = fluid_->thresholds[i];
    if (x[a.place] < a.weight) continue;
    if (x[a.place] > a.weight) return false;
    const bool from_above = side_[a.place] < 0 && side_level_[a.place] == a.weight;
    if (!from_above && !moves(k, a.place, false)) return false;
  }
  return true;
}

bool FluidSolver::mode(const double* x) {
  const std::size_t places = fluid_->places.size();
  std::copy(x, x + places, values_.begin());
  bool stateful = false;
  for (std::uint32_t k = 0; k < fluid_->flows.size(); ++k) {
    active_[k] = on_[k] && thresholdsHold(k, x);
    stateful = stateful || (active_[k] && fluid_->flows[k].stateful);
  }
  // the places at a bound, where the rules may cut flows
  bounded_.clear();
  for (std::uint32_t p = 0; p < places; ++p) {
    if (x[p] <= 0.0 || x[p] >= full_[p]) bounded_.push_back(p);
  }
  // the places at a threshold of a flow that moves them towards it: a floor (a test) or a
  // ceiling (an inhibitor) for that flow alone
  sliding_.clear();
  for (std::uint32_t k = 0; k < fluid_->flows.size(); ++k) {
    if (!active_[k]) continue;
    const Flow& flow = fluid_->flows[k];
    for (auto i = flow.tests_begin; i < flow.thresholds_end; ++i) {
      const FlowArc& a = fluid_->thresholds[i];
      const bool test = i < flow.inhibitors_begin;
      if (x[a.place] == a.weight && moves(k, a.place, test)) sliding_.push_back({k, a.place, test});
    }
  }
  std::sort(sliding_.begin(), sliding_.end(), [](const Sliding& a, const Sliding& b) {
    return std::tie(a.place, a.floor, a.flow) < std::tie(b.place, b.floor, b.flow);
  });
  return stateful;
}

void FluidSolver::reduce(const double* x) {
  for (std::uint32_t k = 0; k < fluid_->flows.size(); ++k) {
    double v = 0.0;
    if (active_[k]) {
      v = fluid_->flows[k].rate.run(values_.data());
      if (!std::isfinite(v) || v < 0.0) v = 0.0;  // a rate is a speed: none below 0
    }
    v_[k] = v;
    f_[k] = v;
  }
  // the first-order rules: an empty place gives out no more than comes in, a full one takes
  // in no more than goes out; the flows concerned are cut in proportion to their rates
  for (int pass = 0; pass < kMostPasses; ++pass) {
    bool changed = false;
    // a flow at its own threshold moves the place no further than the others let it: its
    // draw (a test's floor) or its feed (an inhibitor's ceiling) is cut by what would take the
    // place past the level, to nothing if need be
    for (std::size_t i = 0; i < sliding_.size();) {
      const std::uint32_t p = sliding_[i].place;
      const bool floor = sliding_[i].floor;
      std::size_t end = i;
      double own = 0.0;  // what the flows sliding on p this way move of it
      for (; end < sliding_.size() && sliding_[end].place == p && sliding_[end].floor == floor; ++end) {
        for (const auto& [k, w] : floor ? draws_[p] : feeds_[p]) own += k == sliding_[end].flow ? w * f_[k] : 0.0;
      }
      double in = 0.0, out = 0.0;
      for (const auto& [k, w] : feeds_[p]) in += w * f_[k];
      for (const auto& [k, w] : draws_[p]) out += w * f_[k];
      const double excess = floor ? out - in : in - out;
      if (excess > 0.0 && own > 0.0) {
        const double cut = std::max(0.0, (own - excess) / own);
        for (auto j = i; j < end; ++j) f_[sliding_[j].flow] *= cut;
        changed = true;
      }
      i = end;
    }
    for (const auto p : bounded_) {
      double in = 0.0, out = 0.0;
      for (const auto& [k, w] : feeds_[p]) in += w * f_[k];
      for (const auto& [k, w] : draws_[p]) out += w * f_[k];
      if (x[p] <= 0.0 && out > in) {
        const double cut = in / out;
        for (const auto& [k, w] : draws_[p]) f_[k] *= cut;
        changed = true;
      } else if (x[p] >= full_[p] && in > out) {
        const double cut = out / in;
        for (const auto& [k, w] : feeds_[p]) f_[k] *= cut;
        changed = true;
      }
    }
    if (!changed) break;
  }
  // a place at a bound whose flows the rules balanced stays there: what rounding leaves of
  // in - out is not a flow (a drift of 1e-17 L would cross 0 again in every step)
  held_.clear();
  // in - out of place p, and what rounding may leave of a balance
  const auto net = [&](std::uint32_t p, double& slack) {
    double in = 0.0, out = 0.0;
    for (const auto& [k, w] : feeds_[p]) in += w * f_[k];
    for (const auto& [k, w] : draws_[p]) out += w * f_[k];
    slack = 1e-12 * (in + out);
    return in - out;
  };
  double slack = 0.0;
  for (const auto p : bounded_) {
    const double d = net(p, slack);
    if ((x[p] <= 0.0 && d <= slack) || (x[p] >= full_[p] && d >= -slack)) held_.push_back(p);
  }
  for (const auto& s : sliding_) {
    // held at the level while the sliding flow still moves it (a flow cut to nothing lets go)
    if (f_[s.flow] > 0.0 && std::abs(net(s.place, slack)) <= slack) held_.push_back(s.place);
  }
}

void FluidSolver::derivative(const double* x, double* dx) {
  std::copy(x, x + fluid_->places.size(), values_.begin());
  reduce(x);
  std::fill(dx, dx + fluid_->places.size(), 0.0);
  for (std::uint32_t k = 0; k < fluid_->flows.size(); ++k) {
    if (f_[k] == 0.0) continue;
    const Flow& flow = fluid_->flows[k];
    for (auto a = flow.inputs_begin; a < flow.outputs_begin; ++a) dx[fluid_->arcs[a].place] -= fluid_->arcs[a].weight * f_[k];
    for (auto a = flow.outputs_begin; a < flow.outputs_end; ++a) dx[fluid_->arcs[a].place] += fluid_->arcs[a].weight * f_[k];
  }
  // at a bound the rules hold the amount there (what is left is rounding)
  for (const auto p : held_) dx[p] = 0.0;
}

void FluidSolver::rates(const std::vector<double>& x, std::span<const std::uint8_t> on, std::span<const double> inputs,
                        std::span<const double> reserved) {
  on_ = on;
  std::copy(inputs.begin(), inputs.end(), values_.begin() + static_cast<std::ptrdiff_t>(fluid_->places.size()));
  for (std::size_t p = 0; p < full_.size(); ++p) full_[p] = fluid_->places[p].capacity - reserved[p];
  mode(x.data());
  dx_.resize(x.size());
  derivative(x.data(), dx_.data());
}

void FluidSolver::extremes(const std::vector<double>& x) {
  for (std::size_t p = 0; p < x.size(); ++p) {
    tally_.lowest[p] = std::min(tally_.lowest[p], x[p]);
    tally_.highest[p] = std::max(tally_.highest[p], x[p]);
  }
}

void FluidSolver::count(const std::vector<double>& x, double tau) {
  // amounts move linearly at dx_ from x: the area is exact; flows at f_ move f_ * tau
  for (std::size_t p = 0; p < x.size(); ++p) tally_.area[p] += (x[p] + 0.5 * dx_[p] * tau) * tau;
  for (std::size_t k = 0; k < f_.size(); ++k) {
    if (f_[k] == 0.0) continue;
    tally_.moved[k] += f_[k] * tau;
    tally_.flowing[k] += tau;
  }
}

bool FluidSolver::flowing() const {
  return std::any_of(f_.begin(), f_.end(), [](double f) { return f != 0.0; });
}

void FluidSolver::advance(std::vector<double>& x, std::span<const std::uint8_t> on, std::span<const double> inputs,
                          std::span<const double> reserved, double t0, double h, std::vector<Crossing>& out) {
  const std::size_t places = fluid_->places.size();
  on_ = on;
  std::copy(inputs.begin(), inputs.end(), values_.begin() + static_cast<std::ptrdiff_t>(places));
  for (std::size_t p = 0; p < places; ++p) full_[p] = fluid_->places[p].capacity - reserved[p];
  dx_.resize(places);
  double t = 0.0;  // from t0
  extremes(x);  // the amounts the step starts with (after the jumps and sets at its boundary)
  // a crossing at `level` of place p, reached at t0 + at
  auto crossed = [&](std::uint32_t p, double level, double at, bool rising) {
    x[p] = level;
    side_[p] = rising ? 1 : -1;
    side_level_[p] = level;
    out.push_back({p, level, t0 + at, rising});
  };
  for (int segment = 0; segment < kMostSegments && t < h; ++segment) {
    const bool stateful = mode(x.data());
    derivative(x.data(), dx_.data());
    if (!stateful) {
      // constant rates until the next level: the exact time each place reaches its next one
      double tau = h - t;
      for (std::uint32_t p = 0; p < places; ++p) {
        const double d = dx_[p];
        if (d == 0.0) continue;
        const double next = nextLevel(p, x[p], d > 0.0);
        if (std::isfinite(next)) tau = std::min(tau, (next - x[p]) / d);
      }
      count(x, tau);
      // every place moves by its rate times tau; those whose next level lies at tau land on it
      for (std::uint32_t p = 0; p < places; ++p) {
        const double d = dx_[p];
        if (d == 0.0) continue;
        const double next = nextLevel(p, x[p], d > 0.0);
        if (std::isfinite(next) && (next - x[p]) / d <= tau) {
          crossed(p, next, t + tau, d > 0.0);
        } else {
          x[p] = std::clamp(x[p] + d * tau, 0.0, fluid_->places[p].capacity);
          if (side_[p] != 0 && x[p] != side_level_[p]) side_[p] = 0;
        }
      }
      t += tau;
      extremes(x);
      continue;
    }
    // a rate reads an amount: CVODE from t, stopping at the first level any place reaches
    if (!cvode_) cvode_ = std::make_unique<Cvode>(places);
    Cvode& cv = *cvode_;
    double* y = N_VGetArrayPointer(cv.y);
    // going on from where the last run stopped: the same amounts (no jump, no clamp), the
    // same flows running, reads and room, at the same time (to rounding: t0 is step * dt)
    const bool goes_on = cv.initialised && std::abs(cv.end - (t0 + t)) <= 1e-9 * std::max(1.0, std::abs(t0)) &&
                         std::equal(x.begin(), x.end(), y) && cv.active == active_ &&
                         std::ranges::equal(cv.inputs, inputs) && cv.full == full_;
    cv.end = std::numeric_limits<double>::quiet_NaN();
    // otherwise a fresh start from x (where it goes on, CVODE's history stays valid: its
    // right-hand side is the same function, and so are the root functions)
    if (!goes_on) {
      std::copy(x.begin(), x.end(), y);
      cv.roots.clear();
      for (std::uint32_t p = 0; p < places; ++p) {
        for (const double level : fluid_->places[p].levels) {
          if (level <= fluid_->places[p].capacity) cv.roots.emplace_back(p, level);
        }
        if (full_[p] < fluid_->places[p].capacity) cv.roots.emplace_back(p, full_[p]);
      }
      if (!cv.initialised) {
        CVodeInit(cv.mem, &Cvode::rhs, t0 + t, cv.y);
        CVodeSetUserData(cv.mem, this);
        CVodeSetNonlinearSolver(cv.mem, cv.nls);
        CVodeSStolerances(cv.mem, kRelTol, kAbsTol);
        CVodeSetMaxNumSteps(cv.mem, 1000000);
        CVodeSetErrHandlerFn(cv.mem, &Cvode::quiet, nullptr);
        CVodeSetNoInactiveRootWarn(cv.mem);
        cv.initialised = true;
      } else {
        CVodeReInit(cv.mem, t0 + t, cv.y);
      }
      CVodeRootInit(cv.mem, static_cast<int>(cv.roots.size()), &Cvode::root);
    }
    CVodeSetStopTime(cv.mem, t0 + h);
    f_start_ = f_;
    x_start_ = x;
    sunrealtype reached = t0 + t;
    const int flag = CVode(cv.mem, t0 + h, cv.y, &reached, CV_NORMAL);
    if (flag < 0) {
      // the solver gave up (a rate that jumps without end): the step ends with what it has
      for (std::uint32_t p = 0; p < places; ++p) x[p] = std::clamp(y[p], 0.0, fluid_->places[p].capacity);
      break;
    }
    const double at = std::min(reached - t0, h);
    for (std::uint32_t p = 0; p < places; ++p) {
      x[p] = std::clamp(y[p], 0.0, fluid_->places[p].capacity);
      if (side_[p] != 0 && x[p] != side_level_[p]) side_[p] = 0;
    }
    if (flag == CV_ROOT_RETURN) {
      cv.found.assign(cv.roots.size(), 0);
      CVodeGetRootInfo(cv.mem, cv.found.data());
      for (std::size_t i = 0; i < cv.roots.size(); ++i) {
        if (cv.found[i] != 0) crossed(cv.roots[i].first, cv.roots[i].second, at, cv.found[i] > 0);
      }
    }
    // the tally by the trapezoid rule over the segment: amounts, and the rates at its end
    const double len = (flag == CV_ROOT_RETURN ? at : h) - t;
    mode(x.data());
    derivative(x.data(), dx_.data());
    for (std::uint32_t p = 0; p < places; ++p) tally_.area[p] += 0.5 * (x_start_[p] + x[p]) * len;
    for (std::size_t k = 0; k < f_.size(); ++k) {
      if (f_start_[k] == 0.0 && f_[k] == 0.0) continue;
      tally_.moved[k] += 0.5 * (f_start_[k] + f_[k]) * len;
      tally_.flowing[k] += len;
    }
    extremes(x);
    if (flag != CV_ROOT_RETURN) {
      cv.end = t0 + h;
      cv.active = active_;
      cv.inputs.assign(inputs.begin(), inputs.end());
      cv.full = full_;
    }
    t = flag == CV_ROOT_RETURN ? at : h;
  }
  tally_.time += h;
  // the rates as they stand at the end of the step
  mode(x.data());
  derivative(x.data(), dx_.data());
}

double FluidSolver::nextLevel(std::uint32_t p, double x, bool up) const {
  const auto& levels = fluid_->places[p].levels;
  double next = kNoBound;
  if (up) {
    const auto it = std::upper_bound(levels.begin(), levels.end(), x);
    if (it != levels.end()) next = *it;
    if (full_[p] > x) next = std::min(next, full_[p]);
  } else {
    const auto it = std::lower_bound(levels.begin(), levels.end(), x);
    if (it != levels.begin()) next = *(it - 1);
  }
  return next;
}

}  // namespace gdpn::net

// The run controls over a Session made from the document's snapshot.

#include "gdpn/ide/run_control.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>

#include "gdpn/ide/document.h"
#include "gdpn/model/io.h"

namespace gdpn::ide {

const char* runSpeedName(RunSpeed speed) {
  switch (speed) {
    case RunSpeed::RealTime: return "real time";
    case RunSpeed::Faster: return "faster";
    case RunSpeed::Fastest: return "as fast as possible";
  }
  return "real time";
}

const char* runModeName(RunMode mode) {
  switch (mode) {
    case RunMode::Edit: return "edit";
    case RunMode::Running: return "running";
    case RunMode::Paused: return "paused";
  }
  return "edit";
}

bool RunControl::open(Document& doc, core::Diagnostics& diags, session::SessionOptions options) {
  endServing();
  doc_ = &doc;
  revision_ = doc.revision();
  mode_ = RunMode::Edit;
  options_ = std::move(options);
  session_ = session::Session::create(doc.snapshot(), diags, options_);
  if (session_) checkIo(diags);
  diags_ = diags;
  if (session_) (void)startServing();
  return session_ != nullptr;
}

std::string RunControl::serveOpcua(const std::string& where) {
  endServing();
  serve_where_ = where;
  const std::string why = startServing();
  if (!why.empty()) serve_where_.clear();
  return why;
}

void RunControl::stopServing() {
  endServing();
  serve_where_.clear();
  message_ = "OPC UA: no longer served";
}

std::string RunControl::startServing() {
  if (serve_where_.empty() || !session_) return "";
  link::ServeRequest request;
  request.opcua = serve_where_;
  request.pace = false;  // the IDE keeps the clock
  auto serving = std::make_unique<link::Serving>();
  std::ostringstream err;
  int code = 0;
  if (!serving->start(request, session_->simulation(), nullptr, true, err, code)) {
    std::string why = err.str();
    if (why.starts_with("error: ")) why.erase(0, 7);
    while (!why.empty() && why.back() == '\n') why.pop_back();
    message_ = "OPC UA: " + why;
    return why;
  }
  serving_ = std::move(serving);
  const std::string url = serving_->opcuaUrl();
  // the port the system picked for 0 is kept: a reset serves at the same address
  const auto colon = serve_where_.rfind(':');
  serve_where_ = (colon == std::string::npos ? "" : serve_where_.substr(0, colon + 1)) + url.substr(url.rfind(':') + 1);
  message_ = "serving the run over OPC UA on " + url;
  return "";
}

void RunControl::endServing() {
  if (!serving_) return;
  std::ostringstream sink;  // the closing table is for gdpn run
  if (session_) serving_->finish(session_->simulation(), sink);
  serving_.reset();
}

void RunControl::checkIo(core::Diagnostics& diags) {
  // as gdpn check does: the io section resolved against the run (the map made is not kept)
  const auto& io = session_->model().io;
  if (!io.empty()) (void)model::IoMap::create(session_->simulation(), io, diags);
}

bool RunControl::prepare() {
  if (doc_ == nullptr) return false;
  if (mode_ == RunMode::Edit && (!session_ || doc_->revision() != revision_)) {
    core::Diagnostics diags;
    if (!reset(diags)) {
      message_ = "the edited model does not compile: see Diagnostics";
      return false;
    }
  }
  return session_ != nullptr;
}

void RunControl::run(RunSpeed speed) {
  if (!prepare()) return;
  speed_ = speed;
  mode_ = RunMode::Running;
  owed_ = 0.0;
  message_.clear();
}

void RunControl::pause() {
  if (mode_ == RunMode::Running) mode_ = RunMode::Paused;
  rtf_ = 0.0;
}

void RunControl::takeSteps(std::int64_t n) {
  if (!session_ || n <= 0) return;
  if (plant_only_) {
    for (std::int64_t i = 0; i < n && (stop_ == nullptr || !stop_->load()); ++i) session_->stepPlant();
    return;
  }
  const auto outcome = session_->run(model::RunLimits{.until = {}, .steps = steps() + n}, {}, stop_);
  if (outcome.reason != model::StopReason::Until) {
    mode_ = RunMode::Paused;
    message_ = std::string("stopped: ") + model::stopReasonName(outcome.reason);
    if (outcome.reason == model::StopReason::Breakpoint && session_->hit()) {
      for (const auto& [id, bp] : session_->breakpoints()) {
        if (id == *session_->hit()) message_ = "stopped at breakpoint: " + bp.describe();
      }
    } else if (!outcome.message.empty()) {
      message_ += ": " + outcome.message;
    }
  }
}

void RunControl::step() { runSteps(1); }

void RunControl::runSteps(std::int64_t n) {
  if (!prepare()) return;
  mode_ = RunMode::Paused;
  message_.clear();
  takeSteps(n);
}

void RunControl::runFor(double seconds) {
  if (!prepare()) return;
  const double dt = session_->model().settings.dt;
  runSteps(static_cast<std::int64_t>(std::llround(seconds / dt)));
}

std::string RunControl::fire(const std::string& name) {
  if (!prepare()) return message_ = "the model does not compile";
  auto why = session_->fire(name);
  message_ = why.empty() ? "fired " + name : "cannot fire " + name + ": " + why;
  if (mode_ == RunMode::Edit) mode_ = RunMode::Paused;
  return why;
}

std::string RunControl::fire(const std::string& name, const net::Binding& binding) {
  if (!prepare()) return message_ = "the model does not compile";
  auto why = session_->fire(name, binding);
  message_ = why.empty() ? "fired " + name + " in the binding chosen" : "cannot fire " + name + ": " + why;
  if (mode_ == RunMode::Edit) mode_ = RunMode::Paused;
  return why;
}

bool RunControl::reset(core::Diagnostics& diags) {
  if (doc_ == nullptr) return false;
  mode_ = RunMode::Edit;
  rtf_ = 0.0;
  owed_ = 0.0;
  message_.clear();
  if (!session_) return open(*doc_, diags, options_);
  endServing();  // the run is made anew: served again once it is
  bool ok = false;
  if (doc_->revision() != revision_) {
    // the document changed since the run was made: the run takes the edited model
    ok = session_->rebuild(doc_->snapshot(), diags);
    if (ok) revision_ = doc_->revision();
  } else {
    ok = session_->reset(diags);
  }
  if (ok) checkIo(diags);
  diags_ = diags;
  if (ok) (void)startServing();
  return ok;
}

void RunControl::advance(double wall_seconds) {
  if (serving_ && mode_ != RunMode::Running) serving_->idle();  // paused: clients are still answered
  if (!session_ || mode_ != RunMode::Running) return;
  const double dt = session_->model().settings.dt;
  const double before = time();
  if (speed_ == RunSpeed::Fastest) {
    // as many steps as fit in about 20 ms of this frame
    const auto start = std::chrono::steady_clock::now();
    while (mode_ == RunMode::Running &&
           std::chrono::steady_clock::now() - start < std::chrono::milliseconds(20)) {
      takeSteps(10);
    }
  } else {
    // real time or faster: the steps the clock owes, at most a quarter of a second's worth a frame
    const double factor = speed_ == RunSpeed::Faster ? kFasterFactor : 1.0;
    owed_ = std::min(owed_ + wall_seconds * factor, 0.25 * factor);
    const auto n = static_cast<std::int64_t>(std::floor(owed_ / dt + 1e-9));
    owed_ -= static_cast<double>(n) * dt;
    takeSteps(n);
  }
  if (wall_seconds > 0) rtf_ = 0.8 * rtf_ + 0.2 * ((time() - before) / wall_seconds);
}

std::string RunControl::addBreakpoint(session::Breakpoint breakpoint) {
  if (!session_) return "the model does not compile";
  std::string why;
  if (!session_->addBreakpoint(std::move(breakpoint), why)) return why;
  return {};
}

bool RunControl::removeBreakpoint(const std::string& description) {
  if (!session_) return false;
  for (const auto& [id, bp] : session_->breakpoints()) {
    if (bp.describe() == description) return session_->removeBreakpoint(id);
  }
  return false;
}

std::vector<std::string> RunControl::breakpoints() const {
  std::vector<std::string> out;
  if (!session_) return out;
  for (const auto& [id, bp] : session_->breakpoints()) out.push_back(bp.describe());
  return out;
}

void RunControl::push(sensors::InputEvent event) {
  if (session_) session_->push(std::move(event));
}

sensors::ClickTarget RunControl::click(const core::Ray& ray) {
  if (!session_ || mode_ == RunMode::Edit || session_->simulation().plant() == nullptr) return {};
  // what the sensors will decide at the next step, for the status line
  auto target = sensors::clickTarget(session_->simulation().plant()->root(), ray);
  sensors::InputEvent event;
  event.t = time();
  event.kind = sensors::InputEvent::Kind::Click;
  event.ray = ray;
  session_->push(std::move(event));
  if (!target.sensors.empty()) {
    message_ = "clicked " + target.hit.shape->path() + ":";
    for (std::size_t i = 0; i < target.sensors.size(); ++i) {
      message_ += (i == 0 ? " " : ", ") + target.sensors[i]->path();
    }
    message_ += target.sensors.size() == 1 ? " feels it at the next step" : " feel it at the next step";
  }
  return target;
}

double RunControl::time() const { return session_ ? session_->simulation().kernel().now() : 0.0; }

std::int64_t RunControl::steps() const { return session_ ? session_->simulation().kernel().steps() : 0; }

std::vector<std::string> RunControl::transitions() const {
  std::vector<std::string> names;
  if (!session_) return names;
  const auto& net = session_->simulation().net();
  for (net::TransitionId t{0}; t < net.transitions().size(); ++t) names.push_back(net.transitionName(t));
  return names;
}

}  // namespace gdpn::ide

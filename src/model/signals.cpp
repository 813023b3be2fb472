// Signals: the specs a run records, the recorder that samples them after each step, and the
// table they make.

#include "gdpn/model/signals.h"

#include <algorithm>
#include <cmath>

#include "gdpn/core/text.h"
#include "gdpn/model/simulation.h"
#include "gdpn/net/inscription.h"
#include "probe.h"
#include "signal_recorder.h"

namespace gdpn::model {

std::optional<SignalSpec> parseSignalArgument(const std::string& argument, std::string& why) {
  SignalSpec s;
  s.loc = {"--signal " + argument, 0, 0};
  const auto colon = argument.find(':');
  const std::string kind = colon == std::string::npos ? "" : argument.substr(0, colon);
  const std::string rest = colon == std::string::npos ? "" : argument.substr(colon + 1);
  s.name = rest;
  if (kind == "place" && !rest.empty()) {
    s.kind = SignalSpec::Kind::Place;
    s.target = rest;
    // place:NAME=VALUE: one value's tokens (a place's name has no '=')
    if (const auto eq = rest.find('='); eq != std::string::npos) {
      s.target = rest.substr(0, eq);
      s.value = rest.substr(eq + 1);
      s.value_loc = s.loc;
      core::Diagnostics found;
      const bool parsed = net::parseInscription(s.value, {}, found).has_value() && !found.hasErrors();
      if (s.target.empty() || s.value.empty()) {
        why = "expects place:NAME=VALUE (main/idle=lathe), got '" + argument + "'";
        return std::nullopt;
      }
      if (!parsed) {
        why = "value '" + s.value + "': " + (found.all().empty() ? "no value" : found.all().front().message);
        return std::nullopt;
      }
    }
  } else if (kind == "node" && rest.find('.') != std::string::npos) {
    s.kind = SignalSpec::Kind::Node;
    // the quantity follows the last dot, or the one before when it picks an axis: ball.position.x
    auto dot = rest.rfind('.');
    const bool axis = dot + 2 == rest.size() && rest[dot + 1] >= 'x' && rest[dot + 1] <= 'z';
    if (axis && dot > 0 && rest.rfind('.', dot - 1) != std::string::npos) dot = rest.rfind('.', dot - 1);
    s.target = rest.substr(0, dot);
    s.quantity = rest.substr(dot + 1);
    if (s.target.empty() || s.quantity.empty()) {
      why = "expects node:PATH.QUANTITY (ball.position, arm/joint.angle), got '" + argument + "'";
      return std::nullopt;
    }
  } else if (kind == "python" && !rest.empty()) {
    s.kind = SignalSpec::Kind::Expression;
    s.target = rest;
  } else {
    why = "expects place:NAME, node:PATH.QUANTITY or python:EXPRESSION, got '" + argument + "'";
    return std::nullopt;
  }
  return s;
}

void SignalTable::writeCsv(std::ostream& out) const {
  // a column name with a comma, a quote or a line break is quoted, its quotes doubled
  const auto cell = [](const std::string& text) {
    if (text.find_first_of(",\"\n\r") == std::string::npos) return text;
    std::string q = "\"";
    for (char c : text) q += c == '"' ? std::string("\"\"") : std::string(1, c);
    return q + "\"";
  };
  out << "time";
  for (const auto& c : columns) out << ',' << cell(c);
  out << '\n';
  for (std::size_t r = 0; r < rows.size(); ++r) {
    out << core::formatTime(time[r]);
    for (const auto& v : rows[r]) {
      out << ',';
      if (v) out << core::formatDouble(*v);
    }
    out << '\n';
  }
}

std::unique_ptr<SignalRecorder> SignalRecorder::create(Simulation& sim, const std::vector<SignalSpec>& specs,
                                                       core::Diagnostics& diags) {
  auto rec = std::unique_ptr<SignalRecorder>(new SignalRecorder(sim));
  bool ok = true;
  for (const auto& spec : specs) {
    Entry p;
    p.spec = spec;
    // a period of less than a step samples every step
    p.period_steps = spec.every > 0 ? spec.every / sim.kernel().dt() : 0.0;
    if (p.period_steps < 1.0) p.period_steps = 0.0;
    p.first_column = rec->table_.columns.size();
    const auto fail = [&](const std::string& why) {
      diags.error(spec.loc, "signal '" + spec.name + "': " + why);
      ok = false;
    };
    std::string why;
    std::optional<Probe> probe;
    switch (spec.kind) {
      case SignalSpec::Kind::Place: probe = placeProbe(sim, spec.target, why); break;
      case SignalSpec::Kind::Node: probe = nodeProbe(sim, spec.target, spec.quantity, why); break;
      case SignalSpec::Kind::Expression: probe = Probe{}; break;
    }
    if (!probe) {
      fail(why);
      continue;
    }
    if (!spec.value.empty() && !countValue(sim, *probe, spec.value, spec.value_loc, "signal '" + spec.name + "': ", diags)) {
      ok = false;
      continue;
    }
    p.probe = std::move(*probe);
    const bool vector = spec.kind == SignalSpec::Kind::Node && p.probe.width() == 3;
    if (std::any_of(specs.begin(), specs.begin() + (&spec - specs.data()),
                    [&](const SignalSpec& other) { return other.name == spec.name; })) {
      fail("another signal has this name (each names its own column)");
      continue;
    }
    if (vector) {
      for (const char* axis : {".x", ".y", ".z"}) rec->table_.columns.push_back(spec.name + axis);
    } else {
      rec->table_.columns.push_back(spec.name);
    }
    rec->probes_.push_back(std::move(p));
  }
  if (!ok) return nullptr;
  return rec;
}

void SignalRecorder::sample() {
  const std::int64_t step = sim_.kernel().steps();
  bool any = false;
  for (auto& p : probes_) {
    // due at the first step at or after each multiple of the period (every step without one)
    p.due_now = p.period_steps <= 0 || static_cast<double>(step) + 1e-6 >= p.next * p.period_steps;
    any = any || p.due_now;
  }
  if (!any) return;
  std::vector<std::optional<double>> row(table_.columns.size());
  for (auto& p : probes_) {
    if (!p.due_now) continue;
    if (p.period_steps > 0) p.next = std::floor((static_cast<double>(step) + 1e-6) / p.period_steps) + 1;
    read(p, row);
    if (!error_.empty()) return;
  }
  table_.time.push_back(sim_.kernel().now());
  table_.rows.push_back(std::move(row));
}

void SignalRecorder::read(const Entry& p, std::vector<std::optional<double>>& row) {
  auto* at = row.data() + p.first_column;
  if (p.spec.kind == SignalSpec::Kind::Expression) {
    std::string why;
    if (auto v = sim_.evaluateNumber(p.spec.target, why)) {
      if (std::isfinite(*v)) *at = *v;
    } else {
      error_ = p.spec.loc.str() + ": error: signal '" + p.spec.name + "' at t = " + core::formatTime(sim_.kernel().now()) +
               " s: " + why;
    }
    return;
  }
  double v[3];
  if (!readProbe(sim_, p.probe, v)) return;  // deleted: no value from now on
  for (int k = 0; k < p.probe.width(); ++k) at[k] = v[k];
}

}  // namespace gdpn::model

// Signals: the specs a run records, the recorder that samples them after each step, and the
// table they make.

#include "gdpn/model/signals.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "gdpn/core/text.h"
#include "gdpn/model/simulation.h"
#include "gdpn/scene/actions.h"
#include "gdpn/scene/fields.h"
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
  } else if (kind == "node" && rest.find('.') != std::string::npos) {
    s.kind = SignalSpec::Kind::Node;
    const auto dot = rest.rfind('.');
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
    Probe p;
    p.spec = spec;
    // a period of less than a step samples every step
    p.period_steps = spec.every > 0 ? spec.every / sim.kernel().dt() : 0.0;
    if (p.period_steps < 1.0) p.period_steps = 0.0;
    p.first_column = rec->table_.columns.size();
    const auto fail = [&](const std::string& why) {
      diags.error(spec.loc, "signal '" + spec.name + "': " + why);
      ok = false;
    };
    switch (spec.kind) {
      case SignalSpec::Kind::Place: {
        const auto place = sim.net().findPlace(spec.target);
        if (place < 0) {
          fail("no place '" + spec.target + "' (names are qualified: page/place)");
          continue;
        }
        p.place = static_cast<net::PlaceId>(place);
        break;
      }
      case SignalSpec::Kind::Expression: break;
      case SignalSpec::Kind::Node: {
        const scene::Node* node = sim.plant() ? sim.plant()->find(spec.target) : nullptr;
        if (node == nullptr) {
          fail(sim.plant() ? "no scene node '" + spec.target + "'" : "the model has no scene");
          continue;
        }
        if (scene::inTemplate(*node)) {
          fail("'" + spec.target + "' lies in a template, which is neither simulated nor sensed");
          continue;
        }
        p.node = node->handle();
        const std::string& q = spec.quantity;
        if (q == "position") {
          p.what = What::Position;
        } else if (q == "velocity") {
          if (!sim.physics() || !sim.physics()->isBody(*node)) {
            fail("'" + spec.target + "' is no body the physics moves: it has no velocity");
            continue;
          }
          p.what = What::Velocity;
        } else if (q == "angle" || q == "rate") {
          if (node->kind() != scene::NodeKind::Joint || !sim.physics()) {
            fail("'" + spec.target + "' is no joint: it has no " + q);
            continue;
          }
          p.what = q == "angle" ? What::JointAngle : What::JointRate;
          p.linear = node->choice<scene::JointKind>(scene::field::Joint::Kind) == scene::JointKind::Slider;
        } else if (q == "reading") {
          if (node->type().category != scene::Category::Sensor) {
            fail("'" + spec.target + "' is no sensor: it has no reading");
            continue;
          }
          p.what = What::Reading;
        } else {
          const int i = node->type().fieldIndex(q);
          const auto* f = i >= 0 ? node->type().fields[static_cast<std::size_t>(i)] : nullptr;
          if (f == nullptr || (f->kind != scene::FieldKind::Float && f->kind != scene::FieldKind::Int)) {
            // what this node has: a position always, the others by its kind
            std::vector<std::string> known = {"position"};
            if (sim.physics() && sim.physics()->isBody(*node)) known.emplace_back("velocity");
            if (node->kind() == scene::NodeKind::Joint) known.insert(known.end(), {"angle", "rate"});
            if (node->type().category == scene::Category::Sensor) known.emplace_back("reading");
            for (const auto& fd : node->type().fields) {
              if (fd->kind == scene::FieldKind::Float || fd->kind == scene::FieldKind::Int) known.push_back(fd->name);
            }
            std::string list;
            for (const auto& k : known) list += (list.empty() ? "" : ", ") + k;
            fail("a " + node->type().name + " has no number '" + q + "'" + core::didYouMean(q, known) + " (it has: " +
                 list + ")");
            continue;
          }
          p.what = What::Field;
          p.field = static_cast<std::size_t>(i);
        }
        break;
      }
    }
    const bool vector = p.what == What::Position || p.what == What::Velocity;
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

void SignalRecorder::read(const Probe& p, std::vector<std::optional<double>>& row) {
  auto* at = row.data() + p.first_column;
  if (p.spec.kind == SignalSpec::Kind::Place) {
    const auto& place = sim_.net().places()[p.place];
    std::int64_t tokens = 0;
    for (auto ps = place.slots_begin; ps < place.slots_end; ++ps) tokens += sim_.kernel().marking(ps);
    *at = static_cast<double>(tokens);
    return;
  }
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
  const scene::Node* node = sim_.plant()->resolve(p.node);
  if (node == nullptr) return;  // deleted: no value from now on
  const bool degrees = sim_.model().settings.angles == scene::AngleUnit::Degrees;
  switch (p.what) {
    case What::Position: {
      const core::Vec3 v = node->framePose().position;
      at[0] = v.x;
      at[1] = v.y;
      at[2] = v.z;
      break;
    }
    case What::Velocity: {
      const core::Vec3 v = sim_.physics()->velocity(*node);
      at[0] = v.x;
      at[1] = v.y;
      at[2] = v.z;
      break;
    }
    case What::JointAngle:
    case What::JointRate: {
      const double v = p.what == What::JointAngle ? sim_.physics()->jointPosition(*node) : sim_.physics()->jointRate(*node);
      *at = !p.linear && degrees ? v * 180.0 / std::numbers::pi : v;
      break;
    }
    case What::Reading: {
      const auto& r = sim_.reading(p.node);
      *at = node->kind() == scene::NodeKind::Region ? static_cast<double>(r.items.size()) : r.value;
      break;
    }
    case What::Field: {
      const auto v = scene::convertAngle(*node, p.field, node->value(p.field), sim_.model().settings.angles, false);
      if (const auto* d = std::get_if<double>(&v)) *at = *d;
      else if (const auto* i = std::get_if<std::int64_t>(&v)) *at = static_cast<double>(*i);
      break;
    }
    case What::None: break;
  }
}

}  // namespace gdpn::model

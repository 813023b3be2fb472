// The parts of a run: their I/O bound to the plant, read, written and forced at step
// boundaries.

#include "gdpn/model/part_run.h"

#include <algorithm>
#include <cmath>

#include "gdpn/core/expression.h"
#include "gdpn/core/text.h"
#include "gdpn/model/simulation.h"
#include "gdpn/physics/world.h"
#include "probe.h"

namespace gdpn::model {

struct PartRun::Bound {
  std::size_t part = 0;
  const PartIoSpec* spec = nullptr;
  Probe probe;                          // an input's quantity, or an output's field
  scene::NodeHandle node = 0;           // an output's node
  std::vector<scene::NodeHandle> also;  // an output's further nodes (a `*` in its path): set alike
  std::size_t field = 0;                // an output's field
  scene::FieldKind kind = scene::FieldKind::Float;
  scene::FieldValue on, off;            // a digital output's values
  std::optional<double> forced;         // in force: the value held
  double wanted = 0;                    // a forced output: what was written last, for its release
  bool written = false;                 // whether anything was written while forced
};

PartRun::PartRun(Simulation& sim) : sim_(&sim) {}
PartRun::~PartRun() = default;

namespace {

/// The nodes at `path` below `from`, where a `*` segment stands for every child, in order.
void findAll(scene::Node* from, std::string_view path, std::vector<scene::Node*>& out) {
  if (from == nullptr) return;
  if (path.empty()) {
    out.push_back(from);
    return;
  }
  const auto slash = path.find('/');
  const std::string_view segment = path.substr(0, slash), rest = slash == std::string_view::npos ? "" : path.substr(slash + 1);
  if (segment != "*") {
    findAll(from->find(segment), rest, out);
    return;
  }
  for (const auto& c : from->children()) findAll(c.get(), rest, out);
}

/// `v` as a field of kind `kind` holds it (a bool, a whole number, a number).
scene::FieldValue numberAs(scene::FieldKind kind, double v) {
  if (kind == scene::FieldKind::Bool) return v != 0.0;
  if (kind == scene::FieldKind::Int) return static_cast<std::int64_t>(std::llround(v));
  return v;
}

/// The value `texts` write for a field of kind `kind` (one number, or three for a vector or
/// colour), each a number, `$name` or `=expression` of `lookup`'s names; nullopt and `why`.
std::optional<scene::FieldValue> valueOf(const std::vector<std::string>& texts, scene::FieldKind kind,
                                         const core::NameLookup& lookup, std::string& why) {
  std::vector<double> numbers;
  for (const auto& t : texts) {
    core::ExpressionError e;
    const std::string expr = t.empty() ? t : (t[0] == '$' || t[0] == '=') ? t.substr(1) : t;
    const auto v = core::evaluate(expr, lookup, e);
    if (!v) {
      why = "'" + t + "': " + e.message;
      return std::nullopt;
    }
    numbers.push_back(*v);
  }
  const bool vector = kind == scene::FieldKind::Vec3 || kind == scene::FieldKind::Color;
  if (vector) {
    if (numbers.size() != 3) {
      why = "a three-number field takes three numbers for 'on' and 'off'";
      return std::nullopt;
    }
    return std::array<double, 3>{numbers[0], numbers[1], numbers[2]};
  }
  if (numbers.size() != 1 || (kind != scene::FieldKind::Float && kind != scene::FieldKind::Int &&
                              kind != scene::FieldKind::Bool)) {
    why = "'on' and 'off' give one number for a number field, three for a vector or colour";
    return std::nullopt;
  }
  return numberAs(kind, numbers[0]);
}

}  // namespace

std::unique_ptr<PartRun> PartRun::create(Simulation& sim, std::vector<PlacedPart> placed, core::Diagnostics& diags) {
  std::unique_ptr<PartRun> run(new PartRun(sim));
  const Model& model = sim.model();
  const std::size_t errors = diags.errorCount();
  for (auto& p : placed) {
    const auto spec = model.parts.find(p.type);
    if (spec == model.parts.end()) continue;
    Instance inst{std::move(p), &spec->second, 0};
    if (const scene::Node* frame = sim.plant() ? sim.plant()->find(inst.placed.frame) : nullptr) {
      inst.frame = frame->handle();
    }
    const std::size_t part = run->instances_.size();
    run->first_.push_back(run->bound_.size());
    const auto lookup = [&inst, &model](std::string_view name) -> std::optional<double> {
      for (const auto& [n, v] : inst.placed.params) {
        if (n == name) return v;
      }
      for (const auto& mp : model.params) {
        if (mp.name == name) return mp.value;
      }
      return std::nullopt;
    };
    for (const auto& io : inst.spec->io) {
      const std::string path = inst.placed.frame + "/" + io.node;
      const auto fail = [&](const std::string& why) {
        diags.error(io.loc, "I/O '" + io.name + "' of part '" + inst.placed.name + "': " + why);
      };
      Bound b;
      b.part = part;
      b.spec = &io;
      std::string why;
      if (io.direction == IoDirection::Input) {
        // (a '*' in an input's path is refused where the file is read)
        const auto probe = nodeProbe(sim, path, io.of, why);
        if (!probe) {
          fail(why);
          continue;
        }
        if (probe->width() != 1) {
          fail("'" + io.of + "' is three numbers: name one axis (" + io.of + ".z)");
          continue;
        }
        b.probe = *probe;
        run->bound_.push_back(std::move(b));
        continue;
      }
      std::vector<scene::Node*> nodes;
      if (sim.plant()) findAll(&sim.plant()->root(), path, nodes);
      if (nodes.empty()) {
        fail("its scene has no node '" + io.node + "'");
        continue;
      }
      const scene::Node* node = nodes.front();
      if (const auto other = std::ranges::find_if(nodes, [node](const scene::Node* n) { return n->kind() != node->kind(); });
          other != nodes.end()) {
        fail("'" + io.node + "' sets " + node->path() + ", a " + node->type().name + ", and " + (*other)->path() +
             ", a " + (*other)->type().name + ": an output sets nodes of one type");
        continue;
      }
      for (std::size_t i = 1; i < nodes.size(); ++i) b.also.push_back(nodes[i]->handle());
      const auto index = node->type().fieldIndex(io.field);
      if (index < 0) {
        std::vector<std::string> names;
        for (const auto* f : node->type().fields) names.push_back(f->name);
        fail("a " + node->type().name + " has no field '" + io.field + "'" + core::didYouMean(io.field, names));
        continue;
      }
      b.node = node->handle();
      b.field = static_cast<std::size_t>(index);
      b.kind = node->type().fields[b.field]->kind;
      if (io.signal == IoSignal::Digital) {
        const bool vector = b.kind == scene::FieldKind::Vec3 || b.kind == scene::FieldKind::Color;
        const auto on = valueOf(io.on.empty() ? std::vector<std::string>(vector ? 0 : 1, "1") : io.on, b.kind, lookup, why);
        const auto off = on ? valueOf(io.off.empty() ? std::vector<std::string>(vector ? 0 : 1, "0") : io.off, b.kind,
                                      lookup, why)
                            : std::nullopt;
        if (!on || !off) {
          fail(why);
          continue;
        }
        for (const auto* v : {&*on, &*off}) {
          if (const auto no = scene::refusal(*node, b.field, *v, model.settings.angles); !no.empty()) {
            fail("'" + std::string(v == &*on ? "on" : "off") + "': " + no);
            why = no;
          }
        }
        if (!why.empty()) continue;
        b.on = *on;
        b.off = *off;
      } else if (b.kind != scene::FieldKind::Float && b.kind != scene::FieldKind::Int) {
        fail("an analogue output sets a number field; '" + io.field + "' is not one");
        continue;
      }
      run->bound_.push_back(std::move(b));
    }
    run->instances_.push_back(std::move(inst));
  }
  if (diags.errorCount() > errors) return nullptr;
  return run;
}

std::optional<std::size_t> PartRun::find(const std::string& name, std::string& why) const {
  if (const auto it = found_.find(name); it != found_.end() && it->second) return it->second;
  std::vector<std::size_t> found;
  std::vector<std::string> names;
  for (std::size_t i = 0; i < instances_.size(); ++i) {
    const std::string& q = instances_[i].placed.name;
    names.push_back(q);
    if (q == name) return found_[name] = i;
    const auto slash = q.rfind('/');
    if (q.substr(slash == std::string::npos ? 0 : slash + 1) == name) found.push_back(i);
  }
  if (found.size() == 1) return found_[name] = found[0];
  if (found.empty()) {
    why = "no part '" + name + "'" + core::didYouMean(name, names);
    if (names.empty()) why += " (the model has none)";
  } else {
    why = "'" + name + "' names " + std::to_string(found.size()) + " parts: write one's qualified name (" +
          instances_[found[0]].placed.name + ")";
  }
  return std::nullopt;
}

std::optional<std::size_t> PartRun::ownerOf(const std::string& construct) const {
  if (const auto it = owner_of_.find(construct); it != owner_of_.end()) return it->second;
  auto& out = owner_of_[construct];
  // the deepest instance whose qualified name prefixes the construct's
  std::optional<std::size_t> best;
  std::size_t longest = 0;
  for (std::size_t i = 0; i < instances_.size(); ++i) {
    const std::string& q = instances_[i].placed.name;
    if (construct.size() > q.size() && construct.compare(0, q.size(), q) == 0 && construct[q.size()] == '/' &&
        q.size() > longest) {
      best = i;
      longest = q.size();
    }
  }
  return out = best;
}

std::vector<std::pair<std::string, std::optional<std::size_t>>> PartRun::usesOf(std::size_t owner) const {
  std::vector<std::pair<std::string, std::optional<std::size_t>>> out;
  if (owner >= instances_.size()) return out;
  const auto& inst = instances_[owner];
  for (const auto& role : inst.spec->uses) {
    std::optional<std::size_t> filled;
    for (const auto& [name, part] : inst.placed.uses) {
      std::string why;
      if (name == role.name) filled = find(part, why);
    }
    out.emplace_back(role.name, filled);
  }
  return out;
}

std::optional<std::size_t> PartRun::ofConstruct(const std::string& construct) const {
  if (const auto it = of_construct_.find(construct); it != of_construct_.end()) return it->second;
  auto& out = of_construct_[construct];
  std::optional<std::size_t> best = ownerOf(construct);
  // a control pattern's construct: its instance names the part it controls
  if (best && !instances_[*best].placed.controls.empty()) {
    std::string why;
    best = find(instances_[*best].placed.controls, why);
  }
  return out = best;
}

const PartRun::Bound* PartRun::bound(std::size_t part, const std::string& io, std::string& why) const {
  if (part >= instances_.size()) {
    why = "no such part";
    return nullptr;
  }
  const std::size_t end = part + 1 < first_.size() ? first_[part + 1] : bound_.size();
  for (std::size_t i = first_[part]; i < end; ++i) {
    if (bound_[i].spec->name == io) return &bound_[i];
  }
  std::vector<std::string> names;
  for (std::size_t i = first_[part]; i < end; ++i) names.push_back(bound_[i].spec->name);
  std::string list;
  for (const auto& n : names) list += (list.empty() ? "" : ", ") + n;
  why = "part '" + instances_[part].placed.name + "' has no I/O '" + io + "'" + core::didYouMean(io, names) +
        (list.empty() ? " (it has none)" : " (it has: " + list + ")");
  return nullptr;
}

double PartRun::plantValue(const Bound& b) const {
  if (b.spec->direction == IoDirection::Output) {
    const scene::Node* node = sim_->plant()->resolve(b.node);
    if (node == nullptr) return 0.0;
    if (b.spec->signal == IoSignal::Digital) return node->value(b.field) == b.on ? 1.0 : 0.0;
    return numberOf(scene::convertAngle(*node, b.field, node->value(b.field), sim_->model().settings.angles, false));
  }
  double v = 0.0;
  if (!readProbe(*sim_, b.probe, &v)) return 0.0;
  if (b.spec->signal == IoSignal::Digital) return v != 0.0 ? 1.0 : 0.0;
  return v;
}

std::optional<double> PartRun::read(std::size_t part, const std::string& io, std::string& why) const {
  const Bound* b = bound(part, io, why);
  if (b == nullptr) return std::nullopt;
  if (b->forced) return *b->forced;
  return plantValue(*b);
}

bool PartRun::assign(Bound& b, double value, std::string& why) {
  scene::Node* node = sim_->plant()->resolve(b.node);
  if (node == nullptr) {
    why = "its node was deleted";
    return false;
  }
  const scene::FieldValue v = b.spec->signal == IoSignal::Digital ? (value != 0.0 ? b.on : b.off) : numberAs(b.kind, value);
  why = physics::assignField(*node, b.field, v, sim_->model().settings.angles, sim_->physics());
  // the further nodes of a `*` path, alike
  for (const scene::NodeHandle h : b.also) {
    if (scene::Node* more = why.empty() ? sim_->plant()->resolve(h) : nullptr) {
      why = physics::assignField(*more, b.field, v, sim_->model().settings.angles, sim_->physics());
    }
  }
  return why.empty();
}

bool PartRun::write(std::size_t part, const std::string& io, double value, std::string& why) {
  const Bound* found = bound(part, io, why);
  if (found == nullptr) return false;
  Bound& b = bound_[static_cast<std::size_t>(found - bound_.data())];
  if (b.spec->direction == IoDirection::Input) {
    why = refusal(part, io, value);
    return false;
  }
  if (b.forced) {
    // a forced output keeps its force; the value waits for the release
    b.wanted = value;
    b.written = true;
    return true;
  }
  return assign(b, value, why);
}

std::string PartRun::fieldRefusal(const Bound& b, double value) const {
  if (b.spec->direction != IoDirection::Output || b.spec->signal != IoSignal::Analog) return {};
  const scene::Node* node = sim_->plant()->resolve(b.node);
  if (node == nullptr) return "its node was deleted";
  return scene::refusal(*node, b.field, numberAs(b.kind, value), sim_->model().settings.angles);
}

std::string PartRun::refusal(std::size_t part, const std::string& io, double value) const {
  std::string why;
  const Bound* b = bound(part, io, why);
  if (b == nullptr) return why;
  if (b->spec->direction == IoDirection::Input) {
    return "'" + io + "' of part '" + instances_[part].placed.name + "' is an input: the plant sets it";
  }
  return fieldRefusal(*b, value);
}

bool PartRun::force(std::size_t part, const std::string& io, double value, std::string& why) {
  const Bound* found = bound(part, io, why);
  if (found == nullptr) return false;
  const auto i = static_cast<std::size_t>(found - bound_.data());
  if (found->spec->signal == IoSignal::Digital) value = value != 0.0 ? 1.0 : 0.0;
  why = fieldRefusal(*found, value);
  if (!why.empty()) return false;
  asked_[i] = value;
  return true;
}

bool PartRun::release(std::size_t part, const std::string& io) {
  std::string why;
  const Bound* found = bound(part, io, why);
  if (found == nullptr) return false;
  const auto i = static_cast<std::size_t>(found - bound_.data());
  if (!found->forced && !asked_.contains(i)) return false;
  asked_[i] = std::nullopt;
  return true;
}

void PartRun::releaseAll() {
  for (std::size_t i = 0; i < bound_.size(); ++i) {
    if (bound_[i].forced || asked_.contains(i)) asked_[i] = std::nullopt;
  }
}

void PartRun::atStepBoundary() {
  for (const auto& [i, value] : asked_) {
    Bound& b = bound_[i];
    const std::string who = "\"part\":" + core::jsonQuote(instances_[b.part].placed.name) +
                            ",\"io\":" + core::jsonQuote(b.spec->name);
    if (value) {
      if (!b.forced && b.spec->direction == IoDirection::Output) {
        b.wanted = plantValue(b);  // what the output held: back to it on release, unless written
        b.written = false;
      }
      b.forced = value;
      sim_->note("force", who + ",\"value\":" + core::formatDouble(*value));
    } else if (b.forced) {
      b.forced.reset();
      if (b.spec->direction == IoDirection::Output) {
        std::string why;
        (void)assign(b, b.wanted, why);
      }
      sim_->note("release", who);
    }
  }
  asked_.clear();
  // forced outputs hold their value whatever wrote the field in between
  for (auto& b : bound_) {
    if (b.forced && b.spec->direction == IoDirection::Output) {
      std::string why;
      (void)assign(b, *b.forced, why);
    }
  }
}

std::vector<PartRun::Row> PartRun::rows() const {
  std::vector<Row> out;
  out.reserve(bound_.size());
  for (std::size_t i = 0; i < bound_.size(); ++i) {
    const Bound& b = bound_[i];
    const auto asked = asked_.find(i);
    out.push_back({b.part, b.spec, b.forced ? *b.forced : plantValue(b), b.forced.has_value(), asked != asked_.end(),
                   asked != asked_.end() ? asked->second : std::nullopt});
  }
  return out;
}

}  // namespace gdpn::model

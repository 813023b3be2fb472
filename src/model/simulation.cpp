#include "gdpn/model/simulation.h"

#include "gdpn/core/expression.h"
#include "gdpn/model/part_library.h"
#include "gdpn/model/part_run.h"

#include "fluid_plant.h"
#include "signal_recorder.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>
#include <unordered_map>
#include <unordered_set>

#include "gdpn/scene/actions.h"
#include <filesystem>
#include <iostream>

#include "gdpn/core/text.h"

#include "gdpn/net/compile.h"

namespace gdpn::model {

const char* stopReasonName(StopReason reason) {
  switch (reason) {
    case StopReason::Until: return "until";
    case StopReason::Dead: return "dead";
    case StopReason::Interrupted: return "interrupted";
    case StopReason::Stopped: return "stopped";
    case StopReason::ScriptError: return "script error";
    case StopReason::Breakpoint: return "breakpoint";
    case StopReason::PhysicsError: return "physics error";
  }
  return "?";
}

namespace {

/// The first location `where(place)` gives for a place of any page or page type, or none.
template <class Where>
core::SourceLoc findInPlaces(const net::NetSpec& spec, Where where) {
  for (const auto* pages : {&spec.pages, &spec.page_types}) {
    for (const auto& page : *pages) {
      for (const auto& place : page.places) {
        if (auto loc = where(place)) return *loc;
      }
    }
  }
  return {};
}

/// True when a flat path names what `written` names (in a page type it is relative).
bool names(const std::string& path, const std::string& written) {
  return path == written || path.ends_with("/" + written);
}

/// Where the sensor slot reading `path` is bound, for messages.
core::SourceLoc sensorLoc(const net::NetSpec& spec, const std::string& path) {
  return findInPlaces(spec, [&](const net::PlaceSpec& p) -> std::optional<core::SourceLoc> {
    for (const auto& b : p.sensors) {
      if (names(path, b.path)) return b.loc;
    }
    return std::nullopt;
  });
}

/// Where the node token `name` is written, for messages; a page type's token stands for all
/// its instances.
core::SourceLoc tokenLoc(const net::NetSpec& spec, const std::string& name) {
  return findInPlaces(spec, [&](const net::PlaceSpec& p) -> std::optional<core::SourceLoc> {
    for (const auto& slot : p.nodes) {
      for (const auto& n : slot.nodes) {
        if (names(name, n)) return slot.loc;
      }
    }
    return std::nullopt;
  });
}

/// Copies the scene each instance's page type owns into `scene`, under a Transform named after
/// the instance and placed by its translation and rotation; nested instances nest the same way.
class InstancePlacer {
 public:
  InstancePlacer(const Model& model, scene::Scene* scene, core::Diagnostics& diags)
      : model_(model), scene_(scene), diags_(diags) {
    for (const auto& t : model.net.page_types) types_[t.name] = &t;
  }

  /// Places the instances of `page` (named `prefix`) and, below them, theirs: each instance of
  /// a type that owns scene nodes gets its Transform under `parent` with a copy of its type's
  /// scene, its parameters applied; each part instance is noted.
  void placePage(const net::PageSpec& page, const std::string& prefix, scene::Node* parent,
                 std::vector<std::string>& stack) {
    for (const auto& inst : page.instances) {
      auto type = types_.find(inst.type);
      if (type == types_.end() || std::find(stack.begin(), stack.end(), inst.type) != stack.end()) continue;
      const std::string name = prefix + "/" + inst.name;
      const auto part = model_.parts.find(inst.type);
      PlacedPart placed;
      placed.name = name;
      placed.type = inst.type;
      placed.loc = inst.loc;
      if (part != model_.parts.end()) resolveParams(inst, part->second, placed);
      checkControl(page, prefix, inst, part == model_.parts.end() ? nullptr : &part->second, placed);
      checkUses(page, prefix, inst, part == model_.parts.end() ? nullptr : &part->second, placed);
      scene::Node* frame = nullptr;
      if (scene_ && parent && ownsScene(*type->second)) {
        frame = scene_->create(*scene_->types().find(scene::NodeKind::Transform), inst.name, *parent);
        if (!frame) {
          diags_.error(inst.loc, "instance '" + inst.name + "' places its machine at '" +
                                     (parent->path().empty() ? "" : parent->path() + "/") + inst.name +
                                     "', but the scene already has a node there");
          continue;
        }
        frame->loc = inst.loc;
        frame->setValue(0, inst.translation);
        frame->setValue(1, inst.rotation);
        if (auto own = model_.type_scenes.find(inst.type); own != model_.type_scenes.end()) {
          for (const auto& c : own->second->root().children()) scene_->copy(*c, *frame);
        }
        applyParams(*frame, inst, placed);
        placed.frame = frame->path();
      }
      if (part != model_.parts.end()) placed_.push_back(std::move(placed));
      stack.push_back(inst.type);
      placePage(*type->second, name, frame ? frame : parent, stack);
      stack.pop_back();
    }
  }

  /// The part instances placed, in placement order.
  std::vector<PlacedPart> takePlaced() { return std::move(placed_); }

 private:
  /// The type's parameters with the instance's values; an unknown name is an error.
  void resolveParams(const net::InstanceSpec& inst, const PartSpec& part, PlacedPart& placed) {
    for (const auto& p : part.params) placed.params.emplace_back(p.name, p.value);
    for (const auto& set : inst.params) {
      auto it = std::find_if(placed.params.begin(), placed.params.end(), [&](const auto& p) { return p.first == set.name; });
      if (it == placed.params.end()) {
        std::vector<std::string> names;
        for (const auto& p : part.params) names.push_back(p.name);
        diags_.error(set.loc, "page type '" + inst.type + "' has no parameter '" + set.name + "'" +
                                  core::didYouMean(set.name, names) +
                                  (names.empty() ? " (it declares none)" : ""));
        continue;
      }
      const auto declared = std::find_if(part.params.begin(), part.params.end(), [&](const Param& p) { return p.name == set.name; });
      if (declared->integer && std::floor(set.value) != set.value) {
        diags_.error(set.loc, "parameter '" + set.name + "' of page type '" + inst.type + "' is a whole number; " +
                                  core::formatDouble(set.value) + " is not");
        continue;
      }
      it->second = set.value;
    }
  }

  /// A control pattern's instance names the part it controls, on its own page, of its type.
  void checkControl(const net::PageSpec& page, const std::string& prefix, const net::InstanceSpec& inst,
                    const PartSpec* part, PlacedPart& placed) {
    const bool pattern = part && !part->controls.empty();
    if (inst.part.empty()) {
      if (pattern) {
        diags_.error(inst.loc, "instance '" + inst.name + "' of control pattern '" + inst.type +
                                   "' needs 'part': the " + part->controls + " it controls");
      }
      return;
    }
    if (!pattern) {
      diags_.error(inst.part_loc, "'part' is for instances of control patterns; '" + inst.type + "' controls no part");
      return;
    }
    const auto target = std::find_if(page.instances.begin(), page.instances.end(),
                                      [&](const net::InstanceSpec& i) { return i.name == inst.part; });
    if (target == page.instances.end()) {
      std::vector<std::string> names;
      for (const auto& i : page.instances) {
        if (i.type == part->controls) names.push_back(i.name);
      }
      diags_.error(inst.part_loc, "no instance '" + inst.part + "' on page '" + page.name + "'" +
                                      core::didYouMean(inst.part, names));
      return;
    }
    if (target->type != part->controls) {
      diags_.error(inst.part_loc, "'" + inst.part + "' is a " + target->type + "; control pattern '" + inst.type +
                                      "' controls a " + part->controls);
      return;
    }
    placed.controls = prefix + "/" + inst.part;
  }

  /// A control pattern's instance fills each of its roles with a part instance on its page that
  /// has the role's I/O (an optional role may stay unfilled).
  void checkUses(const net::PageSpec& page, const std::string& prefix, const net::InstanceSpec& inst,
                 const PartSpec* part, PlacedPart& placed) {
    const std::vector<PartUse> none;
    const auto& roles = part ? part->uses : none;
    for (const auto& u : inst.uses) {
      const PartUse* role = part ? part->findUse(u.role) : nullptr;
      if (role == nullptr) {
        std::vector<std::string> names;
        for (const auto& r : roles) names.push_back(r.name);
        diags_.error(u.loc, "page type '" + inst.type + "' has no role '" + u.role + "'" + core::didYouMean(u.role, names) +
                                (names.empty() ? " (it uses no other parts)" : ""));
        continue;
      }
      const auto target = std::find_if(page.instances.begin(), page.instances.end(),
                                        [&](const net::InstanceSpec& i) { return i.name == u.part; });
      std::string needs;
      for (const auto& n : role->io) needs += (needs.empty() ? "" : ", ") + n;
      if (target == page.instances.end()) {
        std::vector<std::string> names;
        for (const auto& i : page.instances) {
          if (roleRefusal(model_, i, inst.part, *role).empty()) names.push_back(i.name);
        }
        diags_.error(u.loc, "no part instance '" + u.part + "' on page '" + page.name + "'" +
                                core::didYouMean(u.part, names));
        continue;
      }
      if (const auto refusal = roleRefusal(model_, *target, inst.part, *role); !refusal.empty()) {
        diags_.error(u.loc, refusal + ": role '" + u.role + "' of '" + inst.type + "' needs a part with " + needs);
        continue;
      }
      placed.uses.emplace_back(u.role, prefix + "/" + u.part);
    }
    for (const auto& r : roles) {
      const bool filled = std::any_of(inst.uses.begin(), inst.uses.end(), [&](const auto& u) { return u.role == r.name; });
      if (filled || r.optional) continue;
      std::string needs;
      for (const auto& n : r.io) needs += (needs.empty() ? "" : ", ") + n;
      diags_.error(inst.loc, "instance '" + inst.name + "' of '" + inst.type + "' needs 'uses: {" + r.name +
                                 ": ...}': a part with " + needs + (r.description.empty() ? "" : " (" + r.description + ")"));
    }
  }

  /// Gives every field of the copy under `frame` that refers to parameters its value for this
  /// instance: the instance's parameters first, then the model's.
  void applyParams(scene::Node& frame, const net::InstanceSpec& inst, const PlacedPart& placed) {
    const core::NameLookup lookup = [&](std::string_view name) -> std::optional<double> {
      for (const auto& [n, v] : placed.params) {
        if (n == name) return v;
      }
      for (const auto& p : model_.params) {
        if (p.name == name) return p.value;
      }
      return std::nullopt;
    };
    const auto angles = model_.settings.angles;
    for (const auto& child : frame.children()) {
      scene::traverse(*child, [&](scene::Node& n, const scene::TraversalState&) {
        for (const auto& b : n.params) {
          core::ExpressionError e;
          const std::string text = b.text[0] == '=' ? b.text.substr(1) : b.text;
          const auto v = core::evaluate(text, lookup, e);
          if (!v) {
            diags_.error(inst.loc, "instance '" + inst.name + "': " + n.path() + "." + n.type().fields[b.field]->name +
                                       " = " + referenceText(b.text) + ": " + e.message);
            continue;
          }
          // the number in the file's unit, as written; stored as the field stores it
          scene::FieldValue written = scene::convertAngle(n, b.field, n.value(b.field), angles, false);
          if (b.component < 0) {
            written = n.type().fields[b.field]->kind == scene::FieldKind::Int
                          ? scene::FieldValue(static_cast<std::int64_t>(std::llround(*v)))
                          : scene::FieldValue(*v);
          } else if (auto* a3 = std::get_if<std::array<double, 3>>(&written)) {
            (*a3)[static_cast<std::size_t>(b.component)] = *v;
          } else if (auto* a4 = std::get_if<std::array<double, 4>>(&written)) {
            (*a4)[static_cast<std::size_t>(b.component)] = *v;
          }
          const scene::FieldValue stored = scene::convertAngle(n, b.field, written, angles, true);
          if (auto bad = n.type().fields[b.field]->check(stored)) {
            diags_.error(inst.loc, "instance '" + inst.name + "': " + n.path() + "." + n.type().fields[b.field]->name +
                                       " = " + referenceText(b.text) + ": " + bad->message);
            continue;
          }
          n.setValue(b.field, stored);
        }
      });
    }
  }

  /// True when the type, or a page type it instantiates, owns scene nodes.
  bool ownsScene(const net::PageSpec& type, int depth = 0) const {
    if (depth > 64) return false;
    if (auto own = model_.type_scenes.find(type.name);
        own != model_.type_scenes.end() && !own->second->root().children().empty()) {
      return true;
    }
    for (const auto& inst : type.instances) {
      auto t = types_.find(inst.type);
      if (t != types_.end() && ownsScene(*t->second, depth + 1)) return true;
    }
    return false;
  }

  const Model& model_;
  scene::Scene* scene_;
  core::Diagnostics& diags_;
  std::unordered_map<std::string, const net::PageSpec*> types_;
  std::vector<PlacedPart> placed_;
};

}  // namespace

std::shared_ptr<const net::Net> checkModel(const Model& model, core::Diagnostics& diags, script::ScriptLimits limits) {
  auto net = net::compile(model.net, diags);
  if (!net || !(net->scripted() || model.scene || !model.signals.empty() || !model.io.empty())) return net;
  // the simulation compiles the net again: what that says twice is said once
  core::Diagnostics more;
  auto sim = Simulation::create(model, more, std::nullopt, limits);
  if (sim && !model.signals.empty()) sim->recordSignals({}, more);
  if (sim && !model.io.empty()) IoMap::create(*sim, model.io, more);
  std::set<std::string> said;
  for (const auto& d : diags.all()) said.insert(d.str());
  for (const auto& d : more.all()) {
    if (said.insert(d.str()).second) {
      if (d.severity == core::Severity::Error) diags.error(d.loc, d.message);
      else if (d.severity == core::Severity::Warning) diags.warning(d.loc, d.message);
      else diags.note(d.loc, d.message);
    }
  }
  return net;
}

std::unique_ptr<Simulation> Simulation::create(const Model& model, core::Diagnostics& diags,
                                               std::optional<std::uint64_t> seed, script::ScriptLimits limits,
                                               bool echo_log) {
  auto net = net::compile(model.net, diags);
  if (!net) return nullptr;
  std::unique_ptr<Simulation> sim(new Simulation());
  sim->log_echo_ = echo_log;  // before the globals script runs
  sim->model_ = model;
  sim->net_ = std::move(net);
  sim->seed_ = seed.value_or(model.settings.seed);
  // the plant: the run's own copy of the scene, with each instance's copy of its page
  // type's scene, and its physics
  const bool typed = std::any_of(model.type_scenes.begin(), model.type_scenes.end(),
                                 [](const auto& t) { return !t.second->root().children().empty(); });
  if ((model.scene && !model.scene->root().children().empty()) || typed) {
    sim->scene_ = model.scene ? model.scene->clone() : std::make_unique<scene::Scene>();
  }
  InstancePlacer placer(model, sim->scene_.get(), diags);
  for (const auto& page : model.net.pages) {
    std::vector<std::string> stack;
    placer.placePage(page, page.name, sim->scene_ ? &sim->scene_->root() : nullptr, stack);
  }
  if (diags.hasErrors()) return nullptr;
  if (sim->scene_) {
    const auto dir = std::filesystem::path(model.path).parent_path().string();
    sim->physics_ = physics::World::create(*sim->scene_, dir, sim->seed_, diags);
    if (!sim->physics_) return nullptr;
  }
  net::KernelSettings settings{model.settings.dt, sim->seed_, {}};
  settings.random_ties = model.settings.random_ties;
  if (sim->scene_) {
    // node tokens are scene nodes: each name in an initial marking is a path in the scene
    for (const auto& name : sim->net_->nodeNames()) {
      const scene::Node* node = sim->scene_->find(name);
      if (!node) {
        diags.error(tokenLoc(model.net, name), "node token '" + name + "' names no node of the scene");
        continue;
      }
      settings.node_refs.push_back(node->handle());
    }
    if (diags.hasErrors()) return nullptr;
  }
  // sensor slots read sensor nodes of the plant
  sim->slot_sensor_.assign(sim->net_->placeSlots().size(), 0);
  for (net::PlaceSlotId ps{0}; ps < sim->net_->placeSlots().size(); ++ps) {
    const std::string& path = sim->net_->sensorPath(ps);
    if (path.empty()) continue;
    const scene::Node* sensor = sim->scene_ ? sim->scene_->find(path) : nullptr;
    if (!sensor || sensor->type().category != scene::Category::Sensor) {
      diags.error(sensorLoc(model.net, path), "'" + path + "' names no sensor of the scene");
      continue;
    }
    sim->slot_sensor_[ps] = sensor->handle();
    sim->sensor_slots_[sensor->handle()].push_back(ps);
  }
  for (net::TermId id{0}; id < sim->net_->terms().size(); ++id) {
    const auto& term = sim->net_->terms()[id];
    // sensor conditions (a continuous place's terms are the kernel's own)
    const bool fluid = sim->net_->fluid() && sim->net_->fluid()->of_term[id] >= 0;
    if (term.kind == net::TermKind::Condition && !fluid) sim->conditions_of_[term.place_slot].push_back(id);
  }
  if (diags.hasErrors()) return nullptr;
  if (sim->scene_) {
    // sensors, or templates holding some that copies will bring
    bool any = false;
    scene::traverse(sim->scene_->root(), [&](scene::Node& n, const scene::TraversalState&) {
      any = any || n.type().category == scene::Category::Sensor;
    });
    if (any) {
      const auto dir = std::filesystem::path(model.path).parent_path().string();
      if (!sensors::Hub::check(*sim->scene_, diags, dir.empty() ? "." : dir)) return nullptr;
      sim->hub_ = std::make_unique<sensors::Hub>(*sim->scene_, sim->physics_.get(), sim->seed_);
      sim->hub_->setModelDir(dir.empty() ? "." : dir);
    }
  }
  if (!model.parts.empty()) {
    sim->parts_ = PartRun::create(*sim, placer.takePlaced(), diags);
    if (!sim->parts_) return nullptr;
  }
  sim->kernel_ = std::make_unique<net::Kernel>(sim->net_, settings);
  sim->stats_ = std::make_unique<net::StatsCollector>(*sim->net_);
  sim->kernel_->addObserver(sim->stats_.get());
  sim->limits_ = limits;
  if (sim->net_->fluid()) {
    sim->fluid_ = FluidPlant::create(*sim, diags);
    if (!sim->fluid_) return nullptr;
  }
  if (sim->net_->scripted() && !sim->makeEngine(diags)) return nullptr;
  return sim;
}

void Simulation::dropStatistics() {
  if (!stats_) return;
  kernel_->removeObserver(stats_.get());
  stats_.reset();
}

bool Simulation::makeEngine(core::Diagnostics& diags) {
  script::EngineCallbacks callbacks;
  callbacks.log = [this](const std::string& text) {
    if (log_echo_) std::cerr << "[t=" << core::formatTime(kernel_->now()) << "] " << text << '\n';
    if (trace_) trace_->event(kernel_->steps(), "log", "\"text\":" + core::jsonQuote(text));
  };
  callbacks.node_name = [this](net::NodeRef r) { return nodeName(r); };
  callbacks.plant = scene_.get();
  callbacks.physics = physics_.get();
  callbacks.spawn = [this](const scene::Node& templ, scene::Node& parent, std::optional<core::Vec3> at,
                           std::string& why) { return spawn(templ, parent, at, why); };
  callbacks.erase = [this](scene::Node& node) { deleteNode(node); };
  callbacks.reading = [this](scene::NodeHandle h) -> const sensors::Reading& {
    static const sensors::Reading none;
    return hub_ ? hub_->reading(h) : none;
  };
  callbacks.image = [this](scene::NodeHandle h, std::string& why) -> std::shared_ptr<const sensors::Image> {
    if (!hub_) {
      why = "the scene has no sensors";
      return nullptr;
    }
    return hub_->image(h, why);
  };
  if (parts_) {
    PartRun* parts = parts_.get();
    auto& access = callbacks.parts;
    access.find = [parts](const std::string& name, std::string& why) { return parts->find(name, why); };
    access.of_construct = [parts](const std::string& construct) { return parts->ofConstruct(construct); };
    access.owner = [parts](const std::string& construct) { return parts->ownerOf(construct); };
    access.uses = [parts](std::size_t owner) { return parts->usesOf(owner); };
    access.name = [parts](std::size_t i) { return parts->instances()[i].placed.name; };
    access.io = [parts](std::size_t i) {
      std::vector<std::pair<std::string, bool>> out;
      for (const auto& io : parts->instances()[i].spec->io) out.emplace_back(io.name, io.signal == IoSignal::Digital);
      return out;
    };
    access.params = [parts](std::size_t i) {
      std::vector<script::ScriptParam> out;
      const auto& inst = parts->instances()[i];
      for (const auto& param : inst.placed.params) {
        const auto declared = std::find_if(inst.spec->params.begin(), inst.spec->params.end(),
                                           [&](const Param& p) { return p.name == param.first; });
        out.push_back({param.first, param.second, declared != inst.spec->params.end() && declared->integer});
      }
      return out;
    };
    access.frame = [parts](std::size_t i) { return parts->instances()[i].frame; };
    access.read = [parts](std::size_t i, const std::string& io, std::string& why) { return parts->read(i, io, why); };
    access.write = [parts](std::size_t i, const std::string& io, double v, std::string& why) {
      return parts->write(i, io, v, why);
    };
  }
  script::EngineOptions options;
  options.timeout_s = limits_.timeout_s;
  options.memory_mib = limits_.memory_mib;
  options.angles = model_.settings.angles;
  for (const auto& p : model_.params) options.params.push_back({p.name, p.value, p.integer});
  engine_ = script::Engine::create(*net_, *kernel_, model_.path, options,
                                   std::move(callbacks), diags);
  if (!engine_) return false;
  kernel_->setHooks(engine_.get());
  return true;
}

bool Simulation::engineReady(std::string& error) {
  if (engine_) return true;
  core::Diagnostics diags;
  if (makeEngine(diags)) return true;
  error = diags.str();
  return false;
}

std::optional<bool> Simulation::evaluate(const std::string& expression, std::string& error) {
  if (!engineReady(error)) return std::nullopt;
  return engine_->evaluate(expression, error);
}

std::optional<double> Simulation::evaluateNumber(const std::string& expression, std::string& error) {
  if (!engineReady(error)) return std::nullopt;
  return engine_->evaluateNumber(expression, error);
}

bool Simulation::recordSignals(const std::vector<SignalSpec>& extra, core::Diagnostics& diags) {
  std::vector<SignalSpec> all = model_.signals;
  all.insert(all.end(), extra.begin(), extra.end());
  signals_ = SignalRecorder::create(*this, all, diags);
  if (signals_ && started_) signals_->sample();
  return signals_ != nullptr;
}

const SignalTable* Simulation::signals() const { return signals_ ? &signals_->table() : nullptr; }

void Simulation::recordLevels() {
  if (!net_->fluid()) return;
  std::vector<SignalSpec> specs;
  for (const auto& fp : net_->fluid()->places) {
    SignalSpec s;
    s.name = net_->placeName(fp.place);
    s.kind = SignalSpec::Kind::Place;
    s.target = s.name;
    specs.push_back(std::move(s));
  }
  core::Diagnostics diags;  // a continuous place's amount is always there to read
  levels_ = SignalRecorder::create(*this, specs, diags);
  if (levels_ && started_) levels_->sample();
}

const SignalTable* Simulation::levels() const { return levels_ ? &levels_->table() : nullptr; }

const sensors::Reading& Simulation::reading(scene::NodeHandle sensor) const {
  static const sensors::Reading none;
  return hub_ ? hub_->reading(sensor) : none;
}

void Simulation::keepCycles(std::unique_ptr<CyclePlan> plan) {
  if (cycles_ && cycles_->trips) kernel_->removeObserver(cycles_->trips.get());
  cycles_ = std::move(plan);
  if (cycles_ && cycles_->trips) kernel_->addObserver(cycles_->trips.get());
}

Simulation::~Simulation() {
  // the kernel must not call hooks of a dead engine
  if (kernel_) kernel_->setHooks(nullptr);
  engine_.reset();
}

scene::Node* Simulation::spawn(const scene::Node& templ, scene::Node& parent, std::optional<core::Vec3> at,
                               std::string& why) {
  if (!scene_) {
    why = "the model has no scene";
    return nullptr;
  }
  if (!parent.type().has_children) {
    why = "a " + parent.type().name + " takes no children";
    return nullptr;
  }
  // a copy goes where it is simulated: not into the template, nor into any template
  for (const scene::Node* p = &parent; p != nullptr; p = p->parent()) {
    if (p == &templ) {
      why = "'" + parent.path() + "' is the template or inside it";
      return nullptr;
    }
    if (p->is_template) {
      why = "'" + parent.path() + "' is inside template '" + p->path() + "', which is not simulated";
      return nullptr;
    }
  }
  // a fresh name: the template's, numbered
  const std::string base = templ.name().empty() ? "spawn" : templ.name();
  const std::string name = scene_->freshName(parent, base);
  // the copy keeps the Material in effect at the template: a copy of it goes first, where it
  // holds for the copy only, unless the same one is in effect where the copy goes
  const scene::Node* look = scene::materialAt(templ);
  const scene::Node* there = parent.lastChild(scene::NodeKind::Material);
  while (there != nullptr && there->is_template) there = there->previous(scene::NodeKind::Material);
  if (there == nullptr) there = scene::materialAt(parent);
  const bool carry = look != nullptr && look != there;
  // a node of its own that holds the copy: with `at`, to place what cannot place itself (a
  // Transform is moved itself), and to hold the material carried
  const bool placeable = templ.is(scene::NodeKind::Transform);
  scene::Node* home = &parent;
  if ((at && !placeable) || carry) {
    home = scene_->create(*scene_->types().find(scene::NodeKind::Transform), name, parent);
  }
  if (home != &parent) holders_.insert(home->handle());
  if (carry) scene_->copy(*look, *home);
  scene::Node* copy = scene_->copy(templ, *home, home == &parent ? name : templ.name());
  copy->is_template = false;  // a copy to simulate and draw
  scene::Node* top = home == &parent ? copy : home;
  if (at) {
    // the holder, when there is one, stands where its parent's frame is
    scene::Node* placed = placeable ? copy : home;
    const core::Vec3 local = parent.world.inverse().apply(*at);
    placed->setValue(scene::field::Transform::Translation, std::array<double, 3>{local.x, local.y, local.z});
  }
  // its bodies join the physics, its sensors are read from the next step on
  core::Diagnostics diags;
  if ((physics_ && !physics_->add(*top, diags)) || (hub_ && !hub_->add(*top, diags))) {
    why = diags.str();
    if (physics_) physics_->remove(*top);
    scene_->destroy(*top);
    return nullptr;
  }
  if (!physics_) scene::updateTransforms(*top);
  if (trace_) {
    trace_->event(kernel_->steps(), "spawn", "\"node\":" + core::jsonQuote(copy->path()) + ",\"from\":" +
                                                 core::jsonQuote(templ.path()));
  }
  return copy;
}

void Simulation::deleteNode(scene::Node& node) {
  if (!scene_ || !node.parent()) return;
  std::unordered_set<net::NodeRef> gone;
  scene::traverse(node, [&](scene::Node& n, const scene::TraversalState&) { gone.insert(n.handle()); });
  const std::string path = node.path();
  if (trace_) trace_->event(kernel_->steps(), "delete", "\"node\":" + core::jsonQuote(path));
  // tokens first (the trace names them while they still resolve), then the physics, the nodes
  kernel_->dropNodes([&](net::NodeRef r) { return gone.count(r) > 0; });
  scene::Node* up = node.parent();
  if (physics_) physics_->remove(node);
  if (hub_) hub_->forget(node);
  scene_->destroy(node);
  // the Transform spawn made to hold a copy goes with it, once it holds nothing but the
  // Material carried for it, so that spawning and deleting for ever does not grow the scene
  if (holders_.count(up->handle()) > 0 &&
      std::all_of(up->children().begin(), up->children().end(),
                  [](const auto& c) { return c->kind() == scene::NodeKind::Material; })) {
    holders_.erase(up->handle());
    if (physics_) physics_->remove(*up);
    scene_->destroy(*up);
  }
}

std::optional<RunOutcome> Simulation::scriptHalt() const {
  // a signal's expression that failed ends the run as a script's error does
  const bool signal_failed = signals_ && !signals_->error().empty();
  if (!signal_failed && (!engine_ || !engine_->halted())) return std::nullopt;
  RunOutcome o;
  o.steps = kernel_->steps();
  o.time = kernel_->now();
  if (signal_failed) {
    o.reason = StopReason::ScriptError;
    o.message = signals_->error();
    return o;
  }
  o.message = engine_->message();
  switch (engine_->halt()) {
    case script::Halt::Stop: o.reason = StopReason::Stopped; break;
    case script::Halt::Interrupted: o.reason = StopReason::Interrupted; break;
    case script::Halt::None:
    case script::Halt::Error:
    case script::Halt::Timeout: o.reason = StopReason::ScriptError; break;
  }
  return o;
}

std::optional<RunOutcome> Simulation::physicsHalt() const {
  if (!physics_fault_at_) return std::nullopt;
  RunOutcome o;
  o.steps = kernel_->steps();
  o.time = kernel_->now();
  o.reason = StopReason::PhysicsError;
  char at[64];
  std::snprintf(at, sizeof at, "%.9g", *physics_fault_at_);
  o.message = std::string("physics error at t = ") + at + " s: " + physics_->fault();
  return o;
}

void Simulation::stepPhysics() {
  if (!physics_ || physics_fault_at_) return;
  physics_->step(kernel_->dt());
  if (!physics_->fault().empty()) physics_fault_at_ = kernel_->now();
}

std::string Simulation::nodeName(net::NodeRef ref) const {
  if (scene_) {
    const scene::Node* node = scene_->resolve(ref);
    return node ? node->path() : "(deleted node)";
  }
  const auto names = net_->nodeNames();
  return ref < names.size() ? names[ref] : "#" + std::to_string(ref);
}

void Simulation::traceTo(std::ostream& out) {
  trace_out_ = &out;
  trace_ = std::make_unique<net::TraceWriter>(out, *net_, kernel_->dt(),
                                              [this](net::NodeRef r) { return nodeName(r); });
  kernel_->addObserver(trace_.get());
}

void Simulation::traceSensor(const sensors::Change& change) {
  if (!trace_) return;
  const scene::Node* sensor = scene_->resolve(change.sensor);
  if (!sensor) return;
  for (auto h : change.entered) {
    trace_->event(kernel_->steps(), "enter",
                  "\"sensor\":" + core::jsonQuote(sensor->path()) + ",\"item\":" + core::jsonQuote(nodeName(h)));
  }
  for (auto h : change.exited) {
    trace_->event(kernel_->steps(), "exit",
                  "\"sensor\":" + core::jsonQuote(sensor->path()) + ",\"item\":" + core::jsonQuote(nodeName(h)));
  }
}

void Simulation::readConditions() {
  if (!engine_) return;
  for (const auto& [ps, terms] : conditions_of_) {
    for (auto term : terms) kernel_->setCondition(term, engine_->condition(term, slot_sensor_[ps]));
  }
  stale_conditions_ = false;
}

void Simulation::sense(bool net_on) {
  if (!hub_) return;
  const auto& changes = hub_->update(kernel_->now());
  if (!net_on) {
    // the readings move on without the net: its conditions are read again when it is back
    stale_conditions_ = !conditions_of_.empty();
    for (const auto& change : changes) traceSensor(change);
    return;
  }
  const auto& scripts_of = [&](net::PlaceSlotId ps) { return net_->placeSlots()[ps].scripts; };
  for (const auto& change : changes) {
    const scene::Node* sensor = scene_->resolve(change.sensor);
    const bool region = sensor && sensor->kind() == scene::NodeKind::Region;
    traceSensor(change);
    auto it = sensor_slots_.find(change.sensor);
    if (it == sensor_slots_.end()) continue;
    for (auto ps : it->second) {
      // handlers: entered before exited, each in path order; on_change for value sensors
      if (engine_) {
        if (scripts_of(ps) & net::kOnEnter) {
          for (auto h : change.entered) engine_->sensorEvent(ps, net::ScriptKind::OnEnter, change.sensor, h);
        }
        if (scripts_of(ps) & net::kOnExit) {
          for (auto h : change.exited) engine_->sensorEvent(ps, net::ScriptKind::OnExit, change.sensor, h);
        }
        if (!region && (scripts_of(ps) & net::kOnChange)) {
          engine_->sensorEvent(ps, net::ScriptKind::OnChange, change.sensor);
        }
      }
    }
  }
  // on_sample while the sensor reports anything
  if (engine_) {
    for (const auto& [sensor, slots] : sensor_slots_) {
      if (!hub_->reading(sensor).active) continue;
      for (auto ps : slots) {
        if (scripts_of(ps) & net::kOnSample) engine_->sensorEvent(ps, net::ScriptKind::OnSample, sensor);
      }
    }
  }
  // then the arcs that read a changed sensor
  for (const auto& change : changes) {
    auto it = sensor_slots_.find(change.sensor);
    if (it == sensor_slots_.end() || !engine_) continue;
    for (auto ps : it->second) {
      auto c = conditions_of_.find(ps);
      if (c == conditions_of_.end()) continue;
      for (auto term : c->second) kernel_->setCondition(term, engine_->condition(term, change.sensor));
    }
  }
}

void Simulation::start() { start({}); }

void Simulation::start(const std::function<void()>& first) {
  if (started_) return;
  started_ = true;
  // time 0: the sensors' first readings (every one is a change), then the first firing phase
  sense(true);
  readConditions();
  if (fluid_) {
    fluid_->drive();
    fluid_->feed();
  }
  if (engine_ && engine_->halted() && engine_->halt() != script::Halt::Stop) return;
  if (first) first();
  firePhase();
  if (signals_) signals_->sample();
  if (levels_) levels_->sample();
}

void Simulation::replay(std::vector<net::TransitionId> sequence) {
  replay_ = std::move(sequence);
  replayed_ = 0;
  replay_blocked_.clear();
}

void Simulation::firePhase() {
  if (!replay_) {
    kernel_->fireEnabled();
    return;
  }
  replay_blocked_.clear();
  while (replayed_ < replay_->size()) {
    replay_blocked_ = kernel_->fire((*replay_)[replayed_]);
    if (!replay_blocked_.empty()) break;
    ++replayed_;
  }
}

void Simulation::note(const char* event, const std::string& fields) {
  if (trace_) trace_->event(kernel_->steps(), event, fields);
}

bool Simulation::hasCameras() const {
  bool any = false;
  if (scene_) {
    scene::traverse(scene_->root(), [&](scene::Node& n, const scene::TraversalState&) {
      any = any || n.kind() == scene::NodeKind::ColorCamera || n.kind() == scene::NodeKind::DepthCamera;
    }, {}, scene::Templates::Skip);
  }
  return any;
}

bool Simulation::dead() const {
  if (open_) return false;
  const bool net_dead = replay_ ? kernel_->occurringCount() == 0 && (replayed_ == replay_->size() || !replay_blocked_.empty())
                                : kernel_->dead();
  return net_dead && (!physics_ || physics_->awakeCount() == 0) && (!hub_ || !hub_->mayChange());
}

void Simulation::step() {
  if (!started_) start();
  kernel_->beginStep();
  if (parts_) parts_->atStepBoundary();
  // phase 1: the world advances; phase 2: the sensors feel it (not a world that failed)
  stepPhysics();
  if (physics_fault_at_) return;
  // phase 1 of the continuous part: the amounts flow over the same step, at the rates the
  // reads held from the step before; the plant fields they drive follow
  if (fluid_) {
    kernel_->advanceFluid();
    fluid_->drive();
  }
  sense(true);
  if (fluid_) fluid_->feed();
  // back from steps with the net off: the sensors' conditions as they are now
  if (stale_conditions_) readConditions();
  if (engine_ && engine_->halted() && engine_->halt() != script::Halt::Stop) return;
  kernel_->completeOccurrences();
  // a script that failed stops the run at the end of its phase
  if (engine_ && engine_->halted() && engine_->halt() != script::Halt::Stop) return;
  firePhase();
  if (signals_) signals_->sample();
  if (levels_) levels_->sample();
}

void Simulation::stepPlant() {
  kernel_->idleStep();
  if (parts_) parts_->atStepBoundary();  // a force holds the plant with the net off too
  stepPhysics();
  if (physics_fault_at_) return;
  sense(false);
}

RunOutcome Simulation::run(const RunLimits& limits, const ProgressFn& progress,
                           const std::atomic<bool>* interrupt) {
  const bool fresh = !started_;
  start();
  // a breakpoint may already hold after time 0's firing phase
  if (fresh && stop_check_ && !scriptHalt() && stop_check_()) {
    RunOutcome at_start;
    at_start.reason = StopReason::Breakpoint;
    if (trace_out_) trace_out_->flush();
    return at_start;
  }
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
    if (auto halt = scriptHalt()) {
      outcome = *halt;
      break;
    }
    if (auto halt = physicsHalt()) {
      outcome = *halt;
      break;
    }
    // a dead net ends the run unless the plant is still moving or a sensor may yet change
    if (dead()) {
      outcome.reason = StopReason::Dead;
      break;
    }
    const auto interrupted = [&] { return interrupt && interrupt->load(std::memory_order_relaxed); };
    if (interrupted()) {
      outcome.reason = StopReason::Interrupted;
      break;
    }
    if (before_step_) {
      before_step_();
      if (interrupted()) {
        outcome.reason = StopReason::Interrupted;
        break;
      }
    }
    step();
    if (auto halt = physicsHalt()) {
      outcome = *halt;
      break;
    }
    if (step_hook_) step_hook_();
    if (stop_check_ && !scriptHalt() && stop_check_()) {
      outcome.reason = StopReason::Breakpoint;
      break;
    }
    if (progress && (kernel_->steps() & 4095) == 0) progress(kernel_->steps() - first, total);
  }
  if (auto halt = scriptHalt(); halt && outcome.reason == StopReason::Until) outcome = *halt;
  if (progress) progress(kernel_->steps() - first, total);
  if ((outcome.reason == StopReason::ScriptError || outcome.reason == StopReason::Interrupted ||
       outcome.reason == StopReason::PhysicsError) &&
      trace_) {
    trace_->event(kernel_->steps(), "error", "\"message\":" + core::jsonQuote(outcome.message));
  }
  if (trace_out_) trace_out_->flush();
  if (stats_) stats_->finish(kernel_->steps());
  outcome.steps = kernel_->steps();
  outcome.time = kernel_->now();
  return outcome;
}

}  // namespace gdpn::model

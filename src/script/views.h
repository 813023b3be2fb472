#pragma once
// Internal: no promises. The Python objects scripts see (self, sim, slots, node tokens) and
// what they need of the engine.

#include <pybind11/pybind11.h>

#include <memory>
#include <string>

#include "gdpn/net/kernel.h"
#include "gdpn/script/engine.h"
#include "gdpn/physics/world.h"
#include "gdpn/scene/node.h"
#include "gdpn/sensors/hub.h"

namespace gdpn::script::detail {

/// What the views ask of the engine that made them.
class Context {
 public:
  virtual ~Context() = default;
  virtual const net::Net& netRef() const = 0;
  virtual net::Kernel& kernelRef() = 0;
  virtual std::string nodeName(net::NodeRef ref) const = 0;
  virtual pybind11::object transitionView(net::TransitionId t) = 0;
  virtual pybind11::object placeView(net::PlaceId p) = 0;
  virtual pybind11::object nodeView(net::NodeRef ref) = 0;
  virtual void log(const std::string& text) = 0;
  virtual void stop(const std::string& reason) = 0;
  /// The scene node behind a node token (null without a scene, or when it was deleted).
  virtual scene::Node* sceneNode(net::NodeRef ref) const = 0;
  /// The plant's physics, or null.
  virtual physics::World* physicsWorld() const = 0;
  /// The run's scene, or null.
  virtual scene::Scene* plant() const = 0;
  /// Copies `templ` under `parent` (at a world position if given); null and `why` on failure.
  virtual scene::Node* spawn(const scene::Node& templ, scene::Node& parent, std::optional<core::Vec3> at,
                             std::string& why) = 0;
  /// Deletes a node, its subtree and their tokens.
  virtual void erase(scene::Node& node) = 0;
  /// The unit of the angles scripts read and write.
  virtual scene::AngleUnit angles() const = 0;
  /// The reading of sensor node `sensor`.
  virtual const sensors::Reading& reading(scene::NodeHandle sensor) const = 0;
  /// The picture of camera sensor `sensor` (rendered now if not yet); null with `why`.
  virtual std::shared_ptr<const sensors::Image> image(scene::NodeHandle sensor, std::string& why) const = 0;
  /// `sim.params`: the model's parameters, read-only.
  virtual pybind11::object params() = 0;
  /// The run's parts (its functions empty when the model has none).
  virtual const PartAccess& parts() const = 0;

  /// False once the engine is gone; a view kept past that raises instead of crashing.
  std::shared_ptr<bool> alive = std::make_shared<bool>(true);
};

/// A view's handle on its engine.
struct Ref {
  Context* ctx = nullptr;
  std::shared_ptr<bool> alive;
  /// The engine; raises RuntimeError when it is gone.
  Context& get() const;
};

/// A handle on `ctx` for a new view.
inline Ref refTo(Context& ctx) { return {&ctx, ctx.alive}; }

/// The path of the sensor transition `t` sees in `slot` (or ""): the sensor slot of that name
/// on a place its arcs touch (the first arc's), unless its own arcs carry tokens in `slot`.
const std::string& sensorAround(const net::Net& net, net::TransitionId t, net::SlotId slot);

/// Registers the view classes with Python (once per process).
void registerViews();

pybind11::object makeTransitionView(Ref r, net::TransitionId t);
pybind11::object makePlaceView(Ref r, net::PlaceId p);
pybind11::object makeNodeView(Ref r, net::NodeRef ref);
pybind11::object makeSimView(Ref r);
pybind11::object makeSensorView(Ref r, scene::NodeHandle sensor);
/// `sim.params` over `values` (a dict of names to numbers): read by attribute or item, never set.
pybind11::object makeParamsView(pybind11::dict values);

}  // namespace gdpn::script::detail

#pragma once
// A scene, its physics and its sensors, made from the text of a model's scene section.

#include <gtest/gtest.h>

#include <memory>
#include <string>

#include "gdpn/model/model.h"
#include "gdpn/sensors/hub.h"

namespace gdpn::sensors {

struct Rig {
  std::unique_ptr<scene::Scene> scene;
  std::unique_ptr<physics::World> world;
  std::unique_ptr<Hub> hub;
  /// `dir`: where the scene's files are; `seed`: the noise's.
  explicit Rig(const std::string& scene_text, std::uint64_t seed = 1, const std::string& dir = ".") {
    core::Diagnostics diags;
    auto m = model::parseModel("gdpn: 1\nscene:\n" + scene_text, dir + "/rig.gdpn.yaml", diags);
    EXPECT_TRUE(m) << diags.str();
    scene = m->scene->clone();
    world = physics::World::create(*scene, dir, seed, diags);
    EXPECT_TRUE(world) << diags.str();
    hub = std::make_unique<Hub>(*scene, world.get(), seed);
    hub->setModelDir(dir);
  }
  scene::NodeHandle handle(const char* path) const { return scene->find(path)->handle(); }
  /// Steps the world and the sensors `n` times by `dt` seconds from `t`; returns the new time.
  double run(double t, int n, double dt) {
    for (int i = 0; i < n; ++i) {
      world->step(dt);
      t += dt;
      hub->update(t);
    }
    return t;
  }
};

}  // namespace gdpn::sensors

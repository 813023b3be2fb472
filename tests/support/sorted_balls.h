#pragma once
// Test support: where the sorting device's balls (examples/sorting and sorting/coloured) lie
// after a run, checked ball by ball.

#include <gtest/gtest.h>

#include <utility>

#include "gdpn/model/simulation.h"
#include "gdpn/scene/fields.h"

namespace gdpn::testing {

/// Expects 50 balls under `falling`, each landed on the side of its colour (its group's
/// material says which: blue left, -y; red right, +y); the numbers of blue and red balls.
inline std::pair<int, int> sortedBalls(const model::Simulation& sim) {
  int blue = 0, red = 0;
  const auto* falling = sim.plant()->find("falling");
  EXPECT_NE(falling, nullptr);
  if (!falling) return {blue, red};
  EXPECT_EQ(falling->children().size(), 50u);
  for (const auto& group : falling->children()) {
    const bool is_blue = group->child("#0")->vec3(scene::field::Material::Diffuse).z > 0.5;
    const auto* ball = group->child("ball");
    EXPECT_NE(ball, nullptr) << group->path();
    if (!ball) continue;
    EXPECT_LT(ball->world.position.z, 0.3) << group->path() << " has not landed";
    if (is_blue) {
      EXPECT_LT(ball->world.position.y, -0.05) << group->path() << " is blue";
      ++blue;
    } else {
      EXPECT_GT(ball->world.position.y, 0.05) << group->path() << " is red";
      ++red;
    }
  }
  return {blue, red};
}

}  // namespace gdpn::testing

// Physics cost: 100 boxes on a conveyor through gdpn against the same scene in raw ODE (same
// settings), 1,000 resting boxes with auto-disable on and off, and 20 boxes on a belt among
// 100 to 10,000 static pillars (the broad phase: the step should not grow with them).
// Record results in docs/performance.md.

#include <benchmark/benchmark.h>
#include <ode/ode.h>

#include <cmath>

#include "gdpn/core/text.h"
#include "gdpn/model/model.h"
#include "gdpn/physics/world.h"

namespace {

using namespace gdpn;

constexpr double kDt = 0.002;  // 2 ms

/// A scene text: a belt (or ground) and `n` boxes of 0.1 m and 0.5 kg in a grid on it.
std::string boxes(int n, bool conveyor, bool auto_disable) {
  std::string t = "gdpn: 1\nscene:\n  - World: {auto_disable: " + std::string(auto_disable ? "true" : "false") +
                  "}\n  - Transform:\n      children:\n";
  if (conveyor) t += "        - Conveyor: {speed: 1}\n";
  t += "        - Cube: {size: [400, 40, 0.1]}\n";
  const int side = static_cast<int>(std::ceil(std::sqrt(n)));
  for (int i = 0; i < n; ++i) {
    const double x = (i % side) * 0.25, y = (i / side) * 0.25 - side * 0.125;
    t += "  - Transform: {translation: [" + core::formatDouble(x) + ", " + core::formatDouble(y) +
         ", 0.1], children: [{Body: {mass: 0.5, children: [{Cube: {size: [0.1, 0.1, 0.1]}}]}}]}\n";
  }
  return t;
}

struct GdpnPlant {
  std::unique_ptr<scene::Scene> scene;
  std::unique_ptr<physics::World> world;
  explicit GdpnPlant(const std::string& text) {
    core::Diagnostics diags;
    auto m = model::parseModel(text, "bench.gdpn.yaml", diags);
    scene = m->scene->clone();
    world = physics::World::create(*scene, ".", 1, diags);
  }
};

void BM_ConveyorGdpn(benchmark::State& state) {
  GdpnPlant p(boxes(100, true, true));
  for (auto _ : state) p.world->step(kDt);
  state.counters["realtime_x"] = benchmark::Counter(static_cast<double>(state.iterations()) * kDt,
                                                    benchmark::Counter::kIsRate);
}
BENCHMARK(BM_ConveyorGdpn)->Unit(benchmark::kMicrosecond);

// ---- the same scene in raw ODE, with gdpn's settings ----

struct RawOde {
  dWorldID world;
  dSpaceID space;
  dJointGroupID contacts;
  dGeomID belt;

  RawOde() {
    dInitODE2(0);
    dAllocateODEDataForThread(dAllocateMaskAll);
    dRandSetSeed(1);
    world = dWorldCreate();
    space = dHashSpaceCreate(nullptr);
    contacts = dJointGroupCreate(0);
    dWorldSetGravity(world, 0, 0, -9.81);
    dWorldSetERP(world, 0.2);
    dWorldSetCFM(world, 1e-5);
    dWorldSetQuickStepNumIterations(world, 40);
    dWorldSetAutoDisableFlag(world, 1);
    dWorldSetContactSurfaceLayer(world, 0.001);
    belt = dCreateBox(space, 400, 40, 0.1);
    const int side = 10;
    for (int i = 0; i < 100; ++i) {
      dBodyID b = dBodyCreate(world);
      dMass m;
      dMassSetBox(&m, 1000, 0.1, 0.1, 0.1);
      dMassAdjust(&m, 0.5);
      dBodySetMass(b, &m);
      dBodySetPosition(b, (i % side) * 0.25, (i / side) * 0.25 - side * 0.125, 0.1);
      dGeomID g = dCreateBox(space, 0.1, 0.1, 0.1);
      dGeomSetBody(g, b);
    }
  }
  ~RawOde() {
    dJointGroupDestroy(contacts);
    dSpaceDestroy(space);
    dWorldDestroy(world);
  }
  static void near(void* data, dGeomID o1, dGeomID o2) {
    auto& self = *static_cast<RawOde*>(data);
    dBodyID b1 = dGeomGetBody(o1), b2 = dGeomGetBody(o2);
    if (!b1 && !b2) return;
    dContact c[8];
    const int n = dCollide(o1, o2, 8, &c[0].geom, sizeof(dContact));
    for (int i = 0; i < n; ++i) {
      c[i].surface.mode = dContactBounce | dContactApprox1;
      c[i].surface.mu = 0.8;
      c[i].surface.bounce = 0;
      c[i].surface.bounce_vel = 0.01;
      if (o1 == self.belt || o2 == self.belt) {
        c[i].surface.mode |= dContactFDir1 | dContactMotion1;
        c[i].fdir1[0] = 1;
        c[i].fdir1[1] = 0;
        c[i].fdir1[2] = 0;
        c[i].surface.motion1 = o1 == self.belt ? -1.0 : 1.0;
      }
      dJointAttach(dJointCreateContact(self.world, self.contacts, &c[i]), b1, b2);
    }
  }
  void step() {
    dSpaceCollide(space, this, &near);
    dWorldQuickStep(world, kDt);
    dJointGroupEmpty(contacts);
  }
};

void BM_ConveyorRawOde(benchmark::State& state) {
  RawOde ode;
  for (auto _ : state) ode.step();
  state.counters["realtime_x"] = benchmark::Counter(static_cast<double>(state.iterations()) * kDt,
                                                    benchmark::Counter::kIsRate);
}
BENCHMARK(BM_ConveyorRawOde)->Unit(benchmark::kMicrosecond);

// 1,000 boxes at rest on the ground, with auto-disable on (1) and off (0)
void BM_RestingBoxes(benchmark::State& state) {
  GdpnPlant p(boxes(1000, false, state.range(0) != 0));
  for (int i = 0; i < 1500; ++i) p.world->step(kDt);  // let them settle (and sleep)
  for (auto _ : state) p.world->step(kDt);
  state.counters["steps_per_s"] = benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
  state.counters["awake"] = static_cast<double>(p.world->awakeCount());
}
BENCHMARK(BM_RestingBoxes)->Arg(1)->Arg(0)->Unit(benchmark::kMicrosecond);

// 20 boxes riding a belt through a hall of `n` static pillars (0.2 m, 1 m apart, beside the
// belt): the pillars never move, so the step's cost should not grow with their number
void BM_StaticPillars(benchmark::State& state) {
  const auto n = static_cast<int>(state.range(0));
  std::string t = boxes(20, true, true);
  const int side = static_cast<int>(std::ceil(std::sqrt(n)));
  for (int i = 0; i < n; ++i) {
    const double x = (i % side) * 1.0, y = 25.0 + (i / side) * 1.0;
    t += "  - Transform: {translation: [" + core::formatDouble(x) + ", " + core::formatDouble(y) +
         ", 1], children: [{Cube: {size: [0.2, 0.2, 2]}}]}\n";
  }
  GdpnPlant p(t);
  for (auto _ : state) p.world->step(kDt);
  state.counters["steps_per_s"] = benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_StaticPillars)->Arg(100)->Arg(1000)->Arg(10000)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();

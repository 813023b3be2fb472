// The net and the plant together: node tokens are scene nodes, scripts drive joints and
// bodies, and a run with physics is reproducible bit for bit.

#include <gtest/gtest.h>

#include <sstream>

#include "gdpn/core/text.h"
#include "gdpn/model/report.h"
#include "gdpn/model/simulation.h"
#include "gdpn/scene/actions.h"
#include "support/sim_helpers.h"

namespace gdpn::model {
namespace {

std::unique_ptr<Simulation> open(const std::string& text, core::Diagnostics& diags) {
  auto m = parseModel(text, "plant.gdpn.yaml", diags);
  return m ? Simulation::create(*m, diags) : nullptr;
}

const std::string kArm = R"Y(gdpn: 1
settings: {dt: 0.01, until: 2}
scene:
  - Joint:
      name: shoulder
      kind: hinge
      axis1: [0, 0, 1]
      children:
        - Body:
            name: arm
            mass: 1
            children: [{Transform: {translation: [0.5, 0, 0], children: [{Cube: {size: [1, 0.1, 0.1]}}]}}]
pages:
  main:
    places:
      idle: {tokens: {d0: [shoulder]}}
      done: {}
    transitions:
      turn:
        duration: 1
        pre_fire: |
          self.d0.vel1 = 90
          self.d0.fmax1 = 100
        post_fire: |
          self.d0.vel1 = 0
          sim.log("turned", round(self.d0[0].angle))
    arcs:
      - {from: idle, to: turn, weight: {d0: 1}}
      - {from: turn, to: done, weight: {d0: 1}}
)Y";

TEST(Plant, ANetDrivesAJoint) {
  // pre_fire sets the motor to 90 deg/s; post_fire stops it after 1 s: the arm turned 90 deg
  core::Diagnostics diags;
  auto sim = open(kArm, diags);
  ASSERT_TRUE(sim) << diags.str();
  std::ostringstream trace;
  sim->traceTo(trace);
  sim->run({});
  const auto* shoulder = sim->plant()->find("shoulder");
  ASSERT_NE(shoulder, nullptr);
  EXPECT_NEAR(sim->physics()->jointPosition(*shoulder), core::radians(90), core::radians(2));
  EXPECT_NE(trace.str().find("\"text\":\"turned 90\""), std::string::npos) << trace.str();
  // the token kept its identity: the joint is on 'done' now
  EXPECT_NE(trace.str().find("\"place\":\"main/done\",\"slot\":\"d0\",\"count\":1,\"tokens\":[\"shoulder\"]"),
            std::string::npos);
}

TEST(Plant, AScriptSwitchingAJointToPositionControlTakesEffect) {
  // the physics keeps a joint's control mode; a script that changes it is heard at once:
  // turning at 90 deg/s for 1 s, then switched to hold 30 deg, the arm comes back to 30
  std::string text = kArm;
  const std::string old_post = R"(        post_fire: |
          self.d0.vel1 = 0
)";
  const std::string new_post = R"(        post_fire: |
          self.d0.control = "position"
          self.d0.target1 = 30
)";
  text.replace(text.find(old_post), old_post.size(), new_post);
  text.replace(text.find("until: 2"), 8, "until: 4");
  core::Diagnostics diags;
  auto sim = open(text, diags);
  ASSERT_TRUE(sim) << diags.str();
  sim->run({});
  const auto* shoulder = sim->plant()->find("shoulder");
  EXPECT_NEAR(sim->physics()->jointPosition(*shoulder), core::radians(30), core::radians(1));
  // a word the field does not take is refused where the script wrote it
  text.replace(text.find("\"position\""), 10, "\"positon\"");
  auto bad = open(text, diags);
  ASSERT_TRUE(bad) << diags.str();
  const auto outcome = bad->run({});
  EXPECT_EQ(outcome.reason, StopReason::ScriptError);
  EXPECT_NE(outcome.message.find("'control' is one of velocity, position, got \"positon\" (did you mean 'position'?)"),
            std::string::npos)
      << outcome.message;
}

TEST(Plant, ScriptsSeeNodeFieldsTreeAndBodies) {
  core::Diagnostics diags;
  auto sim = open(R"Y(gdpn: 1
settings: {dt: 0.01, until: 0.5}
scene:
  - World: {auto_disable: false}
  - Transform:
      name: cell
      translation: [0, 0, 5]
      children:
        - Body: {name: box, mass: 2, children: [{Cube: {name: shape, size: [0.2, 0.2, 0.2]}}]}
        - Body: {name: lid, mass: 1, children: [{Sphere: {radius: 0.1}}]}
pages:
  main:
    places:
      p: {tokens: {d0: [cell/box]}}
    transitions:
      look:
        pre_fire: |
          box = self.d0[0]
          sim.log(box.type, box.mass, box.parent.name, [c.name for c in box.children], box.next.name)
          sim.log(box.find("shape").size, box.find("../lid").name, box.position)
          box.mass = 3
          sim.log(box.mass, box.linear_damping)
          box.set_velocity((1, 0, 0))
          box.attach(box.next)
          try:
              box.mas = 1
          except AttributeError as e:
              sim.log("error:", e)
          try:
              box.mass = -1
          except ValueError as e:
              sim.log("error:", e)
    arcs:
      - {from: p, to: look, weight: {d0: 1}}
      - {from: look, to: p, weight: {d0: 1}}
)Y", diags);
  ASSERT_TRUE(sim) << diags.str();
  std::ostringstream trace;
  sim->traceTo(trace);
  sim->step();
  const std::string t = trace.str();
  EXPECT_NE(t.find("\"text\":\"Body 2.0 cell ['cell/box/shape'] cell/lid\""), std::string::npos) << t;
  EXPECT_NE(t.find("\"text\":\"(0.2, 0.2, 0.2) cell/lid (0.0, 0.0, 5.0)\""), std::string::npos) << t;
  EXPECT_NE(t.find("\"text\":\"3.0 0.0\""), std::string::npos) << t;
  EXPECT_NE(t.find("a Body has no field 'mas' (did you mean 'mass'?)"), std::string::npos) << t;
  EXPECT_NE(t.find("'mass' must be at least 0, got -1"), std::string::npos) << t;
  // the velocity and the attachment took effect: both move along +x together
  sim->run({});
  const auto* box = sim->plant()->find("cell/box");
  const auto* lid = sim->plant()->find("cell/lid");
  EXPECT_GT(box->world.position.x, 0.3);
  EXPECT_NEAR(lid->world.position.x - box->world.position.x, 0.0, 1e-3);
  EXPECT_NEAR(lid->world.position.z - box->world.position.z, 0.0, 1e-3);
}

TEST(Plant, ANodeTokenMustNameASceneNode) {
  core::Diagnostics diags;
  EXPECT_FALSE(open(R"Y(gdpn: 1
scene:
  - Cube: {name: box}
pages:
  main:
    places:
      p: {tokens: {d0: [box, crate]}}
)Y", diags));
  EXPECT_NE(diags.str().find("plant.gdpn.yaml:7:20: error: node token 'crate' names no node of the scene"),
            std::string::npos)
      << diags.str();
}

/// 20 boxes dropped onto the ground from staggered heights; the trace and final positions.
std::string fallingBoxes() {
  std::string text = "gdpn: 1\nsettings: {dt: 0.005, until: 2, seed: 11}\nscene:\n  - Plane: {}\n";
  for (int i = 0; i < 20; ++i) {
    const double x = (i % 5) * 0.23 - 0.4, y = (i / 5) * 0.21 - 0.3, z = 0.5 + 0.13 * i;
    text += "  - Transform:\n      translation: [" + core::formatDouble(x) + ", " + core::formatDouble(y) + ", " +
            core::formatDouble(z) + "]\n      rotation: [1, 1, 0, " + std::to_string(7 * i) +
            "]\n      children: [{Body: {name: box" + std::to_string(i) +
            ", mass: 0.5, children: [{Cube: {size: [0.2, 0.2, 0.2]}}]}}]\n";
  }
  core::Diagnostics diags;
  auto sim = open(text, diags);
  EXPECT_TRUE(sim) << diags.str();
  if (!sim) return {};
  std::ostringstream out;
  sim->traceTo(out);
  sim->run({});
  for (int i = 0; i < 20; ++i) {
    const auto* box = sim->plant()->find("#" + std::to_string(i + 1) + "/box" + std::to_string(i));
    const auto p = box->world.position;
    const auto q = box->world.rotation;
    out << core::formatDouble(p.x) << ' ' << core::formatDouble(p.y) << ' ' << core::formatDouble(p.z) << ' '
        << core::formatDouble(q.w) << ' ' << core::formatDouble(q.x) << '\n';
  }
  return out.str();
}

TEST(Plant, TwentyFallingBoxesGiveTheSameRunBitForBit) {
  const std::string first = fallingBoxes();
  EXPECT_EQ(first, fallingBoxes());
  // they landed: every box ends near the ground
  std::istringstream lines(first);
  double x = 0, y = 0, z = 0, w = 0, qx = 0;
  int n = 0;
  while (lines >> x >> y >> z >> w >> qx) {
    EXPECT_LT(z, 0.5) << "box " << n;
    ++n;
  }
  EXPECT_EQ(n, 20);
  EXPECT_EQ(core::fnv1a(first), 0x921ceef2f9ba7c93ULL) << std::hex << core::fnv1a(first);
}

}  // namespace
}  // namespace gdpn::model

namespace gdpn::model {
namespace {

TEST(Plant, EachInstanceGetsItsOwnCopyOfItsPageTypesScene) {
  // a station owns a pusher body and a box on a hinge; two instances stand 3 m apart
  core::Diagnostics diags;
  auto sim = open(R"Y(gdpn: 1
settings: {dt: 0.01, until: 1}
scene:
  - World: {gravity: [0, 0, 0]}
pages:
  line:
    instances:
      stationA: {type: station}
      stationB: {type: station, translation: [3, 0, 0], rotation: [0, 0, 1, 90]}
page_types:
  station:
    places:
      devices: {tokens: {d0: [rail/pusher]}}
      pushed: {}
    transitions:
      push:
        pre_fire: "self.d0.set_velocity((0, 1, 0))"
    arcs:
      - {from: devices, to: push, weight: {d0: 1}}
      - {from: push, to: pushed, weight: {d0: 1}}
    scene:
      - Transform:
          name: rail
          translation: [1, 0, 0]
          children:
            - Body: {name: pusher, mass: 1, children: [{Cube: {size: [0.1, 0.1, 0.1]}}]}
)Y", diags);
  ASSERT_TRUE(sim) << diags.str();
  const auto* a = sim->plant()->find("stationA/rail/pusher");
  const auto* b = sim->plant()->find("stationB/rail/pusher");
  ASSERT_NE(a, nullptr);
  ASSERT_NE(b, nullptr);
  // placed by the instance: B is turned a quarter about z and moved 3 m along x
  EXPECT_NEAR(a->world.position.x, 1.0, 1e-9);
  EXPECT_NEAR(b->world.position.x, 3.0, 1e-9);
  EXPECT_NEAR(b->world.position.y, 1.0, 1e-9);
  // each instance's token is its own pusher: both pushed, each its own body
  sim->run({});
  EXPECT_NEAR(sim->physics()->velocity(*a).y, 1.0, 1e-6);
  EXPECT_NEAR(sim->physics()->velocity(*b).y, 1.0, 1e-6);
  EXPECT_NEAR(a->world.position.y, 1.0, 0.02);
  EXPECT_NE(a, b);
}

TEST(Plant, AnInstanceCannotTakeAPlaceInTheSceneThatIsTaken) {
  core::Diagnostics diags;
  EXPECT_FALSE(open(R"Y(gdpn: 1
scene:
  - Group: {name: stationA}
pages:
  line:
    instances:
      stationA: station
page_types:
  station:
    scene:
      - Cube: {}
)Y", diags));
  EXPECT_NE(diags.str().find("plant.gdpn.yaml:7:7: error: instance 'stationA' places its machine at 'stationA', but "
                             "the scene already has a node there"),
            std::string::npos)
      << diags.str();
}

}  // namespace
}  // namespace gdpn::model

namespace gdpn::model {
namespace {

TEST(Plant, ScriptsSpawnCopiesAndDeleteNodes) {
  core::Diagnostics diags;
  auto sim = open(R"Y(gdpn: 1
settings: {dt: 0.01, until: 2}
scene:
  - Plane: {}
  - Transform:
      name: store
      translation: [50, 0, 0.05]
      children: [{Body: {name: box, mass: 0.5, children: [{Cube: {size: [0.1, 0.1, 0.1]}}]}}]
  - Group: {name: area}
  - Group:
      name: pile
      children:
        - Transform: {name: spot1, translation: [-5, 0, 0.05], children: [{Body: {name: crate1, children: [{Cube: {size: [0.1, 0.1, 0.1]}}]}}]}
        - Transform: {name: spot2, translation: [-6, 0, 0.05], children: [{Body: {name: crate2, children: [{Cube: {size: [0.1, 0.1, 0.1]}}]}}]}
pages:
  main:
    places:
      feed: {tokens: 3}
      boxes: {slots: {d0: node}}
      crates: {tokens: {d0: [pile/spot1/crate1, pile/spot2/crate2]}}
      once: {tokens: 1}
    transitions:
      make:
        duration: 0.2
        pre_fire: |
          box = sim.node("area").spawn("store/box", at=(sim.step * 0.01, 0, 0.5))
          sim.place("main/boxes").d0.add(box)
      scrap:
        pre_fire: 'sim.place("main/crates").d0[0].delete()'
    arcs:
      - feed -> make
      - once -> scrap
)Y", diags);
  ASSERT_TRUE(sim) << diags.str();
  std::ostringstream trace;
  sim->traceTo(trace);
  const auto bodies_before = sim->physics()->bodyCount();
  const auto outcome = sim->run({});
  ASSERT_NE(outcome.reason, StopReason::ScriptError) << outcome.message;  // it ends dead: all asleep
  // three copies, each a body that fell onto the ground, each a token on 'boxes'
  const auto* area = sim->plant()->find("area");
  ASSERT_EQ(area->children().size(), 3u);
  const auto* first = sim->plant()->find("area/box_1/box");
  ASSERT_NE(first, nullptr);
  EXPECT_NEAR(first->world.position.z, 0.05, 0.01);
  const auto boxes = sim->net().findPlace("main/boxes");
  EXPECT_EQ(sim->kernel().placeTokens(boxes.value()), 3);
  // the deleted crate left the scene, the physics and its place; the trace says so
  EXPECT_EQ(sim->plant()->find("pile/spot1/crate1"), nullptr);
  EXPECT_NE(sim->plant()->find("pile/spot1"), nullptr);
  EXPECT_EQ(sim->physics()->bodyCount(), bodies_before + 3 - 1);
  const auto crates = sim->net().findPlace("main/crates");
  EXPECT_EQ(sim->kernel().placeTokens(crates.value()), 1);
  const std::string t = trace.str();
  EXPECT_NE(t.find("\"ev\":\"delete\",\"node\":\"pile/spot1/crate1\""), std::string::npos) << t;
  EXPECT_NE(t.find("\"ev\":\"remove\",\"place\":\"main/crates\",\"slot\":\"d0\",\"count\":1,\"tokens\":"
                   "[\"pile/spot1/crate1\"]"),
            std::string::npos)
      << t;
  EXPECT_NE(t.find("\"ev\":\"spawn\",\"node\":\"area/box_1/box\",\"from\":\"store/box\""), std::string::npos) << t;
}

}  // namespace
}  // namespace gdpn::model

namespace gdpn::model {
namespace {

TEST(PlantExample, TheFeederFillsTheBeltAndTheArmKeepsItsCycle) {
  auto sim = testing::openModelFile("examples/plant/feeder/feeder.gdpn.yaml");
  ASSERT_TRUE(sim);
  const auto outcome = sim->run({});
  ASSERT_EQ(outcome.reason, StopReason::Until) << outcome.message;
  // ten boxes spawned; the belt carried the first to its end, where it fell off
  EXPECT_EQ(sim->plant()->find("boxes")->children().size(), 10u);
  const auto* first = sim->plant()->find("boxes/box_1/box");
  ASSERT_NE(first, nullptr);
  EXPECT_GT(first->world.position.x, 4.5);
  EXPECT_LT(first->world.position.z, 0.3);
  // the net's cycles are what its durations say
  const auto r = makeReport(*sim, outcome);
  for (const auto& t : r.transitions) {
    if (t.name == "main/swing_out") {
      EXPECT_DOUBLE_EQ(t.max_cycle, 2.0);
    }
    if (t.name == "main/feed") {
      EXPECT_DOUBLE_EQ(t.mean_cycle, 1.5);
    }
  }
}

}  // namespace
}  // namespace gdpn::model

namespace gdpn::model {
namespace {

// A template is kept to be copied: not simulated; its copies are ordinary nodes that keep
// the template's material and carry its user data, which scripts read and set.
TEST(Plant, TemplatesAreCopiedNotSimulatedAndCopiesKeepTheirLookAndData) {
  core::Diagnostics diags;
  auto sim = open(R"Y(gdpn: 1
settings: {dt: 0.01, until: 1}
scene:
  - Material: {diffuse: [0.4, 0.4, 0.4]}
  - Plane: {}
  - Group:
      name: store
      template: true
      children:
        - Material: {diffuse: [0.9, 0.6, 0.2], friction: 0.3}
        - Body: {name: box, mass: 0.5, data: {kind: crate, code: "007", weight: 2.0, sizes: [1, 2]}, children: [{Cube: {size: [0.1, 0.1, 0.1]}}]}
        - Transform: {name: spot, children: [{Body: {name: ball, children: [{Sphere: {radius: 0.05}}]}}]}
  - Group: {name: area}
pages:
  main:
    places:
      feed: {tokens: 2}
      seen: {}
    transitions:
      make:
        duration: 0.2
        pre_fire: |
          box = sim.node("area").spawn("store/box", at=(sim.step * 0.01, 0, 0.5))
          assert not box.template and sim.node("store").template
          assert (box.data.kind, box.data["code"], box.data.weight, box.data.sizes) == ("crate", "007", 2.0, [1.0, 2.0])
          box.data.order = sim.step
          box.data["fresh"] = True
          del box.data.sizes
          assert "sizes" not in box.data and box.data.get("sizes", 5) == 5 and len(box.data) == 5
          assert list(box.data) == ["kind", "code", "weight", "order", "fresh"], list(box.data)
          sim.log(repr(box.data))
    arcs:
      - feed -> make
      - make -> seen
)Y", diags);
  ASSERT_TRUE(sim) << diags.str();
  std::ostringstream trace;
  sim->traceTo(trace);
  // the template's two bodies are not in the physics; nothing else is
  EXPECT_EQ(sim->physics()->bodyCount(), 0u);
  const auto outcome = sim->run({});
  ASSERT_NE(outcome.reason, StopReason::ScriptError) << outcome.message;
  EXPECT_EQ(sim->physics()->bodyCount(), 2u);
  // the template stayed where it was, untouched by gravity
  const auto* templ = sim->plant()->find("store/box");
  EXPECT_FALSE(templ->dynamic_pose.has_value());
  // each copy: a Transform holding a copy of the template's material, then the box
  const auto* holder = sim->plant()->find("area/box_1");
  ASSERT_NE(holder, nullptr);
  ASSERT_EQ(holder->children().size(), 2u);
  const auto& look = *holder->children()[0];
  ASSERT_EQ(look.kind(), scene::NodeKind::Material);
  EXPECT_EQ(look.vec3(scene::field::Material::Diffuse).x, 0.9);
  EXPECT_EQ(look.number(scene::field::Material::Friction), 0.3);
  const auto* box = sim->plant()->find("area/box_1/box");
  ASSERT_NE(box, nullptr);
  EXPECT_EQ(scene::materialAt(*box), &look);
  EXPECT_FALSE(box->is_template);
  EXPECT_NEAR(box->world.position.z, 0.05, 0.01);  // simulated: it fell onto the ground
  // its data: the template's, then the script's
  ASSERT_NE(box->datum("order"), nullptr);
  EXPECT_EQ(std::get<std::int64_t>(*box->datum("order")), 0);
  EXPECT_EQ(std::get<bool>(*box->datum("fresh")), true);
  EXPECT_EQ(box->datum("sizes"), nullptr);
  EXPECT_EQ(templ->data.size(), 4u);  // the template's own data is unchanged
  const auto lines = testing::logLines(trace.str());
  ASSERT_EQ(lines.size(), 2u);
  EXPECT_EQ(lines[0], "{'kind': 'crate', 'code': '007', 'weight': 2.0, 'order': 0, 'fresh': True}");
}

TEST(Plant, ASpawnedCopyNeedsNoHolderWhereItsMaterialIsInEffect) {
  core::Diagnostics diags;
  auto sim = open(R"Y(gdpn: 1
settings: {dt: 0.01, until: 0.05}
scene:
  - Material: {diffuse: [0.9, 0.6, 0.2]}
  - Group: {name: store, template: true, children: [{Body: {name: box, children: [{Cube: {size: [0.1, 0.1, 0.1]}}]}}]}
  - Group: {name: area}
pages:
  main:
    places: {feed: {tokens: 1}}
    transitions:
      make: {pre_fire: 'sim.node("area").spawn("store/box")'}
    arcs: [feed -> make]
)Y", diags);
  ASSERT_TRUE(sim) << diags.str();
  (void)sim->run({});
  // the same material is in effect at the template and in 'area': the copy goes in as it is
  const auto* area = sim->plant()->find("area");
  ASSERT_EQ(area->children().size(), 1u);
  EXPECT_EQ(area->children()[0]->kind(), scene::NodeKind::Body);
  EXPECT_EQ(area->children()[0]->name(), "box_1");
}

TEST(Plant, AMissingDatumIsAKeyErrorNamingTheNodeAndItsData) {
  core::Diagnostics diags;
  auto sim = open(R"Y(gdpn: 1
settings: {dt: 0.01, until: 1}
scene:
  - Body: {name: box, data: {kind: crate, order: 3}, children: [{Cube: {size: [0.1, 0.1, 0.1]}}]}
pages:
  main:
    places: {p: {tokens: {d0: [box]}}, q: {}}
    transitions:
      t: {pre_fire: 'print(self.d0[0].data.kinds)'}
    arcs: [{from: p, to: t, weight: {d0: 1}}, {from: t, to: q, weight: {d0: 1}}]
)Y", diags);
  ASSERT_TRUE(sim) << diags.str();
  const auto outcome = sim->run({});
  ASSERT_EQ(outcome.reason, StopReason::ScriptError);
  EXPECT_NE(outcome.message.find("node box has no datum 'kinds' (did you mean 'kind'?); it has kind, order"),
            std::string::npos)
      << outcome.message;
}

TEST(Plant, ADatumOfAnotherKindIsATypeError) {
  core::Diagnostics diags;
  auto sim = open(R"Y(gdpn: 1
settings: {dt: 0.01, until: 1}
scene:
  - Body: {name: box, children: [{Cube: {size: [0.1, 0.1, 0.1]}}]}
pages:
  main:
    places: {p: {tokens: {d0: [box]}}, q: {}}
    transitions:
      t: {pre_fire: 'self.d0[0].data.where = {"x": 1}'}
    arcs: [{from: p, to: t, weight: {d0: 1}}, {from: t, to: q, weight: {d0: 1}}]
)Y", diags);
  ASSERT_TRUE(sim) << diags.str();
  const auto outcome = sim->run({});
  ASSERT_EQ(outcome.reason, StopReason::ScriptError);
  EXPECT_NE(outcome.message.find("TypeError: datum 'where' of node box is a bool, an int, a finite float, a str or a "
                                 "list of numbers, got dict {'x': 1}"),
            std::string::npos)
      << outcome.message;
}

}  // namespace
}  // namespace gdpn::model

namespace gdpn::model {
namespace {

TEST(Plant, ACopyGoesNeitherIntoItsTemplateNorIntoAnyTemplate) {
  for (const char* into : {"store", "store/box", "spare"}) {
    SCOPED_TRACE(into);
    core::Diagnostics diags;
    auto sim = open(std::string(R"Y(gdpn: 1
settings: {dt: 0.01, until: 1}
scene:
  - Group: {name: store, template: true, children: [{Group: {name: box}}]}
  - Group: {name: spare, template: true}
pages:
  main:
    places: {p: {tokens: 1}}
    transitions:
      t: {pre_fire: 'sim.node(")Y") + into + R"Y(").spawn("store/box")'}
    arcs: [p -> t]
)Y", diags);
    ASSERT_TRUE(sim) << diags.str();
    const auto outcome = sim->run({});
    ASSERT_EQ(outcome.reason, StopReason::ScriptError);
    const std::string why = std::string(into) == "store/box" ? "'store/box' is the template or inside it"
                                                             : "'" + std::string(into) + "' is inside template '" + into +
                                                                   "', which is not simulated";
    EXPECT_NE(outcome.message.find(why), std::string::npos)
        << outcome.message;
  }
}

TEST(Plant, TheTransformThatHoldsASpawnedCopyGoesWithIt) {
  core::Diagnostics diags;
  auto sim = open(R"Y(gdpn: 1
settings: {dt: 0.01, until: 1}
scene:
  - Material: {diffuse: [0.4, 0.4, 0.4]}
  - Group:
      name: store
      template: true
      children:
        - Material: {diffuse: [0.9, 0.6, 0.2]}
        - Body: {name: box, children: [{Cube: {size: [0.1, 0.1, 0.1]}}]}
  - Group: {name: area}
pages:
  main:
    places: {p: {tokens: 5}}
    transitions:
      t:
        duration: 0.1
        pre_fire: |
          box = sim.node("area").spawn("store/box", at=(0, 0, 1))
          assert box.parent.children[0].type == "Material"
          box.delete()
    arcs: [p -> t]
)Y", diags);
  ASSERT_TRUE(sim) << diags.str();
  const auto outcome = sim->run({});
  ASSERT_NE(outcome.reason, StopReason::ScriptError) << outcome.message;
  // five copies made and deleted: nothing left of them, their holders included
  EXPECT_TRUE(sim->plant()->find("area")->children().empty());
  EXPECT_EQ(sim->physics()->bodyCount(), 0u);
}

TEST(Plant, ATemplateMaterialColoursNothingAfterIt) {
  core::Diagnostics diags;
  auto sim = open(R"Y(gdpn: 1
settings: {dt: 0.01, until: 0.02}
scene:
  - Material: {name: grey, diffuse: [0.4, 0.4, 0.4]}
  - Material: {name: orange, template: true, diffuse: [0.9, 0.6, 0.2]}
  - Group: {name: area}
pages:
  main:
    places: {p: {tokens: 1}}
)Y", diags);
  ASSERT_TRUE(sim) << diags.str();
  EXPECT_EQ(scene::materialAt(*sim->plant()->find("area")), sim->plant()->find("grey"));
}

}  // namespace
}  // namespace gdpn::model

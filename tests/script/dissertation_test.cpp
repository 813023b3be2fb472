// The dissertation's own scripts, loaded verbatim from tests/data/dissertation (Figure 5.4's
// OnEnter of the sorting device, Table 7.1's inscriptions of the robotic arm), run unchanged;
// and what they rely on: `item` as the list of geometries in a region, a slot holding one
// node where a node is expected, `angles: radians`, sensor slots seen by the transitions
// around them, each construct its own bare slot names, a place's capacity from scripts.

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>

#include "gdpn/core/text.h"
#include "gdpn/model/simulation.h"
#include "script/script_model.h"
#include "support/sim_helpers.h"

namespace gdpn::model {
namespace {

using testing::ScriptModel;

/// A file of tests/data/dissertation, as written.
std::string dissertation(const std::string& name) {
  std::ifstream in(std::string(GDPN_SOURCE_DIR) + "/tests/data/dissertation/" + name);
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_FALSE(text.str().empty()) << name;
  return text.str();
}

/// `code` as a YAML block scalar's lines, indented by `indent` spaces.
std::string block(const std::string& code, int indent) {
  std::string out, pad(static_cast<std::size_t>(indent), ' ');
  std::istringstream lines(code);
  for (std::string line; std::getline(lines, line);) out += pad + line + "\n";
  return out;
}

struct Ran {
  std::unique_ptr<Simulation> sim;
  std::vector<std::string> logs;
  RunOutcome outcome;
};

Ran run(const ScriptModel& model, double until) {
  Ran r;
  core::Diagnostics diags;
  r.sim = model.open(diags);
  EXPECT_TRUE(r.sim) << diags.str();
  if (!r.sim) return r;
  std::ostringstream trace;
  r.sim->traceTo(trace);
  r.outcome = r.sim->run({until, std::nullopt});
  r.logs = testing::logLines(trace.str());
  return r;
}

core::Vec3 velocityOf(const Ran& r, const std::string& path) {
  return r.sim->physics()->velocity(*r.sim->plant()->find(path));
}

// Figure 5.4: a blue ball (ambient blue = 1.0) and a red one fall through the sensor; the
// script, character for character, reads each one's material through `item[0].prev` and
// pushes its body with setForce(x, y, z) for one step (ODE's dBodySetForce): 100 N for 5 ms
// on 0.1 kg is 5 m/s sideways, +y for the blue ball and +x for the red. A static bracket
// inside the region is not reported (`report: bodies`), so it never triggers the script.
TEST(Dissertation, Figure54SortsTheBallsAsWritten) {
  const std::string ball = R"(children:
            - Body:
                name: ball
                mass: 0.1
                children:
                  - Material: {ambient: [$COLOUR]}
                  - Sphere: {radius: 0.05}
)";
  auto coloured = [&](const std::string& c) {
    std::string b = ball;
    b.replace(b.find("$COLOUR"), 7, c);
    return b;
  };
  const ScriptModel model(R"(gdpn: 1
settings: {dt: 0.005}
scene:
  - World: {}
  - Transform:
      name: sorter
      translation: [0, 0, 1]
      children:
        - Region: {name: gate, size: [0.6, 0.6, 0.2], report: bodies}
        - Transform: {translation: [0.22, -0.22, 0], children: [{Cube: {name: bracket, size: [0.1, 0.1, 0.1]}}]}
  - Transform:
      name: blue
      translation: [0, 0, 1.5]
      )" + coloured("0, 0, 1") + R"(  - Transform:
      name: red
      translation: [0, 0, 2.5]
      )" + coloured("1, 0, 0") + R"(pages:
  main:
    places:
      sensor:
        sensors: {d0: sorter/gate}
        on_enter: |
)" + block(dissertation("figure_5_4.py"), 10));
  const Ran r = run(model, 1.0);
  ASSERT_TRUE(r.sim);
  EXPECT_EQ(r.outcome.reason, StopReason::Until) << r.outcome.message;
  // falling freely: the push is all the sideways motion there is
  const core::Vec3 blue = velocityOf(r, "blue/ball"), red = velocityOf(r, "red/ball");
  EXPECT_NEAR(blue.y, 5.0, 1e-9);
  EXPECT_NEAR(blue.x, 0.0, 1e-9);
  EXPECT_NEAR(red.x, 5.0, 1e-9);
  EXPECT_NEAR(red.y, 0.0, 1e-9);
}

// `item` is the list of the geometries in the region, those of what entered first; its
// attributes are those of what entered (`item.name`), so handlers written for gdpn still run.
TEST(Dissertation, ItemListsTheGeometriesInsideTheOneThatEnteredFirst) {
  const ScriptModel model(R"(gdpn: 1
settings: {dt: 0.005}
scene:
  - World: {}
  - Transform: {name: zone, translation: [0, 0, 1], children: [{Region: {name: gate, size: [2, 2, 4]}}]}
  - Transform: {translation: [0, 0, 0.5], children: [{Cube: {name: shelf, size: [0.2, 0.2, 0.2]}}]}
  - Transform:
      name: a
      translation: [0.5, 0, 1.5]
      children: [{Body: {name: body, children: [{Cube: {name: box, size: [0.1, 0.1, 0.1]}}, {Sphere: {name: knob, radius: 0.05}}]}}]
  - Transform:
      name: b
      translation: [-0.5, 0, 3.2]
      children: [{Body: {name: body, children: [{Sphere: {name: ball, radius: 0.05}}]}}]
pages:
  main:
    places:
      watch:
        sensors: {c0: zone/gate}
        on_enter: 'sim.log(item.name, [g.name for g in item], item[0].parent.name)'
)");
  const Ran r = run(model, 0.3);
  ASSERT_TRUE(r.sim);
  // at t = 0 (in path order): the shelf (a static shape), then a, each with the other's
  // geometries after its own; then b enters from above, ahead of both
  EXPECT_EQ(r.logs, (std::vector<std::string>{
                        "#2/shelf ['#2/shelf', 'a/body/box', 'a/body/knob'] #2",
                        "a/body ['a/body/box', 'a/body/knob', '#2/shelf'] a/body",
                        "b/body ['b/body/ball', '#2/shelf', 'a/body/box', 'a/body/knob'] b/body",
                    }));
}

// Table 7.1: deliver turns the vertical joint at 2 rad/s (`angles: radians`) and attaches the
// box in d0 to the effector in b2, a slot holding one node where attach expects a node;
// drop turns the others and detaches the box when it completes.
TEST(Dissertation, Table71MovesTheArmAsWritten) {
  const ScriptModel model(R"(gdpn: 1
settings: {dt: 0.005, angles: radians}
scene:
  - World: {gravity: [0, 0, 0]}
  - Joint:
      name: vertical
      kind: hinge
      axis1: [0, 0, 1]
      fmax1: 5000
      children:
        - Body:
            name: column
            mass: 5
            children:
              - Transform: {translation: [0, 0, 0.5], children: [{Cylinder: {radius: 0.1, height: 1}}]}
              - Joint:
                  name: horizontal
                  kind: hinge
                  anchor: [0, 0, 1]
                  axis1: [0, 1, 0]
                  lo1: -0.5
                  hi1: 0.5
                  fmax1: 5000
                  children:
                    - Body:
                        name: boom
                        mass: 2
                        children:
                          - Transform: {translation: [0.5, 0, 1], children: [{Cube: {size: [1, 0.1, 0.1]}}]}
                          - Joint:
                              name: effector
                              kind: hinge
                              anchor: [1, 0, 1]
                              axis1: [0, 0, 1]
                              fmax1: 500
                              children:
                                - Body:
                                    name: hand
                                    mass: 0.5
                                    children:
                                      - Transform: {translation: [1, 0, 0.9], children: [{Cube: {size: [0.1, 0.1, 0.1]}}]}
  - Transform:
      name: box_at
      translation: [1, 0, 0.75]
      children: [{Body: {name: box, mass: 1, children: [{Cube: {size: [0.2, 0.2, 0.2]}}]}}]
pages:
  main:
    places:
      ready:
        tokens:
          b0: [vertical]
          b1: [vertical/column/horizontal]
          b2: [vertical/column/horizontal/boom/effector]
          d0: [box_at/box]
      carrying: {}
      done: {}
      seen: {}
    transitions:
      deliver:
        duration: 1
        pre_fire: |
)" + block(dissertation("table_7_1_deliver_pre_fire.py"), 10) +
                          R"(      drop:
        duration: 0.5
        pre_fire: |
)" + block(dissertation("table_7_1_drop_pre_fire.py"), 10) +
                          R"(        post_fire: |
)" + block(dissertation("table_7_1_drop_post_fire.py"), 10) +
                          R"(      observe:
        pre_fire: 'sim.log(round(sim.node("vertical").rate, 1), round(sim.node("vertical").vel1, 3))'
    arcs:
      - {from: ready, to: deliver, weight: {b0: 1, b1: 1, b2: 1, d0: 1}}
      - {from: deliver, to: carrying, weight: {b0: 1, b1: 1, b2: 1, d0: 1}}
      - {from: carrying, to: drop, weight: {b0: 1, b1: 1, b2: 1, d0: 1}}
      - {from: drop, to: done, weight: {b0: 1, b1: 1, b2: 1, d0: 1}}
      - {from: done, to: observe, weight: {b0: 1, b1: 1, b2: 1, d0: 1}}
      - {from: observe, to: seen, weight: {b0: 1, b1: 1, b2: 1, d0: 1}}
)");
  const Ran r = run(model, 2.0);
  ASSERT_TRUE(r.sim);
  EXPECT_EQ(r.outcome.reason, StopReason::Until) << r.outcome.message;
  // the motor's target is stored in degrees; the script and the log read radians
  const scene::Node& vertical = *r.sim->plant()->find("vertical");
  EXPECT_NEAR(vertical.number(scene::field::Joint::Vel1), 2.0 * 180.0 / M_PI, 1e-9);
  EXPECT_EQ(r.logs, (std::vector<std::string>{"2.0 2.0"}));
  // the box went round with the arm while attached (about 3 rad in 1.5 s at 2 rad/s), and
  // stayed where it was let go
  const core::Vec3 box = r.sim->plant()->find("box_at/box")->world.position;
  const double turned = std::atan2(box.y, box.x);
  EXPECT_GT(std::abs(turned), 2.0);
  const core::Vec3 v = velocityOf(r, "box_at/box");
  const core::Vec3 hand = velocityOf(r, "vertical/column/horizontal/boom/effector/hand");
  EXPECT_GT(std::hypot(hand.x - v.x, hand.y - v.y), 0.5);  // detached: the hand moves on without it
}

// A transition's slot named like a sensor slot of a place its arcs touch is that sensor
// (the dissertation's contents view), and each construct sees its own sensors by bare name:
// two places with a sensor in c0 each read theirs, from the first step on.
TEST(Dissertation, SensorSlotsAreSeenByTheirOwnConstructsAndTheTransitionsAround) {
  const ScriptModel model(R"(gdpn: 1
settings: {dt: 0.01}
scene:
  - World: {gravity: [0, 0, 0]}
  - Transform: {name: left, translation: [-2, 0, 0], children: [{Region: {name: eye, size: [1, 1, 1]}}]}
  - Transform: {name: right, translation: [2, 0, 0], children: [{Region: {name: eye, size: [1, 1, 1]}}]}
  - Transform: {name: box, translation: [2, 0, 0], children: [{Body: {name: body, children: [{Cube: {size: [0.2, 0.2, 0.2]}}]}}]}
  - Transform: {name: b1, translation: [-2, 0.3, 0], children: [{Body: {name: body, children: [{Cube: {size: [0.2, 0.2, 0.2]}}]}}]}
  - Transform: {name: b2, translation: [-2, -0.3, 0], children: [{Body: {name: body, children: [{Cube: {size: [0.2, 0.2, 0.2]}}]}}]}
pages:
  main:
    places:
      west:
        sensors: {c0: left/eye}
        on_sample: 'sim.log("west", len(c0), c0.active)'
      east:
        sensors: {c0: right/eye}
        tokens: 1
        on_sample: 'sim.log("east", len(c0), c0.active)'
    transitions:
      push:
        guard: 'self.c0.active'
        pre_fire: 'sim.log("push sees", [n.name for n in self.c0.items], len(c0))'
    arcs:
      - east -> push
)");
  const Ran r = run(model, 0.0);
  ASSERT_TRUE(r.sim);
  EXPECT_EQ(r.outcome.reason, StopReason::Until) << r.outcome.message;
  EXPECT_EQ(r.logs, (std::vector<std::string>{"east 1 True", "west 2 True", "push sees ['box/body'] 1"}));
}

// A place's capacity, read and raised by a script (the dissertation raises one on a key
// press); lowering it below what the place holds, or giving one to a place the model left
// unbounded, is refused with the reason.
TEST(Dissertation, APlacesCapacityIsReadAndSetFromScripts) {
  const ScriptModel model(R"(gdpn: 1
pages:
  main:
    places:
      buffer: {capacity: 1}
      free: {}
      once: {tokens: 1}
      later: {}
    transitions:
      feed: {}
      widen:
        duration: 5
        pre_fire: |
          sim.log("capacity", sim.place("main/buffer").capacity, sim.place("main/free").capacity)
        post_fire: |
          buffer = sim.place("main/buffer")
          buffer.capacity = 3
          for wrong in (0, None):
              try:
                  (buffer if wrong == 0 else sim.place("main/free")).capacity = 0 if wrong == 0 else 2
              except ValueError as e:
                  sim.log(e)
          try:
              buffer.capacity = "3"
          except TypeError as e:
              sim.log(e)
      unbound:
        duration: 8
        pre_fire: |
          buffer = sim.place("main/buffer")
          buffer.capacity = None
          sim.log("capacity", buffer.capacity)
    arcs:
      - feed -> buffer
      - once -> widen
      - later -> unbound
      - widen -> free
      - widen -> later
)");
  const Ran r = run(model, 10.0);
  ASSERT_TRUE(r.sim);
  const std::vector<std::string> expected = {
      "capacity 1 None",
      "capacity of place 'main/buffer' slot a0: it holds 1 and has 0 promised: more than 0",
      "capacity of place 'main/free' slot a0: it has no capacity in the model (give it one to change it)",
      "capacity of place 'main/buffer' slot a0 expects a whole number or None, got str '3'",
      "capacity None",
  };
  EXPECT_EQ(r.logs, expected);
  // 1 until t = 5 (capacity 1), then unbounded: feed puts one more in at every step's end
  const auto buffer = *r.sim->net().findPlaceSlot(*r.sim->net().findPlace("main/buffer"), net::kDefaultSlot);
  EXPECT_EQ(r.sim->kernel().marking(buffer), 1 + std::llround(5.0 * 60.0));
}

// The dissertation's spellings beside gdpn's, with their mistakes reported as gdpn's are.
TEST(Dissertation, TheDissertationsSpellingsAreAcceptedBesideGdpns) {
  const ScriptModel model(R"(gdpn: 1
settings: {dt: 0.01}
scene:
  - World: {gravity: [0, 0, 0]}
  - Body: {name: a, mass: 2, children: [{Sphere: {radius: 0.1}}]}
  - Transform: {name: far, translation: [5, 0, 0], children: [{Body: {name: b, mass: 1, children: [{Sphere: {radius: 0.1}}]}}]}
pages:
  main:
    places:
      P: {tokens: {d0: [a, far/b]}}
      Q: {}
    transitions:
      T:
        pre_fire: |
          a = sim.node("a")
          a.setVelocity(2, 0, 0)
          a.addForce((0, 4, 0))
          for call in (lambda: a.setForce(1, 2), lambda: a.attach(self.d0), lambda: a.attach(3)):
              try:
                  call()
              except TypeError as e:
                  sim.log(e)
    arcs:
      - {from: P, to: T, weight: {d0: 2}}
      - {from: T, to: Q, weight: {d0: 2}}
)");
  const Ran r = run(model, 0.05);
  ASSERT_TRUE(r.sim);
  // 4 N on 2 kg for one 0.01 s step: 0.02 m/s, and nothing after it
  const core::Vec3 v = velocityOf(r, "a");
  EXPECT_NEAR(v.x, 2.0, 1e-12);
  EXPECT_NEAR(v.y, 0.02, 1e-12);
  const std::vector<std::string> expected = {
      "setForce() takes (x, y, z) or three numbers, got 2 arguments",
      "attach(): transition 'main/T' slot d0 holds 2 node tokens; pass one node (d0[0], say)",
      "attach() expects a node or a slot holding one, got int",
  };
  EXPECT_EQ(r.logs, expected);
}

// `angles: radians` holds in the file as in scripts: the scene stores degrees, and saving
// writes radians back.
TEST(Dissertation, RadiansInTheFileAreStoredAsDegreesAndSavedAsRadians) {
  const std::string text = R"(gdpn: 1
settings:
  angles: radians
scene:
  - Transform: {rotation: [0, 0, 1, 1.5], children: [{Camera: {fov: 0.5}}]}
  - Joint:
      kind: hinge
      lo1: -0.25
      hi1: 0.1
      vel1: 2
      children: [{Body: {children: [{Sphere: {}}]}}]
  - Joint:
      kind: slider
      lo1: -0.25
      children: [{Body: {children: [{Sphere: {}}]}}]
)";
  core::Diagnostics diags;
  const auto m = parseModel(text, "m.gdpn.yaml", diags);
  ASSERT_TRUE(m) << diags.str();
  const auto& root = m->scene->root();
  const double k = 180.0 / M_PI;
  const auto& rotation = root.children()[0]->value(scene::field::Transform::Rotation);
  EXPECT_NEAR((std::get<std::array<double, 4>>(rotation)[3]), 1.5 * k, 1e-12);
  EXPECT_NEAR(root.children()[0]->children()[0]->number(scene::field::Camera::Fov), 0.5 * k, 1e-12);
  EXPECT_NEAR(root.children()[1]->number(scene::field::Joint::Lo1), -0.25 * k, 1e-12);
  EXPECT_NEAR(root.children()[1]->number(scene::field::Joint::Vel1), 2 * k, 1e-12);
  EXPECT_EQ(root.children()[2]->number(scene::field::Joint::Lo1), -0.25);  // a slider's metres
  const std::string saved = writeModel(*m);
  EXPECT_NE(saved.find("angles: radians"), std::string::npos) << saved;
  EXPECT_NE(saved.find("rotation: [0, 0, 1, 1.5]"), std::string::npos) << saved;
  EXPECT_NE(saved.find("fov: 0.5"), std::string::npos) << saved;
  EXPECT_NE(saved.find("lo1: -0.25"), std::string::npos) << saved;
  // saved as written, not as 0.10000000000000002 (the shortest decimal that gives the degrees)
  EXPECT_NE(saved.find("hi1: 0.1\n"), std::string::npos) << saved;
}

// `item` stands for the node that entered where gdpn's handlers use a node: compared, hashed,
// added to a slot, printed. A model's global named like a slot comes back after the slot's
// construct has run, and a transition's own token slot is not hidden by a sensor slot of the
// same name on a place around it.
TEST(Dissertation, ItemActsAsItsNodeAndSlotNamesHideNothingForGood) {
  const ScriptModel model(R"(gdpn: 1
settings: {dt: 0.01}
scripts:
  globals: |
    c0 = "mine"
    d0 = "also mine"
scene:
  - World: {gravity: [0, 0, 0]}
  - Transform: {name: zone, children: [{Region: {name: gate, size: [1, 1, 1]}}]}
  - Transform: {name: box, children: [{Body: {name: body, children: [{Cube: {size: [0.2, 0.2, 0.2]}}]}}]}
  - Transform: {name: far, translation: [5, 0, 0], children: [{Body: {name: crate, children: [{Sphere: {radius: 0.1}}]}}]}
pages:
  main:
    places:
      watch:
        sensors: {c0: zone/gate, d0: zone/gate}
        on_enter: |
          sim.log(item, item == sim.node("box/body"), item in items, len({item: 1, sim.node("box/body"): 2}))
          sim.place("main/kept").d0.add(item)
          sim.log(sim.place("main/kept").d0[0])
      kept: {slots: {d0: node}}
      store: {tokens: {d0: [far/crate]}}
      done: {}
      gone: {}
    transitions:
      look:
        pre_fire: 'sim.log(c0, self.d0.name, len(self.c0))'
      after:
        pre_fire: 'sim.log(c0, d0)'
    arcs:
      - {from: watch, to: look, condition: 'len(c0) > 0'}
      - {from: store, to: look, weight: {d0: 1}}
      - {from: look, to: done, weight: {d0: 1}}
      - {from: done, to: after, weight: {d0: 1}}
      - {from: after, to: gone, weight: {d0: 1}}
)");
  const Ran r = run(model, 0.05);
  ASSERT_TRUE(r.sim);
  EXPECT_EQ(r.outcome.reason, StopReason::Until) << r.outcome.message;
  EXPECT_EQ(r.logs, (std::vector<std::string>{"<node box/body> True True 1", "<node box/body>",
                                               "<sensor zone/gate> far/crate 1", "mine also mine"}));
}

}  // namespace
}  // namespace gdpn::model

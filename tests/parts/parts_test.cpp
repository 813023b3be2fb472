// The parts library (parts/): every part loads and declares its palette entry and its I/O as
// documented in parts/README.md, its demo runs, and it behaves physically against a known
// answer (the belt carries at its speed, the pusher's stroke takes stroke/speed, the beam
// sees only what crosses it, the remover and the bin count, the emitter keeps its period and
// colours, the lamps light, the button counts clicks). Nothing here measures wall time.

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <filesystem>
#include <initializer_list>
#include <limits>
#include <map>
#include <memory>
#include <numbers>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "gdpn/model/part_run.h"
#include "gdpn/model/simulation.h"
#include "gdpn/scene/actions.h"

namespace gdpn::model {
namespace {

/// A part file of the source tree: `group/name` -> parts/group/name.gdpn.yaml.
std::string partPath(const std::string& rel) { return std::string(GDPN_SOURCE_DIR) + "/parts/" + rel + kModelSuffix; }

/// The model of part file `rel`; nullopt after a failed expectation showing the diagnostics.
std::optional<Model> loadPart(const std::string& rel) {
  core::Diagnostics diags;
  auto m = loadModel(partPath(rel), diags);
  EXPECT_TRUE(m) << diags.str();
  return m;
}

/// A model of `body` (pages and scene: a test's station) with the page types of the part
/// files `parts`, made ready to run; null after a failed expectation.
std::unique_ptr<Simulation> compose(const std::string& body, std::initializer_list<const char*> parts,
                                    std::optional<std::uint64_t> seed = {}) {
  core::Diagnostics diags;
  auto m = parseModel("gdpn: 1\nsettings: {dt: 0.01}\n" + body, "station.gdpn.yaml", diags);
  EXPECT_TRUE(m) << diags.str();
  if (!m) return nullptr;
  for (const char* rel : parts) {
    auto p = loadPart(rel);
    if (!p) return nullptr;
    for (auto& type : p->net.page_types) m->net.page_types.push_back(std::move(type));
    for (auto& [name, part] : p->parts) m->parts[name] = std::move(part);
    for (auto& [name, scene] : p->type_scenes) m->type_scenes[name] = std::move(scene);
  }
  auto sim = Simulation::create(*m, diags, seed);
  EXPECT_TRUE(sim) << diags.str();
  return sim;
}

constexpr double kNan = std::numeric_limits<double>::quiet_NaN();

/// A floor, and the scene of a test's station after it.
const char* const kFloor = "scene:\n  - World: {}\n  - Plane: {name: floor}\n";

/// Part `part`'s I/O `io` now.
double io(const Simulation& sim, const std::string& part, const std::string& io) {
  std::string why;
  const auto p = sim.parts()->find(part, why);
  EXPECT_TRUE(p) << why;
  if (!p) return kNan;
  const auto v = sim.parts()->read(*p, io, why);
  EXPECT_TRUE(v) << why;
  return v ? *v : kNan;
}

/// Sets output `io` of part `part`.
void write(Simulation& sim, const std::string& part, const std::string& io, double value) {
  std::string why;
  const auto p = sim.parts()->find(part, why);
  ASSERT_TRUE(p) << why;
  ASSERT_TRUE(sim.parts()->write(*p, io, value, why)) << why;
}

/// The tokens on place `place` (qualified), all its slots.
std::int64_t tokens(const Simulation& sim, const std::string& place) {
  const auto id = sim.net().findPlace(place);
  EXPECT_TRUE(id) << place;
  if (!id) return -1;
  std::int64_t n = 0;
  for (const auto ps : sim.net().placeSlotsOf(*id)) n += sim.kernel().marking(ps);
  return n;
}

/// The world position of scene node `path` (a body's as the physics moves it).
core::Vec3 position(const Simulation& sim, const std::string& path) {
  const scene::Node* n = sim.plant()->find(path);
  EXPECT_NE(n, nullptr) << path;
  return n ? n->framePose().position : core::Vec3{kNan, kNan, kNan};
}

/// Colour (or vector) field `field` of scene node `path`.
std::array<double, 3> colour(const Simulation& sim, const std::string& path, const std::string& field) {
  const scene::Node* n = sim.plant()->find(path);
  EXPECT_NE(n, nullptr) << path;
  if (!n) return {kNan, kNan, kNan};
  const int i = n->type().fieldIndex(field);
  EXPECT_GE(i, 0) << field;
  return std::get<std::array<double, 3>>(n->value(static_cast<std::size_t>(i)));
}

/// Steps `sim` for `seconds` of model time.
void runFor(Simulation& sim, double seconds) {
  const auto steps = static_cast<std::int64_t>(std::llround(seconds / sim.model().settings.dt));
  for (std::int64_t i = 0; i < steps; ++i) sim.step();
}

// ---------------------------------------------------------------------------------------
// every part: its file, its palette entry, its I/O

/// One I/O as parts/README.md documents it.
struct IoRow {
  const char* name;
  IoDirection direction;
  IoSignal signal;
  const char* unit;
};

/// One part as parts/README.md documents it.
struct PartRow {
  const char* file;   // group/name
  const char* group;  // the palette's group
  const char* control;
  std::vector<IoRow> io;
};

constexpr auto In = IoDirection::Input;
constexpr auto Out = IoDirection::Output;
constexpr auto Dig = IoSignal::Digital;
constexpr auto Ana = IoSignal::Analog;

const std::vector<PartRow>& library() {
  static const std::vector<PartRow> rows = {
      {"items/small_box", "Items", "", {}},
      {"items/medium_box", "Items", "", {}},
      {"items/large_box", "Items", "", {}},
      {"items/metal_base", "Items", "", {}},
      {"items/plastic_lid", "Items", "", {}},
      {"sources_and_sinks/emitter", "Sources and sinks", "",
       {{"emit", Out, Dig, ""}, {"emitted", In, Ana, "boxes"}, {"occupied", In, Dig, ""}}},
      {"sources_and_sinks/remover", "Sources and sinks", "", {{"removed", In, Ana, "items"}}},
      {"conveyors/belt_conveyor", "Conveyors", "", {{"run", Out, Dig, ""}, {"speed", Out, Ana, "m/s"}}},
      {"storage/bin", "Storage", "", {{"count", In, Ana, "items"}}},
      {"sensors/diffuse_sensor", "Sensors", "", {{"detected", In, Dig, ""}, {"colour", In, Ana, ""}}},
      {"sensors/through_beam", "Sensors", "", {{"blocked", In, Dig, ""}}},
      {"sensors/inductive_sensor", "Sensors", "", {{"detected", In, Dig, ""}}},
      {"sensors/capacitive_sensor", "Sensors", "", {{"detected", In, Dig, ""}}},
      {"sensors/code_reader", "Sensors", "", {{"code", In, Ana, ""}, {"read", In, Dig, ""}}},
      {"conveyors/chute", "Conveyors", "", {}},
      {"items/pallet", "Items", "", {}},
      {"conveyors/scale_conveyor", "Conveyors", "",
       {{"mass", In, Ana, "kg"}, {"loaded", In, Dig, ""}, {"run", Out, Dig, ""}, {"speed", Out, Ana, "m/s"}}},
      {"actuators/pusher", "Actuators", "pusher_control",
       {{"extend", Out, Dig, ""}, {"front_limit", In, Dig, ""}, {"back_limit", In, Dig, ""}}},
      {"actuators/pick_and_place", "Actuators", "pick_and_place_control",
       {{"x", Out, Ana, "m"}, {"down", Out, Dig, ""}, {"vacuum", Out, Dig, ""}, {"x_at", In, Ana, "m"}, {"z_at", In, Ana, "m"},
        {"holding", In, Dig, ""}}},
      {"operator/stack_light", "Operator", "", {{"red", Out, Dig, ""}, {"amber", Out, Dig, ""}, {"green", Out, Dig, ""}}},
      {"operator/push_button", "Operator", "", {{"pressed", In, Dig, ""}, {"presses", In, Ana, "presses"}}},
      {"operator/emergency_stop", "Operator", "", {{"latched", In, Dig, ""}, {"released", In, Dig, ""}}},
      {"operator/selector_switch", "Operator", "", {{"on", In, Dig, ""}}},
      {"operator/beacon", "Operator", "", {{"on", Out, Dig, ""}, {"lit", In, Dig, ""}}},
      {"conveyors/curved_belt", "Conveyors", "", {{"run", Out, Dig, ""}, {"speed", Out, Ana, "m/s"}}},
      {"conveyors/roller_conveyor", "Conveyors", "", {{"run", Out, Dig, ""}, {"backwards", Out, Dig, ""}}},
      {"actuators/elevator", "Actuators", "",
       {{"up", Out, Dig, ""}, {"run", Out, Dig, ""}, {"speed", Out, Ana, "m/s"}, {"at_bottom", In, Dig, ""}, {"at_top", In, Dig, ""},
        {"loaded", In, Dig, ""}}},
      {"storage/stacker", "Storage", "stacker_control",
       {{"x", Out, Ana, "m"}, {"z", Out, Ana, "m"}, {"fork_out", Out, Dig, ""}, {"lift", Out, Dig, ""}, {"x_at", In, Ana, "m"},
        {"z_at", In, Ana, "m"}, {"fork_home", In, Dig, ""}, {"fork_out_limit", In, Dig, ""}, {"loaded", In, Dig, ""}}},
      {"conveyors/turntable", "Conveyors", "",
       {{"turn", Out, Dig, ""}, {"run", Out, Dig, ""}, {"speed", Out, Ana, "m/s"}, {"at_home", In, Dig, ""},
        {"at_angle", In, Dig, ""}, {"angle_at", In, Ana, "deg"}}},
      {"conveyors/transfer", "Conveyors", "",
       {{"run", Out, Dig, ""}, {"speed", Out, Ana, "m/s"}, {"up", Out, Dig, ""}, {"left", Out, Dig, ""}, {"right", Out, Dig, ""}}},
      {"conveyors/stopper_belt", "Conveyors", "",
       {{"run", Out, Dig, ""}, {"speed", Out, Ana, "m/s"}, {"stop", Out, Dig, ""}, {"waiting", In, Dig, ""}}},
      {"actuators/pivot_arm_sorter", "Actuators", "pivot_arm_control",
       {{"swing", Out, Dig, ""}, {"home", In, Dig, ""}, {"out", In, Dig, ""}}},
      {"operator/potentiometer", "Operator", "", {{"value", In, Ana, ""}}},
      {"operator/digital_display", "Operator", "", {{"value", Out, Ana, ""}}},
      {"sensors/light_array", "Sensors", "", {{"blocked", In, Dig, ""}, {"beams", In, Ana, "beams"}, {"top", In, Ana, "m"}}},
  };
  return rows;
}

std::string stem(const std::string& file) { return file.substr(file.find('/') + 1); }

class EveryPart : public ::testing::TestWithParam<PartRow> {};

TEST_P(EveryPart, LoadsWithItsPaletteEntryAndPicture) {
  // the page type named as the file, listed in its group, version 1, a picture beside it
  const PartRow& row = GetParam();
  const auto m = loadPart(row.file);
  ASSERT_TRUE(m);
  const std::string name = stem(row.file);
  ASSERT_TRUE(m->parts.contains(name));
  const PartSpec& spec = m->parts.at(name);
  EXPECT_TRUE(spec.listed);
  EXPECT_GE(spec.version, 1);
  EXPECT_EQ(spec.group, row.group);
  EXPECT_EQ(spec.picture, name + ".png");
  EXPECT_TRUE(std::filesystem::is_regular_file(std::filesystem::path(partPath(row.file)).parent_path() / spec.picture))
      << spec.picture;
  EXPECT_EQ(spec.control, row.control);
  EXPECT_TRUE(m->type_scenes.contains(name)) << "a part brings its machine";
  // every parameter says what it is
  for (const auto& p : spec.params) EXPECT_FALSE(p.description.empty()) << name << "." << p.name;
  // a control pattern, when it has one, says which part it controls
  if (!spec.control.empty()) {
    ASSERT_TRUE(m->parts.contains(spec.control));
    EXPECT_EQ(m->parts.at(spec.control).controls, name);
    EXPECT_EQ(m->parts.at(spec.control).group, row.group);
  }
}

TEST_P(EveryPart, DeclaresItsIoAsDocumented) {
  const PartRow& row = GetParam();
  const auto m = loadPart(row.file);
  ASSERT_TRUE(m);
  const PartSpec& spec = m->parts.at(stem(row.file));
  ASSERT_EQ(spec.io.size(), row.io.size());
  for (std::size_t i = 0; i < row.io.size(); ++i) {
    SCOPED_TRACE(row.io[i].name);
    EXPECT_EQ(spec.io[i].name, row.io[i].name);
    EXPECT_EQ(spec.io[i].direction, row.io[i].direction);
    EXPECT_EQ(spec.io[i].signal, row.io[i].signal);
    EXPECT_EQ(spec.io[i].unit, row.io[i].unit);
    EXPECT_FALSE(spec.io[i].description.empty());
  }
}

TEST_P(EveryPart, ItsDemoRunsAndItsIoBindToThePlant) {
  // the demo page runs 1 s; every I/O reads a value (bound to a node of the part's copy)
  const PartRow& row = GetParam();
  const auto m = loadPart(row.file);
  ASSERT_TRUE(m);
  core::Diagnostics diags;
  auto sim = Simulation::create(*m, diags);
  ASSERT_TRUE(sim) << diags.str();
  runFor(*sim, 1.0);
  EXPECT_FALSE(sim->scriptHalt()) << sim->scriptHalt()->message;
  EXPECT_FALSE(sim->physicsHalt());
  ASSERT_NE(sim->parts(), nullptr);
  for (const auto& r : sim->parts()->rows()) {
    EXPECT_TRUE(std::isfinite(r.value)) << r.io->name;
  }
}

TEST_P(EveryPart, SavesAndReadsBackTheSame) {
  // a model keeps a copy of the parts it uses: the part's file written out and read back is
  // the same model, its =expressions and $params as written
  const auto m = loadPart(GetParam().file);
  ASSERT_TRUE(m);
  const std::string text = writeModel(*m);
  core::Diagnostics diags;
  const auto back = parseModel(text, "saved.gdpn.yaml", diags);
  ASSERT_TRUE(back) << diags.str() << text;
  EXPECT_TRUE(*back == *m);
  EXPECT_EQ(writeModel(*back), text);
}

INSTANTIATE_TEST_SUITE_P(Library, EveryPart, ::testing::ValuesIn(library()),
                         [](const auto& p) { return stem(p.param.file); });

// ---------------------------------------------------------------------------------------
// items

/// The same node types, names and field values all the way down.
bool sameTree(const scene::Node& a, const scene::Node& b) {
  if (a.kind() != b.kind() || a.name() != b.name() || a.children().size() != b.children().size()) return false;
  for (std::size_t i = 0; i < a.type().fields.size(); ++i) {
    if (a.value(i) != b.value(i)) return false;
  }
  for (std::size_t i = 0; i < a.children().size(); ++i) {
    if (!sameTree(*a.children()[i], *b.children()[i])) return false;
  }
  return true;
}

TEST(Items, BoxesStandOnTheFloorWithTheirUserData) {
  // each box settles with its base on the floor (its origin at z = 0), brown cardboard
  for (const char* type : {"small_box", "medium_box", "large_box"}) {
    SCOPED_TRACE(type);
    auto sim = compose(std::string(kFloor) + "pages:\n  main:\n    instances:\n      box1: {type: " + type +
                           ", translation: [0, 0, 0.05]}\n",
                       {(std::string("items/") + type).c_str()});
    ASSERT_TRUE(sim);
    runFor(*sim, 1.0);
    EXPECT_NEAR(position(*sim, "box1/box").z, 0.0, 0.005);
    const scene::Node* box = sim->plant()->find("box1/box");
    ASSERT_NE(box, nullptr);
    ASSERT_NE(box->datum("colour"), nullptr);
    ASSERT_NE(box->datum("material"), nullptr);
    EXPECT_EQ(std::get<std::string>(*box->datum("colour")), "brown");
    EXPECT_EQ(std::get<std::string>(*box->datum("material")), "cardboard");
  }
}

TEST(Items, TheEmittersBoxesAreTheItemsBoxes) {
  // the emitter's templates have the items' masses, sizes and looks
  const auto emitter = loadPart("sources_and_sinks/emitter");
  ASSERT_TRUE(emitter);
  const auto& templates = *emitter->type_scenes.at("emitter");
  for (const auto& [size, file] : std::vector<std::pair<std::string, std::string>>{
           {"small", "small_box"}, {"medium", "medium_box"}, {"large", "large_box"}}) {
    SCOPED_TRACE(size);
    const auto item = loadPart("items/" + file);
    ASSERT_TRUE(item);
    const scene::Node* made = templates.find("templates/" + size + "/box");
    const scene::Node* box = item->type_scenes.at(file)->find("box");
    ASSERT_NE(made, nullptr);
    ASSERT_NE(box, nullptr);
    ASSERT_EQ(made->children().size(), box->children().size());
    for (std::size_t i = 0; i < box->children().size(); ++i) EXPECT_TRUE(sameTree(*made->children()[i], *box->children()[i]));
    EXPECT_EQ(made->data, box->data);
  }
}


// ---------------------------------------------------------------------------------------
// the belt conveyor

TEST(BeltConveyor, CarriesABoxAtItsSpeed) {
  // a medium box on a 4 m belt at 0.8 m/s: once it has settled, it goes 1.6 m in 2 s (2 %)
  auto sim = compose(std::string(kFloor) + R"Y(pages:
  main:
    instances:
      belt1: {type: belt_conveyor, params: {length: 4, speed: 0.8}}
      box1: {type: medium_box, translation: [-1.6, 0, 0.801]}
)Y",
                     {"conveyors/belt_conveyor", "items/medium_box"});
  ASSERT_TRUE(sim);
  runFor(*sim, 1.0);
  const core::Vec3 a = position(*sim, "box1/box");
  runFor(*sim, 2.0);
  const core::Vec3 b = position(*sim, "box1/box");
  EXPECT_NEAR((b.x - a.x) / 2.0, 0.8, 0.8 * 0.02);
  EXPECT_NEAR(b.y, 0.0, 0.01);
  EXPECT_NEAR(b.z, 0.8, 0.005) << "on the belt's top";
  EXPECT_DOUBLE_EQ(io(*sim, "belt1", "run"), 1.0);
  EXPECT_DOUBLE_EQ(io(*sim, "belt1", "speed"), 0.8);
}

TEST(BeltConveyor, RunAndSpeedDriveOneMotor) {
  // start: 0 stands still; run switches the parameter's speed on and off; speed sets any
  // speed (backwards too), and then run reads 0: the belt no longer runs at its speed
  auto sim = compose(std::string(kFloor) + R"Y(pages:
  main:
    instances:
      belt1: {type: belt_conveyor, params: {length: 4, start: 0}}
      box1: {type: small_box, translation: [0, 0, 0.801]}
)Y",
                     {"conveyors/belt_conveyor", "items/small_box"});
  ASSERT_TRUE(sim);
  runFor(*sim, 1.0);
  EXPECT_DOUBLE_EQ(io(*sim, "belt1", "run"), 0.0);
  EXPECT_NEAR(position(*sim, "box1/box").x, 0.0, 0.002) << "stands until driven";
  write(*sim, "belt1", "run", 1);
  runFor(*sim, 0.5);
  double x = position(*sim, "box1/box").x;
  runFor(*sim, 1.0);
  EXPECT_NEAR(position(*sim, "box1/box").x - x, 0.5, 0.01) << "run: the speed parameter, 0.5 m/s";
  write(*sim, "belt1", "speed", -0.3);
  EXPECT_DOUBLE_EQ(io(*sim, "belt1", "run"), 0.0);
  EXPECT_DOUBLE_EQ(io(*sim, "belt1", "speed"), -0.3);
  runFor(*sim, 0.5);
  x = position(*sim, "box1/box").x;
  runFor(*sim, 1.0);
  EXPECT_NEAR(position(*sim, "box1/box").x - x, -0.3, 0.01) << "speed: backwards at 0.3 m/s";
  write(*sim, "belt1", "run", 0);
  runFor(*sim, 0.5);
  x = position(*sim, "box1/box").x;
  runFor(*sim, 1.0);
  EXPECT_NEAR(position(*sim, "box1/box").x, x, 0.002) << "run off: stopped";
}

TEST(BeltConveyor, BeltsPlacedAtLengthIntervalsHandOverABox) {
  // two 2 m belts, the second 2 m further on: a box rides from the first onto the second
  auto sim = compose(std::string(kFloor) + R"Y(pages:
  main:
    instances:
      belt1: {type: belt_conveyor}
      belt2: {type: belt_conveyor, translation: [2, 0, 0]}
      box1: {type: small_box, translation: [-0.7, 0, 0.801]}
)Y",
                     {"conveyors/belt_conveyor", "items/small_box"});
  ASSERT_TRUE(sim);
  runFor(*sim, 6.0);  // 3 m at 0.5 m/s
  const core::Vec3 p = position(*sim, "box1/box");
  EXPECT_NEAR(p.x, 2.3, 0.05);
  EXPECT_NEAR(p.z, 0.8, 0.005) << "still on a belt's top";
}

// ---------------------------------------------------------------------------------------
// the curved belt and the roller conveyor

/// The heading (degrees from +x, about z) of scene node `path`'s x axis.
double heading(const Simulation& sim, const std::string& path) {
  const scene::Node* n = sim.plant()->find(path);
  EXPECT_NE(n, nullptr) << path;
  if (!n) return kNan;
  const core::Vec3 x = n->framePose().rotation.rotate({1, 0, 0});
  return std::atan2(x.y, x.x) * 180.0 / std::acos(-1.0);
}

TEST(CurvedBelt, CarriesABoxRoundItsCentreAtItsSpeed) {
  // radius 1 m at 0.5 m/s: 0.5 rad/s round the centre (0, 1); a small box on the centre
  // line 10 degrees in turns 1 rad (57.3 degrees) in 2 s, stays 1 m out and turns with it
  auto sim = compose(std::string(kFloor) + R"Y(pages:
  main:
    instances:
      curve1: {type: curved_belt}
      box1: {type: small_box, translation: [0.17365, 0.01519, 0.801], rotation: [0, 0, 1, 10]}
)Y",
                     {"conveyors/curved_belt", "items/small_box"});
  ASSERT_TRUE(sim);
  const auto around = [&sim] {
    const core::Vec3 p = position(*sim, "box1/box");
    return std::atan2(p.y - 1.0, p.x) * 180.0 / std::acos(-1.0);
  };
  runFor(*sim, 0.5);
  const double a = around(), yaw = heading(*sim, "box1/box");
  runFor(*sim, 2.0);
  EXPECT_NEAR(around() - a, 57.3, 57.3 * 0.03);
  EXPECT_NEAR(heading(*sim, "box1/box") - yaw, 57.3, 57.3 * 0.05) << "it turns with the belt";
  const core::Vec3 p = position(*sim, "box1/box");
  EXPECT_NEAR(std::hypot(p.x, p.y - 1.0), 1.0, 0.03) << "on the centre line still";
  EXPECT_NEAR(p.z, 0.8, 0.005) << "on the belt's top";
  EXPECT_DOUBLE_EQ(io(*sim, "curve1", "run"), 1.0);
  // the motor off: every piece of the belt stops
  write(*sim, "curve1", "run", 0);
  runFor(*sim, 0.5);
  const double b = around();
  runFor(*sim, 1.0);
  EXPECT_NEAR(around(), b, 0.2);
  // backwards, at 0.25 m/s: a quarter of a radian a second the other way
  write(*sim, "curve1", "speed", -0.25);
  runFor(*sim, 0.5);
  const double c = around();
  runFor(*sim, 2.0);
  EXPECT_NEAR(around() - c, -28.65, 28.65 * 0.05);
}

TEST(CurvedBelt, TakesABoxFromOneBeltToAnotherAtRightAngles) {
  // a 2 m belt ending at the curve's entry, the curve, a 2 m belt leaving its exit (1, 1)
  // along +y: 1.3 m + pi/2 m + 0.8 m at 0.5 m/s is 7.5 s; the box is then on the second belt
  auto sim = compose(std::string(kFloor) + R"Y(pages:
  main:
    instances:
      belt1: {type: belt_conveyor, translation: [-1, 0, 0]}
      curve1: {type: curved_belt}
      belt2: {type: belt_conveyor, translation: [1, 2, 0], rotation: [0, 0, 1, 90]}
      box1: {type: small_box, translation: [-1.3, 0, 0.801]}
)Y",
                     {"conveyors/belt_conveyor", "conveyors/curved_belt", "items/small_box"});
  ASSERT_TRUE(sim);
  runFor(*sim, 7.5);
  const core::Vec3 p = position(*sim, "box1/box");
  EXPECT_NEAR(p.x, 1.0, 0.06) << "on the second belt's centre line";
  EXPECT_NEAR(p.y, 1.8, 0.25);
  EXPECT_NEAR(p.z, 0.8, 0.005) << "on a belt's top all the way";
}

TEST(RollerConveyor, CarriesABoxAtItsSpeedOnRollersThatTurn) {
  // a medium box on two 2 m modules end to end at 0.8 m/s: 1.6 m in 2 s once it has settled,
  // across the joint; each roller (radius 30 mm) turns at 0.8 / 0.03 rad/s: 0.8 rad in 30 ms
  auto sim = compose(std::string(kFloor) + R"Y(pages:
  main:
    instances:
      rollers1: {type: roller_conveyor, translation: [-1, 0, 0], params: {speed: 0.8}}
      rollers2: {type: roller_conveyor, translation: [1, 0, 0], params: {speed: 0.8}}
      box1: {type: medium_box, translation: [-1.6, 0, 0.801]}
)Y",
                     {"conveyors/roller_conveyor", "items/medium_box"});
  ASSERT_TRUE(sim);
  runFor(*sim, 1.0);
  const core::Vec3 a = position(*sim, "box1/box");
  const std::string roller = "rollers1/rollers/roller16/axle/roller";
  const core::Quat r0 = sim->plant()->find(roller)->framePose().rotation;
  runFor(*sim, 0.03);
  const auto [axis, turned] = (sim->plant()->find(roller)->framePose().rotation * r0.conjugate()).toAxisAngle();
  EXPECT_NEAR(turned, 0.8, 0.8 * 0.03);
  EXPECT_NEAR(axis.y, 1.0, 0.01) << "about its axle, its top going +x";
  runFor(*sim, 1.97);
  const core::Vec3 b = position(*sim, "box1/box");
  EXPECT_NEAR((b.x - a.x) / 2.0, 0.8, 0.8 * 0.03);
  EXPECT_NEAR(b.y, 0.0, 0.01);
  EXPECT_NEAR(b.z, 0.8, 0.005) << "on the rollers' tops";
}

TEST(RollerConveyor, RunAndBackwardsDriveOneMotor) {
  // start 0: it stands; run carries the box along +x at 0.5 m/s, backwards along -x, and
  // off, the rollers stop and so does the box
  auto sim = compose(std::string(kFloor) + R"Y(pages:
  main:
    instances:
      rollers1: {type: roller_conveyor, params: {start: 0}}
      box1: {type: small_box, translation: [0, 0, 0.801]}
)Y",
                     {"conveyors/roller_conveyor", "items/small_box"});
  ASSERT_TRUE(sim);
  runFor(*sim, 1.0);
  EXPECT_DOUBLE_EQ(io(*sim, "rollers1", "run"), 0.0);
  EXPECT_NEAR(position(*sim, "box1/box").x, 0.0, 0.002) << "stands until driven";
  write(*sim, "rollers1", "run", 1);
  runFor(*sim, 0.5);
  double x = position(*sim, "box1/box").x;
  runFor(*sim, 1.0);
  EXPECT_NEAR(position(*sim, "box1/box").x - x, 0.5, 0.015) << "forwards at 0.5 m/s";
  write(*sim, "rollers1", "backwards", 1);
  EXPECT_DOUBLE_EQ(io(*sim, "rollers1", "run"), 0.0);
  EXPECT_DOUBLE_EQ(io(*sim, "rollers1", "backwards"), 1.0);
  runFor(*sim, 0.5);
  x = position(*sim, "box1/box").x;
  runFor(*sim, 1.0);
  EXPECT_NEAR(position(*sim, "box1/box").x - x, -0.5, 0.015) << "backwards at 0.5 m/s";
  write(*sim, "rollers1", "backwards", 0);
  runFor(*sim, 0.5);
  x = position(*sim, "box1/box").x;
  runFor(*sim, 1.0);
  EXPECT_NEAR(position(*sim, "box1/box").x, x, 0.003) << "off: stopped";
}

// ---------------------------------------------------------------------------------------
// the pusher

TEST(Pusher, AStrokeTakesStrokeOverSpeedAndTheLimitsSwitch) {
  // 0.6 m at 0.5 m/s: out in 1.2 s (the front limit 15 mm before the end), at 0.5 m/s on the
  // way; the back limit drops at once; back in 1.2 s too
  auto sim = compose(std::string(kFloor) + R"Y(pages:
  main:
    instances:
      pusher1: {type: pusher, params: {stroke: 0.6, speed: 0.5}}
)Y",
                     {"actuators/pusher"});
  ASSERT_TRUE(sim);
  runFor(*sim, 0.2);
  EXPECT_DOUBLE_EQ(io(*sim, "pusher1", "back_limit"), 1.0);
  EXPECT_DOUBLE_EQ(io(*sim, "pusher1", "front_limit"), 0.0);
  const scene::Node* slide = sim->plant()->find("pusher1/cylinder/slide");
  ASSERT_NE(slide, nullptr);
  write(*sim, "pusher1", "extend", 1);
  EXPECT_DOUBLE_EQ(io(*sim, "pusher1", "extend"), 1.0);
  const double t0 = sim->kernel().now();
  double back_off = -1, front_on = -1, x_at_03 = 0, x_at_08 = 0;
  while (sim->kernel().now() - t0 < 3.0 && front_on < 0) {
    sim->step();
    const double t = sim->kernel().now() - t0;
    if (back_off < 0 && io(*sim, "pusher1", "back_limit") == 0.0) back_off = t;
    if (io(*sim, "pusher1", "front_limit") != 0.0) front_on = t;
    if (std::abs(t - 0.3) < 1e-6) x_at_03 = sim->physics()->jointPosition(*slide);
    if (std::abs(t - 0.8) < 1e-6) x_at_08 = sim->physics()->jointPosition(*slide);
  }
  EXPECT_NEAR(front_on, 0.6 / 0.5, 0.06) << "stroke / speed, within 5 %";
  EXPECT_GT(back_off, 0.0);
  EXPECT_LT(back_off, 0.1) << "the back limit drops as the plate leaves";
  EXPECT_NEAR((x_at_08 - x_at_03) / 0.5, 0.5, 0.01) << "at its speed on the way";
  runFor(*sim, 0.3);
  EXPECT_NEAR(sim->physics()->jointPosition(*slide), 0.6, 0.002) << "out by its stroke";
  EXPECT_DOUBLE_EQ(io(*sim, "pusher1", "front_limit"), 1.0);
  write(*sim, "pusher1", "extend", 0);
  const double t1 = sim->kernel().now();
  double back_on = -1;
  while (sim->kernel().now() - t1 < 3.0 && back_on < 0) {
    sim->step();
    if (io(*sim, "pusher1", "back_limit") != 0.0) back_on = sim->kernel().now() - t1;
  }
  EXPECT_NEAR(back_on, 0.6 / 0.5, 0.06);
  EXPECT_DOUBLE_EQ(io(*sim, "pusher1", "front_limit"), 0.0);
}

TEST(Pusher, ItsControlPatternMakesOneStrokePerRequest) {
  // two requests: two strokes, two tokens on done, the valve closed and the plate home
  auto sim = compose(std::string(kFloor) + R"Y(pages:
  main:
    instances:
      pusher1: {type: pusher}
      pusher1_control: {type: pusher_control, part: pusher1}
    places:
      asks: {tokens: 2}
    transitions:
      ask: {}
    arcs:
      - asks -> ask
      - ask -> pusher1_control/request
)Y",
                     {"actuators/pusher"});
  ASSERT_TRUE(sim);
  const scene::Node* slide = sim->plant()->find("pusher1/cylinder/slide");
  ASSERT_NE(slide, nullptr);
  double reach = 0;
  int outs = 0;
  bool was_front = false;
  for (int i = 0; i < 600; ++i) {
    sim->step();
    reach = std::max(reach, sim->physics()->jointPosition(*slide));
    const bool front = io(*sim, "pusher1", "front_limit") != 0.0;
    if (front && !was_front) ++outs;
    was_front = front;
  }
  EXPECT_EQ(tokens(*sim, "main/pusher1_control/done"), 2);
  EXPECT_EQ(outs, 2);
  EXPECT_GT(reach, 1.0 - 0.015) << "out to the front limit";
  EXPECT_DOUBLE_EQ(io(*sim, "pusher1", "extend"), 0.0);
  EXPECT_DOUBLE_EQ(io(*sim, "pusher1", "back_limit"), 1.0);
  EXPECT_EQ(tokens(*sim, "main/pusher1_control/idle"), 1);
}

TEST(Pusher, ItsControlPatternGivesUpAStrokeThatIsBlocked) {
  // a wall 0.3 m in front of the plate: the stroke never reaches the front limit; after 1.5
  // times stroke/speed and 0.5 s (2 s) the plate comes back: done, and a jam counted
  auto sim = compose(std::string(kFloor) + R"Y(  - Transform: {translation: [0, 0, 0.9], children: [{Cube: {name: wall, size: [1, 0.1, 0.4]}}]}
pages:
  main:
    instances:
      pusher1: {type: pusher}
      pusher1_control: {type: pusher_control, part: pusher1}
    places:
      asks: {tokens: 1}
    transitions:
      ask: {}
    arcs:
      - asks -> ask
      - ask -> pusher1_control/request
)Y",
                     {"actuators/pusher"});
  ASSERT_TRUE(sim);
  runFor(*sim, 1.9);
  EXPECT_DOUBLE_EQ(io(*sim, "pusher1", "extend"), 1.0) << "still pushing against the wall";
  EXPECT_DOUBLE_EQ(io(*sim, "pusher1", "front_limit"), 0.0);
  runFor(*sim, 1.6);
  EXPECT_DOUBLE_EQ(io(*sim, "pusher1", "extend"), 0.0);
  EXPECT_DOUBLE_EQ(io(*sim, "pusher1", "back_limit"), 1.0);
  EXPECT_EQ(tokens(*sim, "main/pusher1_control/jams"), 1);
  EXPECT_EQ(tokens(*sim, "main/pusher1_control/done"), 1);
}

TEST(Pusher, PushesABoxOffABelt) {
  // a belt standing still, a medium box in front of the plate: one stroke and it is off the
  // far side (+y), on the floor
  auto sim = compose(std::string(kFloor) + R"Y(pages:
  main:
    instances:
      belt1: {type: belt_conveyor, params: {start: 0}}
      pusher1: {type: pusher}
      box1: {type: medium_box, translation: [0, 0, 0.801]}
)Y",
                     {"conveyors/belt_conveyor", "actuators/pusher", "items/medium_box"});
  ASSERT_TRUE(sim);
  runFor(*sim, 0.2);
  write(*sim, "pusher1", "extend", 1);
  runFor(*sim, 1.5);
  write(*sim, "pusher1", "extend", 0);
  runFor(*sim, 1.5);
  const core::Vec3 p = position(*sim, "box1/box");
  EXPECT_GT(p.y, 0.35 + 0.2);
  EXPECT_LT(p.z, 0.5) << "fell off the belt";
}

// ---------------------------------------------------------------------------------------
// the photo-eyes

/// A belt carrying a medium box (front face at x = -1) at 0.5 m/s past sensors at x = 0.5:
/// its front reaches them at 3 s, its back leaves at 3.8 s.
std::string beltWithBox(const std::string& sensors) {
  return std::string(kFloor) + R"Y(pages:
  main:
    instances:
      belt1: {type: belt_conveyor, params: {length: 4}}
      box1: {type: medium_box, translation: [-1.2, 0, 0.801]}
)Y" + sensors;
}

/// When input `io` of `part` went on and off while `sim` ran `seconds` (-1: never).
std::pair<double, double> onOff(Simulation& sim, const std::string& part, const std::string& io_name, double seconds,
                                int* switches = nullptr) {
  double on = -1, off = -1;
  bool was = io(sim, part, io_name) != 0.0;
  int n = 0;
  const auto steps = static_cast<int>(std::llround(seconds / sim.model().settings.dt));
  for (int i = 0; i < steps; ++i) {
    sim.step();
    const bool now = io(sim, part, io_name) != 0.0;
    if (now != was) ++n;
    if (now && !was && on < 0) on = sim.kernel().now();
    if (!now && was && off < 0) off = sim.kernel().now();
    was = now;
  }
  if (switches) *switches = n;
  return {on, off};
}

TEST(ThroughBeam, SeesAnItemCrossingItAndNothingElse) {
  // the belt, its rails and the posts never break the beam; the box does from 3 s to 3.8 s,
  // and while it does the box is all the beam holds
  auto sim = compose(beltWithBox("      eye1: {type: through_beam, translation: [0.5, 0, 0]}\n"),
                     {"conveyors/belt_conveyor", "items/medium_box", "sensors/through_beam"});
  ASSERT_TRUE(sim);
  int switches = 0;
  const auto [on, off] = onOff(*sim, "eye1", "blocked", 3.4, &switches);
  EXPECT_NEAR(on, 3.0, 0.05);
  const scene::Node* ray = sim->plant()->find("eye1/sender/beam/ray");
  ASSERT_NE(ray, nullptr);
  const auto& items = sim->reading(ray->handle()).get<std::vector<scene::NodeHandle>>(0);
  ASSERT_EQ(items.size(), 1u);
  EXPECT_EQ(sim->plant()->resolve(items[0])->path(), "box1/box");
  EXPECT_EQ(colour(*sim, "eye1/receiver/led", "emissive")[0], 1.0) << "the receiver's LED is lit";
  const auto [on2, off2] = onOff(*sim, "eye1", "blocked", 2.0, &switches);
  EXPECT_NEAR(off2, 3.8, 0.05);
  EXPECT_LT(on2, 0.0) << "blocked once only";
  EXPECT_EQ(switches, 1) << "on until the box has passed, then off";
  EXPECT_EQ(colour(*sim, "eye1/receiver/led", "emissive")[0], 0.0);
  (void)off;
}

TEST(ThroughBeam, AnEmptyBeltNeverBreaksTheBeam) {
  // a running belt with nothing on it, and a pusher plate going out and back beside the
  // beam: never blocked
  auto sim = compose(std::string(kFloor) + R"Y(pages:
  main:
    instances:
      belt1: {type: belt_conveyor}
      eye1: {type: through_beam, translation: [0.4, 0, 0]}
      pusher1: {type: pusher}
)Y",
                     {"conveyors/belt_conveyor", "sensors/through_beam", "actuators/pusher"});
  ASSERT_TRUE(sim);
  write(*sim, "pusher1", "extend", 1);
  int switches = 0;
  onOff(*sim, "eye1", "blocked", 1.5, &switches);
  write(*sim, "pusher1", "extend", 0);
  onOff(*sim, "eye1", "blocked", 1.5, &switches);
  EXPECT_EQ(switches, 0);
}

TEST(DiffuseSensor, DetectsABoxWithinItsRangeOnly) {
  // two eyes at x = 0.5 and 1.0: the box's near face is 0.17 m from the lens, so the eye of
  // range 0.7 sees it and the eye of range 0.1 does not
  auto sim = compose(beltWithBox("      near: {type: diffuse_sensor, translation: [0.5, 0, 0]}\n"
                                 "      short: {type: diffuse_sensor, translation: [1.0, 0, 0], params: {range: 0.1}}\n"),
                     {"conveyors/belt_conveyor", "items/medium_box", "sensors/diffuse_sensor"});
  ASSERT_TRUE(sim);
  bool short_saw = false;
  double on = -1, off = -1;
  bool was = false;
  for (int i = 0; i < 600; ++i) {
    sim->step();
    short_saw = short_saw || io(*sim, "short", "detected") != 0.0;
    const bool now = io(*sim, "near", "detected") != 0.0;
    // the colour of what it sees: the box's colour_code (5, brown cardboard), else 0
    EXPECT_EQ(io(*sim, "near", "colour"), now ? 5.0 : 0.0) << sim->kernel().now();
    if (now && !was && on < 0) on = sim->kernel().now();
    if (!now && was && off < 0) off = sim->kernel().now();
    was = now;
  }
  EXPECT_NEAR(on, 3.0, 0.05);
  EXPECT_NEAR(off, 3.8, 0.05);
  EXPECT_FALSE(short_saw);
}

/// The part file's own demo, running.
std::unique_ptr<Simulation> demoOf(const std::string& rel) {
  core::Diagnostics diags;
  auto m = loadModel(partPath(rel), diags);
  EXPECT_TRUE(m) << diags.str();
  if (!m) return nullptr;
  auto sim = Simulation::create(*m, diags);
  EXPECT_TRUE(sim) << diags.str();
  return sim;
}

/// Each step's value of I/O `io` of `part` over `seconds` (from the demo's start): the times
/// (to 0.01 s) at which it changed, with the value it took.
std::vector<std::pair<double, double>> changesOf(Simulation& sim, const std::string& part, const std::string& io,
                                                 double seconds) {
  std::vector<std::pair<double, double>> out;
  double last = 0;
  while (sim.kernel().now() < seconds - 1e-9) {
    sim.step();
    const double v = ::gdpn::model::io(sim, part, io);
    if (v != last) out.emplace_back(std::round(sim.kernel().now() * 100) / 100, v);
    last = v;
  }
  return out;
}

TEST(ProximitySensors, TheInductiveOneSeesMetalOnlyTheCapacitiveOneEverything) {
  // the demos carry a metal base (front 0.3 m from the head at 0.5 m/s), then a plastic lid
  auto inductive = demoOf("sensors/inductive_sensor");
  auto capacitive = demoOf("sensors/capacitive_sensor");
  ASSERT_TRUE(inductive && capacitive);
  using C = std::vector<std::pair<double, double>>;
  // the base's 0.3 m pass the ray in 0.6 s; the lid's too, 1.2 s later
  EXPECT_EQ(changesOf(*inductive, "inductive_sensor1", "detected", 4), (C{{0.95, 1}, {1.55, 0}}));
  EXPECT_EQ(changesOf(*capacitive, "capacitive_sensor1", "detected", 4), (C{{0.95, 1}, {1.55, 0}, {2.14, 1}, {2.74, 0}}));
}

TEST(CodeReader, ReadsTheCodeOfTheItemUnderIt) {
  auto sim = demoOf("sensors/code_reader");
  ASSERT_TRUE(sim);
  using C = std::vector<std::pair<double, double>>;
  EXPECT_EQ(changesOf(*sim, "code_reader1", "code", 4), (C{{0.95, 1}, {1.55, 0}, {2.14, 2}, {2.74, 0}}));
}

TEST(Chute, AnItemSlidesDownAtGravitysPullLessFriction) {
  // its demo: a box at rest on the slope (atan(0.4 / 1.0) = 21.8 degrees), friction sqrt(0.1 *
  // 0.1) = 0.1: it slides with a = g (sin - 0.1 cos), 2.73 m/s^2, so 0.342 m along the slope in
  // 0.5 s
  auto sim = demoOf("conveyors/chute");
  ASSERT_TRUE(sim);
  const double angle = std::atan2(0.4, 1.0);
  const double a = 9.81 * (std::sin(angle) - 0.1 * std::cos(angle));
  const auto start = sim->plant()->find("box/box")->framePose().position;
  runFor(*sim, 0.5);
  const auto p = sim->plant()->find("box/box")->framePose().position;
  const double along = std::hypot(p.x - start.x, p.z - start.z);
  EXPECT_NEAR(along, 0.5 * a * 0.25, 0.05 * 0.5 * a * 0.25);
  EXPECT_NEAR((start.z - p.z) / (p.x - start.x), 0.4, 0.01) << "down the slope";
  EXPECT_NEAR(p.y, 0.0, 1e-3);
}

TEST(ScaleConveyor, WeighsWhatRidesOnItAndCarriesIt) {
  // a medium box (1.2 kg), then a metal base (4.5 kg), across the scale from belt to belt
  auto sim = demoOf("conveyors/scale_conveyor");
  ASSERT_TRUE(sim);
  std::vector<double> masses;
  while (sim->kernel().now() < 6 - 1e-9) {
    sim->step();
    const double m = io(*sim, "scale1", "mass");
    EXPECT_EQ(m != 0.0, io(*sim, "scale1", "loaded") != 0.0);
    if (m != 0 && (masses.empty() || masses.back() != m)) masses.push_back(m);
  }
  EXPECT_EQ(masses, (std::vector<double>{1.2, 4.5}));
  // both rode on onto the belt out
  EXPECT_GT(sim->plant()->find("box/box")->framePose().position.x, 0.6);
  EXPECT_GT(sim->plant()->find("base/base")->framePose().position.x, 0.3);
}

TEST(PickAndPlace, ItsControlPatternMovesAnItemFromPickToPlace) {
  // the demo: a metal base on a table under the cup's home (x = 0), one request; the pattern
  // goes down, grips, lifts it, carries it 1.5 m at 0.6 m/s, sets it down, lets go and goes home
  auto sim = demoOf("actuators/pick_and_place");
  ASSERT_TRUE(sim);
  double lifted = 0, carried_from = -1, carried_to = -1;
  while (sim->kernel().now() < 9 - 1e-9) {
    sim->step();
    const auto p = sim->plant()->find("base/base")->framePose().position;
    lifted = std::max(lifted, p.z);
    const double x = io(*sim, "pp1", "x_at");
    if (io(*sim, "pp1", "holding") != 0.0) {
      if (carried_from < 0 && io(*sim, "pp1", "x") > 0) carried_from = sim->kernel().now();  // sent on
      if (x > 1.49) carried_to = carried_to < 0 ? sim->kernel().now() : carried_to;
    }
  }
  const auto p = sim->plant()->find("base/base")->framePose().position;
  EXPECT_NEAR(p.x, 1.5, 0.01);
  EXPECT_NEAR(p.y, 0.0, 0.01);
  EXPECT_NEAR(p.z, 0.8, 0.005) << "set down on the second table";
  EXPECT_GT(lifted, 1.1) << "lifted clear of the tables";
  EXPECT_NEAR(carried_to - carried_from, 1.5 / 0.6, 0.15) << "carried at the carriage's speed: " << carried_from << " to " << carried_to;
  EXPECT_EQ(io(*sim, "pp1", "holding"), 0.0);
  EXPECT_LT(io(*sim, "pp1", "x_at"), 0.005) << "home again";
  EXPECT_EQ(tokens(*sim, "main/pp1_control/idle"), 1) << "the move done";
}

// ---------------------------------------------------------------------------------------
// the remover and the bin

TEST(Remover, TakesAwayAndCountsWhatEntersIt) {
  // three boxes fall into it and are gone, counted on its place and its input; a fourth
  // beside it stays
  auto sim = compose(std::string(kFloor) + R"Y(pages:
  main:
    instances:
      remover1: {type: remover}
      box1: {type: small_box, translation: [0, 0, 2.0]}
      box2: {type: small_box, translation: [0.1, 0.2, 2.5]}
      box3: {type: small_box, translation: [-0.1, -0.2, 3.0]}
      box4: {type: small_box, translation: [2, 0, 0.5]}
)Y",
                     {"sources_and_sinks/remover", "items/small_box"});
  ASSERT_TRUE(sim);
  EXPECT_DOUBLE_EQ(io(*sim, "remover1", "removed"), 0.0);
  runFor(*sim, 1.5);
  EXPECT_EQ(tokens(*sim, "main/remover1/removed"), 3);
  EXPECT_DOUBLE_EQ(io(*sim, "remover1", "removed"), 3.0);
  for (const char* gone : {"box1/box", "box2/box", "box3/box"}) EXPECT_EQ(sim->plant()->find(gone), nullptr) << gone;
  EXPECT_NE(sim->plant()->find("box4/box"), nullptr);
}

TEST(Bin, CountsWhatFallsIn) {
  // three boxes fall in, one beside it: 3 inside, 3 entries
  auto sim = compose(std::string(kFloor) + R"Y(pages:
  main:
    instances:
      bin1: {type: bin}
      box1: {type: small_box, translation: [-0.2, 0, 1.0]}
      box2: {type: small_box, translation: [0.2, 0.1, 1.3]}
      box3: {type: small_box, translation: [0, -0.15, 1.6]}
      box4: {type: small_box, translation: [1.5, 0, 1.0]}
)Y",
                     {"storage/bin", "items/small_box"});
  ASSERT_TRUE(sim);
  runFor(*sim, 2.0);
  EXPECT_DOUBLE_EQ(io(*sim, "bin1", "count"), 3.0);
  EXPECT_EQ(tokens(*sim, "main/bin1/entered"), 3);
  EXPECT_LT(position(*sim, "box1/box").z, 0.1) << "on the bin's bottom";
}

// ---------------------------------------------------------------------------------------
// the emitter

/// An emitter with `params` over a 6 m belt at `speed` that carries its boxes away, into a
/// remover at its end.
std::unique_ptr<Simulation> emitterOverBelt(const std::string& params, double speed = 0.5,
                                            const std::string& more = "") {
  return compose(std::string(kFloor) + "pages:\n  main:\n    instances:\n"
                 "      belt1: {type: belt_conveyor, translation: [2.5, 0, 0], params: {length: 6, speed: " +
                     std::to_string(speed) + "}}\n      remover1: {type: remover, translation: [5.5, 0, 0]}\n      emitter1: {type: emitter, params: " + params + "}\n" + more,
                 {"conveyors/belt_conveyor", "sources_and_sinks/emitter", "sources_and_sinks/remover"});
}

/// The model times at which `emitted` grew while `sim` ran `seconds`.
std::vector<double> emissions(Simulation& sim, double seconds) {
  std::vector<double> at;
  double count = io(sim, "emitter1", "emitted");
  const auto steps = static_cast<int>(std::llround(seconds / sim.model().settings.dt));
  for (int i = 0; i < steps; ++i) {
    sim.step();
    const double now = io(sim, "emitter1", "emitted");
    for (; count < now; count += 1) at.push_back(sim.kernel().now());
  }
  return at;
}

/// The boxes the emitter made, in order: each one's colour datum and its Material's diffuse.
std::vector<std::pair<std::string, std::array<double, 3>>> boxesMade(const Simulation& sim) {
  std::vector<std::pair<std::string, std::array<double, 3>>> out;
  const scene::Node* items = sim.plant()->find("emitter1/items");
  EXPECT_NE(items, nullptr);
  if (!items) return out;
  for (const auto& holder : items->children()) {
    const scene::Node* box = holder->find("box");
    EXPECT_NE(box, nullptr);
    if (!box) continue;
    EXPECT_EQ(std::get<std::string>(*box->datum("material")), "cardboard");
    out.emplace_back(std::get<std::string>(*box->datum("colour")),
                     colour(sim, box->path() + "/look", "diffuse"));
  }
  return out;
}

TEST(Emitter, RedAndBlueInTurnEvery4sByDefault) {
  // the defaults are the station's: a small box every 4 s, red and blue in turn, each on the
  // belt's top under the portal
  auto sim = emitterOverBelt("{}");
  ASSERT_TRUE(sim);
  const auto at = emissions(*sim, 12.5);
  ASSERT_EQ(at.size(), 4u);
  for (std::size_t i = 0; i < at.size(); ++i) EXPECT_NEAR(at[i], 4.0 * static_cast<double>(i), 0.03) << i;
  // the first has reached the remover at the belt's end (5 m at 0.5 m/s); the others ride on
  EXPECT_EQ(tokens(*sim, "main/remover1/removed"), 1);
  const auto boxes = boxesMade(*sim);
  ASSERT_EQ(boxes.size(), 3u);
  const std::array<double, 3> red{0.8, 0.12, 0.1}, blue{0.1, 0.3, 0.85};
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    const bool even = (i + 1) % 2 == 0;  // box i + 1 of 0, 1, 2, 3
    EXPECT_EQ(boxes[i].first, even ? "red" : "blue") << i;
    EXPECT_EQ(boxes[i].second, even ? red : blue) << i;
  }
  // the latest stands on the belt, carried off
  const scene::Node* last = sim->plant()->find("emitter1/items")->children().back()->find("box");
  EXPECT_NEAR(last->framePose().position.z, 0.8, 0.005);
  EXPECT_GT(last->framePose().position.x, 0.1);
  EXPECT_DOUBLE_EQ(io(*sim, "emitter1", "emitted"), 4.0);
}

TEST(Emitter, ShuffledItsColoursComeAtRandomFromTheSeed) {
  // shuffle: 1 with red and blue, a box a second onto a fast belt, for 40 s: both colours
  // about as often (of 40 draws, between 10 and 30 red: more than 3 sigma), not in turn, and the
  // same seed gives the same order
  const auto order = [](std::uint64_t seed) {
    std::string out;
    auto sim = compose(std::string(kFloor) + "pages:\n  main:\n    instances:\n"
                       "      belt1: {type: belt_conveyor, translation: [2.5, 0, 0], params: {length: 6, speed: 2}}\n"
                       "      remover1: {type: remover, translation: [5.5, 0, 0]}\n"
                       "      emitter1: {type: emitter, params: {period: 1, shuffle: 1}}\n",
                       {"conveyors/belt_conveyor", "sources_and_sinks/emitter", "sources_and_sinks/remover"},
                       seed);
    if (!sim) return out;
    // each box's colour when it is made (the newest is the items' last)
    std::int64_t seen = 0;
    for (int i = 0; i < 4000; ++i) {
      sim->step();
      const scene::Node* items = sim->plant()->find("emitter1/items");
      const auto made = static_cast<std::int64_t>(io(*sim, "emitter1", "emitted"));
      for (; seen < made; ++seen) {
        const scene::Node* box = items->children().back()->find("box");
        out += std::get<std::string>(*box->datum("colour")) == "red" ? 'r' : 'b';
      }
    }
    return out;
  };
  const std::string a = order(7);
  ASSERT_EQ(a.size(), 40u);
  const auto reds = std::count(a.begin(), a.end(), 'r');
  EXPECT_GT(reds, 10);
  EXPECT_LT(reds, 30);
  EXPECT_NE(a.find("rr"), std::string::npos) << a << ": not in turn";
  EXPECT_EQ(order(7), a) << "the seed's order";
  EXPECT_NE(order(8), a) << "another seed, another order";
}

TEST(Emitter, AtRandomItsIntervalsAverageThePeriod) {
  // random: 1, period 1 s, small boxes, a fast belt: 60 s make about 60 boxes at
  // irregular intervals of about 1 s on average (the seed fixes them)
  auto sim = emitterOverBelt("{period: 1, random: 1, size: 1, colours: 3}", 1.5);
  ASSERT_TRUE(sim);
  const auto at = emissions(*sim, 60.0);
  ASSERT_GE(at.size(), 10u);
  const double mean = (at.back() - at.front()) / static_cast<double>(at.size() - 1);
  EXPECT_GT(mean, 0.75);
  EXPECT_LT(mean, 1.33);
  double shortest = 1e9, longest = 0;
  for (std::size_t i = 1; i < at.size(); ++i) {
    shortest = std::min(shortest, at[i] - at[i - 1]);
    longest = std::max(longest, at[i] - at[i - 1]);
  }
  EXPECT_LT(shortest, 0.5);
  EXPECT_GT(longest, 2.0);
  EXPECT_EQ(tokens(*sim, "main/remover1/removed") + static_cast<std::int64_t>(boxesMade(*sim).size()),
            static_cast<std::int64_t>(at.size()))
      << "every box made is on the belt or was taken at its end";
  auto sim2 = emitterOverBelt("{period: 1, colours: 3}", 1.5);
  ASSERT_TRUE(sim2);
  runFor(*sim2, 2.5);
  const auto boxes = boxesMade(*sim2);
  ASSERT_EQ(boxes.size(), 3u);
  EXPECT_EQ(boxes[0].first, "red");
  EXPECT_EQ(boxes[1].first, "blue");
  EXPECT_EQ(boxes[2].first, "green");
}

TEST(Emitter, OnRequestOnePerRisingEdgeOrToken) {
  // mode 1: nothing by itself; emit held on gives one box, off and on again another; a
  // token on request one more
  auto sim = emitterOverBelt("{mode: 1}", 0.5, R"Y(    places:
      asks: {}
    transitions:
      ask: {guard: 'sim.time > 5'}
    arcs:
      - asks -> ask
      - ask -> emitter1/request
)Y");
  ASSERT_TRUE(sim);
  EXPECT_TRUE(emissions(*sim, 1.0).empty());
  write(*sim, "emitter1", "emit", 1);
  EXPECT_EQ(emissions(*sim, 1.5).size(), 1u);
  write(*sim, "emitter1", "emit", 0);
  EXPECT_TRUE(emissions(*sim, 0.5).empty());
  write(*sim, "emitter1", "emit", 1);
  EXPECT_EQ(emissions(*sim, 1.0).size(), 1u);
  EXPECT_EQ(colour(*sim, "emitter1/portal/lamp", "emissive")[2], 1.0) << "the request lamp is lit";
  EXPECT_EQ(tokens(*sim, "main/emitter1/emitted"), 2);
}

TEST(Emitter, WaitsForItsOutletAndStopsAtItsLimit) {
  // a belt standing still: the first box stays in the outlet, so no second comes; with the
  // belt running, limit: 2 stops it at two
  auto sim = compose(std::string(kFloor) + R"Y(pages:
  main:
    instances:
      belt1: {type: belt_conveyor, translation: [2.5, 0, 0], params: {length: 6, start: 0}}
      emitter1: {type: emitter, params: {period: 1, limit: 2}}
)Y",
                     {"conveyors/belt_conveyor", "sources_and_sinks/emitter"});
  ASSERT_TRUE(sim);
  EXPECT_EQ(emissions(*sim, 3.0).size(), 1u);
  EXPECT_DOUBLE_EQ(io(*sim, "emitter1", "occupied"), 1.0);
  write(*sim, "belt1", "run", 1);
  EXPECT_EQ(emissions(*sim, 6.0).size(), 1u) << "the one waiting, then no more";
  EXPECT_DOUBLE_EQ(io(*sim, "emitter1", "emitted"), 2.0);
}

// ---------------------------------------------------------------------------------------
// the operator's parts

TEST(StackLight, EachOutputLightsItsLamp) {
  auto sim = compose(std::string(kFloor) + "pages:\n  main:\n    instances:\n      light1: {type: stack_light}\n",
                     {"operator/stack_light"});
  ASSERT_TRUE(sim);
  runFor(*sim, 0.1);
  const std::array<double, 3> dark{0, 0, 0};
  for (const char* lamp : {"red", "amber", "green"}) EXPECT_EQ(colour(*sim, std::string("light1/lamps/") + lamp, "emissive"), dark);
  write(*sim, "light1", "red", 1);
  write(*sim, "light1", "green", 1);
  runFor(*sim, 0.02);
  EXPECT_DOUBLE_EQ(io(*sim, "light1", "red"), 1.0);
  EXPECT_DOUBLE_EQ(io(*sim, "light1", "amber"), 0.0);
  EXPECT_EQ(colour(*sim, "light1/lamps/red", "emissive"), (std::array<double, 3>{1, 0, 0}));
  EXPECT_EQ(colour(*sim, "light1/lamps/amber", "emissive"), dark);
  EXPECT_EQ(colour(*sim, "light1/lamps/green", "emissive"), (std::array<double, 3>{0, 1, 0}));
  write(*sim, "light1", "red", 0);
  write(*sim, "light1", "amber", 1);
  runFor(*sim, 0.02);
  EXPECT_EQ(colour(*sim, "light1/lamps/red", "emissive"), dark);
  EXPECT_EQ(colour(*sim, "light1/lamps/amber", "emissive"), (std::array<double, 3>{1, 0.6, 0}));
}

TEST(StackLight, AForcedOutputHoldsItsLamp) {
  // forced on, the red lamp stays lit whatever is written; released, it takes what was
  // written meanwhile (off)
  auto sim = compose(std::string(kFloor) + "pages:\n  main:\n    instances:\n      light1: {type: stack_light}\n",
                     {"operator/stack_light"});
  ASSERT_TRUE(sim);
  std::string why;
  const auto light = sim->parts()->find("light1", why);
  ASSERT_TRUE(light) << why;
  ASSERT_TRUE(sim->parts()->force(*light, "red", 1, why)) << why;
  runFor(*sim, 0.03);
  EXPECT_EQ(colour(*sim, "light1/lamps/red", "emissive"), (std::array<double, 3>{1, 0, 0}));
  write(*sim, "light1", "red", 0);
  runFor(*sim, 0.03);
  EXPECT_DOUBLE_EQ(io(*sim, "light1", "red"), 1.0);
  EXPECT_EQ(colour(*sim, "light1/lamps/red", "emissive"), (std::array<double, 3>{1, 0, 0}));
  ASSERT_TRUE(sim->parts()->release(*light, "red"));
  runFor(*sim, 0.03);
  EXPECT_DOUBLE_EQ(io(*sim, "light1", "red"), 0.0);
  EXPECT_EQ(colour(*sim, "light1/lamps/red", "emissive"), (std::array<double, 3>{0, 0, 0}));
}

TEST(PushButton, AClickOnItsHeadPressesIt) {
  // a click straight down on the head: pressed in that step, one press counted; a click
  // beside it: nothing
  auto sim = compose(std::string(kFloor) + "pages:\n  main:\n    instances:\n      button1: {type: push_button}\n",
                     {"operator/push_button"});
  ASSERT_TRUE(sim);
  const auto click = [](double t, double x) {
    sensors::InputEvent e;
    e.t = t;
    e.kind = sensors::InputEvent::Kind::Click;
    e.ray = {{x, 0, 2}, {0, 0, -1}};
    return e;
  };
  sim->setInput({click(0.5, 0.0), click(1.0, 0.5)});
  int pressed_steps = 0;
  for (int i = 0; i < 150; ++i) {
    sim->step();
    if (io(*sim, "button1", "pressed") != 0.0) {
      ++pressed_steps;
      EXPECT_NEAR(sim->kernel().now(), 0.5, 0.011);
    }
  }
  EXPECT_EQ(pressed_steps, 1);
  EXPECT_DOUBLE_EQ(io(*sim, "button1", "presses"), 1.0);
  EXPECT_EQ(tokens(*sim, "main/button1/presses"), 1);
}

/// A click straight down at (x, 0) at `t` s, as the IDE's world view or `--input` gives one.
sensors::InputEvent clickAt(double t, double x) {
  sensors::InputEvent e;
  e.t = t;
  e.kind = sensors::InputEvent::Kind::Click;
  e.ray = {{x, 0, 2}, {0, 0, -1}};
  return e;
}

TEST(EmergencyStop, AClickLatchesItUntilTheNextClickReleasesIt) {
  auto sim = compose(std::string(kFloor) + "pages:\n  main:\n    instances:\n      stop1: {type: emergency_stop}\n",
                     {"operator/emergency_stop"});
  ASSERT_TRUE(sim);
  // latched at 0.5 s, a click beside it at 1.0 s changes nothing, released at 1.5 s
  sim->setInput({clickAt(0.5, 0.0), clickAt(1.0, 0.5), clickAt(1.5, 0.01)});
  const double top = sim->plant()->find("stop1/head")->vec3(scene::field::Transform::Translation).z;
  std::map<double, std::pair<double, double>> seen;  // time: latched, released
  for (int i = 0; i < 200; ++i) {
    sim->step();
    const double t = std::round(sim->kernel().now() * 100) / 100;
    seen[t] = {io(*sim, "stop1", "latched"), io(*sim, "stop1", "released")};
    if (t == 1.2) {
      EXPECT_EQ(tokens(*sim, "main/stop1/latched"), 1);
      EXPECT_NEAR(sim->plant()->find("stop1/head")->vec3(scene::field::Transform::Translation).z, top - 0.015, 1e-12)
          << "the head sinks while latched";
    }
  }
  EXPECT_EQ(seen[0.4], (std::pair<double, double>{0, 1}));
  EXPECT_EQ(seen[0.6], (std::pair<double, double>{1, 0}));
  EXPECT_EQ(seen[1.4], (std::pair<double, double>{1, 0})) << "a click beside it does not release it";
  EXPECT_EQ(seen[1.6], (std::pair<double, double>{0, 1}));
  EXPECT_EQ(tokens(*sim, "main/stop1/latched"), 0);
}

TEST(SelectorSwitch, EachClickTurnsItToTheOtherSide) {
  auto sim = compose(std::string(kFloor) + "pages:\n  main:\n    instances:\n      a: {type: selector_switch}\n"
                                           "      b: {type: selector_switch, translation: [2, 0, 0], params: {start: 1}}\n",
                     {"operator/selector_switch"});
  ASSERT_TRUE(sim);
  sim->setInput({clickAt(0.5, 0.0), clickAt(1.0, 2.0), clickAt(1.5, 0.0)});
  const auto knob = [&](const std::string& path) {
    return sim->plant()->find(path + "/head/knob")->value(scene::field::Transform::Rotation);
  };
  runFor(*sim, 0.3);
  EXPECT_EQ(io(*sim, "a", "on"), 0.0);
  EXPECT_EQ(io(*sim, "b", "on"), 1.0) << "start: 1";
  runFor(*sim, 0.5);  // 0.8 s
  EXPECT_EQ(io(*sim, "a", "on"), 1.0);
  EXPECT_EQ(tokens(*sim, "main/a/on"), 1);
  EXPECT_EQ((std::get<std::array<double, 4>>(knob("a"))[3]), -45.0) << "turned right";
  runFor(*sim, 0.5);  // 1.3 s
  EXPECT_EQ(io(*sim, "b", "on"), 0.0);
  runFor(*sim, 0.5);  // 1.8 s
  EXPECT_EQ(io(*sim, "a", "on"), 0.0);
  EXPECT_EQ((std::get<std::array<double, 4>>(knob("a"))[3]), 45.0) << "turned left";
}

TEST(Beacon, FlashesAtItsRateWhileOnOrLightsSteady) {
  auto sim = compose(std::string(kFloor) + "pages:\n  main:\n    instances:\n      a: {type: beacon}\n"
                                           "      b: {type: beacon, translation: [1, 0, 0], params: {flash: 0}}\n",
                     {"operator/beacon"});
  ASSERT_TRUE(sim);
  runFor(*sim, 0.2);
  EXPECT_EQ(io(*sim, "a", "lit"), 0.0);
  write(*sim, "a", "on", 1);
  write(*sim, "b", "on", 1);
  // 2 Hz: lit a quarter second, dark a quarter second; b steady
  int changes = 0, b_dark = 0;
  double last = io(*sim, "a", "lit");
  for (int i = 0; i < 200; ++i) {  // 2 s
    sim->step();
    const double now = io(*sim, "a", "lit");
    changes += now != last ? 1 : 0;
    last = now;
    if (i > 5) b_dark += io(*sim, "b", "lit") == 0.0 ? 1 : 0;
  }
  EXPECT_EQ(changes, 8);
  EXPECT_EQ(b_dark, 0);
  EXPECT_EQ(colour(*sim, "b/lamp", "emissive"), (std::array<double, 3>{1.0, 0.55, 0.0}));
  write(*sim, "a", "on", 0);
  write(*sim, "b", "on", 0);
  runFor(*sim, 0.6);
  EXPECT_EQ(io(*sim, "a", "lit"), 0.0);
  EXPECT_EQ(io(*sim, "b", "lit"), 0.0);
  EXPECT_EQ(colour(*sim, "b/lamp", "emissive"), (std::array<double, 3>{0, 0, 0}));
}

// ---------------------------------------------------------------------------------------
// the parts together: issue 54's station

TEST(Station, RedBoxesGoToTheBinBlueOnesToTheRemover) {
  // the emitter's defaults (red and blue in turn every 4 s) over a belt; a photo-eye 0.3 m
  // past the pusher (just beyond its plate, which it would see) sees a box's front when the
  // box is in front of the plate; a red one stops
  // the belt and asks the pusher's control pattern for a stroke into the bin; at done the belt
  // runs again; blue ones ride on into the remover at the belt's end
  auto sim = compose(std::string(kFloor) + R"Y(pages:
  main:
    instances:
      emitter1: {type: emitter}
      belt1: {type: belt_conveyor, translation: [1.5, 0, 0], params: {length: 4}}
      pusher1: {type: pusher, translation: [2, 0, 0]}
      pusher1_control: {type: pusher_control, part: pusher1}
      eye1: {type: diffuse_sensor, translation: [2.3, 0, 0]}
      bin1: {type: bin, translation: [2, 0.95, 0], params: {length: 1.2, width: 1.0}}
      remover1: {type: remover, translation: [3.5, 0, 0]}
    places:
      eye: {sensors: {c0: eye1/head/beam/ray}}
      ready: {tokens: 1}
      pushing: {}
    transitions:
      red:
        pre_fire: 'sim.part("belt1").run = False'
      resume:
        pre_fire: 'sim.part("belt1").run = True'
    arcs:
      - {from: eye, to: red, condition: 'c0.active and c0.items[0].data.colour == "red"'}
      - ready -> red
      - red -> pushing
      - red -> pusher1_control/request
      - pushing -> resume
      - pusher1_control/done -> resume
      - resume -> ready
)Y",
                     {"sources_and_sinks/emitter", "conveyors/belt_conveyor", "actuators/pusher",
                      "sensors/diffuse_sensor", "storage/bin", "sources_and_sinks/remover"});
  ASSERT_TRUE(sim);
  runFor(*sim, 120.0);
  ASSERT_FALSE(sim->scriptHalt()) << sim->scriptHalt()->message;
  const auto emitted = static_cast<std::int64_t>(io(*sim, "emitter1", "emitted"));
  const auto removed = tokens(*sim, "main/remover1/removed");
  const auto binned = static_cast<std::int64_t>(io(*sim, "bin1", "count"));
  EXPECT_EQ(emitted, 30);
  EXPECT_GE(binned, 13);
  EXPECT_GE(removed, 13);
  EXPECT_EQ(tokens(*sim, "main/pusher1_control/jams"), 0);
  EXPECT_EQ(tokens(*sim, "main/bin1/entered"), binned) << "what went in stayed in";
  // every box made is in the bin (red), taken by the remover, or still on the belt before it
  int in_bin = 0, on_belt = 0;
  for (const auto& holder : sim->plant()->find("emitter1/items")->children()) {
    const scene::Node* box = holder->find("box");
    ASSERT_NE(box, nullptr);
    const core::Vec3 p = box->framePose().position;
    const auto& colour_name = std::get<std::string>(*box->datum("colour"));
    if (p.y > 0.45) {
      ++in_bin;
      EXPECT_EQ(colour_name, "red") << box->path();
      EXPECT_LT(p.z, 0.75) << box->path() << " lies in the bin or its heap";
    } else {
      ++on_belt;
      EXPECT_NEAR(p.z, 0.8, 0.01) << box->path() << " is on the belt";
      EXPECT_TRUE(colour_name == "blue" || p.x < 2.3) << box->path() << ": no red box rides past the pusher";
    }
  }
  EXPECT_EQ(in_bin, binned);
  EXPECT_EQ(in_bin + on_belt + removed, emitted);
}

TEST(Station, ThePusherSortPatternSortsByColourWithItsRolesFilled) {
  // the same station with the pusher's other pattern: it watches the eye for red (colour 1),
  // stops the belt it uses, strokes, and runs it again; the stack light follows
  auto sim = compose(std::string(kFloor) + R"Y(pages:
  main:
    instances:
      emitter1: {type: emitter}
      belt1: {type: belt_conveyor, translation: [1.5, 0, 0], params: {length: 4}}
      pusher1: {type: pusher, translation: [2, 0, 0]}
      eye1: {type: diffuse_sensor, translation: [2.3, 0, 0]}
      bin1: {type: bin, translation: [2, 0.95, 0], params: {length: 1.2, width: 1.0}}
      remover1: {type: remover, translation: [3.5, 0, 0]}
      light1: {type: stack_light, translation: [2.6, -1, 0]}
      sort1: {type: pusher_sort, part: pusher1, uses: {eye: eye1, belt: belt1, light: light1}}
)Y",
                     {"sources_and_sinks/emitter", "conveyors/belt_conveyor", "actuators/pusher",
                      "sensors/diffuse_sensor", "storage/bin", "sources_and_sinks/remover", "operator/stack_light"});
  ASSERT_TRUE(sim);
  // the first step starts the belt and lights green
  runFor(*sim, 0.1);
  EXPECT_EQ(io(*sim, "belt1", "run"), 1.0);
  EXPECT_EQ(io(*sim, "light1", "green"), 1.0);
  // the first box (red) reaches the eye 0.3 m past the pusher: the belt stands, amber, a stroke
  bool stood = false;
  for (int i = 0; i < 1000 && !stood; ++i) {
    sim->step();
    stood = io(*sim, "belt1", "run") == 0.0;
  }
  ASSERT_TRUE(stood);
  EXPECT_EQ(io(*sim, "eye1", "colour"), 1.0);
  EXPECT_EQ(io(*sim, "light1", "amber"), 1.0);
  EXPECT_EQ(io(*sim, "light1", "green"), 0.0);
  EXPECT_EQ(io(*sim, "pusher1", "extend"), 1.0);
  runFor(*sim, 120.0 - sim->kernel().now());
  ASSERT_FALSE(sim->scriptHalt()) << sim->scriptHalt()->message;
  EXPECT_EQ(io(*sim, "emitter1", "emitted"), 30);
  EXPECT_EQ(tokens(*sim, "main/sort1/sorted"), 15);
  EXPECT_EQ(tokens(*sim, "main/bin1/entered"), 15);
  EXPECT_EQ(tokens(*sim, "main/remover1/removed") + 1, 15) << "the last blue box is still on the belt";
  for (const auto& holder : sim->plant()->find("emitter1/items")->children()) {
    const scene::Node* box = holder->find("box");
    ASSERT_NE(box, nullptr);
    EXPECT_EQ(box->framePose().position.y > 0.45, std::get<std::string>(*box->datum("colour")) == "red") << box->path();
  }
}

TEST(MaterialLine, ThePickAndPlaceTakesTheMetalBasesOffTheLidsRideOn) {
  // examples/material: a metal base and a plastic lid in turn every 4 s; the inductive sensor
  // past the pick-and-place feels the bases, which pick_and_place_sort sets down in the bin
  core::Diagnostics diags;
  auto m = loadModel(std::string(GDPN_SOURCE_DIR) + "/examples/material/material_line.gdpn.yaml", diags);
  ASSERT_TRUE(m) << diags.str();
  auto sim = Simulation::create(*m, diags);
  ASSERT_TRUE(sim) << diags.str();
  runFor(*sim, 60.0);
  ASSERT_FALSE(sim->scriptHalt()) << sim->scriptHalt()->message;
  // 14 in 60 s (the first at 0): 7 bases, the last one just put down on the belt; 7 lids,
  // the last two on the belt
  EXPECT_EQ(io(*sim, "emitter1", "emitted"), 14);
  EXPECT_EQ(tokens(*sim, "main/pick_and_place1_sort/taken"), 6);
  EXPECT_EQ(tokens(*sim, "main/bin1/entered"), 6);
  int bases_in_bin = 0, bases_on_belt = 0, lids_on_belt = 0;
  for (const auto& holder : sim->plant()->find("emitter1/items")->children()) {
    for (const auto& item : holder->children()) {
      const auto p = item->framePose().position;
      if (item->name() == "base") {
        (p.y > 0.9 ? bases_in_bin : bases_on_belt) += 1;
        if (p.y <= 0.9) {
          EXPECT_LT(std::abs(p.y), 0.35) << item->path() << ": in the bin or on the belt";
        }
      } else {
        EXPECT_LT(std::abs(p.y), 0.35) << item->path() << ": a lid is never taken off";
        ++lids_on_belt;
      }
    }
  }
  EXPECT_EQ(bases_in_bin, 6);
  EXPECT_EQ(bases_on_belt, 1);
  EXPECT_EQ(lids_on_belt + static_cast<int>(io(*sim, "remover1", "removed")), 7);
}

TEST(SortingFromParts, FiftyBoxesEachInTheBinOfItsColour) {
  // examples/sorting/from_parts: fifty small boxes, red or blue at random (seed 7), two
  // pusher_sort stations: every red box ends within the right bin's walls, every blue one
  // within the left's; none left on the belt, none reaches its end
  core::Diagnostics diags;
  auto m = loadModel(std::string(GDPN_SOURCE_DIR) + "/examples/sorting/from_parts/sorting.gdpn.yaml", diags);
  ASSERT_TRUE(m) << diags.str();
  auto sim = Simulation::create(*m, diags);
  ASSERT_TRUE(sim) << diags.str();
  runFor(*sim, 270.0);
  ASSERT_FALSE(sim->scriptHalt()) << sim->scriptHalt()->message;
  EXPECT_EQ(io(*sim, "emitter1", "emitted"), 50);
  EXPECT_EQ(io(*sim, "remover1", "removed"), 0);
  std::map<std::string, int> in;
  for (const auto& holder : sim->plant()->find("emitter1/items")->children()) {
    const scene::Node* box = holder->find("box");
    const std::string colour = std::get<std::string>(*box->datum("colour"));
    const core::Vec3 p = box->framePose().position;
    // the bins, 2 m by 1.4 m, stand at (1.6, 1.195) and (3.4, -1.195)
    const bool right = std::abs(p.x - 1.6) < 0.98 && std::abs(p.y - 1.195) < 0.68;
    const bool left = std::abs(p.x - 3.4) < 0.98 && std::abs(p.y + 1.195) < 0.68;
    ++in[colour + (right ? " right" : left ? " left" : " elsewhere")];
  }
  EXPECT_EQ(in["red right"] + in["blue left"], 50) << "red right " << in["red right"] << ", blue left "
                                                   << in["blue left"];
  EXPECT_GT(in["red right"], 10);
  EXPECT_GT(in["blue left"], 10);
}

// ---------------------------------------------------------------------------------------
// the elevator

TEST(Elevator, TheCarriageRisesHighLessLowInThatOverTheLiftSpeed) {
  // 0.8 m at 0.4 m/s: at 0.4 m/s on the way; the top switch (1 cm before the end) in 2 s
  // within 5 % (the servo, 0.1 s, slows it over the last 4 cm: (0.8 - 0.04) / 0.4 + 0.1 ln 4
  // = 2.04 s); the bottom switch drops at once; and back down in as long
  auto sim = compose(std::string(kFloor) + R"Y(pages:
  main:
    instances:
      lift1: {type: elevator, params: {low: 0.8, high: 1.6, lift_speed: 0.4}}
)Y",
                     {"actuators/elevator"});
  ASSERT_TRUE(sim);
  runFor(*sim, 0.2);
  EXPECT_DOUBLE_EQ(io(*sim, "lift1", "at_bottom"), 1.0);
  EXPECT_DOUBLE_EQ(io(*sim, "lift1", "at_top"), 0.0);
  EXPECT_DOUBLE_EQ(io(*sim, "lift1", "loaded"), 0.0);
  EXPECT_NEAR(position(*sim, "lift1/lift/slide/carriage").z, 0.8, 0.002) << "the belt's top at low";
  const scene::Node* slide = sim->plant()->find("lift1/lift/slide");
  ASSERT_NE(slide, nullptr);
  write(*sim, "lift1", "up", 1);
  const double t0 = sim->kernel().now();
  double bottom_off = -1, top_on = -1, z05 = 0, z15 = 0;
  while (sim->kernel().now() - t0 < 4.0 && top_on < 0) {
    sim->step();
    const double t = sim->kernel().now() - t0;
    if (bottom_off < 0 && io(*sim, "lift1", "at_bottom") == 0.0) bottom_off = t;
    if (io(*sim, "lift1", "at_top") != 0.0) top_on = t;
    if (std::abs(t - 0.5) < 1e-6) z05 = sim->physics()->jointPosition(*slide);
    if (std::abs(t - 1.5) < 1e-6) z15 = sim->physics()->jointPosition(*slide);
  }
  EXPECT_NEAR(top_on, 0.8 / 0.4, 0.1) << "(high - low) / lift_speed, within 5 %";
  EXPECT_GT(bottom_off, 0.0);
  EXPECT_LT(bottom_off, 0.05) << "the bottom switch drops as the carriage leaves";
  EXPECT_NEAR(z15 - z05, 0.4, 0.008) << "at the lift speed on the way (2 %: the joint gives a little under the load)";
  runFor(*sim, 0.5);
  EXPECT_NEAR(position(*sim, "lift1/lift/slide/carriage").z, 1.6, 0.002) << "the belt's top at high";
  EXPECT_DOUBLE_EQ(io(*sim, "lift1", "at_top"), 1.0);
  write(*sim, "lift1", "up", 0);
  const double t1 = sim->kernel().now();
  double bottom_on = -1;
  while (sim->kernel().now() - t1 < 4.0 && bottom_on < 0) {
    sim->step();
    if (io(*sim, "lift1", "at_bottom") != 0.0) bottom_on = sim->kernel().now() - t1;
  }
  EXPECT_NEAR(bottom_on, 0.8 / 0.4, 0.1);
  EXPECT_DOUBLE_EQ(io(*sim, "lift1", "at_top"), 0.0);
}

TEST(Elevator, AnItemRidesUpAndTheBeltCarriesItOffAtItsSpeed) {
  // a medium box on the carriage: loaded; up, it rides 0.6 m up with the carriage and stays
  // where it lay; the belt, run at 0.6 m/s, carries it along +x at that speed (2 %) onto an
  // upper belt at 1.4 m, and the carriage is empty
  auto sim = compose(std::string(kFloor) + R"Y(  - Transform:
      translation: [1.285, 0, 1.38]
      children: [{Conveyor: {speed: 0.6}}, {Cube: {name: upper, size: [1.5, 0.7, 0.04]}}]
pages:
  main:
    instances:
      lift1: {type: elevator, params: {low: 0.8, high: 1.4, speed: 0.6}}
      box1: {type: medium_box, translation: [0, 0, 0.801]}
)Y",
                     {"actuators/elevator", "items/medium_box"});
  ASSERT_TRUE(sim);
  runFor(*sim, 0.5);
  EXPECT_DOUBLE_EQ(io(*sim, "lift1", "loaded"), 1.0);
  const core::Vec3 a = position(*sim, "box1/box");
  write(*sim, "lift1", "up", 1);
  runFor(*sim, 2.0);
  EXPECT_DOUBLE_EQ(io(*sim, "lift1", "at_top"), 1.0);
  EXPECT_DOUBLE_EQ(io(*sim, "lift1", "loaded"), 1.0);
  const core::Vec3 b = position(*sim, "box1/box");
  EXPECT_NEAR(b.z - a.z, 0.6, 0.005) << "up with the carriage";
  EXPECT_NEAR(b.x, a.x, 0.01) << "where it lay on the belt";
  EXPECT_NEAR(b.y, a.y, 0.01);
  write(*sim, "lift1", "run", 1);
  EXPECT_DOUBLE_EQ(io(*sim, "lift1", "speed"), 0.6);
  runFor(*sim, 0.2);
  const core::Vec3 c = position(*sim, "box1/box");
  runFor(*sim, 0.5);
  const core::Vec3 d = position(*sim, "box1/box");
  EXPECT_NEAR((d.x - c.x) / 0.5, 0.6, 0.6 * 0.02) << "at the belt's speed, along +x";
  EXPECT_NEAR(d.y, a.y, 0.01);
  runFor(*sim, 1.5);
  const core::Vec3 e = position(*sim, "box1/box");
  EXPECT_GT(e.x - 0.2, 0.5) << "off the carriage";
  EXPECT_NEAR(e.z, 1.4, 0.005) << "on the upper belt";
  EXPECT_DOUBLE_EQ(io(*sim, "lift1", "loaded"), 0.0);
}

// ---------------------------------------------------------------------------------------
// the stacker crane

/// Steps `sim` until `done()` holds or `seconds` pass; the time it took, or -1.
template <class Done>
double runUntil(Simulation& sim, Done done, double seconds) {
  const double t0 = sim.kernel().now();
  while (sim.kernel().now() - t0 < seconds - 1e-9) {
    sim.step();
    if (done()) return sim.kernel().now() - t0;
  }
  return -1;
}

TEST(Stacker, TheCraneReachesACellsXAndZInDistanceOverSpeed) {
  // to column 2, level 2: 2.1 m along the aisle at 0.5 m/s, 1.2 m up at 0.3 m/s. On the way
  // at those speeds; each servo (0.15 s along, 0.1 s up) slows the last v tau, so it is within
  // 5 mm at d/v - tau + tau ln(v tau / 5 mm): 4.51 s and 4.08 s (0.1 s, the start's
  // acceleration and the steps)
  auto sim = compose(std::string(kFloor) + R"Y(pages:
  main:
    instances:
      stacker1: {type: stacker}
)Y",
                     {"storage/stacker"});
  ASSERT_TRUE(sim);
  runFor(*sim, 0.2);
  EXPECT_DOUBLE_EQ(io(*sim, "stacker1", "fork_home"), 1.0);
  EXPECT_DOUBLE_EQ(io(*sim, "stacker1", "fork_out_limit"), 0.0);
  EXPECT_DOUBLE_EQ(io(*sim, "stacker1", "loaded"), 0.0);
  write(*sim, "stacker1", "x", 2.1);
  write(*sim, "stacker1", "z", 1.2);
  const double t0 = sim->kernel().now();
  double tx = -1, tz = -1, x1 = 0, x2 = 0, z1 = 0, z2 = 0;
  while (sim->kernel().now() - t0 < 6.0 && (tx < 0 || tz < 0)) {
    sim->step();
    const double t = sim->kernel().now() - t0;
    const double x = io(*sim, "stacker1", "x_at"), z = io(*sim, "stacker1", "z_at");
    if (tx < 0 && std::abs(x - 2.1) < 0.005) tx = t;
    if (tz < 0 && std::abs(z - 1.2) < 0.005) tz = t;
    if (std::abs(t - 1.0) < 1e-6) x1 = x, z1 = z;
    if (std::abs(t - 3.0) < 1e-6) x2 = x, z2 = z;
  }
  EXPECT_NEAR((x2 - x1) / 2.0, 0.5, 0.005) << "along the aisle at its speed";
  EXPECT_NEAR((z2 - z1) / 2.0, 0.3, 0.006) << "up at the lift speed (2 %: the joint gives a little under the load)";
  EXPECT_NEAR(tx, 2.1 / 0.5 - 0.15 + 0.15 * std::log(0.5 * 0.15 / 0.005), 0.1);
  EXPECT_NEAR(tz, 1.2 / 0.3 - 0.1 + 0.1 * std::log(0.3 * 0.1 / 0.005), 0.1);
  runFor(*sim, 1.0);
  EXPECT_NEAR(position(*sim, "stacker1/crane/x_slide/mast").x, 2.1, 0.002);
  EXPECT_NEAR(position(*sim, "stacker1/crane/x_slide/mast/z_slide/carriage").z, 0.4 - 0.015 + 1.2, 0.003)
      << "the fork's top 1.5 cm under level 2's arms";
}

TEST(Stacker, ItsIoTakeAnItemFromTheStandIntoACellWhereItStays) {
  // a medium box on the pick-up stand: the fork goes under it, lifts, comes in loaded; the
  // crane goes to column 2, level 1, the fork goes out, down and in: the box stands in that
  // cell (x 2.1, y 0.75, on the arms at 1.0 m) within 2 cm and is still there after the crane
  // has gone home
  auto sim = compose(std::string(kFloor) + R"Y(pages:
  main:
    instances:
      stacker1: {type: stacker}
      box1: {type: medium_box, translation: [0, 0.75, 0.401]}
)Y",
                     {"storage/stacker", "items/medium_box"});
  ASSERT_TRUE(sim);
  runFor(*sim, 0.3);
  EXPECT_DOUBLE_EQ(io(*sim, "stacker1", "loaded"), 0.0) << "the box is on the stand, not over the fork";
  write(*sim, "stacker1", "fork_out", 1);
  EXPECT_GT(runUntil(*sim, [&] { return io(*sim, "stacker1", "fork_out_limit") != 0.0; }, 3.0), 0.75 / 0.5 * 0.9);
  EXPECT_DOUBLE_EQ(io(*sim, "stacker1", "fork_home"), 0.0);
  EXPECT_DOUBLE_EQ(io(*sim, "stacker1", "loaded"), 1.0) << "under the box";
  write(*sim, "stacker1", "lift", 1);
  runFor(*sim, 0.8);
  // taken 3.5 cm off the stand, less what the fork, out 0.75 m from its carriage, gives
  // under the joints' softness (about 6 mm): at least 2 cm clear
  EXPECT_GT(position(*sim, "box1/box").z, 0.4 + 0.02) << "taken off the stand";
  EXPECT_LT(position(*sim, "box1/box").z, 0.4 + 0.036);
  write(*sim, "stacker1", "fork_out", 0);
  EXPECT_GT(runUntil(*sim, [&] { return io(*sim, "stacker1", "fork_home") != 0.0; }, 3.0), 0.0);
  runFor(*sim, 0.3);
  EXPECT_DOUBLE_EQ(io(*sim, "stacker1", "loaded"), 1.0);
  EXPECT_NEAR(position(*sim, "box1/box").y, 0.0, 0.03) << "in with the fork";
  write(*sim, "stacker1", "x", 2.1);
  write(*sim, "stacker1", "z", 0.6);
  EXPECT_GT(runUntil(
                *sim,
                [&] {
                  return std::abs(io(*sim, "stacker1", "x_at") - 2.1) < 0.003 && std::abs(io(*sim, "stacker1", "z_at") - 0.6) < 0.003;
                },
                8.0),
            0.0);
  write(*sim, "stacker1", "fork_out", 1);
  EXPECT_GT(runUntil(*sim, [&] { return io(*sim, "stacker1", "fork_out_limit") != 0.0; }, 3.0), 0.0);
  write(*sim, "stacker1", "lift", 0);
  runFor(*sim, 0.8);
  write(*sim, "stacker1", "fork_out", 0);
  EXPECT_GT(runUntil(*sim, [&] { return io(*sim, "stacker1", "fork_home") != 0.0; }, 3.0), 0.0);
  runFor(*sim, 0.3);
  EXPECT_DOUBLE_EQ(io(*sim, "stacker1", "loaded"), 0.0) << "the fork came back empty";
  const core::Vec3 p = position(*sim, "box1/box");
  EXPECT_NEAR(p.x, 2.1, 0.02);
  EXPECT_NEAR(p.y, 0.75, 0.02);
  EXPECT_NEAR(p.z, 1.0, 0.005) << "on the arms of level 1";
  write(*sim, "stacker1", "x", 0);
  write(*sim, "stacker1", "z", 0);
  runFor(*sim, 6.0);
  const core::Vec3 q = position(*sim, "box1/box");
  EXPECT_NEAR(q.x, p.x, 0.002) << "it stays";
  EXPECT_NEAR(q.y, p.y, 0.002);
  EXPECT_NEAR(q.z, p.z, 0.002);
}

TEST(Stacker, ItsControlPatternStoresWhatWaitsInTheNextFreeCell) {
  // a box on the stand, one request: stored in the first cell (column 0, level 0: x 0.7,
  // y 0.75, on the arms at 0.4 m) within 2 cm; a token on stored, eight free cells left,
  // home with the fork in
  auto sim = compose(std::string(kFloor) + R"Y(pages:
  main:
    instances:
      stacker1: {type: stacker}
      stacker1_control: {type: stacker_control, part: stacker1}
      box1: {type: medium_box, translation: [0, 0.75, 0.401]}
    places:
      asks: {tokens: 1}
    transitions:
      ask: {}
    arcs:
      - asks -> ask
      - ask -> stacker1_control/store
)Y",
                     {"storage/stacker", "items/medium_box"});
  ASSERT_TRUE(sim);
  runFor(*sim, 11.0);
  EXPECT_EQ(tokens(*sim, "main/stacker1_control/stored"), 1);
  EXPECT_EQ(tokens(*sim, "main/stacker1_control/free"), 8);
  EXPECT_EQ(tokens(*sim, "main/stacker1_control/idle"), 1);
  const core::Vec3 p = position(*sim, "box1/box");
  EXPECT_NEAR(p.x, 0.7, 0.02);
  EXPECT_NEAR(p.y, 0.75, 0.02);
  EXPECT_NEAR(p.z, 0.4, 0.005);
  EXPECT_DOUBLE_EQ(io(*sim, "stacker1", "fork_home"), 1.0);
  EXPECT_LT(std::abs(io(*sim, "stacker1", "x_at")), 0.003) << "home";
  EXPECT_DOUBLE_EQ(io(*sim, "stacker1", "loaded"), 0.0);
}

// ---------------------------------------------------------------------------------------
// the turntable and the pop-up wheel transfer

TEST(Turntable, TurnsByItsAngleInAngleOverTurnSpeedAndItsSwitchesSeeTheEnds) {
  // 60 degrees at 30 deg/s: the platform turns at 30 deg/s (1 %); `at_home` drops about 1
  // degree out, `at_angle` comes about 1 degree before the end, 59/30 = 1.967 s after `turn`
  // (the drive takes a step or two to start: 0.05 s); back home the same way
  auto sim = compose(std::string(kFloor) + R"Y(pages:
  main:
    instances:
      table1: {type: turntable, params: {angle: 60, turn_speed: 30}}
)Y",
                     {"conveyors/turntable"});
  ASSERT_TRUE(sim);
  runFor(*sim, 0.2);
  EXPECT_DOUBLE_EQ(io(*sim, "table1", "at_home"), 1.0);
  EXPECT_DOUBLE_EQ(io(*sim, "table1", "at_angle"), 0.0);
  EXPECT_NEAR(io(*sim, "table1", "angle_at"), 0.0, 0.01);
  write(*sim, "table1", "turn", 1);
  const double t0 = sim->kernel().now();
  double home_off = -1, home_off_angle = 0, angle_on = -1, angle_on_angle = 0, a_05 = 0, a_15 = 0;
  while (sim->kernel().now() - t0 < 3.0 && angle_on < 0) {
    sim->step();
    const double t = sim->kernel().now() - t0;
    const double a = io(*sim, "table1", "angle_at");
    if (home_off < 0 && io(*sim, "table1", "at_home") == 0.0) home_off = t, home_off_angle = a;
    if (io(*sim, "table1", "at_angle") != 0.0) angle_on = t, angle_on_angle = a;
    if (std::abs(t - 0.5) < 1e-6) a_05 = a;
    if (std::abs(t - 1.5) < 1e-6) a_15 = a;
  }
  EXPECT_NEAR((a_15 - a_05) / 1.0, 30.0, 0.3) << "at its turn speed on the way";
  EXPECT_NEAR(angle_on, 59.0 / 30.0, 0.05) << "angle / turn_speed, less the switch's degree";
  EXPECT_NEAR(home_off_angle, 1.0, 0.4) << "the home switch opens about 1 degree out";
  EXPECT_NEAR(angle_on_angle, 59.0, 0.4) << "the angle switch closes about 1 degree before the end";
  EXPECT_GT(home_off, 0.0);
  runFor(*sim, 0.3);
  EXPECT_NEAR(io(*sim, "table1", "angle_at"), 60.0, 0.1) << "turned by its angle";
  EXPECT_DOUBLE_EQ(io(*sim, "table1", "at_angle"), 1.0);
  EXPECT_DOUBLE_EQ(io(*sim, "table1", "at_home"), 0.0);
  write(*sim, "table1", "turn", 0);
  const double t1 = sim->kernel().now();
  double home_on = -1;
  while (sim->kernel().now() - t1 < 3.0 && home_on < 0) {
    sim->step();
    if (io(*sim, "table1", "at_home") != 0.0) home_on = sim->kernel().now() - t1;
  }
  EXPECT_NEAR(home_on, 59.0 / 30.0, 0.05);
  EXPECT_DOUBLE_EQ(io(*sim, "table1", "at_angle"), 0.0);
  runFor(*sim, 0.3);
  EXPECT_NEAR(io(*sim, "table1", "angle_at"), 0.0, 0.1) << "home again";
}

TEST(Turntable, CarriesAlongXHomeAndAlongTheTurnedDirectionAfterATurn) {
  // a medium box at rest on the platform: home, the belt carries it along +x at 0.5 m/s
  // (2 %); stopped, the platform turns 90 degrees with the box on it (the box turns about the
  // axis with it); then the belt carries it along +y at 0.5 m/s and its x holds
  auto sim = compose(std::string(kFloor) + R"Y(pages:
  main:
    instances:
      table1: {type: turntable}
      box1: {type: medium_box, translation: [-0.3, 0, 0.801]}
)Y",
                     {"conveyors/turntable", "items/medium_box"});
  ASSERT_TRUE(sim);
  runFor(*sim, 0.2);
  write(*sim, "table1", "run", 1);
  runFor(*sim, 0.2);
  core::Vec3 a = position(*sim, "box1/box");
  runFor(*sim, 0.4);
  core::Vec3 b = position(*sim, "box1/box");
  EXPECT_NEAR((b.x - a.x) / 0.4, 0.5, 0.5 * 0.02) << "along +x at the belt's speed";
  EXPECT_NEAR(b.y - a.y, 0.0, 0.002);
  write(*sim, "table1", "run", 0);
  runFor(*sim, 0.2);
  const core::Vec3 stopped = position(*sim, "box1/box");
  write(*sim, "table1", "turn", 1);
  runFor(*sim, 90.0 / 45.0 + 0.3);
  EXPECT_DOUBLE_EQ(io(*sim, "table1", "at_angle"), 1.0);
  const core::Vec3 turned = position(*sim, "box1/box");
  EXPECT_NEAR(turned.x, -stopped.y, 0.01) << "turned about the axis with the platform";
  EXPECT_NEAR(turned.y, stopped.x, 0.01);
  EXPECT_NEAR(turned.z, 0.8, 0.005) << "still on the belt's top";
  write(*sim, "table1", "run", 1);
  runFor(*sim, 0.2);
  a = position(*sim, "box1/box");
  runFor(*sim, 0.4);
  b = position(*sim, "box1/box");
  EXPECT_NEAR((b.y - a.y) / 0.4, 0.5, 0.5 * 0.02) << "along +y, the turned direction, at the belt's speed";
  EXPECT_NEAR(b.x - a.x, 0.0, 0.002);
}

/// A transfer `length` long (0.7 m wide, belt 0.5 m/s, wheels 0.4 m/s) and a medium box on
/// it at x = `box_x`.
std::unique_ptr<Simulation> transferWithABox(double length, double box_x) {
  return compose(std::string(kFloor) + "pages:\n  main:\n    instances:\n      transfer1: {type: transfer, params: {length: " +
                     std::to_string(length) + ", wheel_speed: 0.4}}\n      box1: {type: medium_box, translation: [" +
                     std::to_string(box_x) + ", 0, 0.801]}\n",
                 {"conveyors/transfer", "items/medium_box"});
}

TEST(Transfer, WheelsDownTheBeltCarriesAlongXAtItsSpeed) {
  // on a 1.6 m transfer with the wheels down: 0.5 m/s along +x (2 %), whatever the wheels do
  // under the belt (`left` on), the box on the strips' top
  auto sim = transferWithABox(1.6, -0.6);
  ASSERT_TRUE(sim);
  runFor(*sim, 0.2);
  write(*sim, "transfer1", "run", 1);
  write(*sim, "transfer1", "left", 1);
  runFor(*sim, 0.3);
  const core::Vec3 a = position(*sim, "box1/box");
  runFor(*sim, 1.0);
  const core::Vec3 b = position(*sim, "box1/box");
  EXPECT_NEAR((b.x - a.x) / 1.0, 0.5, 0.5 * 0.02);
  EXPECT_NEAR(b.y, 0.0, 0.002) << "the wheels under the belt do not touch it";
  EXPECT_NEAR(b.z, 0.8, 0.005) << "on the strips";
  // every strip and every wheel runs as the first one (one motor drives them all)
  for (const char* drive : {"transfer1/belt/strip4/drive", "transfer1/lift/raise/wheels/w34/drive"}) {
    const scene::Node* n = sim->plant()->find(drive);
    ASSERT_NE(n, nullptr) << drive;
    EXPECT_DOUBLE_EQ(n->number(scene::field::Conveyor::Speed), std::string(drive).find("strip") != std::string::npos ? 0.5 : 0.4);
  }
}

TEST(Transfer, WheelsUpDriveTheBoxAcrossAtWheelSpeedAndItsXHolds) {
  // the box at rest in the middle, the belt running: `up` lifts it 1.2 cm onto the wheels,
  // `left` sends it along +y at 0.4 m/s (3 %) while its x holds (the belt no longer touches
  // it); `right`, written last, turns the same wheels round: -y at 0.4 m/s; `up` off sets it
  // down on the belt, which carries it along x again
  auto sim = transferWithABox(0.8, 0.0);
  ASSERT_TRUE(sim);
  runFor(*sim, 0.2);
  write(*sim, "transfer1", "run", 1);
  write(*sim, "transfer1", "up", 1);
  write(*sim, "transfer1", "left", 1);
  runFor(*sim, 0.25);
  core::Vec3 a = position(*sim, "box1/box");
  runFor(*sim, 0.2);
  core::Vec3 b = position(*sim, "box1/box");
  EXPECT_NEAR((b.y - a.y) / 0.2, 0.4, 0.4 * 0.03) << "along +y at the wheels' speed";
  EXPECT_NEAR(b.x - a.x, 0.0, 0.002) << "its x holds";
  EXPECT_NEAR(b.z, 0.8 + 0.012, 0.003) << "riding on the wheels, 1.2 cm above the belt";
  write(*sim, "transfer1", "right", 1);
  EXPECT_DOUBLE_EQ(io(*sim, "transfer1", "left"), 0.0) << "one motor: the last one written wins";
  EXPECT_DOUBLE_EQ(io(*sim, "transfer1", "right"), 1.0);
  runFor(*sim, 0.2);
  a = position(*sim, "box1/box");
  runFor(*sim, 0.2);
  b = position(*sim, "box1/box");
  EXPECT_NEAR((b.y - a.y) / 0.2, -0.4, 0.4 * 0.03) << "along -y at the wheels' speed";
  EXPECT_NEAR(b.x - a.x, 0.0, 0.002);
  write(*sim, "transfer1", "up", 0);
  runFor(*sim, 0.3);
  a = position(*sim, "box1/box");
  runFor(*sim, 0.2);
  b = position(*sim, "box1/box");
  EXPECT_NEAR(b.z, 0.8, 0.003) << "down on the belt";
  EXPECT_NEAR((b.x - a.x) / 0.2, 0.5, 0.5 * 0.03) << "the belt carries it along x again";
}

// ---------------------------------------------------------------------------------------
// the stopper belt and the pivot arm sorter

/// A 3 m stopper belt (blade at x = 0.5, its face at 0.4925; the eye's beam at 0.47) carrying
/// a medium box (0.4 m long) whose front starts at x = -0.4, with the blade `up` or down.
std::unique_ptr<Simulation> stopperWithBox(bool up) {
  auto sim = compose(std::string(kFloor) + R"Y(pages:
  main:
    instances:
      stopper1: {type: stopper_belt, params: {length: 3}}
      box1: {type: medium_box, translation: [-0.6, 0, 0.801]}
)Y",
                     {"conveyors/stopper_belt", "items/medium_box"});
  if (sim && up) write(*sim, "stopper1", "stop", 1);
  return sim;
}

TEST(StopperBelt, TheBladeHoldsAnItemWhileTheBeltRunsAndLetsItGo) {
  // blade up: the box's front reaches the beam (0.87 m at 0.5 m/s: 1.74 s) and stops at the
  // blade's face; it stands there, within 2 mm, for 3 s while the belt runs and `waiting`
  // holds 1; blade down: it leaves at the belt's speed and `waiting` drops when its back has
  // crossed the beam: 0.3775 m, 0.755 s at speed, and under 0.15 s more for the blade to drop
  // below the belt's top (5.5 cm) and the box to get up to speed (0.5 m/s at about 7 m/s^2)
  auto sim = stopperWithBox(true);
  ASSERT_TRUE(sim);
  EXPECT_DOUBLE_EQ(io(*sim, "stopper1", "stop"), 1.0);
  const auto [on, off] = onOff(*sim, "stopper1", "waiting", 2.5);
  EXPECT_NEAR(on, 1.74, 0.05);
  EXPECT_LT(off, 0.0);
  const core::Vec3 held = position(*sim, "box1/box");
  EXPECT_NEAR(held.x + 0.2, 0.4925, 0.005) << "its front against the blade's face";
  for (int i = 0; i < 300; ++i) {
    sim->step();
    ASSERT_DOUBLE_EQ(io(*sim, "stopper1", "waiting"), 1.0) << sim->kernel().now();
  }
  const core::Vec3 still = position(*sim, "box1/box");
  EXPECT_NEAR(still.x, held.x, 0.002) << "held for 3 s";
  EXPECT_NEAR(still.y, 0.0, 0.002);
  EXPECT_NEAR(still.z, 0.8, 0.005) << "on the belt, not climbing the blade";
  EXPECT_DOUBLE_EQ(io(*sim, "stopper1", "run"), 1.0) << "the belt ran all the while";
  write(*sim, "stopper1", "stop", 0);
  const double t0 = sim->kernel().now();
  const auto [on2, off2] = onOff(*sim, "stopper1", "waiting", 1.0);
  EXPECT_LT(on2, 0.0);
  EXPECT_GT(off2 - t0, 0.755);
  EXPECT_LT(off2 - t0, 0.755 + 0.15);
  const double x = position(*sim, "box1/box").x;
  runFor(*sim, 1.0);
  EXPECT_NEAR(position(*sim, "box1/box").x - x, 0.5, 0.01) << "past the blade at the belt's speed";
  EXPECT_NEAR(position(*sim, "box1/box").z, 0.8, 0.005);
}

TEST(StopperBelt, WithTheBladeDownAnItemRidesPastAtTheBeltsSpeed) {
  // blade down: the box crosses the gap onto the belt past it without a check: 1.0 m in 2 s
  // (2 %) from 1.5 s to 3.5 s; `waiting` is on once, while the box crosses the beam: from
  // 1.74 s for its length over the speed, 0.8 s
  auto sim = stopperWithBox(false);
  ASSERT_TRUE(sim);
  const auto [on, off] = onOff(*sim, "stopper1", "waiting", 1.5);
  EXPECT_LT(on, 0.0);
  const double x = position(*sim, "box1/box").x;
  int switches = 0;
  const auto [on2, off2] = onOff(*sim, "stopper1", "waiting", 2.0, &switches);
  const core::Vec3 p = position(*sim, "box1/box");
  EXPECT_NEAR(p.x - x, 1.0, 0.02);
  EXPECT_NEAR(p.z, 0.8, 0.005);
  EXPECT_NEAR(on2, 1.74, 0.05);
  EXPECT_NEAR(off2 - on2, 0.8, 0.03);
  EXPECT_EQ(switches, 2);
  (void)off;
}

TEST(StopperBelt, TheBladeAloneNeverTripsTheEyeAndBothBeltsRunAsOne) {
  // an empty belt standing (start 0): the blade goes up and down, `waiting` stays 0; a box on
  // the belt past the gap moves as `run` and `speed` drive the motor: 0.5 m/s, then -0.3 m/s
  auto sim = compose(std::string(kFloor) + R"Y(pages:
  main:
    instances:
      stopper1: {type: stopper_belt, params: {length: 3, start: 0}}
      box1: {type: small_box, translation: [0.7, 0, 0.801]}
)Y",
                     {"conveyors/stopper_belt", "items/small_box"});
  ASSERT_TRUE(sim);
  int switches = 0;
  write(*sim, "stopper1", "stop", 1);
  onOff(*sim, "stopper1", "waiting", 0.5, &switches);
  const scene::Node* lift = sim->plant()->find("stopper1/stopper/lift");
  ASSERT_NE(lift, nullptr);
  EXPECT_NEAR(sim->physics()->jointPosition(*lift), 0.055, 0.002) << "up: 5 cm above the belt's top";
  write(*sim, "stopper1", "stop", 0);
  onOff(*sim, "stopper1", "waiting", 0.5, &switches);
  EXPECT_NEAR(sim->physics()->jointPosition(*lift), 0.0, 0.002);
  EXPECT_EQ(switches, 0);
  EXPECT_NEAR(position(*sim, "box1/box").x, 0.7, 0.002) << "stands until driven";
  write(*sim, "stopper1", "run", 1);
  runFor(*sim, 0.5);
  double x = position(*sim, "box1/box").x;
  runFor(*sim, 0.6);
  EXPECT_NEAR(position(*sim, "box1/box").x - x, 0.3, 0.01) << "run: 0.5 m/s past the gap too";
  write(*sim, "stopper1", "speed", -0.3);
  runFor(*sim, 0.5);
  x = position(*sim, "box1/box").x;
  runFor(*sim, 1.0);
  EXPECT_NEAR(position(*sim, "box1/box").x - x, -0.3, 0.01) << "speed: backwards at 0.3 m/s";
}

/// The arm's angle now, degrees.
double armAngle(const Simulation& sim, const std::string& part) {
  const scene::Node* turn = sim.plant()->find(part + "/pivot/turn");
  EXPECT_NE(turn, nullptr);
  return turn ? sim.physics()->jointPosition(*turn) * 180.0 / std::acos(-1.0) : kNan;
}

TEST(PivotArmSorter, ASwingTakesAngleOverTurnSpeedAndTheLimitsSwitch) {
  // 60 degrees at 60 deg/s: out in 1 s (the motor follows its target at turn_speed, and its
  // last degree in about servo_time, 0.02 s: 5 % covers it), 30 degrees from 0.3 s to 0.8 s;
  // `home` drops within 0.1 s; `out` comes on within 3.5 degrees of the angle; back in 1 s
  auto sim = compose(std::string(kFloor) + R"Y(pages:
  main:
    instances:
      arm1: {type: pivot_arm_sorter, params: {angle: 60, turn_speed: 60}}
)Y",
                     {"actuators/pivot_arm_sorter"});
  ASSERT_TRUE(sim);
  runFor(*sim, 0.2);
  EXPECT_DOUBLE_EQ(io(*sim, "arm1", "home"), 1.0);
  EXPECT_DOUBLE_EQ(io(*sim, "arm1", "out"), 0.0);
  write(*sim, "arm1", "swing", 1);
  EXPECT_DOUBLE_EQ(io(*sim, "arm1", "swing"), 1.0);
  const double t0 = sim->kernel().now();
  double home_off = -1, out_on = -1, out_on_angle = 0, reached = -1, at_03 = 0, at_08 = 0;
  while (sim->kernel().now() - t0 < 2.0) {
    sim->step();
    const double t = sim->kernel().now() - t0, a = armAngle(*sim, "arm1");
    if (home_off < 0 && io(*sim, "arm1", "home") == 0.0) home_off = t;
    if (out_on < 0 && io(*sim, "arm1", "out") != 0.0) {
      out_on = t;
      out_on_angle = a;
    }
    if (reached < 0 && a > 59.5) reached = t;
    if (std::abs(t - 0.3) < 1e-6) at_03 = a;
    if (std::abs(t - 0.8) < 1e-6) at_08 = a;
  }
  EXPECT_NEAR(reached, 60.0 / 60.0, 0.05) << "angle / turn_speed, within 5 %";
  EXPECT_NEAR(at_08 - at_03, 30.0, 0.6) << "at its speed on the way";
  EXPECT_GT(home_off, 0.0);
  EXPECT_LT(home_off, 0.1);
  EXPECT_GT(out_on_angle, 60.0 - 4.0) << "the out switch: within 3.5 degrees";
  EXPECT_LT(out_on_angle, 60.0);
  EXPECT_NEAR(armAngle(*sim, "arm1"), 60.0, 0.1) << "out by its angle";
  EXPECT_DOUBLE_EQ(io(*sim, "arm1", "out"), 1.0);
  EXPECT_DOUBLE_EQ(io(*sim, "arm1", "home"), 0.0);
  write(*sim, "arm1", "swing", 0);
  const double t1 = sim->kernel().now();
  double home_on = -1, out_off = -1;
  while (sim->kernel().now() - t1 < 2.0 && home_on < 0) {
    sim->step();
    const double t = sim->kernel().now() - t1;
    if (out_off < 0 && io(*sim, "arm1", "out") == 0.0) out_off = t;
    if (io(*sim, "arm1", "home") != 0.0) home_on = t;
  }
  EXPECT_NEAR(home_on, (60.0 - 3.5) / 60.0, 0.05);
  EXPECT_LT(out_off, 0.1);
  runFor(*sim, 0.5);
  EXPECT_NEAR(armAngle(*sim, "arm1"), 0.0, 0.1) << "home again";
}

/// A 4 m belt carrying a medium box (front at x = -0.8) at 0.5 m/s past a pivot arm at x = 0,
/// its arm out (`swing`) or home, for `seconds`; the box's position then.
core::Vec3 boxPastTheArm(bool swing, double seconds) {
  auto sim = compose(std::string(kFloor) + R"Y(pages:
  main:
    instances:
      belt1: {type: belt_conveyor, params: {length: 4}}
      arm1: {type: pivot_arm_sorter}
      box1: {type: medium_box, translation: [-1.0, 0, 0.801]}
)Y",
                     {"conveyors/belt_conveyor", "actuators/pivot_arm_sorter", "items/medium_box"});
  if (!sim) return {kNan, kNan, kNan};
  write(*sim, "arm1", "swing", swing ? 1 : 0);
  runFor(*sim, seconds);
  EXPECT_DOUBLE_EQ(io(*sim, "arm1", "swing"), swing ? 1.0 : 0.0);
  return position(*sim, "box1/box");
}

TEST(PivotArmSorter, AnItemMeetingTheArmOutLeavesTheBeltOnTheFarSide) {
  // out (45 degrees, reaching 0.33 m past the centre line): the box runs against the arm, is
  // guided along it and falls off the far side (+y) onto the floor; home: it rides on, 2 m in
  // 4 s, on the centre line
  const core::Vec3 off = boxPastTheArm(true, 5.0);
  EXPECT_GT(off.y, 0.35 + 0.1) << "past the belt's far edge";
  EXPECT_LT(off.z, 0.5) << "fell off the belt";
  const core::Vec3 on = boxPastTheArm(false, 4.0);
  EXPECT_NEAR(on.x, -1.0 + 2.0, 0.05);
  EXPECT_NEAR(on.y, 0.0, 0.01);
  EXPECT_NEAR(on.z, 0.8, 0.005) << "still on the belt's top";
}

TEST(PivotArmSorter, ItsControlPatternMakesOneSwingPerRequest) {
  // two requests, hold 1 s: two swings, each out (the out switch on) for the hold and the
  // few hundredths the arm takes to leave the switch; two tokens on done, the arm home
  auto sim = compose(std::string(kFloor) + R"Y(pages:
  main:
    instances:
      arm1: {type: pivot_arm_sorter}
      arm1_control: {type: pivot_arm_control, part: arm1, params: {hold: 1.0}}
    places:
      asks: {tokens: 2}
    transitions:
      ask: {}
    arcs:
      - asks -> ask
      - ask -> arm1_control/request
)Y",
                     {"actuators/pivot_arm_sorter"});
  ASSERT_TRUE(sim);
  int outs = 0;
  bool was_out = false;
  double since = 0, reach = 0;
  std::vector<double> held;
  for (int i = 0; i < 500; ++i) {
    sim->step();
    reach = std::max(reach, armAngle(*sim, "arm1"));
    const bool out = io(*sim, "arm1", "out") != 0.0;
    if (out && !was_out) {
      ++outs;
      since = sim->kernel().now();
    }
    if (!out && was_out) held.push_back(sim->kernel().now() - since);
    was_out = out;
  }
  EXPECT_EQ(tokens(*sim, "main/arm1_control/done"), 2);
  EXPECT_EQ(outs, 2);
  ASSERT_EQ(held.size(), 2u);
  for (const double h : held) {
    EXPECT_GT(h, 1.0);
    EXPECT_LT(h, 1.1);
  }
  EXPECT_NEAR(reach, 45.0, 0.5) << "out to its angle";
  EXPECT_DOUBLE_EQ(io(*sim, "arm1", "swing"), 0.0);
  EXPECT_DOUBLE_EQ(io(*sim, "arm1", "home"), 1.0);
  EXPECT_EQ(tokens(*sim, "main/arm1_control/idle"), 1);
}

// ---------------------------------------------------------------------------------------
// the potentiometer, the digital display, the light array

/// A click straight down at (x, y) at `t` s.
sensors::InputEvent clickAtXY(double t, double x, double y) {
  sensors::InputEvent e;
  e.t = t;
  e.kind = sensors::InputEvent::Kind::Click;
  e.ray = {{x, y, 2}, {0, 0, -1}};
  return e;
}

/// Where dot `mark` (0 to 20) of a potentiometer at (x0, 0) lies: 0.055 m from the knob's
/// axis, 135 - 13.5 x mark degrees counter-clockwise from +y.
std::pair<double, double> dialMark(int mark, double x0 = 0) {
  const double a = (135.0 - 13.5 * mark) * std::numbers::pi / 180;
  return {x0 - 0.055 * std::sin(a), 0.055 * std::cos(a)};
}

TEST(Potentiometer, AClickOnADotTurnsThePointerThereAndSetsItsValue) {
  // a: max 10 from 0; b: max 100 from 50 (the pointer straight up). Clicks on dots 15, 0,
  // 10 and 20 of a give 7.5, 0, 5, 10; clicks on a's knob and on the plate below it, where
  // the scale has its gap, change nothing; dot 4 of b gives 20
  auto sim = compose(std::string(kFloor) + "pages:\n  main:\n    instances:\n      a: {type: potentiometer}\n"
                                           "      b: {type: potentiometer, translation: [2, 0, 0], params: {max: 100, start: 50}}\n",
                     {"operator/potentiometer"});
  ASSERT_TRUE(sim);
  const auto at = [](double t, int mark, double x0 = 0) {
    const auto [x, y] = dialMark(mark, x0);
    return clickAtXY(t, x, y);
  };
  sim->setInput({at(0.2, 15), at(0.4, 0), clickAtXY(0.6, 0.005, 0.005), clickAtXY(0.8, 0, -0.055), at(1.0, 10),
                 at(1.2, 20), at(1.4, 4, 2.0)});
  const auto pointer = [&](const std::string& part) {
    return std::get<std::array<double, 4>>(sim->plant()->find(part + "/head/pointer")->value(scene::field::Transform::Rotation))[3];
  };
  // the pointer's white line (its middle 0.0125 m out from the axis) lies towards the dot
  // (the world frames of the still Transforms a script turned are brought up to date first:
  // the physics does so for bodies only)
  const auto pointsAt = [&](const std::string& part, int mark, double x0) {
    const auto [x, y] = dialMark(mark, x0);
    scene::updateTransforms(*sim->plant()->find(part));
    const auto p = position(*sim, part + "/head/pointer/line");
    EXPECT_NEAR(p.x, x0 + (x - x0) * 0.0125 / 0.055, 1e-6) << part << " mark " << mark;
    EXPECT_NEAR(p.y, y * 0.0125 / 0.055, 1e-6) << part << " mark " << mark;
  };
  runFor(*sim, 0.1);
  EXPECT_EQ(io(*sim, "a", "value"), 0.0);
  EXPECT_EQ(pointer("a"), 135.0) << "0: the lower left";
  EXPECT_EQ(io(*sim, "b", "value"), 50.0);
  EXPECT_EQ(pointer("b"), 0.0) << "half scale: straight up";
  const std::vector<std::pair<double, int>> expected = {{7.5, 15}, {0, 0}, {0, 0}, {0, 0}, {5, 10}, {10, 20}};
  for (const auto& [value, mark] : expected) {
    runFor(*sim, 0.2);
    SCOPED_TRACE(sim->kernel().now());
    EXPECT_DOUBLE_EQ(io(*sim, "a", "value"), value);
    EXPECT_DOUBLE_EQ(pointer("a"), 135.0 - 13.5 * mark);
    pointsAt("a", mark, 0);
  }
  EXPECT_EQ(pointer("a"), -135.0) << "full scale: the lower right";
  runFor(*sim, 0.2);  // 1.5 s
  EXPECT_DOUBLE_EQ(io(*sim, "b", "value"), 20.0);
  EXPECT_DOUBLE_EQ(pointer("b"), 135.0 - 13.5 * 4);
  pointsAt("b", 4, 2.0);
  EXPECT_DOUBLE_EQ(io(*sim, "a", "value"), 10.0) << "a click on b leaves a as it was";
}

/// What display `part` shows: per digit, the character whose segments are lit ('?' for
/// none); every segment lit as a lamp (red, glowing) or dark (nearly black, not glowing).
std::string shown(const Simulation& sim, const std::string& part) {
  static const std::map<std::string, char> chars = {
      {"abcdef", '0'}, {"bc", '1'},      {"abdeg", '2'},   {"abcdg", '3'},  {"bcfg", '4'}, {"acdfg", '5'},
      {"acdefg", '6'}, {"abc", '7'},     {"abcdefg", '8'}, {"abcdfg", '9'}, {"g", '-'},    {"", ' '}};
  std::string out;
  for (int d = 1; d <= 4; ++d) {
    std::string lit;
    for (const char s : std::string("abcdefg")) {
      const std::string led = part + "/face/d" + std::to_string(d) + "/" + s + "/led";
      const auto emissive = colour(sim, led, "emissive");
      const auto diffuse = colour(sim, led, "diffuse");
      if (emissive[0] > 0) {
        lit += s;
        EXPECT_EQ(emissive, (std::array<double, 3>{1.0, 0.1, 0.05})) << led;
        EXPECT_GT(diffuse[0], 0.9) << led << ": red";
        EXPECT_LT(diffuse[1], 0.2) << led;
      } else {
        EXPECT_EQ(emissive, (std::array<double, 3>{0, 0, 0})) << led;
        EXPECT_LT(std::max({diffuse[0], diffuse[1], diffuse[2]}), 0.1) << led << ": nearly black";
      }
    }
    const auto c = chars.find(lit);
    out += c == chars.end() ? '?' : c->second;
  }
  return out;
}

TEST(DigitalDisplay, ShowsTheNumberWrittenRightAlignedOrDashesWhenItDoesNotFit) {
  auto sim = compose(std::string(kFloor) + "pages:\n  main:\n    instances:\n      display1: {type: digital_display}\n",
                     {"operator/digital_display"});
  ASSERT_TRUE(sim);
  runFor(*sim, 0.05);
  EXPECT_EQ(shown(*sim, "display1"), "   0") << "0 at the start";
  const std::vector<std::pair<double, std::string>> cases = {
      {42, "  42"},    {-7, "  -7"},    {8888, "8888"}, {0, "   0"},    {9999, "9999"},   {-999, "-999"},
      {10000, "----"}, {-1000, "----"}, {3.6, "   4"},  {-0.4, "   0"}, {1234, "1234"}};
  for (const auto& [value, text] : cases) {
    write(*sim, "display1", "value", value);
    runFor(*sim, 0.05);  // it reads every 0.02 s
    EXPECT_EQ(shown(*sim, "display1"), text) << value;
    EXPECT_EQ(io(*sim, "display1", "value"), value) << "the output reads back as written";
  }
  // " 42" is segments b, c, f, g of the third digit and a, b, d, e, g of the fourth, no other
  write(*sim, "display1", "value", 42);
  runFor(*sim, 0.05);
  EXPECT_EQ(colour(*sim, "display1/face/d3/f/led", "emissive")[0], 1.0);
  EXPECT_EQ(colour(*sim, "display1/face/d3/a/led", "emissive")[0], 0.0);
  EXPECT_EQ(colour(*sim, "display1/face/d4/e/led", "emissive")[0], 1.0);
  EXPECT_EQ(colour(*sim, "display1/face/d4/c/led", "emissive")[0], 0.0);
  EXPECT_EQ(colour(*sim, "display1/face/d2/g/led", "emissive")[0], 0.0);
}

TEST(DigitalDisplay, ShowsTheTokensOfTheLinkedPlaceAndFollowsThem) {
  // 5 tokens go onto the display's place at once; from 0.5 s one is taken every 0.1 s (at
  // the start of each occurrence); the display follows. Then a written value shows until the
  // place changes again
  auto sim = compose(std::string(kFloor) + R"Y(pages:
  main:
    instances:
      display1: {type: digital_display}
    places:
      stock: {tokens: 5}
      more: {}
    transitions:
      load: {duration: 0}
      take: {guard: 'sim.time >= 0.5 and sim.time < 0.75', duration: 0.1}
      again: {duration: 0}
    arcs:
      - stock -> load
      - load -> display1/shows
      - display1/shows -> take
      - more -> again
      - again -> display1/shows
)Y",
                     {"operator/digital_display"});
  ASSERT_TRUE(sim);
  runFor(*sim, 0.3);
  EXPECT_EQ(tokens(*sim, "main/display1/shows"), 5);
  EXPECT_EQ(shown(*sim, "display1"), "   5");
  runFor(*sim, 0.25);  // 0.55 s: one taken at 0.5
  EXPECT_EQ(tokens(*sim, "main/display1/shows"), 4);
  EXPECT_EQ(shown(*sim, "display1"), "   4");
  runFor(*sim, 0.1);  // 0.65 s
  EXPECT_EQ(shown(*sim, "display1"), "   3");
  runFor(*sim, 0.3);  // 0.95 s: taken at 0.5, 0.6 and 0.7, then no more
  EXPECT_EQ(tokens(*sim, "main/display1/shows"), 2);
  EXPECT_EQ(shown(*sim, "display1"), "   2");
  write(*sim, "display1", "value", -42);
  runFor(*sim, 0.05);
  EXPECT_EQ(shown(*sim, "display1"), " -42") << "the value written last";
  const auto id = sim->net().findPlace("main/more");
  ASSERT_TRUE(id);
  EXPECT_EQ(sim->kernel().setMarking(*sim->net().placeSlotsOf(*id).begin(), 10), "");
  runFor(*sim, 0.1);
  EXPECT_EQ(tokens(*sim, "main/display1/shows"), 12);
  EXPECT_EQ(shown(*sim, "display1"), "  12") << "the place changed last";
}

TEST(LightArray, ABoxBreaksTheBeamsBelowItsTopAndItsHeightReadsTheHighest) {
  // four belts, a light array across each at x = 0.5 and a box on each centred at x = -1.2:
  // at 0.5 m/s every box is centred in its curtain at 3.4 s. Beams at 0.03 + 0.06 k above
  // the belt: the small box (0.2 m high) breaks the 3 under 0.2 (top one at 0.15), the
  // medium (0.3 m) 5 (0.27), the large (0.4 m) 7 (0.39); with a pitch of 0.04 the medium box
  // breaks the 7 under 0.3 (0.03 + 0.04 k, k = 0 to 6: top one at 0.27). A fifth belt, empty,
  // never breaks one
  std::string body = std::string(kFloor) + "pages:\n  main:\n    instances:\n";
  const std::vector<std::pair<std::string, std::string>> lanes = {
      {"small_box", ""}, {"medium_box", ""}, {"large_box", ""}, {"medium_box", ", params: {pitch: 0.04}"}, {"", ""}};
  for (std::size_t i = 0; i < lanes.size(); ++i) {
    const std::string y = std::to_string(2.0 * static_cast<double>(i));
    const std::string n = std::to_string(i);
    body += "      belt" + n + ": {type: belt_conveyor, translation: [0, " + y + ", 0], params: {length: 4}}\n";
    body += "      curtain" + n + ": {type: light_array, translation: [0.5, " + y + ", 0]" + lanes[i].second + "}\n";
    if (!lanes[i].first.empty()) {
      body += "      box" + n + ": {type: " + lanes[i].first + ", translation: [-1.2, " + y + ", 0.801]}\n";
    }
  }
  auto sim = compose(body, {"conveyors/belt_conveyor", "items/small_box", "items/medium_box", "items/large_box",
                            "sensors/light_array"});
  ASSERT_TRUE(sim);
  const std::vector<double> beams = {3, 5, 7, 7, 0};
  const std::vector<double> heights = {0.15, 0.27, 0.39, 0.27, 0};
  std::vector<double> most(lanes.size(), 0);
  const auto watch = [&](double seconds) {
    const auto steps = static_cast<int>(std::llround(seconds / sim->model().settings.dt));
    for (int s = 0; s < steps; ++s) {
      sim->step();
      for (std::size_t i = 0; i < lanes.size(); ++i) {
        const std::string c = "curtain" + std::to_string(i);
        most[i] = std::max(most[i], io(*sim, c, "beams"));
        EXPECT_EQ(io(*sim, c, "blocked"), io(*sim, c, "beams") > 0 ? 1.0 : 0.0);
      }
    }
  };
  watch(1.0);
  for (std::size_t i = 0; i < lanes.size(); ++i) EXPECT_EQ(io(*sim, "curtain" + std::to_string(i), "beams"), 0) << i;
  watch(2.4);  // 3.4 s
  for (std::size_t i = 0; i < lanes.size(); ++i) {
    SCOPED_TRACE(i);
    const std::string c = "curtain" + std::to_string(i);
    EXPECT_EQ(io(*sim, c, "beams"), beams[i]);
    EXPECT_NEAR(io(*sim, c, "top"), heights[i], 1e-9);
    EXPECT_EQ(io(*sim, c, "blocked"), beams[i] > 0 ? 1.0 : 0.0);
  }
  EXPECT_EQ(colour(*sim, "curtain0/receiver/led", "emissive")[0], 1.0) << "red while broken";
  watch(1.6);  // 5 s: the large box's back (0.275 m behind its centre) passed at 4.0 s
  for (std::size_t i = 0; i < lanes.size(); ++i) {
    SCOPED_TRACE(i);
    const std::string c = "curtain" + std::to_string(i);
    EXPECT_EQ(io(*sim, c, "beams"), 0);
    EXPECT_EQ(io(*sim, c, "top"), 0);
    EXPECT_EQ(most[i], beams[i]) << "never more beams than its height implies";
  }
  EXPECT_EQ(colour(*sim, "curtain0/receiver/led", "emissive")[1], 0.9) << "green when clear";
}

}  // namespace
}  // namespace gdpn::model

// Parts: per-instance parameters and expressions, named I/O read, written and forced, control
// patterns bound to their part, and the library: search path, copies, updates.

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "gdpn/core/file.h"
#include "gdpn/model/part_library.h"
#include "gdpn/model/part_run.h"
#include "gdpn/model/simulation.h"
#include "gdpn/scene/fields.h"
#include "support/sim_helpers.h"

namespace gdpn::model {
namespace {

namespace fs = std::filesystem;

const std::string kLampFile = std::string(GDPN_SOURCE_DIR) + "/tests/data/parts/lamp.gdpn.yaml";

/// The lamp part's file with a page using it, as model text.
std::string lampModel(const std::string& page) {
  std::ifstream in(kLampFile);
  std::stringstream text;
  text << in.rdbuf();
  return text.str() + "pages:\n" + page;
}

/// A control pattern of the lamp that works with another part by role: it lights its lamp
/// while the part in role `other` sees something, `gain` times as bright (its own parameter).
const char* const kMirror = R"Y(  lamp_mirror:
    part: {version: 1, group: Test, controls: lamp}
    params:
      gain: {value: 2, description: "how much brighter"}
    uses:
      other: {io: [seen], description: "the lamp it mirrors"}
      spare: {io: [light, seen], optional: true}
    places:
      off: {tokens: 1}
      on: {}
    transitions:
      light: {guard: "self.uses.other.seen and self.uses.spare is None", post_fire: "self.part.speed = self.params.gain; self.part.light = True"}
    arcs: [off -> light, light -> on]
)Y";

/// The lamp's file with the mirror pattern and a page, as model text.
std::string mirrorModel(const std::string& page) {
  auto text = lampModel(page);
  text.insert(text.find("pages:\n"), kMirror);
  return text;
}

std::unique_ptr<Simulation> make(const std::string& text, core::Diagnostics& diags) {
  auto m = parseModel(text, "m.gdpn.yaml", diags);
  if (!m) return nullptr;
  return Simulation::create(*m, diags);
}

TEST(Part, EachInstanceComputesItsFieldsFromItsParameters) {
  core::Diagnostics diags;
  auto sim = make(lampModel("  main:\n    instances:\n      a: {type: lamp}\n"
                            "      b: {type: lamp, translation: [0, 3, 0], params: {length: 4, count: 5}}\n"),
                  diags);
  ASSERT_TRUE(sim) << diags.str();
  const auto size = [&](const std::string& path) { return sim->plant()->find(path)->vec3(scene::field::Cube::Size); };
  EXPECT_EQ(size("a/rail/bar"), (core::Vec3{2, 0.1, 0.1 * 3}));
  EXPECT_EQ(size("b/rail/bar"), (core::Vec3{4, 0.1, 0.1 * 5}));
  EXPECT_EQ(sim->plant()->find("b/rail")->vec3(scene::field::Transform::Translation), (core::Vec3{2, 0, 1}));
  // the model's own copy keeps the expressions
  EXPECT_NE(writeModel(sim->model()).find("size: [=length, 0.1, =0.1*count]"), std::string::npos);
}

TEST(Part, BadParametersAreLocatedErrors) {
  core::Diagnostics diags;
  EXPECT_FALSE(make(lampModel("  main:\n    instances:\n      a: {type: lamp, params: {lenght: 4}}\n"), diags));
  EXPECT_NE(diags.str().find("m.gdpn.yaml:38:32: error: page type 'lamp' has no parameter 'lenght' (did you mean "
                             "'length'?)"),
            std::string::npos)
      << diags.str();
  core::Diagnostics refused;
  EXPECT_FALSE(make(lampModel("  main:\n    instances:\n      a: {type: lamp, params: {length: -1}}\n"), refused));
  EXPECT_NE(refused.str().find("m.gdpn.yaml:38:7: error: instance 'a': a/rail/bar.size = =length:"), std::string::npos)
      << refused.str();
  core::Diagnostics whole;
  EXPECT_FALSE(make(lampModel("  main:\n    instances:\n      a: {type: lamp, params: {count: 2.5}}\n"), whole));
  EXPECT_NE(whole.str().find("parameter 'count' of page type 'lamp' is a whole number; 2.5 is not"), std::string::npos)
      << whole.str();
  core::Diagnostics expr;
  EXPECT_FALSE(parseModel("gdpn: 1\npage_types:\n  t:\n    params: {w: 1}\n    scene:\n      - Cube: {size: [=w/(w-1), 1, 1]}\n",
                          "m.gdpn.yaml", expr));
  EXPECT_NE(expr.str().find("m.gdpn.yaml:6:26: error: division by zero"), std::string::npos) << expr.str();
}

TEST(Part, IoIsReadWrittenAndNamedInScriptsAndTheIoSection) {
  core::Diagnostics diags;
  auto sim = make(lampModel("  main:\n    instances:\n      a: {type: lamp, params: {brightness: 0.8}}\n"
                            "    transitions:\n      t: {post_fire: \"sim.log(sim.part('a').light, sim.part('a').height, "
                            "sim.part('main/a').params.brightness, sim.part('a').io)\"}\n"
                            "    places:\n      p: {tokens: 1}\n    arcs: [p -> t]\n"),
                  diags);
  ASSERT_TRUE(sim) << diags.str();
  PartRun& parts = *sim->parts();
  std::string why;
  const auto a = parts.find("a", why);
  ASSERT_TRUE(a) << why;
  EXPECT_EQ(parts.read(*a, "height", why), 1.0);
  EXPECT_EQ(parts.read(*a, "light", why), 0.0);
  ASSERT_TRUE(parts.write(*a, "light", 1, why)) << why;
  EXPECT_EQ(sim->plant()->find("a/rail/paint")->vec3(scene::field::Material::Emissive), (core::Vec3{0.8, 0, 0}));
  EXPECT_EQ(parts.read(*a, "light", why), 1.0);
  EXPECT_FALSE(parts.write(*a, "seen", 1, why));
  EXPECT_EQ(why, "'seen' of part 'main/a' is an input: the plant sets it");
  EXPECT_FALSE(parts.read(*a, "lite", why));
  EXPECT_EQ(why, "part 'main/a' has no I/O 'lite' (it has: light, seen, height, speed)");
  EXPECT_FALSE(parts.find("b", why));
  EXPECT_EQ(why, "no part 'b'");
  std::ostringstream trace;
  sim->traceTo(trace);
  sim->step();
  EXPECT_EQ(testing::logLines(trace.str()), (std::vector<std::string>{"True 1.0 0.8 ['light', 'seen', 'height', 'speed']"}));
}

TEST(Part, TheIoSectionMapsAPartsIoByName) {
  core::Diagnostics diags;
  auto m = parseModel(lampModel("  main:\n    instances:\n      a: {type: lamp}\n") +
                          "io:\n  coils:\n    0: {part: a, io: light}\n  discrete_inputs:\n    0: {name: wrong, part: a, io: light}\n",
                      "m.gdpn.yaml", diags);
  ASSERT_TRUE(m) << diags.str();
  checkModel(*m, diags);
  EXPECT_NE(diags.str().find("m.gdpn.yaml:43:5: error: discrete input 0: 'light' is a digital output: map it in coils"),
            std::string::npos)
      << diags.str();
  core::Diagnostics ok;
  auto good = parseModel(lampModel("  main:\n    instances:\n      a: {type: lamp}\n") +
                             "io:\n  coils:\n    0: {part: a, io: light}\n  discrete_inputs:\n    0: {part: a, io: seen}\n",
                         "m.gdpn.yaml", ok);
  ASSERT_TRUE(good);
  auto sim = Simulation::create(*good, ok);
  ASSERT_TRUE(sim) << ok.str();
  auto io = IoMap::create(*sim, good->io, ok);
  ASSERT_TRUE(io) << ok.str();
  EXPECT_EQ(io->writeBits(0, {true}, "plc"), IoError::None);
  std::string why;
  EXPECT_EQ(sim->parts()->read(0, "light", why), 1.0);
  EXPECT_TRUE(io->bit(IoTable::Coils, 0));
  EXPECT_EQ(io->rows().at(1).what, "a.light");
}

TEST(Part, AControlPatternDrivesThePartItNames) {
  core::Diagnostics diags;
  // a box falls into the lamp's eye: its control pattern lights the lamp
  auto sim = make(lampModel("  main:\n    instances:\n      a: {type: lamp}\n      c: {type: lamp_control, part: a}\n") +
                      "scene:\n  - Transform: {translation: [0, 0, 0.5], children: [{Body: {name: box, children: "
                      "[{Sphere: {radius: 0.1}}]}}]}\n",
                  diags);
  ASSERT_TRUE(sim) << diags.str();
  std::string why;
  for (int i = 0; i < 60 && sim->parts()->read(0, "light", why) == 0.0; ++i) sim->step();
  EXPECT_EQ(sim->parts()->read(0, "seen", why), 1.0);
  EXPECT_EQ(sim->parts()->read(0, "light", why), 1.0);
  core::Diagnostics unbound;
  EXPECT_FALSE(make(lampModel("  main:\n    instances:\n      a: {type: lamp}\n      c: {type: lamp_control}\n"), unbound));
  EXPECT_NE(unbound.str().find("instance 'c' of control pattern 'lamp_control' needs 'part': the lamp it controls"),
            std::string::npos)
      << unbound.str();
  core::Diagnostics wrong;
  EXPECT_FALSE(make(lampModel("  main:\n    instances:\n      a: {type: lamp}\n      c: {type: lamp_control, part: b}\n"),
                    wrong));
  EXPECT_NE(wrong.str().find("no instance 'b' on page 'main'"), std::string::npos) << wrong.str();
}

/// The trace of 30 steps of the lamp with forces asked at steps 5 (light on, seen on) and 20
/// (all released).
std::string forcedRun() {
  core::Diagnostics diags;
  auto sim = make(lampModel("  main:\n    instances:\n      a: {type: lamp}\n      c: {type: lamp_control, part: a}\n"),
                  diags);
  EXPECT_TRUE(sim) << diags.str();
  std::ostringstream trace;
  sim->traceTo(trace);
  std::string why;
  for (int i = 0; i < 30; ++i) {
    if (i == 5) {
      EXPECT_TRUE(sim->parts()->force(0, "seen", 1, why)) << why;
      EXPECT_TRUE(sim->parts()->force(0, "speed", 0.25, why)) << why;
    }
    if (i == 6) {
      // the input reads its force; the output holds its own whatever is written
      EXPECT_EQ(sim->parts()->read(0, "seen", why), 1.0);
      EXPECT_TRUE(sim->parts()->write(0, "speed", 2, why));
      EXPECT_EQ(sim->plant()->find("a/belt")->number(scene::field::Conveyor::Speed), 0.25);
      const auto rows = sim->parts()->rows();
      EXPECT_TRUE(rows[1].forced && rows[3].forced && !rows[0].forced);
    }
    if (i == 20) sim->parts()->releaseAll();
    sim->step();
  }
  // the control pattern saw the forced input and lit the lamp; released, the output takes
  // what was written while it was forced
  EXPECT_EQ(sim->parts()->read(0, "seen", why), 0.0);
  EXPECT_EQ(sim->plant()->find("a/belt")->number(scene::field::Conveyor::Speed), 2.0);
  EXPECT_FALSE(sim->parts()->force(0, "speed", -1e300 * 1e300, why));
  return trace.str();
}

TEST(Part, AControlPatternUsesOtherPartsByRoleAndHasItsOwnParameters) {
  core::Diagnostics diags;
  auto sim = make(mirrorModel("  main:\n    instances:\n      a: {type: lamp}\n      b: {type: lamp, translation: [5, 0, 0]}\n"
                              "      m: {type: lamp_mirror, part: a, uses: {other: b}}\n"),
                  diags);
  ASSERT_TRUE(sim) << diags.str();
  auto* parts = sim->parts();
  std::string why;
  const auto a = parts->find("a", why), b = parts->find("b", why), m = parts->find("m", why);
  ASSERT_TRUE(a && b && m) << why;
  const auto uses = parts->usesOf(*m);
  ASSERT_EQ(uses.size(), 2U);
  EXPECT_EQ(uses[0], (std::pair<std::string, std::optional<std::size_t>>{"other", b}));
  EXPECT_EQ(uses[1], (std::pair<std::string, std::optional<std::size_t>>{"spare", std::nullopt}));
  EXPECT_EQ(parts->ownerOf("main/m/light"), m);
  EXPECT_EQ(parts->ofConstruct("main/m/light"), a);
  // b sees (forced): the pattern lights a, at its own gain
  sim->step();
  EXPECT_EQ(*parts->read(*a, "light", why), 0.0);
  ASSERT_TRUE(parts->force(*b, "seen", 1, why)) << why;
  sim->step();
  sim->step();
  EXPECT_EQ(*parts->read(*a, "light", why), 1.0);
  EXPECT_EQ(*parts->read(*a, "speed", why), 2.0);
  // the file keeps the roles as written
  const auto text = writeModel(sim->model());
  EXPECT_NE(text.find("m: {type: lamp_mirror, part: a, uses: {other: b}}"), std::string::npos) << text;
  EXPECT_NE(text.find("other: {io: [seen], description: \"the lamp it mirrors\"}"), std::string::npos) << text;
  EXPECT_NE(text.find("spare: {io: [light, seen], optional: true}"), std::string::npos) << text;
  auto again = parseModel(text, "again.gdpn.yaml", diags);
  ASSERT_TRUE(again) << diags.str();
  EXPECT_EQ(again->parts.at("lamp_mirror"), sim->model().parts.at("lamp_mirror"));
  EXPECT_EQ(again->net.pages, sim->model().net.pages);
}

TEST(Part, RolesThatCannotBeFilledAreLocatedErrors) {
  const auto errors = [](const std::string& instance) {
    core::Diagnostics diags;
    EXPECT_FALSE(make(mirrorModel("  main:\n    instances:\n      a: {type: lamp}\n      b: {type: lamp}\n" + instance), diags));
    return diags.str();
  };
  EXPECT_NE(errors("      m: {type: lamp_mirror, part: a, uses: {othr: b}}\n")
                .find("m.gdpn.yaml:53:52: error: page type 'lamp_mirror' has no role 'othr' (did you mean 'other'?)"),
            std::string::npos)
      << errors("      m: {type: lamp_mirror, part: a, uses: {othr: b}}\n");
  EXPECT_NE(errors("      m: {type: lamp_mirror, part: a}\n").find("instance 'm' of 'lamp_mirror' needs 'uses: {other: ...}': "
                                                                   "a part with seen (the lamp it mirrors)"),
            std::string::npos);
  EXPECT_NE(errors("      m: {type: lamp_mirror, part: a, uses: {other: c}}\n").find("no part instance 'c' on page 'main'"),
            std::string::npos);
  // a part without the role's I/O: the pattern itself has none
  EXPECT_NE(errors("      m: {type: lamp_mirror, part: a, uses: {other: n}}\n      n: {type: lamp_mirror, part: b, uses: {other: a}}\n")
                .find("'n' is a control pattern (lamp_mirror), not a part: role 'other' of 'lamp_mirror' needs a part with seen"),
            std::string::npos);
  EXPECT_NE(errors("      m: {type: lamp_mirror, part: a, uses: {other: a}}\n")
                .find("'a' is the part the pattern controls: role 'other' of 'lamp_mirror' needs a part with seen"),
            std::string::npos);
  // a role named as Python reserves a word: scripts could not reach it
  {
    core::Diagnostics d;
    auto text = mirrorModel("  main:\n    instances:\n      a: {type: lamp}\n");
    text.replace(text.find("      spare:"), 12, "      class:");
    EXPECT_FALSE(parseModel(text, "m.gdpn.yaml", d));
    EXPECT_NE(d.str().find("role 'class' is a word Python reserves"), std::string::npos) << d.str();
  }
  // a script asking for roles where there are none
  core::Diagnostics diags;
  auto sim = make(lampModel("  main:\n    instances:\n      a: {type: lamp}\n    transitions:\n      t: {guard: 'self.uses.eye'}\n"),
                  diags);
  ASSERT_TRUE(sim) << diags.str();
  sim->step();
  ASSERT_TRUE(sim->scriptHalt());
  EXPECT_NE(sim->scriptHalt()->message.find("'main/t' belongs to no control pattern's instance"), std::string::npos)
      << sim->scriptHalt()->message;
}

TEST(Part, AnInputReadsItsSensorsItemsData) {
  // a Region holding two bodies with user data (the first in path order: a): the first item's
  // datum, a text compared, a field,
  // and the sum over the items; a bad form is located at the I/O
  const std::string scene = R"Y(scene:
  - World: {gravity: [0, 0, 0]}
  - Region: {name: zone, size: [2, 2, 2], report: bodies}
  - Body: {name: a, mass: 2, data: {code: 7, material: metal}, children: [{Sphere: {radius: 0.1}}]}
  - Transform: {name: z, translation: [0.5, 0, 0], children: [{Body: {name: b, mass: 3, data: {material: plastic}, children: [{Sphere: {radius: 0.1}}]}}]}
)Y";
  const auto model = [&](const std::string& of) {
    return "gdpn: 1\npage_types:\n  probe:\n    part: {}\n    io:\n      x: {direction: input, signal: analog, node: zone, of: " +
           of + "}\n    scene:\n      - Region: {name: zone, size: [2, 2, 2], report: bodies}\npages:\n  main:\n    instances:\n      p: {type: probe}\n" + scene;
  };
  const auto value = [&](const std::string& of) -> double {
    core::Diagnostics diags;
    auto sim = make(model(of), diags);
    EXPECT_TRUE(sim) << diags.str();
    if (!sim) return -1;
    sim->step();
    sim->step();
    std::string why;
    return sim->parts()->read(0, "x", why).value_or(-1);
  };
  EXPECT_EQ(value("item.code"), 7);
  EXPECT_EQ(value("item.material=metal"), 1);
  EXPECT_EQ(value("item.material=wood"), 0);
  EXPECT_EQ(value("item.mass"), 2);
  EXPECT_EQ(value("items.mass"), 5);
  EXPECT_EQ(value("items.material=plastic"), 1);
  EXPECT_EQ(value("items.colour"), 0);
  EXPECT_EQ(value("item.x"), 0) << "a datum named x, not an axis";
  core::Diagnostics diags;
  EXPECT_FALSE(make(model("items."), diags));
  EXPECT_NE(diags.str().find("'items.' names no datum: write item.KEY, item.KEY=TEXT, items.KEY"), std::string::npos)
      << diags.str();
  for (const char* bad : {"item.material=", "item.a=b=c"}) {
    core::Diagnostics d;
    EXPECT_FALSE(make(model(bad), d)) << bad;
    EXPECT_NE(d.str().find("names no datum"), std::string::npos) << d.str();
  }
}

TEST(Part, ForcesApplyAtStepBoundariesAreTracedAndReproducible) {
  const std::string trace = forcedRun();
  EXPECT_NE(trace.find("\"step\":6,\"t\":0.1,\"ev\":\"force\",\"part\":\"main/a\",\"io\":\"seen\",\"value\":1"),
            std::string::npos)
      << trace;
  EXPECT_NE(trace.find("\"ev\":\"release\",\"part\":\"main/a\",\"io\":\"speed\""), std::string::npos);
  EXPECT_NE(trace.find("\"transition\":\"main/c/light\""), std::string::npos);
  EXPECT_EQ(forcedRun(), trace);
}

TEST(Part, AForceAppliesInAStepOfThePlantAloneToo) {
  core::Diagnostics diags;
  auto sim = make(lampModel("  main:\n    instances:\n      a: {type: lamp}\n"), diags);
  ASSERT_TRUE(sim) << diags.str();
  sim->start();
  std::string why;
  ASSERT_TRUE(sim->parts()->force(0, "speed", 0.5, why)) << why;
  sim->stepPlant();
  EXPECT_EQ(sim->plant()->find("a/belt")->number(scene::field::Conveyor::Speed), 0.5);
  EXPECT_TRUE(sim->parts()->rows()[3].forced);
  sim->parts()->releaseAll();
  sim->stepPlant();
  EXPECT_FALSE(sim->parts()->rows()[3].forced);
  EXPECT_EQ(sim->plant()->find("a/belt")->number(scene::field::Conveyor::Speed), 0.0);
}

/// A folder of its own under the test's temporary folder.
fs::path scratch(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("gdpn_part_test_" + name + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

TEST(PartLibrary, TheSearchPathFollowsXdgThenTheInstallThenTheSourceTree) {
  ::setenv("XDG_DATA_HOME", "/home/u/data", 1);
  ::setenv("XDG_DATA_DIRS", "/opt/a:/opt/b", 1);
  const auto path = partSearchPath("/work/model");
  ASSERT_GE(path.size(), 5U);
  EXPECT_EQ(path[0], "/work/model");
  EXPECT_EQ(path[1], "/home/u/data/gdpn/parts");
  EXPECT_EQ(path[2], "/opt/a/gdpn/parts");
  EXPECT_EQ(path[3], "/opt/b/gdpn/parts");
  EXPECT_EQ(path.back(), std::string(GDPN_SOURCE_DIR) + "/parts");
  ::unsetenv("XDG_DATA_DIRS");
  EXPECT_EQ(partSearchPath("")[1], "/usr/local/share/gdpn/parts");
  ::unsetenv("XDG_DATA_HOME");
}

TEST(PartLibrary, AModelKeepsItsCopyAndRunsWithoutTheLibrary) {
  // a library folder is searched with its subfolders
  const fs::path lib = scratch("lib") / "parts";
  fs::create_directories(lib / "test");
  fs::copy_file(kLampFile, lib / "test" / "lamp.gdpn.yaml");
  core::Diagnostics diags;
  auto parts = scanParts({lib.string()}, diags);
  ASSERT_EQ(parts.size(), 2U) << diags.str();
  // a model's folder is read without descending
  EXPECT_TRUE(scanParts({lib.parent_path().string()}, diags).empty());
  const LibraryPart* lamp = findLibraryPart(parts, "lamp");
  ASSERT_TRUE(lamp);
  EXPECT_FALSE(lamp->pattern);
  EXPECT_TRUE(findLibraryPart(parts, "lamp_control")->pattern);
  EXPECT_EQ(lamp->description, "a lamp on a rail");
  Model m;
  std::string why;
  const auto names = placePart(m, "main", *lamp, {1, 2, 0}, 90, true, why);
  ASSERT_EQ(names, (std::vector<std::string>{"lamp1", "lamp1_control"})) << why;
  EXPECT_EQ(placePart(m, "main", *lamp, {0, 0, 0}, 0, false, why), (std::vector<std::string>{"lamp2"}));
  const auto mapped = mapPartIo(m, "main", "lamp1", why);
  ASSERT_EQ(mapped.size(), 4U) << why;
  EXPECT_EQ(mapped[2].table, IoTable::InputRegisters);
  EXPECT_EQ(mapped[2].type, IoDataType::Float);
  EXPECT_TRUE(mapPartIo(m, "main", "lamp1", why).empty());  // mapped once
  const fs::path saved = scratch("model") / "m.gdpn.yaml";
  ASSERT_TRUE(saveModel(m, saved.string(), diags)) << diags.str();
  fs::remove_all(lib);
  auto back = loadModel(saved.string(), diags);
  ASSERT_TRUE(back) << diags.str();
  EXPECT_EQ(back->parts.at("lamp").version, 1);
  auto sim = Simulation::create(*back, diags);
  ASSERT_TRUE(sim) << diags.str();
  EXPECT_EQ(sim->plant()->find("lamp1")->value(scene::field::Transform::Rotation),
            scene::FieldValue(std::array<double, 4>{0, 0, 1, 90}));
  EXPECT_TRUE(IoMap::create(*sim, back->io, diags)) << diags.str();
}

TEST(PartLibrary, TheHigherVersionWinsAndOfEqualOnesTheFirstFolder) {
  const fs::path near = scratch("near"), far = scratch("far");
  core::Diagnostics read;
  std::string text = core::readFile(kLampFile, read).value();
  std::ofstream(near / "lamp.gdpn.yaml") << text;
  const std::string v2 = "version: 2, group: Test, control";
  text.replace(text.find("version: 1, group: Test, control"), v2.size(), v2);
  std::ofstream(far / "lamp.gdpn.yaml") << text;
  core::Diagnostics diags;
  auto parts = scanParts({near.string(), far.string()}, diags);
  ASSERT_TRUE(findLibraryPart(parts, "lamp")) << diags.str();
  EXPECT_EQ(findLibraryPart(parts, "lamp")->spec.version, 2);
  EXPECT_EQ(findLibraryPart(parts, "lamp")->file, (far / "lamp.gdpn.yaml").string());
  // of one version, the first folder's
  const fs::path same = scratch("same");
  fs::copy_file(near / "lamp.gdpn.yaml", same / "lamp.gdpn.yaml");
  EXPECT_EQ(findLibraryPart(scanParts({same.string(), near.string()}, diags), "lamp")->file,
            (same / "lamp.gdpn.yaml").string());
  EXPECT_EQ(std::count_if(parts.begin(), parts.end(), [](const LibraryPart& p) { return p.name == "lamp"; }), 1);
  // of one version, a copy without its picture (a saved model's, beside the model being
  // edited) does not hide the file that has it: the palette shows the picture
  const fs::path pictured = scratch("pictured");
  std::string with = core::readFile(kLampFile, read).value();
  const std::string pic = "version: 1, group: Test, picture: lamp.png, control";
  with.replace(with.find("version: 1, group: Test, control"), std::string("version: 1, group: Test, control").size(), pic);
  std::ofstream(pictured / "lamp.gdpn.yaml") << with;
  std::ofstream(pictured / "lamp.png") << "a picture";
  std::ofstream(same / "lamp.gdpn.yaml") << with;  // the copy, its picture not beside it
  const auto found = scanParts({same.string(), pictured.string()}, diags);
  const auto* lamp = findLibraryPart(found, "lamp");
  ASSERT_TRUE(lamp);
  EXPECT_EQ(lamp->file, (pictured / "lamp.gdpn.yaml").string());
  EXPECT_EQ(lamp->picture, (pictured / "lamp.png").string());
}

TEST(PartLibrary, NodesOfAScenePlacedAsANewPart) {
  core::Diagnostics diags;
  auto m = parseModel("gdpn: 1\nparams: {w: 0.5, h: 2}\nscene:\n"
                      "  - Transform: {name: table, translation: [3, 1, 0], children: [{Cube: {name: top, size: [1, $w, 0.05]}}]}\n"
                      "  - Transform: {name: lamp, translation: [3, 2, 1], children: [{Sphere: {radius: 0.1}}]}\n",
                      "m.gdpn.yaml", diags);
  ASSERT_TRUE(m) << diags.str();
  std::string why;
  const std::vector<const scene::Node*> nodes = {m->scene->find("table"), m->scene->find("lamp")};
  auto part = partFromNodes(nodes, "desk", "Furniture", {m->params[0]}, why);
  ASSERT_TRUE(part) << why;
  // the first node's place is the origin; the width stays a parameter of the part
  const scene::Scene& s = *part->type_scenes.at("desk");
  EXPECT_EQ(s.find("table")->vec3(scene::field::Transform::Translation), (core::Vec3{0, 0, 0}));
  EXPECT_EQ(s.find("lamp")->vec3(scene::field::Transform::Translation), (core::Vec3{0, 1, 1}));
  EXPECT_EQ(part->parts.at("desk").params.size(), 1U);
  const fs::path lib = scratch("made");
  ASSERT_TRUE(saveModel(*part, (lib / "desk.gdpn.yaml").string(), diags)) << diags.str();
  auto parts = scanParts({lib.string()}, diags);
  const LibraryPart* desk = findLibraryPart(parts, "desk");
  ASSERT_TRUE(desk) << diags.str();
  EXPECT_EQ(desk->spec.group, "Furniture");
  Model use;
  ASSERT_FALSE(placePart(use, "main", *desk, {5, 0, 0}, 0, false, why).empty()) << why;
  use.net.pages[0].instances[0].params.push_back({"w", 0.8, {}});
  auto sim = Simulation::create(use, diags);
  ASSERT_TRUE(sim) << diags.str();
  EXPECT_EQ(sim->plant()->find("desk1/table/top")->vec3(scene::field::Cube::Size), (core::Vec3{1, 0.8, 0.05}));
  EXPECT_FALSE(partFromNodes({}, "x", "", {}, why));
  EXPECT_EQ(why, "nothing is selected to make a part of");
  EXPECT_FALSE(partFromNodes(nodes, "2desk", "", {}, why));
}

TEST(PartLibrary, ANewerVersionIsOfferedAndAppliedAndRemovedIoIsLocated) {
  const fs::path lib = scratch("newer");
  core::Diagnostics read;
  std::string text = core::readFile(kLampFile, read).value();
  fs::create_directories(lib);
  {
    std::ofstream(lib / "lamp.gdpn.yaml") << text;
  }
  core::Diagnostics diags;
  auto parts = scanParts({lib.string()}, diags);
  Model m;
  std::string why;
  ASSERT_FALSE(placePart(m, "main", *findLibraryPart(parts, "lamp"), {0, 0, 0}, 0, false, why).empty()) << why;
  m.net.pages[0].instances[0].params.push_back({"count", 4, {}});
  ASSERT_FALSE(mapPartIo(m, "main", "lamp1", why).empty());
  EXPECT_TRUE(partUpdates(m, parts).empty());
  // version 2 drops the input 'seen' and the parameter 'count', and adds 'blink'
  auto replace = [&](const std::string& from, const std::string& to) { text.replace(text.find(from), from.size(), to); };
  replace("version: 1, group: Test, control", "version: 2, group: Test, control");
  replace("      seen: {direction: input, signal: digital, description: \"something under it\", node: eye, of: active}\n",
          "      blink: {direction: output, signal: digital, node: belt, field: speed}\n");
  replace("      count: 3\n", "");
  replace("=0.1*count", "0.3");
  replace("guard: \"self.part.seen\"", "guard: \"True\"");
  replace("guard: \"not self.part.seen\"", "guard: \"False\"");
  {
    std::ofstream(lib / "lamp.gdpn.yaml") << text;
  }
  parts = scanParts({lib.string()}, diags);
  const auto updates = partUpdates(m, parts);
  ASSERT_EQ(updates.size(), 1U);
  EXPECT_EQ(updates[0].from, 1);
  EXPECT_EQ(updates[0].to, 2);
  EXPECT_EQ(updates[0].removed, (std::vector<std::string>{"seen"}));
  EXPECT_EQ(updates[0].added, (std::vector<std::string>{"blink"}));
  EXPECT_EQ(updates[0].params_removed, (std::vector<std::string>{"count"}));
  // placing another is refused until the model takes the update
  EXPECT_TRUE(placePart(m, "main", *findLibraryPart(parts, "lamp"), {0, 0, 0}, 0, false, why).empty());
  EXPECT_EQ(why, "the model uses version 1 of 'lamp'; the library has 2: update it first");
  // saved and read back, the model's io section is located
  const fs::path saved = scratch("updated") / "m.gdpn.yaml";
  ASSERT_TRUE(saveModel(m, saved.string(), diags));
  auto back = loadModel(saved.string(), diags);
  ASSERT_TRUE(back);
  std::vector<std::string> uses;
  ASSERT_TRUE(applyPartUpdate(*back, updates[0], uses, why)) << why;
  EXPECT_EQ(back->parts.at("lamp").version, 2);
  EXPECT_TRUE(back->net.pages[0].instances[0].params.empty());
  ASSERT_EQ(uses.size(), 1U);
  EXPECT_NE(uses[0].find("m.gdpn.yaml:4:5: discrete input 0 uses main/lamp1.seen"), std::string::npos) << uses[0];
  core::Diagnostics check;
  checkModel(*back, check);
  EXPECT_NE(check.str().find("m.gdpn.yaml:4:5: error: discrete input 0: part 'main/lamp1' has no I/O 'seen'"),
            std::string::npos)
      << check.str();
}

}  // namespace
}  // namespace gdpn::model

namespace gdpn::model {
namespace {

// examples/station: issue 54's station, made of parts, sorts red boxes into the bin and lets
// blue ones ride to the remover; its summary counts both.
TEST(PartLibrary, AControlPatternsRolesAreFilledByTheNearestPartThatFits) {
  core::Diagnostics diags;
  auto m = parseModel(mirrorModel("  main:\n    instances:\n      a: {type: lamp}\n      far: {type: lamp, translation: [5, 0, 0]}\n"
                                  "      near: {type: lamp, translation: [0, 1, 0]}\n"),
                      "m.gdpn.yaml", diags);
  ASSERT_TRUE(m) << diags.str();
  EXPECT_EQ(controlPatterns(*m, "lamp"), (std::vector<std::string>{"lamp_control", "lamp_mirror"}));
  std::string why;
  // nearest fills the role, and the optional one too (a lamp has light and seen)
  auto roles = fillRoles(*m, "main", "a", "lamp_mirror", {}, why);
  ASSERT_TRUE(why.empty()) << why;
  ASSERT_EQ(roles.size(), 2U);
  EXPECT_EQ(roles[0].part, "near");
  EXPECT_EQ(roles[1].part, "near");
  // what is given stays
  roles = fillRoles(*m, "main", "a", "lamp_mirror", {{"other", "far", {}}}, why);
  EXPECT_EQ(roles[0].part, "far");
  EXPECT_TRUE(fillRoles(*m, "main", "a", "lamp_mirror", {{"nobody", "far", {}}}, why).empty());
  EXPECT_EQ(why, "'lamp_mirror' has no role 'nobody'");
  why.clear();
  EXPECT_TRUE(fillRoles(*m, "main", "a", "lamp_mirror", {{"other", "far", {}}, {"other", "near", {}}}, why).empty());
  EXPECT_EQ(why, "role 'other' is given twice");
  why.clear();
  EXPECT_TRUE(fillRoles(*m, "main", "a", "lamp_mirror", {{"other", "a", {}}}, why).empty());
  EXPECT_EQ(why, "'a' is the part the pattern controls: role 'other' of 'lamp_mirror' needs a part with seen");
  why.clear();
  EXPECT_TRUE(fillRoles(*m, "main", "a", "lamp_mirror", {{"other", "ghost", {}}}, why).empty());
  EXPECT_EQ(why, "no instance 'ghost' on page 'main': role 'other' of 'lamp_mirror' needs a part with seen");
  // added: named after the pattern's own word, and it runs
  why.clear();
  EXPECT_EQ(addPartControl(*m, "main", "a", why, "lamp_mirror"), "a_mirror") << why;
  EXPECT_EQ(addPartControl(*m, "main", "far", why, "lamp_nothing"), "");
  EXPECT_EQ(why, "'lamp_nothing' is no control pattern of 'lamp' (it has: lamp_control, lamp_mirror)");
  auto sim = Simulation::create(*m, diags);
  ASSERT_TRUE(sim) << diags.str();
  // alone on its page, a lamp finds nothing to mirror
  auto alone = parseModel(mirrorModel("  main:\n    instances:\n      a: {type: lamp}\n"), "m.gdpn.yaml", diags);
  ASSERT_TRUE(alone);
  why.clear();
  EXPECT_EQ(addPartControl(*alone, "main", "a", why, "lamp_mirror"), "");
  EXPECT_EQ(why, "'lamp_mirror' needs a part with seen for its role 'other' (the lamp it mirrors): place one on page "
                 "'main' first");
}

TEST(StationExample, RedBoxesEndInTheBinBlueInTheRemover) {
  auto sim = testing::openModelFile("examples/station/sorting_station.gdpn.yaml");
  ASSERT_TRUE(sim);
  const auto outcome = sim->run({120.0, std::nullopt});
  EXPECT_EQ(outcome.reason, StopReason::Until) << outcome.message;
  std::string error;
  const auto figures = sim->modelFigures(error);
  ASSERT_TRUE(error.empty()) << error;
  std::map<std::string, double> f;
  for (const auto& x : figures) f[x.label] = x.value.value_or(-1);
  // a box every 4 s from 0 to 116 s, each red one pushed off, each blue one removed
  EXPECT_EQ(f["boxes made"], 30);
  EXPECT_EQ(f["red boxes in the bin"], 15);
  EXPECT_EQ(f["blue boxes removed"], 15);
  EXPECT_EQ(f["strokes"], 15);
  // and each is where its colour says
  for (const auto& holder : sim->plant()->find("emitter1/items")->children()) {
    const scene::Node* box = holder->find("box");
    ASSERT_NE(box, nullptr);
    const bool red = std::get<std::string>(*box->datum("colour")) == "red";
    EXPECT_TRUE(red) << box->path() << " was not removed";
    EXPECT_GT(box->framePose().position.y, 0.4) << box->path() << " lies in the bin";
  }
}

}  // namespace
}  // namespace gdpn::model

namespace gdpn::model {
namespace {

// docs/parts.md's catalogue is made from the part files of parts/ (GDPN_UPDATE_GOLDEN=1
// rewrites it); every part gdpn ships is in it, with its picture.
TEST(PartDocs, TheCatalogueIsThePartFiles) {
  core::Diagnostics diags;
  const std::string src = GDPN_SOURCE_DIR;
  const auto parts = scanParts({src + "/parts"}, diags);
  EXPECT_TRUE(diags.all().empty()) << diags.str();
  for (const char* name : {"small_box", "medium_box", "large_box", "emitter", "remover", "belt_conveyor",
                           "diffuse_sensor", "through_beam", "pusher", "bin", "stack_light", "push_button",
                           "emergency_stop", "selector_switch", "beacon", "metal_base", "plastic_lid",
                           "inductive_sensor", "capacitive_sensor", "code_reader", "scale_conveyor", "pick_and_place", "pallet", "chute",
                           "curved_belt", "roller_conveyor", "turntable", "transfer", "stopper_belt", "elevator",
                           "stacker", "pivot_arm_sorter", "potentiometer", "digital_display", "light_array"}) {
    const LibraryPart* p = findLibraryPart(parts, name);
    ASSERT_TRUE(p) << name;
    EXPECT_FALSE(p->picture.empty()) << name << " has no picture";
    EXPECT_FALSE(p->description.empty()) << name;
  }
  const std::string want = partsMarkdown(parts, src + "/docs");
  const std::string path = src + "/docs/parts.md";
  core::Diagnostics read;
  std::string text = core::readFile(path, read).value_or("");
  const auto begin = text.find("<!-- parts: from gdpn::model::partsMarkdown() -->");
  const std::string end_marker = "<!-- end of parts -->\n";
  const auto end = text.find(end_marker);
  ASSERT_NE(begin, std::string::npos);
  ASSERT_NE(end, std::string::npos);
  const std::string have = text.substr(begin, end + end_marker.size() - begin);
  if (std::getenv("GDPN_UPDATE_GOLDEN") != nullptr && have != want) {
    text.replace(begin, have.size(), want);
    std::ofstream(path) << text;
    return;
  }
  EXPECT_EQ(have, want) << "docs/parts.md lags the part files; GDPN_UPDATE_GOLDEN=1 rewrites it";
}

}  // namespace
}  // namespace gdpn::model

// The io section resolved against a run: table values read from the plant and the net (scaled,
// rounded, held within range, 32-bit types high word first), and a controller's writes applied
// (checked first, all or nothing), the lockstep register, and what the trace records.

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <limits>
#include <sstream>

#include "gdpn/model/io.h"
#include "gdpn/model/model.h"
#include "gdpn/model/simulation.h"
#include "gdpn/net/kernel.h"
#include "gdpn/scene/node.h"

namespace gdpn::model {
namespace {

constexpr const char* kCell = R"(gdpn: 1
settings: {dt: 0.01}
scene:
  - World: {name: world, gravity: [0, 0, 0]}
  - Camera: {position: [20, 0, 0]}
  - Transform:
      name: panel
      translation: [20, 0, 0]
      children: [{Cube: {size: [2, 2, 2]}}, {KeyboardSensor: {name: keys}}]
  - Transform: {name: belt, children: [{Conveyor: {name: drive, speed: 0.25}}, {Cube: {size: [2, 0.5, 0.1]}}]}
  - Transform: {name: gate, translation: [0, 0, 3], children: [{Region: {name: eye, size: [0.2, 0.2, 0.2], report: bodies}}]}
  - Transform:
      name: post
      translation: [5, 0, 0]
      children: [{Joint: {name: arm, kind: hinge, control: position, target1: 0, fmax1: 50, children: [{Body: {children: [{Sphere: {radius: 0.1}}]}}]}}]
  - Transform: {translation: [0, 0, 3], children: [{Body: {name: ball, children: [{Sphere: {radius: 0.05}}]}}]}
io:
  lockstep: 50
  discrete_inputs:
    0: {node: gate/eye, of: active, opcua: "ns=1;s=Eye"}
    1: {place: main/parts}
    2: {node: panel/keys, key: g}
    3: {node: world, of: auto_disable}
  input_registers:
    0: {node: belt/drive, of: speed, scale: 1000, unit: mm/s}
    1: {name: parts_in, place: main/parts}
    2: {name: speed_float, node: belt/drive, of: speed, type: float32}
    4: {name: speed_int32, node: belt/drive, of: speed, scale: -1e9, type: int32}
    6: {name: speed_high, node: belt/drive, of: speed, scale: 1e6, type: uint16}
    7: {name: speed_low, node: belt/drive, of: speed, scale: -1, type: UInt16}
    8: {name: speed_double, node: belt/drive, of: speed, scale: -1, type: Double}
  coils:
    0: {place: main/start}
    1: {name: belt_on, node: belt/drive, field: speed, on: 0.5, off: 0}
    2: {name: freeze, node: world, field: auto_disable}
  holding_registers:
    0: {node: post/arm, field: target1, scale: 10, unit: 0.1 deg}
    1: {name: parts_set, place: main/parts}
    2: {name: belt_speed, node: belt/drive, field: speed, type: float32}
    4: {name: arm_force, node: post/arm, field: fmax1, type: int32}
    6: {name: parts_float, place: main/parts, type: Float}
    8: {name: arm_target, node: post/arm, field: target1, type: Double, opcua: "ns=2;i=7"}
    12: {name: arm_force_u16, node: post/arm, field: fmax1, type: UInt16}
    13: {name: arm_force_u32, node: post/arm, field: fmax1, type: UInt32}
pages:
  main:
    places: {start: {}, parts: {tokens: 3}, done: {}}
    transitions: {go: {}}
    arcs: [start -> go, go -> done]
)";

class IoMapTest : public ::testing::Test {
 protected:
  void SetUp() override {
    core::Diagnostics diags;
    model_ = parseModel(kCell, "cell.gdpn.yaml", diags);
    ASSERT_TRUE(model_) << diags.str();
    sim_ = Simulation::create(*model_, diags);
    ASSERT_TRUE(sim_) << diags.str();
    sim_->traceTo(trace_);
    io_ = IoMap::create(*sim_, model_->io, diags);
    ASSERT_TRUE(io_) << diags.str();
    sim_->start();
  }
  std::int64_t tokens(const char* place) {
    const auto& net = sim_->net();
    const auto id = net.findPlace(place);
    if (!id) {
      ADD_FAILURE() << "no place " << place;
      return -1;
    }
    return sim_->kernel().marking(net::PlaceSlotId{net.places()[*id].slots_begin});
  }
  double field(const char* path, const char* name) {
    const scene::Node* n = sim_->plant()->find(path);
    return std::get<double>(n->value(static_cast<std::size_t>(n->type().fieldIndex(name))));
  }
  std::optional<Model> model_;
  std::unique_ptr<Simulation> sim_;
  std::unique_ptr<IoMap> io_;
  std::ostringstream trace_;
};

TEST_F(IoMapTest, BitsReadSensorsPlacesKeysAndBoolFields) {
  EXPECT_TRUE(io_->bit(IoTable::DiscreteInputs, 0));   // the ball floats in the eye
  EXPECT_TRUE(io_->bit(IoTable::DiscreteInputs, 1));   // 3 parts
  EXPECT_FALSE(io_->bit(IoTable::DiscreteInputs, 2));
  EXPECT_TRUE(io_->bit(IoTable::DiscreteInputs, 3));   // auto_disable is on by default
  sensors::InputEvent key;
  key.key = "g";
  sim_->push(key);
  sim_->step();
  EXPECT_TRUE(io_->bit(IoTable::DiscreteInputs, 0));
  EXPECT_TRUE(io_->bit(IoTable::DiscreteInputs, 2)) << "the viewer is inside the panel: g is heard";
  EXPECT_FALSE(io_->bit(IoTable::DiscreteInputs, 9)) << "unmapped: false";
}

TEST_F(IoMapTest, RegistersAreScaledRoundedAndHeldWithinTheirType) {
  EXPECT_EQ(io_->word(IoTable::InputRegisters, 0), 250);  // 0.25 m/s x 1000
  EXPECT_EQ(io_->word(IoTable::InputRegisters, 1), 3);
  // float32, high word first: 0.25f is 0x3E800000
  EXPECT_EQ(io_->word(IoTable::InputRegisters, 2), 0x3E80);
  EXPECT_EQ(io_->word(IoTable::InputRegisters, 3), 0x0000);
  // int32: -0.25e9 is 0xF1194D80
  EXPECT_EQ(io_->word(IoTable::InputRegisters, 4), 0xF119);
  EXPECT_EQ(io_->word(IoTable::InputRegisters, 5), 0x4D80);
  EXPECT_EQ(io_->word(IoTable::InputRegisters, 6), 65535) << "250000 held at the top of uint16";
  EXPECT_EQ(io_->word(IoTable::InputRegisters, 7), 0) << "-0.25 held at the bottom of uint16";
  EXPECT_EQ(io_->word(IoTable::HoldingRegisters, 4), 0);   // fmax1 50 N as int32: 0x00000032
  EXPECT_EQ(io_->word(IoTable::HoldingRegisters, 5), 50);
}

TEST_F(IoMapTest, WhatIsMappedCoversEachEntrysWordsAndTheLockstepRegister) {
  EXPECT_TRUE(io_->mapped(IoTable::InputRegisters, 0, 12));
  EXPECT_FALSE(io_->mapped(IoTable::InputRegisters, 0, 13));
  EXPECT_TRUE(io_->mapped(IoTable::HoldingRegisters, 50, 1));
  EXPECT_FALSE(io_->mapped(IoTable::HoldingRegisters, 49, 2));
  EXPECT_FALSE(io_->mapped(IoTable::Coils, 65535, 1));
  EXPECT_FALSE(io_->mapped(IoTable::DiscreteInputs, 65535, 2));
}

TEST_F(IoMapTest, ACoilOnAPlaceAddsATokenOnItsRisingEdge) {
  EXPECT_EQ(io_->writeBits(0, {true}, "plc"), IoError::None);
  EXPECT_EQ(tokens("main/start"), 1);
  EXPECT_EQ(io_->writeBits(0, {true}, "plc"), IoError::None);
  EXPECT_EQ(tokens("main/start"), 1) << "held on: no second token";
  EXPECT_TRUE(io_->bit(IoTable::Coils, 0));
  sim_->step();  // go starts: the token set between steps is there for this step's firing phase
  EXPECT_EQ(tokens("main/start"), 0);
  sim_->step();  // and completes
  EXPECT_EQ(tokens("main/done"), 1);
  EXPECT_EQ(io_->writeBits(0, {false}, "plc"), IoError::None);
  EXPECT_EQ(io_->writeBits(0, {true}, "plc"), IoError::None);
  EXPECT_EQ(tokens("main/start"), 1);
}

TEST_F(IoMapTest, CoilsOnFieldsWriteTheirOnAndOffValues) {
  EXPECT_FALSE(io_->bit(IoTable::Coils, 1)) << "0.25 m/s is not the coil's 0.5";
  EXPECT_EQ(io_->writeBits(1, {true, false}, "plc"), IoError::None);
  EXPECT_DOUBLE_EQ(field("belt/drive", "speed"), 0.5);
  EXPECT_TRUE(io_->bit(IoTable::Coils, 1));
  EXPECT_FALSE(io_->bit(IoTable::Coils, 2));
  EXPECT_EQ(io_->writeBits(1, {false}, "plc"), IoError::None);
  EXPECT_DOUBLE_EQ(field("belt/drive", "speed"), 0.0);
  EXPECT_EQ(io_->writeBits(2, {true, true}, "plc"), IoError::IllegalAddress) << "coil 3 is not mapped";
  EXPECT_FALSE(io_->bit(IoTable::Coils, 2)) << "nothing written";
}

TEST_F(IoMapTest, HoldingRegistersSetFieldsAndPlacesInTheModelsUnits) {
  EXPECT_EQ(io_->writeWords(0, {450, 7}, "plc"), IoError::None);
  EXPECT_DOUBLE_EQ(field("post/arm", "target1"), 45.0) << "450 tenths of a degree";
  EXPECT_EQ(tokens("main/parts"), 7);
  const auto half = std::bit_cast<std::uint32_t>(0.75f);
  EXPECT_EQ(io_->writeWords(2, {static_cast<std::uint16_t>(half >> 16), static_cast<std::uint16_t>(half)}, "plc"),
            IoError::None);
  EXPECT_DOUBLE_EQ(field("belt/drive", "speed"), 0.75);
  EXPECT_EQ(io_->word(IoTable::HoldingRegisters, 0), 450) << "read back in the same scale";
}

TEST_F(IoMapTest, AWriteIsCheckedWholeBeforeAnyOfItIsApplied) {
  // half of the float32 at 2: refused
  EXPECT_EQ(io_->writeWords(3, {0}, "plc"), IoError::IllegalAddress);
  EXPECT_EQ(io_->writeWords(1, {9, 0x3F40}, "plc"), IoError::IllegalAddress);
  EXPECT_EQ(tokens("main/parts"), 3) << "the place before the half entry stays";
  // fmax1 is at least 0: -1 as int32 is refused, and the tokens before it are not set
  EXPECT_EQ(io_->writeWords(1, {9}, "plc"), IoError::None);
  EXPECT_EQ(io_->writeWords(4, {0xFFFF, 0xFFFF}, "plc"), IoError::IllegalValue);
  EXPECT_DOUBLE_EQ(field("post/arm", "fmax1"), 50.0);
  EXPECT_EQ(io_->writeWords(1, {0x8000}, "plc"), IoError::IllegalValue) << "-32768 tokens";
  const auto nan = std::bit_cast<std::uint32_t>(std::nanf(""));
  EXPECT_EQ(io_->writeWords(2, {static_cast<std::uint16_t>(nan >> 16), static_cast<std::uint16_t>(nan)}, "plc"),
            IoError::IllegalValue);
  EXPECT_EQ(tokens("main/parts"), 9);
}

TEST_F(IoMapTest, ANumberTooLargeForAPlaceIsRefused) {
  // tokens are whole numbers from 0 to 2^53: 3e38 as float32 is refused, 5 is taken
  const auto words = [](float f) {
    const auto w = std::bit_cast<std::uint32_t>(f);
    return std::vector<std::uint16_t>{static_cast<std::uint16_t>(w >> 16), static_cast<std::uint16_t>(w)};
  };
  EXPECT_EQ(io_->writeWords(6, words(3.0e38F), "plc"), IoError::IllegalValue);
  EXPECT_EQ(io_->writeWords(6, words(2.5F), "plc"), IoError::IllegalValue);
  EXPECT_EQ(tokens("main/parts"), 3);
  EXPECT_EQ(io_->writeWords(6, words(5.0F), "plc"), IoError::None);
  EXPECT_EQ(tokens("main/parts"), 5);
  // a whole-number field past 2^53 likewise (int32 cannot reach it; a field's own range holds)
  EXPECT_EQ(io_->writeWords(4, {0x7FFF, 0xFFFF}, "plc"), IoError::None);
  EXPECT_DOUBLE_EQ(field("post/arm", "fmax1"), 2147483647.0);
}

TEST_F(IoMapTest, TheLockstepRegisterAsksForSteps) {
  EXPECT_TRUE(io_->lockstep());
  EXPECT_EQ(io_->pendingSteps(), 0u);
  EXPECT_EQ(io_->writeWords(50, {3}, "plc"), IoError::None);
  EXPECT_EQ(io_->writeWords(50, {2}, "plc"), IoError::None);
  EXPECT_EQ(io_->pendingSteps(), 5u);
  EXPECT_EQ(io_->word(IoTable::HoldingRegisters, 50), 5);
  io_->stepTaken();
  EXPECT_EQ(io_->pendingSteps(), 4u);
}

TEST_F(IoMapTest, TheTraceHasTheWritesThatChangedSomething) {
  for (int scan = 0; scan < 3; ++scan) ASSERT_EQ(io_->writeBits(1, {true}, "plc"), IoError::None);
  ASSERT_EQ(io_->writeWords(0, {450}, "plc"), IoError::None);
  ASSERT_EQ(io_->writeWords(50, {1}, "plc"), IoError::None);
  const std::string t = trace_.str();
  EXPECT_NE(t.find(R"("ev":"io","table":"coils","address":1,"value":1)"), std::string::npos) << t;
  EXPECT_NE(t.find(R"("ev":"io","table":"holding_registers","address":0,"value":45)"), std::string::npos) << t;
  std::size_t lines = 0;
  for (std::size_t at = t.find("\"ev\":\"io\""); at != std::string::npos; at = t.find("\"ev\":\"io\"", at + 1)) ++lines;
  EXPECT_EQ(lines, 2u) << "three scans writing the same coil are one change; the lockstep register is not traced\n" << t;
}

TEST_F(IoMapTest, RowsShowEachEntryItsValueAndItsLastWriter) {
  ASSERT_EQ(io_->writeWords(2, {0x3F40, 0}, "10.0.0.7:5020"), IoError::None);
  const auto rows = io_->rows();
  ASSERT_EQ(rows.size(), 22u);
  const auto& speed = rows[16];
  EXPECT_EQ(speed.table, IoTable::HoldingRegisters);
  EXPECT_EQ(speed.address, 2);
  EXPECT_EQ(speed.what, "belt/drive.speed");
  EXPECT_EQ(speed.wire, "Float");
  EXPECT_EQ(speed.name, "belt_speed");
  EXPECT_DOUBLE_EQ(speed.value, 0.75);
  EXPECT_EQ(speed.writer, "10.0.0.7:5020");
  EXPECT_EQ(rows[4].what, "belt/drive.speed");
  EXPECT_EQ(rows[4].wire, "x 1000 mm/s");
  EXPECT_EQ(rows[4].raw, 750);
  EXPECT_EQ(rows[4].name, "drive_speed") << "derived: what it maps";
  EXPECT_EQ(rows[0].writer, "");
}

TEST(IoMapValues, AValueOfAColouredPlaceGivesItsTokensAndABitWhileThereIsOne) {
  // p holds 2'a ++ 1'b; from 1 s, take moves one a at a time to q (1 s each)
  core::Diagnostics diags;
  auto m = loadModel(std::string(GDPN_SOURCE_DIR) + "/tests/data/good/value_counts.gdpn.yaml", diags);
  ASSERT_TRUE(m) << diags.str();
  auto sim = Simulation::create(*m, diags);
  ASSERT_TRUE(sim) << diags.str();
  auto io = IoMap::create(*sim, m->io, diags);
  ASSERT_TRUE(io) << diags.str();
  sim->start();
  EXPECT_TRUE(io->bit(IoTable::DiscreteInputs, 0));   // an a on p
  EXPECT_FALSE(io->bit(IoTable::DiscreteInputs, 1));  // none on q yet
  EXPECT_EQ(io->word(IoTable::InputRegisters, 0), 2);
  EXPECT_EQ(io->word(IoTable::InputRegisters, 1), 3);  // 3'(a, b)
  sim->run({1.5, {}});
  EXPECT_EQ(io->word(IoTable::InputRegisters, 0), 1);
  EXPECT_FALSE(io->bit(IoTable::DiscreteInputs, 1));
  sim->run({2.5, {}});
  EXPECT_FALSE(io->bit(IoTable::DiscreteInputs, 0));
  EXPECT_TRUE(io->bit(IoTable::DiscreteInputs, 1));
  EXPECT_EQ(io->word(IoTable::InputRegisters, 0), 0);
  const auto rows = io->rows();
  ASSERT_EQ(rows.size(), 4u);
  EXPECT_EQ(rows[3].what, "main/pairs=(a, b)");
}

/// The diagnostics of reading the io section `entries` (from line 5 of the file) over a net
/// with a value place, and of making it ready.
std::string valueEntryMistake(const std::string& entries) {
  core::Diagnostics diags;
  auto m = parseModel(R"yaml(gdpn: 1
colours:
  Ab: {enum: [a, b]}
io:
)yaml" + entries + R"yaml(
pages:
  main:
    places:
      p: {colour: Ab, values: "2'a ++ 1'b"}
      plain: {tokens: 1}
)yaml",
                      "io_values.gdpn.yaml", diags);
  if (m) {
    auto sim = Simulation::create(*m, diags);
    EXPECT_TRUE(sim) << diags.str();
    if (sim) {
      EXPECT_FALSE(IoMap::create(*sim, m->io, diags)) << entries;
    }
  }
  EXPECT_TRUE(diags.hasErrors()) << entries;
  return diags.str();
}

TEST(IoMapValues, AValueNotOfThePlaceOrNotReadIsRefusedAtItsPlace) {
  std::string d = valueEntryMistake("  input_registers:\n    0: {place: main/p, value: 3}");
  EXPECT_NE(d.find("io_values.gdpn.yaml:6:31: error: input register 0: "), std::string::npos) << d;
  d = valueEntryMistake("  discrete_inputs:\n    4: {place: main/plain, value: a}");
  EXPECT_NE(d.find("io_values.gdpn.yaml:6:35: error: discrete input 4: place 'main/plain' holds no values"),
            std::string::npos)
      << d;
  // a controller writes no value: coils and holding registers take no 'value'
  d = valueEntryMistake("  coils:\n    0: {place: main/p, value: a}");
  EXPECT_NE(d.find("io_values.gdpn.yaml:6:"), std::string::npos) << d;
  EXPECT_NE(d.find("'value'"), std::string::npos) << d;
  d = valueEntryMistake("  input_registers:\n    0: {node: main/p, of: speed, value: a}");
  EXPECT_NE(d.find("io_values.gdpn.yaml:6:5: error: input register 0: 'value' goes with 'place'"), std::string::npos)
      << d;
  // a syntax error, found when the file is read
  d = valueEntryMistake("  input_registers:\n    0: {place: main/p, value: \"(a,\"}");
  EXPECT_NE(d.find("io_values.gdpn.yaml:6:"), std::string::npos) << d;
}

/// The index of the point named `name` (fails the test when there is none).
std::size_t pointNamed(const IoMap& io, const std::string& name) {
  const auto& points = io.points();
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (points[i].name == name) return i;
  }
  ADD_FAILURE() << "no point " << name;
  return 0;
}

/// `x`'s four words, highest first.
std::vector<std::uint16_t> doubleWords(double x) {
  const auto w = std::bit_cast<std::uint64_t>(x);
  return {static_cast<std::uint16_t>(w >> 48), static_cast<std::uint16_t>(w >> 32), static_cast<std::uint16_t>(w >> 16),
          static_cast<std::uint16_t>(w)};
}

TEST_F(IoMapTest, PointsAreTheEntriesNamedAndTypedInTableOrder) {
  const auto& p = io_->points();
  ASSERT_EQ(p.size(), 22u);
  const std::vector<std::string> names = {
      "eye_active", "parts", "keys_key_g", "world_auto_disable",                                     // derived
      "drive_speed", "parts_in", "speed_float", "speed_int32", "speed_high", "speed_low", "speed_double",
      "start", "belt_on", "freeze",
      "arm_target1", "parts_set", "belt_speed", "arm_force", "parts_float", "arm_target", "arm_force_u16", "arm_force_u32"};
  for (std::size_t i = 0; i < names.size(); ++i) EXPECT_EQ(p[i].name, names[i]) << i;
  EXPECT_EQ(p[0].type, IoDataType::Boolean);
  EXPECT_FALSE(p[0].writable);
  EXPECT_EQ(p[0].what, "gate/eye.active");
  EXPECT_EQ(p[0].table, IoTable::DiscreteInputs);
  EXPECT_EQ(p[0].plc_node, "ns=1;s=Eye");
  EXPECT_EQ(p[0].plc_node_loc.file, "cell.gdpn.yaml");
  EXPECT_EQ(p[0].plc_node_loc.line, 20);
  EXPECT_EQ(p[0].plc_node_loc.column, 44);
  EXPECT_EQ(p[4].type, IoDataType::Int16);
  EXPECT_EQ(p[4].unit, "mm/s");
  EXPECT_FALSE(p[4].writable);
  EXPECT_EQ(p[6].type, IoDataType::Float) << "the old float32";
  EXPECT_EQ(p[8].type, IoDataType::UInt16) << "the old uint16";
  EXPECT_EQ(p[9].type, IoDataType::UInt16);
  EXPECT_EQ(p[10].type, IoDataType::Double);
  EXPECT_EQ(p[10].address, 8);
  EXPECT_EQ(p[11].type, IoDataType::Boolean);
  EXPECT_TRUE(p[11].writable);
  EXPECT_EQ(p[11].table, IoTable::Coils);
  EXPECT_EQ(p[14].unit, "0.1 deg");
  EXPECT_TRUE(p[14].writable);
  EXPECT_EQ(p[17].type, IoDataType::Int32);
  EXPECT_EQ(p[19].type, IoDataType::Double);
  EXPECT_EQ(p[19].plc_node, "ns=2;i=7");
  EXPECT_EQ(p[21].type, IoDataType::UInt32);
  EXPECT_EQ(p[1].plc_node, "");
  EXPECT_STREQ(ioDataTypeName(IoDataType::UInt32), "UInt32");
  EXPECT_STREQ(ioDataTypeName(IoDataType::Boolean), "Boolean");
}

TEST_F(IoMapTest, APointReadsAsTheNumberOnTheWire) {
  EXPECT_EQ(io_->read(0), 1.0);  // the ball floats in the eye
  EXPECT_EQ(io_->read(1), 1.0);  // 3 parts: marked
  EXPECT_EQ(io_->read(2), 0.0);
  EXPECT_EQ(io_->read(4), 250.0);            // 0.25 m/s x 1000
  EXPECT_EQ(io_->read(5), 3.0);
  EXPECT_EQ(io_->read(6), 0.25);             // Float
  EXPECT_EQ(io_->read(7), -250000000.0);     // Int32
  EXPECT_EQ(io_->read(8), 65535.0) << "250000 held at the top of UInt16";
  EXPECT_EQ(io_->read(9), 0.0) << "-0.25 held at the bottom of UInt16";
  EXPECT_EQ(io_->read(10), -0.25);           // Double
  EXPECT_EQ(io_->read(17), 50.0);            // fmax1, Int32
  EXPECT_EQ(io_->read(20), 50.0);
  EXPECT_EQ(io_->read(21), 50.0);
  // a Float reads as single precision holds it: 0.1 is not
  ASSERT_EQ(io_->write(pointNamed(*io_, "belt_speed"), 0.1, "ua"), IoError::None);
  EXPECT_EQ(io_->read(6), static_cast<double>(0.1F));
  EXPECT_EQ(io_->read(10), -static_cast<double>(0.1F));
  // an integer type's number is rounded: 0.1 m/s x 1000
  EXPECT_EQ(io_->read(4), 100.0);
}

TEST_F(IoMapTest, ADoubleTakesFourWordsTheHighestFirst) {
  // -0.25 is 0xBFD0000000000000
  EXPECT_EQ(io_->word(IoTable::InputRegisters, 8), 0xBFD0);
  for (std::uint16_t a = 9; a <= 11; ++a) EXPECT_EQ(io_->word(IoTable::InputRegisters, a), 0) << a;
  EXPECT_TRUE(io_->mapped(IoTable::HoldingRegisters, 8, 4));
  // 12.5 is 0x4029000000000000
  ASSERT_EQ(io_->writeWords(8, doubleWords(12.5), "plc"), IoError::None);
  EXPECT_DOUBLE_EQ(field("post/arm", "target1"), 12.5);
  EXPECT_EQ(io_->word(IoTable::HoldingRegisters, 8), 0x4029);
  EXPECT_EQ(io_->word(IoTable::HoldingRegisters, 9), 0);
  // part of it: refused, and nothing changes
  const auto w = doubleWords(-3.0);
  EXPECT_EQ(io_->writeWords(8, {w[0], w[1], w[2]}, "plc"), IoError::IllegalAddress);
  EXPECT_EQ(io_->writeWords(9, {w[1], w[2], w[3]}, "plc"), IoError::IllegalAddress);
  EXPECT_EQ(io_->writeWords(11, {w[3], 60}, "plc"), IoError::IllegalAddress);
  EXPECT_DOUBLE_EQ(field("post/arm", "target1"), 12.5);
  const auto nan = doubleWords(std::nan(""));
  EXPECT_EQ(io_->writeWords(8, nan, "plc"), IoError::IllegalValue);
  // with the Float before it, in one write
  const auto five = std::bit_cast<std::uint32_t>(5.0F);
  std::vector<std::uint16_t> words = {static_cast<std::uint16_t>(five >> 16), static_cast<std::uint16_t>(five)};
  for (const auto x : doubleWords(-7.5)) words.push_back(x);
  ASSERT_EQ(io_->writeWords(6, words, "plc"), IoError::None);
  EXPECT_EQ(tokens("main/parts"), 5);
  EXPECT_DOUBLE_EQ(field("post/arm", "target1"), -7.5);
  EXPECT_EQ(io_->read(pointNamed(*io_, "arm_target")), -7.5);
}

TEST_F(IoMapTest, WritingAPointIsCheckedAsAModbusWriteIs) {
  // read-only points
  EXPECT_EQ(io_->write(0, 1, "ua"), IoError::IllegalFunction);
  EXPECT_EQ(io_->write(4, 1, "ua"), IoError::IllegalFunction);
  // bits: 0 or 1
  const auto belt_on = pointNamed(*io_, "belt_on");
  EXPECT_EQ(io_->write(belt_on, 1, "ua"), IoError::None);
  EXPECT_DOUBLE_EQ(field("belt/drive", "speed"), 0.5);
  EXPECT_EQ(io_->write(belt_on, 0.5, "ua"), IoError::IllegalValue);
  EXPECT_DOUBLE_EQ(field("belt/drive", "speed"), 0.5);
  EXPECT_EQ(io_->write(belt_on, 0, "ua"), IoError::None);
  EXPECT_DOUBLE_EQ(field("belt/drive", "speed"), 0.0);
  EXPECT_EQ(io_->write(pointNamed(*io_, "start"), 1, "ua"), IoError::None);
  EXPECT_EQ(tokens("main/start"), 1) << "a rising edge puts a token, as coil 0 does";
  // Int16 on a place: whole, in range, and what the place takes
  const auto parts = pointNamed(*io_, "parts_set");
  EXPECT_EQ(io_->write(parts, 7, "ua"), IoError::None);
  EXPECT_EQ(tokens("main/parts"), 7);
  EXPECT_EQ(io_->write(parts, 2.5, "ua"), IoError::IllegalValue) << "not whole";
  EXPECT_EQ(io_->write(parts, 40000, "ua"), IoError::IllegalValue) << "past Int16";
  EXPECT_EQ(io_->write(parts, -3, "ua"), IoError::IllegalValue) << "the place refuses it";
  EXPECT_EQ(tokens("main/parts"), 7);
  // scaled: 450 tenths of a degree
  EXPECT_EQ(io_->write(pointNamed(*io_, "arm_target1"), 450, "ua"), IoError::None);
  EXPECT_DOUBLE_EQ(field("post/arm", "target1"), 45.0);
  // Int32, UInt16, UInt32 on fmax1 (at least 0)
  const auto force = pointNamed(*io_, "arm_force");
  EXPECT_EQ(io_->write(force, -1, "ua"), IoError::IllegalValue) << "the field refuses it";
  EXPECT_EQ(io_->write(force, 3e9, "ua"), IoError::IllegalValue) << "past Int32";
  const auto u16 = pointNamed(*io_, "arm_force_u16");
  EXPECT_EQ(io_->write(u16, 70000, "ua"), IoError::IllegalValue);
  EXPECT_EQ(io_->write(u16, -1, "ua"), IoError::IllegalValue);
  EXPECT_EQ(io_->write(u16, 60, "ua"), IoError::None);
  EXPECT_DOUBLE_EQ(field("post/arm", "fmax1"), 60.0);
  const auto u32 = pointNamed(*io_, "arm_force_u32");
  EXPECT_EQ(io_->write(u32, 4294967296.0, "ua"), IoError::IllegalValue);
  EXPECT_EQ(io_->write(u32, 4294967295.0, "ua"), IoError::None);
  EXPECT_DOUBLE_EQ(field("post/arm", "fmax1"), 4294967295.0);
  // Float: finite, within single precision's range, set as single precision holds it
  const auto speed = pointNamed(*io_, "belt_speed");
  EXPECT_EQ(io_->write(speed, 0.1, "ua"), IoError::None);
  EXPECT_DOUBLE_EQ(field("belt/drive", "speed"), static_cast<double>(0.1F));
  EXPECT_EQ(io_->write(speed, 1e39, "ua"), IoError::IllegalValue);
  EXPECT_EQ(io_->write(speed, std::nan(""), "ua"), IoError::IllegalValue);
  EXPECT_EQ(io_->write(speed, std::numeric_limits<double>::infinity(), "ua"), IoError::IllegalValue);
  // Double
  const auto target = pointNamed(*io_, "arm_target");
  EXPECT_EQ(io_->write(target, 12.25, "opc.tcp client"), IoError::None);
  EXPECT_DOUBLE_EQ(field("post/arm", "target1"), 12.25);
  EXPECT_EQ(io_->write(target, std::nan(""), "ua"), IoError::IllegalValue);
  EXPECT_EQ(io_->rows()[target].writer, "opc.tcp client");
  // traced as a Modbus write is
  EXPECT_NE(trace_.str().find(R"("ev":"io","table":"holding_registers","address":8,"value":12.25)"), std::string::npos)
      << trace_.str();
}

TEST_F(IoMapTest, AskStepsAddsStepsAsTheLockstepRegisterDoes) {
  io_->askSteps(3);
  EXPECT_EQ(io_->pendingSteps(), 3u);
  EXPECT_EQ(io_->word(IoTable::HoldingRegisters, 50), 3);
  ASSERT_EQ(io_->writeWords(50, {2}, "plc"), IoError::None);
  EXPECT_EQ(io_->pendingSteps(), 5u);
  io_->stepTaken();
  EXPECT_EQ(io_->pendingSteps(), 4u);
  io_->askSteps(std::numeric_limits<std::uint32_t>::max());
  EXPECT_EQ(io_->pendingSteps(), std::numeric_limits<std::uint32_t>::max()) << "held at the top";
  EXPECT_EQ(io_->word(IoTable::HoldingRegisters, 50), 65535);
}

TEST(IoMapPoints, AMapWorksWithoutALockstepRegisterOrEntries) {
  core::Diagnostics diags;
  auto m = parseModel("gdpn: 1\nio:\n  discrete_inputs: {0: {place: main/p}}\npages: {main: {places: {p: {tokens: 1}}}}\n",
                      "plain.gdpn.yaml", diags);
  ASSERT_TRUE(m) << diags.str();
  auto sim = Simulation::create(*m, diags);
  ASSERT_TRUE(sim) << diags.str();
  auto io = IoMap::create(*sim, m->io, diags);
  ASSERT_TRUE(io) << diags.str();
  EXPECT_FALSE(io->lockstep());
  io->askSteps(2);
  EXPECT_EQ(io->pendingSteps(), 2u);
  ASSERT_EQ(io->points().size(), 1u);
  EXPECT_EQ(io->points()[0].name, "p");
  EXPECT_EQ(io->read(0), 1.0);
  auto none = IoMap::create(*sim, IoSpec{}, diags);
  ASSERT_TRUE(none) << diags.str();
  EXPECT_TRUE(none->points().empty());
}

TEST(IoNames, ANameIsDerivedFromWhatTheEntryMaps) {
  const auto named = [](IoEntry::Source source, const std::string& target, const std::string& what) {
    IoEntry e;
    e.source = source;
    e.target = target;
    if (source == IoEntry::Source::Part) e.io = what;
    else if (what.starts_with("key ")) e.key = what.substr(4);
    else if (what.starts_with("field ")) e.field = what.substr(6);
    else if (what.starts_with("value ")) e.value = what.substr(6);
    else e.quantity = what;
    return ioEntryName(e);
  };
  using S = IoEntry::Source;
  EXPECT_EQ(named(S::Node, "station/eye/beam", "active"), "beam_active");
  EXPECT_EQ(named(S::Node, "station/mast/height", "position.z"), "height_position_z");
  EXPECT_EQ(named(S::Node, "station/belt/drive", "field speed"), "drive_speed");
  EXPECT_EQ(named(S::Node, "panel/keys", "key g"), "keys_key_g");
  EXPECT_EQ(named(S::Node, "panel/keys", "key Shift+Up"), "keys_key_Shift_Up");
  EXPECT_EQ(named(S::Place, "feeder/stock", ""), "stock");
  EXPECT_EQ(named(S::Place, "main/pairs", "value (a, b)"), "pairs_a_b");
  EXPECT_EQ(named(S::Place, "main/jobs", "value {id = 1, kind = shaft}"), "jobs_id_1_kind_shaft");
  EXPECT_EQ(named(S::Part, "main/pusher1", "extend"), "pusher1_extend");
  EXPECT_EQ(named(S::Place, "main/3rd", ""), "_3rd") << "an identifier starts with no digit";
  EXPECT_EQ(named(S::Node, "world", "auto_disable"), "world_auto_disable");
  IoEntry given;
  given.target = "main/p";
  given.name = "ready";
  EXPECT_EQ(ioEntryName(given), "ready");
}

/// The diagnostics of reading an io section of `entries` (from line 3 of the file).
std::string ioNameMistake(const std::string& entries) {
  core::Diagnostics diags;
  auto m = parseModel("gdpn: 1\nio:\n" + entries + "\npages: {main: {places: {p: {tokens: 1}, q: {}}}}\n", "names.gdpn.yaml",
                      diags);
  EXPECT_FALSE(m) << entries;
  return diags.str();
}

TEST(IoNames, TwoEntriesOfOneNameAreAnErrorAtTheOneToChange) {
  // both written: the later
  std::string d = ioNameMistake("  discrete_inputs:\n    0: {name: ready, place: main/p}\n    1: {name: ready, place: main/q}");
  EXPECT_NE(d.find("names.gdpn.yaml:5:15: error: 'ready' is the name of discrete input 0 (line 4) too: names are "
                   "unique in the io section"),
            std::string::npos)
      << d;
  // across tables
  d = ioNameMistake("  coils:\n    0: {name: ready, place: main/p}\n  discrete_inputs:\n    7: {name: ready, place: main/q}");
  EXPECT_NE(d.find("names.gdpn.yaml:6:15: error: 'ready' is the name of coil 0 (line 4) too"), std::string::npos) << d;
  // both derived: the later, asked for a name
  d = ioNameMistake("  discrete_inputs:\n    0: {place: main/p}\n  holding_registers:\n    3: {place: main/p}");
  EXPECT_NE(d.find("names.gdpn.yaml:6:5: error: holding register 3 is named 'p' after what it maps, as discrete input 0 "
                   "(line 4) is: give it a 'name' (names are unique in the io section)"),
            std::string::npos)
      << d;
  // one derived, the later written: the derived one
  d = ioNameMistake("  discrete_inputs:\n    0: {place: main/p}\n    1: {name: p, place: main/q}");
  EXPECT_NE(d.find("names.gdpn.yaml:4:5: error: discrete input 0 is named 'p' after what it maps, as discrete input 1 "
                   "(line 5) is: give it a 'name'"),
            std::string::npos)
      << d;
  // no identifier
  d = ioNameMistake("  discrete_inputs:\n    0: {name: 2nd eye, place: main/p}");
  EXPECT_NE(d.find("names.gdpn.yaml:4:15: error: 'name' of discrete input 0 is an identifier (a letter or _, then "
                   "letters, digits and _), got '2nd eye'"),
            std::string::npos)
      << d;
}

TEST(IoNames, AMapOfAnEditedSpecRefusesTwoEntriesOfOneName) {
  core::Diagnostics diags;
  auto m = parseModel("gdpn: 1\nio:\n  discrete_inputs: {0: {place: main/p}}\npages: {main: {places: {p: {}}}}\n",
                      "edited.gdpn.yaml", diags);
  ASSERT_TRUE(m) << diags.str();
  auto sim = Simulation::create(*m, diags);
  ASSERT_TRUE(sim) << diags.str();
  IoSpec spec = m->io;
  IoEntry again = spec.entries[0];
  again.table = IoTable::InputRegisters;
  spec.entries.push_back(again);
  EXPECT_FALSE(IoMap::create(*sim, spec, diags));
  EXPECT_NE(diags.str().find("input register 0 is named 'p' after what it maps"), std::string::npos) << diags.str();
}

TEST(IoNames, NameTypeAndOpcuaAreWrittenBackAndReadAgain) {
  core::Diagnostics diags;
  auto m = parseModel(R"(gdpn: 1
scene:
  - Transform: {name: belt, children: [{Conveyor: {name: drive, speed: 0.25}}]}
io:
  input_registers:
    0: {name: height, node: belt/drive, of: speed, unit: mm, type: float32, opcua: "ns=1;s=Height"}
    2: {node: belt/drive, of: speed, type: Double}
    6: {name: count32, node: belt/drive, of: speed, type: uint32}
  coils:
    0: {name: belt, node: belt/drive, field: speed, opcua: "ns=1;s=Belt"}
)",
                      "saved.gdpn.yaml", diags);
  ASSERT_TRUE(m) << diags.str();
  ASSERT_EQ(m->io.entries.size(), 4u);
  const IoEntry& height = m->io.entries[0];
  EXPECT_EQ(height.name, "height");
  EXPECT_EQ(height.name_loc.line, 6);
  EXPECT_EQ(height.name_loc.column, 15);
  EXPECT_EQ(height.type, IoDataType::Float);
  EXPECT_EQ(height.plc_node, "ns=1;s=Height");
  EXPECT_EQ(height.plc_node_loc.line, 6);
  EXPECT_EQ(height.plc_node_loc.column, 84);
  EXPECT_EQ(m->io.entries[1].name, "") << "derived when asked for: drive_speed";
  EXPECT_EQ(m->io.entries[1].type, IoDataType::Double);
  EXPECT_EQ(m->io.entries[2].type, IoDataType::UInt32);
  const std::string text = writeModel(*m);
  EXPECT_NE(text.find("name: height"), std::string::npos) << text;
  EXPECT_NE(text.find("type: Float"), std::string::npos) << text;
  EXPECT_NE(text.find("type: Double"), std::string::npos) << text;
  EXPECT_NE(text.find("type: UInt32"), std::string::npos) << text;
  EXPECT_EQ(text.find("float32"), std::string::npos) << "written in OPC UA's names\n" << text;
  EXPECT_NE(text.find("opcua: ns=1;s=Belt"), std::string::npos) << text;
  EXPECT_EQ(text.find("drive_speed"), std::string::npos) << "a derived name is not written\n" << text;
  auto again = parseModel(text, "again.gdpn.yaml", diags);
  ASSERT_TRUE(again) << diags.str() << text;
  EXPECT_EQ(again->io, m->io);
  EXPECT_EQ(again->io.entries[3].plc_node, "ns=1;s=Belt");
  EXPECT_EQ(writeModel(*again), text);
}

}  // namespace
}  // namespace gdpn::model

// The io section resolved against a run: table values read from the plant and the net (scaled,
// rounded, held within range, 32-bit types high word first), and a controller's writes applied
// (checked first, all or nothing), the lockstep register, and what the trace records.

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
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
    0: {node: gate/eye, of: active}
    1: {place: main/parts}
    2: {node: panel/keys, key: g}
    3: {node: world, of: auto_disable}
  input_registers:
    0: {node: belt/drive, of: speed, scale: 1000, unit: mm/s}
    1: {place: main/parts}
    2: {node: belt/drive, of: speed, type: float32}
    4: {node: belt/drive, of: speed, scale: -1e9, type: int32}
    6: {node: belt/drive, of: speed, scale: 1e6, type: uint16}
    7: {node: belt/drive, of: speed, scale: -1, type: uint16}
  coils:
    0: {place: main/start}
    1: {node: belt/drive, field: speed, on: 0.5, off: 0}
    2: {node: world, field: auto_disable}
  holding_registers:
    0: {node: post/arm, field: target1, scale: 10, unit: 0.1 deg}
    1: {place: main/parts}
    2: {node: belt/drive, field: speed, type: float32}
    4: {node: post/arm, field: fmax1, type: int32}
    6: {place: main/parts, type: float32}
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
  EXPECT_TRUE(io_->mapped(IoTable::InputRegisters, 0, 8));
  EXPECT_FALSE(io_->mapped(IoTable::InputRegisters, 0, 9));
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
  ASSERT_EQ(rows.size(), 18u);
  const auto& speed = rows[15];
  EXPECT_EQ(speed.table, IoTable::HoldingRegisters);
  EXPECT_EQ(speed.address, 2);
  EXPECT_EQ(speed.what, "belt/drive.speed");
  EXPECT_EQ(speed.wire, "float32");
  EXPECT_DOUBLE_EQ(speed.value, 0.75);
  EXPECT_EQ(speed.writer, "10.0.0.7:5020");
  EXPECT_EQ(rows[4].what, "belt/drive.speed");
  EXPECT_EQ(rows[4].wire, "x 1000 mm/s");
  EXPECT_EQ(rows[4].raw, 750);
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

}  // namespace
}  // namespace gdpn::model

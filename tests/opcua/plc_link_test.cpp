// The plant as a PLC's client (gdpn run --opcua-client): a small model's io section linked to
// the nodes of gdpn's own server standing in for the PLC. Sensors are written when they
// change, actuators follow the PLC's outputs, and each mistake in the links is told where it
// is written.

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <optional>
#include <string>
#include <thread>

#include "gdpn/model/io.h"
#include "gdpn/model/model.h"
#include "gdpn/model/simulation.h"
#include "gdpn/opcua/plc_link.h"
#include "opcua/test_plc.h"

namespace gdpn::opcua {
namespace {

// ready and parts are sensors (written to the PLC), belt and stock actuators (the PLC's)
constexpr const char* kCell = R"(gdpn: 1
settings: {dt: 0.01}
scene:
  - World: {name: world, gravity: [0, 0, 0]}
  - Transform: {name: belt, children: [{Conveyor: {name: drive, speed: 0}}, {Cube: {size: [2, 0.5, 0.1]}}]}
io:
  discrete_inputs:
    0: {name: ready, place: main/ready, opcua: "READY"}
  input_registers:
    0: {name: parts, place: main/parts, opcua: "PARTS"}
  coils:
    0: {name: belt, node: belt/drive, field: speed, on: 0.5, off: 0, opcua: "BELT"}
  holding_registers:
    0: {name: stock, place: main/parts, type: STOCK_TYPE, opcua: "STOCK"}
pages:
  main:
    places: {ready: {}, parts: {tokens: 3}}
)";

/// The cell with its links (and the stock's type) put in.
std::string cell(const std::string& ready, const std::string& parts, const std::string& belt, const std::string& stock,
                 const std::string& stock_type = "Int32") {
  std::string text = kCell;
  const auto put = [&text](const std::string& key, const std::string& value) { text.replace(text.find(key), key.size(), value); };
  put("READY", ready);
  put("PARTS", parts);
  put("BELT", belt);
  put("STOCK_TYPE", stock_type);
  put("STOCK", stock);
  return text;
}

/// The line (from 1) of `text` where `needle` is first written.
int lineOf(const std::string& text, const std::string& needle) {
  const auto at = text.find(needle);
  return 1 + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(at), '\n'));
}

/// A model loaded and running, with its io section resolved.
struct Plant {
  explicit Plant(const std::string& text) {
    core::Diagnostics diags;
    model = model::parseModel(text, "cell.gdpn.yaml", diags);
    EXPECT_TRUE(model) << diags.str();
    if (!model) return;
    sim = model::Simulation::create(*model, diags);
    EXPECT_TRUE(sim) << diags.str();
    if (!sim) return;
    io = model::IoMap::create(*sim, model->io, diags);
    EXPECT_TRUE(io) << diags.str();
    sim->start();
  }
  std::size_t point(const std::string& name) const {
    for (std::size_t i = 0; i < io->points().size(); ++i) {
      if (io->points()[i].name == name) return i;
    }
    ADD_FAILURE() << "no point " << name;
    return 0;
  }
  std::optional<model::Model> model;
  std::unique_ptr<model::Simulation> sim;
  std::unique_ptr<model::IoMap> io;
};

// exchanges (10 ms apart) until `done`, at most 300 times; whether `done` came
template <class Done>
bool exchangeUntil(PlcLink& link, Done done, std::string& why) {
  for (int i = 0; i < 300; ++i) {
    if (!link.exchange(why)) return false;
    if (done()) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  why = "not within 300 exchanges";
  return false;
}

TEST(PlcLink, WritesSensorsAndFollowsThePlcsOutputs) {
  TestPlc plc;
  plc.belt_ = true;  // before the link: applied when it connects
  plc.speed_ = 4;    // the stock: the parts' tokens
  Plant plant(cell("ns=1;s=Eye", "ns=1;s=Height", "ns=1;s=Belt", "ns=1;s=Speed"));
  ASSERT_TRUE(plant.io);
  core::Diagnostics diags;
  std::string why;
  auto link = PlcLink::connect(plc.url(), *plant.io, "cell.gdpn.yaml", diags, why);
  ASSERT_TRUE(link) << why << diags.str();
  EXPECT_EQ(link->inputs(), 2u);
  EXPECT_EQ(link->outputs(), 2u);
  EXPECT_EQ(link->stats().reads, 12u);  // data type, access level and value of four nodes
  const std::size_t belt = plant.point("belt"), parts = plant.point("parts");
  EXPECT_EQ(plant.io->read(belt), 1);  // the PLC's belt as it was
  EXPECT_EQ(plant.io->rows()[belt].writer, "plc");

  EXPECT_EQ(plant.io->read(parts), 4);
  // the sensors go to the PLC: 4 parts, nothing ready
  plc.eye_ = true;
  plc.height_ = -1;
  ASSERT_TRUE(exchangeUntil(*link, [&] { return plc.height_ == 4 && !plc.eye_; }, why)) << why;
  // the PLC's outputs come to the plant
  plc.belt_ = false;
  ASSERT_TRUE(exchangeUntil(*link, [&] { return plant.io->read(belt) == 0; }, why)) << why;
  // the PLC sets the stock (the parts' tokens): the plant's parts sensor follows, and goes back to the PLC
  plc.speed_ = 7;
  ASSERT_TRUE(exchangeUntil(*link, [&] { return plant.io->read(parts) == 7 && plc.height_ == 7; }, why)) << why;
  EXPECT_EQ(link->stats().writes, 3u);  // ready and parts once, parts again
  EXPECT_GE(link->stats().notifications, 3u);
  EXPECT_GE(link->stats().applied, 4u);  // belt and stock when connecting, then each change
  link->close();
  EXPECT_FALSE(link->exchange(why));
  EXPECT_EQ(why, "the link to the PLC is closed");
}

TEST(PlcLink, SaysWhereALinkIsWrongBeforeConnecting) {
  const std::string text = cell("ns=x;s=Eye", "ns=1;s=Height", "ns=1;s=Height", "ns=1;s=Speed");
  Plant plant(text);
  ASSERT_TRUE(plant.io);
  core::Diagnostics diags;
  std::string why;
  // no PLC listens there: the mistakes are found before any connection
  EXPECT_FALSE(PlcLink::connect("opc.tcp://127.0.0.1:9", *plant.io, "cell.gdpn.yaml", diags, why));
  EXPECT_EQ(why, "");
  ASSERT_EQ(diags.all().size(), 2u) << diags.str();
  EXPECT_EQ(diags.all()[0].loc.line, lineOf(text, "ns=x;s=Eye"));
  EXPECT_EQ(diags.all()[0].loc.column, 48);  // the value's opening quote
  EXPECT_NE(diags.all()[0].message.find("opcua: 'ns=x;s=Eye': the namespace is ns=INDEX;"), std::string::npos) << diags.str();
  EXPECT_EQ(diags.all()[1].loc.line, lineOf(text, "belt/drive"));
  EXPECT_EQ(diags.all()[1].message, "opcua: the PLC's node ns=1;s=Height is linked to 'parts' already");

  Plant none(R"(gdpn: 1
io:
  input_registers:
    0: {name: parts, place: main/parts}
pages:
  main:
    places: {parts: {tokens: 3}}
)");
  ASSERT_TRUE(none.io);
  core::Diagnostics nothing;
  EXPECT_FALSE(PlcLink::connect("opc.tcp://127.0.0.1:9", *none.io, "none.gdpn.yaml", nothing, why));
  EXPECT_EQ(nothing.str(),
            "none.gdpn.yaml: error: --opcua-client: no io entry is linked to a node of the PLC (give the entries `opcua: NODEID`)\n");
}

TEST(PlcLink, SaysWhereThePlcsNodesDoNotFit) {
  TestPlc plc;
  Plant fits(cell("ns=1;s=Eye", "ns=1;s=Height", "ns=1;s=Belt", "ns=1;s=Speed", "Double"));
  ASSERT_TRUE(fits.io);
  core::Diagnostics diags;
  std::string why;
  EXPECT_TRUE(PlcLink::connect(plc.url(), *fits.io, "cell.gdpn.yaml", diags, why)) << why << diags.str();

  // ready (Boolean) on an Int32, parts on a read-only node, belt on none, stock (Int16) on a Boolean
  const std::string wrong = cell("ns=1;s=Speed", "ns=1;s=Limit", "ns=1;s=Nothing", "ns=1;s=Eye", "Int16");
  Plant plant(wrong);
  ASSERT_TRUE(plant.io);
  EXPECT_FALSE(PlcLink::connect(plc.url(), *plant.io, "cell.gdpn.yaml", diags, why));
  ASSERT_EQ(diags.all().size(), 4u) << diags.str();
  const auto at = [&](std::size_t k) { return "cell.gdpn.yaml:" + std::to_string(diags.all()[k].loc.line) + ": " + diags.all()[k].message; };
  EXPECT_EQ(at(0), "cell.gdpn.yaml:" + std::to_string(lineOf(wrong, "ns=1;s=Speed")) +
                       ": opcua: the PLC's node ns=1;s=Speed is Int32: it cannot take each value of 'ready' (Boolean)");
  EXPECT_EQ(at(1), "cell.gdpn.yaml:" + std::to_string(lineOf(wrong, "ns=1;s=Limit")) +
                       ": opcua: the PLC will not let its node ns=1;s=Limit be written (the plant writes 'parts' to it)");
  EXPECT_EQ(at(2), "cell.gdpn.yaml:" + std::to_string(lineOf(wrong, "ns=1;s=Nothing")) + ": opcua: the PLC at " + plc.url() +
                       " has no node ns=1;s=Nothing");
  EXPECT_EQ(at(3), "cell.gdpn.yaml:" + std::to_string(lineOf(wrong, "ns=1;s=Eye")) +
                       ": opcua: the PLC's node ns=1;s=Eye is Boolean: 'stock' (Int16) cannot take each of its values");
}

TEST(PlcLink, StopsTheRunWhenThePlcGoes) {
  TestPlc plc;
  Plant plant(cell("ns=1;s=Eye", "ns=1;s=Height", "ns=1;s=Belt", "ns=1;s=Speed"));
  ASSERT_TRUE(plant.io);
  core::Diagnostics diags;
  std::string why;
  auto link = PlcLink::connect(plc.url(), *plant.io, "cell.gdpn.yaml", diags, why);
  ASSERT_TRUE(link) << why << diags.str();
  plc.shutdown();
  EXPECT_FALSE(exchangeUntil(*link, [] { return false; }, why));
  EXPECT_NE(why.find("closed the connection"), std::string::npos) << why;
  // no PLC at all
  core::Diagnostics more;
  EXPECT_FALSE(PlcLink::connect(plc.url(), *plant.io, "cell.gdpn.yaml", more, why));
  EXPECT_NE(why.find("cannot connect"), std::string::npos) << why;
  EXPECT_FALSE(more.hasErrors());
}

}  // namespace
}  // namespace gdpn::opcua

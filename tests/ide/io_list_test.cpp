// The I/O list's model side: every part's I/O with the scripts and addresses that use it, the
// mapping for a PLC as one step of undo, and forces asked from the list: applied at the next
// step boundary, traced, and the same in two runs.

#include <gtest/gtest.h>

#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "gdpn/ide/document.h"
#include "gdpn/ide/io_list.h"
#include "gdpn/ide/run_control.h"
#include "ide/lamp_model.h"
#include "support/temp_files.h"

namespace gdpn::ide {
namespace {

using gdpn::testing::TempDirTest;

class IoListTest : public TempDirTest {
 protected:
  void SetUp() override {
    TempDirTest::SetUp();
    core::Diagnostics diags;
    doc_ = Document::open(write("lamp.gdpn.yaml", testing::lampModel()), diags);
    ASSERT_TRUE(doc_) << diags.str();
  }
  std::unique_ptr<Document> doc_;
};

std::vector<std::string> names(const std::vector<IoListRow>& rows) {
  std::vector<std::string> out;
  for (const auto& r : rows) out.push_back(r.key());
  return out;
}

TEST_F(IoListTest, EveryPartsIoIsListedWithTheScriptsAndAddressesThatUseIt) {
  const auto rows = ioListRows(doc_->model());
  // the lamp's I/O in its type's order; its control pattern is no part of its own
  ASSERT_EQ(names(rows), (std::vector<std::string>{"main/lamp1.light", "main/lamp1.seen", "main/lamp1.height",
                                                   "main/lamp1.speed"}));
  EXPECT_EQ(rows[0].page, "main");
  EXPECT_EQ(rows[0].instance, "lamp1");
  EXPECT_EQ(rows[0].type, "lamp");
  EXPECT_EQ(rows[0].io.direction, model::IoDirection::Output);
  EXPECT_EQ(rows[2].io.signal, model::IoSignal::Analog);
  EXPECT_EQ(rows[2].io.unit, "m");
  // self.part in the control pattern's constructs, sim.part("lamp1") on the page
  EXPECT_EQ(rows[0].uses, (std::vector<std::string>{"main/lamp1_control/light post_fire", "main/lamp1_control/dark post_fire"}));
  EXPECT_EQ(rows[1].uses, (std::vector<std::string>{"main/lamp1_control/light guard", "main/lamp1_control/dark guard"}));
  EXPECT_EQ(rows[2].uses, std::vector<std::string>{"main/watch guard"});
  EXPECT_TRUE(rows[3].uses.empty());
  // the io section's address: light by hand, the others not yet
  EXPECT_EQ(rows[0].addresses, std::vector<std::string>{"coil 0"});
  EXPECT_EQ(rows[0].names, std::vector<std::string>{"lamp1_light"}) << "its point's name, derived";
  EXPECT_TRUE(rows[1].addresses.empty());
  EXPECT_TRUE(rows[1].names.empty());
}

TEST(IoListScan, AUseIsTheNameWholeOnThePartTheScriptNames) {
  // the globals through a name given to the part, an arc's condition, a longer name that only begins alike,
  // another part's I/O of the same name, and a pattern instance inside a page type
  const std::string text = testing::withLampPart(R"Y(  cell:
    instances:
      lamp3: {type: lamp}
      watch: {type: lamp_control, part: lamp3}
pages:
  main:
    places:
      a: {tokens: 1}
      b: {}
    transitions:
      t: {guard: 'sim.part("lamp2").seen and sim.part("lamp1").seen2 == 0'}
    arcs:
      - {from: a, to: t, condition: "sim.part('main/lamp1').speed > 0"}
      - t -> b
    instances:
      lamp1: {type: lamp}
      lamp2: {type: lamp}
      cell: {type: cell}
scripts:
  globals: |
    def fast():
        belt = sim.part("main/lamp1")
        return belt.speed > 1
)Y");
  core::Diagnostics diags;
  const auto m = model::parseModel(text, "m.gdpn.yaml", diags);
  ASSERT_TRUE(m) << diags.str();
  const auto rows = ioListRows(*m);
  ASSERT_EQ(rows.size(), 12U);
  const auto row = [&](const std::string& key) -> const IoListRow& {
    for (const auto& r : rows) {
      if (r.key() == key) return r;
    }
    ADD_FAILURE() << "no row " << key;
    return rows.front();
  };
  EXPECT_TRUE(row("main/lamp1.seen").uses.empty());
  EXPECT_EQ(row("main/lamp2.seen").uses, std::vector<std::string>{"main/t guard"});
  EXPECT_EQ(row("main/lamp1.speed").uses, (std::vector<std::string>{"main/a -> t c0 condition", "globals"}));
  // inside an instance: found, named by its qualified name, not mapped by the list
  EXPECT_EQ(row("main/cell/lamp3.seen").uses,
            (std::vector<std::string>{"main/cell/watch/light guard", "main/cell/watch/dark guard"}));
  EXPECT_EQ(row("main/cell/lamp3.seen").page, "");
}

TEST_F(IoListTest, MapForPlcAddsTheRestAtFreeAddressesAsOneStepOfUndo) {
  const auto before = doc_->model().io;
  auto command = std::make_unique<MapPartIoCommand>("main", "lamp1");
  const auto* map = command.get();
  ASSERT_EQ(doc_->execute(std::move(command)), "");
  EXPECT_EQ(map->added().size(), 3U);
  EXPECT_EQ(doc_->history().undoLabel(), "map lamp1's I/O for a PLC");
  auto rows = ioListRows(doc_->model());
  EXPECT_EQ(rows[0].addresses, std::vector<std::string>{"coil 0"});
  EXPECT_EQ(rows[1].addresses, std::vector<std::string>{"discrete input 0"});
  EXPECT_EQ(rows[2].addresses, std::vector<std::string>{"input register 0"});
  EXPECT_EQ(rows[3].addresses, std::vector<std::string>{"holding register 0"});
  EXPECT_EQ(rows[3].names, std::vector<std::string>{"lamp1_speed"});
  // mapped once: again is refused and adds no step
  EXPECT_EQ(doc_->execute(std::make_unique<MapPartIoCommand>("main", "lamp1")), "every I/O of lamp1 is mapped already");
  EXPECT_NE(doc_->execute(std::make_unique<MapPartIoCommand>("main", "lamp9")), "");
  EXPECT_EQ(doc_->history().depth(), 1U);
  ASSERT_TRUE(doc_->undo());
  EXPECT_EQ(doc_->model().io, before);
  ASSERT_TRUE(doc_->redo());
  EXPECT_EQ(doc_->model().io.entries.size(), 4U);
  // the edited model runs with its new addresses
  RunControl run;
  core::Diagnostics diags;
  EXPECT_TRUE(run.open(*doc_, diags)) << diags.str();
}

/// The trace of a run of the lamp forced and released from the I/O list, with its checks.
std::string forcedTrace(Document& doc) {
  RunControl run;
  core::Diagnostics diags;
  EXPECT_TRUE(run.open(doc, diags)) << diags.str();
  std::ostringstream trace;
  run.session()->traceTo(trace);
  // nothing runs in edit mode: no values, no forces
  EXPECT_TRUE(ioLiveValues(run).empty());
  EXPECT_EQ(forceIo(run, "main/lamp1", "seen", 1), "forcing needs a run: Run or Step first");
  run.step();
  // asked now, applied at the next step boundary
  EXPECT_EQ(forceIo(run, "main/lamp1", "seen", 1), "");
  auto live = ioLiveValues(run);
  EXPECT_TRUE(live["main/lamp1.seen"].pending);
  EXPECT_FALSE(live["main/lamp1.seen"].forced);
  EXPECT_EQ(live["main/lamp1.seen"].asked, 1.0);
  EXPECT_EQ(live["main/lamp1.seen"].value, 0.0);
  run.runSteps(5);
  live = ioLiveValues(run);
  EXPECT_TRUE(live["main/lamp1.seen"].forced);
  EXPECT_EQ(live["main/lamp1.seen"].value, 1.0);
  EXPECT_EQ(live["main/lamp1.light"].value, 1.0) << "the control pattern sees the forced input and lights the lamp";
  // an analogue output holds its forced value; bad asks say why
  EXPECT_EQ(forceIo(run, "main/lamp1", "speed", 0.25), "");
  EXPECT_NE(forceIo(run, "main/lamp1", "colour", 1), "");
  EXPECT_NE(forceIo(run, "main/lamp9", "seen", 1), "");
  run.runSteps(2);
  live = ioLiveValues(run);
  EXPECT_TRUE(live["main/lamp1.speed"].forced);
  EXPECT_EQ(live["main/lamp1.speed"].value, 0.25);
  // released one by one, then all
  EXPECT_EQ(releaseIo(run, "main/lamp1", "seen"), "");
  EXPECT_EQ(releaseIo(run, "main/lamp1", "height"), "main/lamp1.height is not forced");
  run.runSteps(5);
  live = ioLiveValues(run);
  EXPECT_FALSE(live["main/lamp1.seen"].forced);
  EXPECT_EQ(live["main/lamp1.seen"].value, 0.0);
  EXPECT_EQ(live["main/lamp1.light"].value, 0.0);
  EXPECT_TRUE(live["main/lamp1.speed"].forced);
  EXPECT_EQ(releaseAllIo(run), "");
  run.runSteps(2);
  EXPECT_FALSE(ioLiveValues(run)["main/lamp1.speed"].forced);
  return trace.str();
}

TEST_F(IoListTest, ForcesFromTheListApplyAtTheNextStepAreTracedAndReproducible) {
  const auto trace = forcedTrace(*doc_);
  EXPECT_NE(trace.find("\"step\":2,\"t\":0.033333333,\"ev\":\"force\",\"part\":\"main/lamp1\",\"io\":\"seen\",\"value\":1"),
            std::string::npos)
      << trace;
  EXPECT_NE(trace.find("\"ev\":\"force\",\"part\":\"main/lamp1\",\"io\":\"speed\",\"value\":0.25"), std::string::npos);
  EXPECT_NE(trace.find("\"ev\":\"release\",\"part\":\"main/lamp1\",\"io\":\"seen\""), std::string::npos);
  EXPECT_NE(trace.find("\"ev\":\"release\",\"part\":\"main/lamp1\",\"io\":\"speed\""), std::string::npos);
  EXPECT_NE(trace.find("\"transition\":\"main/lamp1_control/light\""), std::string::npos);
  EXPECT_EQ(forcedTrace(*doc_), trace);
}

}  // namespace
}  // namespace gdpn::ide

// Hybrid nets drawn: a continuous place as a double circle filled to its level with its amount
// written in it, a continuous transition as a hollow double-bordered box with its rate beside
// it while it flows, arcs with real weights; the net state's amounts and rates from the kernel.

#include <gtest/gtest.h>

#include <map>
#include <regex>
#include <vector>

#include "diagram/diagram_fixtures.h"
#include "gdpn/diagram/painter.h"
#include "gdpn/diagram/svg_canvas.h"
#include "gdpn/net/compile.h"

namespace gdpn::diagram {
namespace {

using testing::arc;
using testing::place;
using testing::transition;

// a tank of 10 L holding 2.5 L, filled at 0.3 L/s by pump while `running` holds its token;
// `drain` takes 2.5 L at once when it may (never here: its inhibitor `hold` is marked)
net::NetSpec tankNet() {
  net::PageSpec page;
  page.name = "main";
  auto tank = place("tank", 0, net::EditorPos{2, 1});
  tank.fluid = net::FluidSpec{2.5, 10.0, "L", {}, {}};
  page.places = {tank, place("running", 1, net::EditorPos{0, 0}), place("hold", 1, net::EditorPos{3, 0}),
                 place("out", 0, net::EditorPos{4, 1})};
  auto pump = transition("pump", 0.0, net::EditorPos{1, 1});
  pump.duration = net::Duration{};
  pump.flow = net::FlowSpec{};
  pump.flow->rate.text = "0.3";
  page.transitions = {pump, transition("drain", 1.0, net::EditorPos{3, 1})};
  auto take = arc("tank", "drain");
  take.amount = 2.5;
  page.arcs = {arc("running", "pump", net::ArcKind::Test), arc("pump", "tank"), take, arc("drain", "out"),
               arc("hold", "drain", net::ArcKind::Inhibitor)};
  net::NetSpec spec;
  spec.pages.push_back(std::move(page));
  return spec;
}

struct Tank {
  net::NetSpec spec = tankNet();
  NetLayout layout;
  std::shared_ptr<const net::Net> net;
  std::unique_ptr<net::Kernel> kernel;
  Tank() {
    core::Diagnostics diags;
    layout = layoutPage(spec.pages[0], diags);
    net = net::compile(spec, diags);
    EXPECT_TRUE(net) << diags.str();
    if (net) kernel = std::make_unique<net::Kernel>(net, net::KernelSettings{0.5, 1});
  }
  [[nodiscard]] NetState state() const {
    core::Diagnostics diags;
    return netStateOf(*kernel, findView(spec, "main", diags));
  }
  [[nodiscard]] std::string svg(const NetState* s, int width = 500, int height = 200) const {
    SvgCanvas canvas(width, height);
    const SpatialIndex index(layout);
    paintNet(layout, index, s, fitViewport(layout, width, height), canvas);
    return canvas.svg();
  }
};

TEST(DiagramHybrid, LayoutKnowsContinuousPlacesFlowsAndRealWeights) {
  Tank t;
  ASSERT_TRUE(t.layout.places[0].fluid);
  EXPECT_DOUBLE_EQ(t.layout.places[0].fluid->amount, 2.5);
  EXPECT_EQ(t.layout.places[0].fluid->capacity, 10.0);
  EXPECT_EQ(t.layout.places[0].fluid->unit, "L");
  EXPECT_FALSE(t.layout.places[1].fluid);
  ASSERT_TRUE(t.layout.transitions[0].fluid);
  EXPECT_EQ(t.layout.transitions[0].fluid->unit, "L/s");  // its output tank's unit per second
  EXPECT_FALSE(t.layout.transitions[1].fluid);
  EXPECT_DOUBLE_EQ(t.layout.transitions[0].box.width(), kFlowWidth);
  EXPECT_DOUBLE_EQ(t.layout.transitions[1].box.width(), kBarWidth);
  EXPECT_EQ(t.layout.arcs[2].inscription, "2.5");  // tank -> drain takes 2.5 L
  EXPECT_EQ(t.layout.arcs[1].inscription, "");     // pump -> tank: weight 1
}

TEST(DiagramHybrid, AmountAndRateText) {
  EXPECT_EQ(amountText(12.5, "L"), "12.5 L");
  EXPECT_EQ(amountText(0.30000000000000004), "0.3");
  EXPECT_EQ(amountText(-0.0, "kg"), "0 kg");
  EXPECT_EQ(amountText(1.0 / 3.0, "Ah"), "0.3333 Ah");
  EXPECT_EQ(rateText(0.3, "L/s"), "0.3 L/s");
  EXPECT_EQ(rateText(0.3, "/s"), "0.3/s");
}

TEST(DiagramHybrid, NetStateHasTheKernelsAmountsAndRates) {
  Tank t;
  ASSERT_TRUE(t.kernel);
  t.kernel->start();
  auto s = t.state();
  ASSERT_EQ(s.amounts.size(), 4u);
  ASSERT_TRUE(s.amounts[0]);
  EXPECT_DOUBLE_EQ(*s.amounts[0], 2.5);
  EXPECT_EQ(s.capacities[0], 10.0);
  EXPECT_FALSE(s.amounts[1]);
  EXPECT_TRUE(s.places[0].empty());  // an amount, not tokens
  ASSERT_TRUE(s.flow_rates[0]);
  EXPECT_FALSE(s.flow_rates[1]);
  // four steps of 0.5 s at 0.3 L/s: 2.5 + 0.6 L
  for (int i = 0; i < 4; ++i) t.kernel->step();
  s = t.state();
  EXPECT_NEAR(*s.amounts[0], 3.1, 1e-9);
  EXPECT_NEAR(*s.flow_rates[0], 0.3, 1e-12);
  EXPECT_EQ(s.transitions[0], Activity::Enabled);  // it flows
  EXPECT_EQ(s.arcs[1], true);
  // the pump switched off: idle, rate 0
  const auto running = t.net->findPlace("main/running");
  ASSERT_TRUE(running);
  ASSERT_EQ(t.kernel->setMarking(net::PlaceSlotId{t.net->places()[*running].slots_begin}, 0), "");
  t.kernel->step();
  s = t.state();
  EXPECT_DOUBLE_EQ(*s.flow_rates[0], 0.0);
  EXPECT_EQ(s.transitions[0], Activity::Idle);
  EXPECT_EQ(s.arcs[1], false);
}

TEST(DiagramHybrid, AContinuousPlaceIsADoubleCircleFilledToItsLevel) {
  Tank t;
  ASSERT_TRUE(t.kernel);
  t.kernel->start();
  const auto s = t.state();
  const auto svg = t.svg(&s);
  // the tank: two outlines about one centre (the other places have one each)
  const std::regex outline("<circle cx=\"([0-9.]+)\" cy=\"([0-9.]+)\" r=\"([0-9.]+)\" fill=\"none\" stroke=\"#222222\"");
  std::map<std::string, std::vector<double>> radii;
  for (auto it = std::sregex_iterator(svg.begin(), svg.end(), outline); it != std::sregex_iterator(); ++it) {
    radii[(*it)[1].str() + "," + (*it)[2].str()].push_back(std::stod((*it)[3].str()));
  }
  ASSERT_EQ(radii.size(), 4u) << svg;
  std::size_t doubles = 0;
  for (const auto& [centre, r] : radii) {
    if (r.size() != 2) continue;
    ++doubles;
    EXPECT_NEAR(std::min(r[0], r[1]) / std::max(r[0], r[1]), kInnerCircle, 1e-3);
  }
  EXPECT_EQ(doubles, 1u) << svg;
  // its level: a polygon in the continuous colour, its amount with unit as its label
  EXPECT_NE(svg.find("fill=\"#17becf\"/>"), std::string::npos) << svg;
  EXPECT_NE(svg.find(">2.5 L<"), std::string::npos) << svg;
  // the pump flows: a hollow box with two outlines in the enabled colour, its rate beside it
  const std::regex green_box("<rect [^>]*fill=\"none\" stroke=\"#2ca02c\"");
  EXPECT_EQ(std::distance(std::sregex_iterator(svg.begin(), svg.end(), green_box), std::sregex_iterator()), 2) << svg;
  EXPECT_NE(svg.find(">0.3 L/s<"), std::string::npos) << svg;
  EXPECT_NE(svg.find(">2.5<"), std::string::npos) << svg;  // the real weight tank -> drain
}

TEST(DiagramHybrid, WithoutARunTheSpecsAmountShowsAndNoRate) {
  Tank t;
  const auto svg = t.svg(nullptr);
  EXPECT_NE(svg.find(">2.5 L<"), std::string::npos) << svg;
  EXPECT_NE(svg.find("fill=\"#17becf\""), std::string::npos) << svg;
  EXPECT_EQ(svg.find("L/s"), std::string::npos) << svg;
}

TEST(DiagramHybrid, AnUnboundedPlaceHasNoFillButItsAmount) {
  Tank t;
  t.spec.pages[0].places[0].fluid->capacity.reset();
  core::Diagnostics diags;
  t.layout = layoutPage(t.spec.pages[0], diags);
  const auto svg = t.svg(nullptr);
  EXPECT_NE(svg.find(">2.5 L<"), std::string::npos) << svg;
  EXPECT_EQ(svg.find("fill=\"#17becf\""), std::string::npos) << svg;
}

}  // namespace
}  // namespace gdpn::diagram

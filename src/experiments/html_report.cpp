#include "gdpn/experiments/html_report.h"

#include <nlohmann/json.hpp>

#include "gdpn/experiments/python_sources.h"
#include "gdpn/script/call.h"

namespace gdpn::experiments {

std::string runJson(const model::Report& report, const net::Net& net, const net::Timeline& timeline,
                    const model::SignalTable* signals, const model::SignalTable* levels) {
  using nlohmann::ordered_json;
  auto run = ordered_json::parse(model::reportJson(report));
  auto& params = run["param_table"] = ordered_json::array();
  for (const auto& p : report.params) {
    params.push_back({{"name", p.name}, {"value", p.value}, {"declared", p.declared}, {"unit", p.unit}});
  }
  const double dt = report.dt;
  auto seconds = [dt](std::int64_t step) { return static_cast<double>(step) * dt; };
  ordered_json tl;
  auto& names = tl["transitions"] = ordered_json::array();
  for (net::TransitionId t{0}; t < net.transitions().size(); ++t) names.push_back(net.transitionName(t));
  auto& occurrences = tl["occurrences"] = ordered_json::array();
  for (const auto& o : timeline.occurrences()) {
    occurrences.push_back({o.transition.index(), seconds(o.start), o.end < 0 ? ordered_json(nullptr) : ordered_json(seconds(o.end))});
  }
  auto& places = tl["places"] = ordered_json::array();
  for (net::PlaceId p{0}; p < net.places().size(); ++p) {
    if (report.places.size() > p && report.places[p].sensors_only) continue;  // no tokens of their own
    auto changes = ordered_json::array();
    for (const auto& c : timeline.places()[p]) changes.push_back({seconds(c.step), c.tokens});
    places.push_back({{"name", net.placeName(p)}, {"changes", std::move(changes)}});
  }
  tl["cut_at"] = timeline.cutAt() < 0 ? ordered_json(nullptr) : ordered_json(seconds(timeline.cutAt()));
  tl["dropped"] = timeline.dropped();
  run["timeline"] = std::move(tl);
  if (signals != nullptr) {
    ordered_json sig;
    sig["columns"] = signals->columns;
    sig["time"] = signals->time;
    auto& values = sig["values"] = ordered_json::array();
    for (std::size_t c = 0; c < signals->columns.size(); ++c) {
      auto column = ordered_json::array();
      for (const auto& row : signals->rows) column.push_back(row[c] ? ordered_json(*row[c]) : ordered_json(nullptr));
      values.push_back(std::move(column));
    }
    run["signals"] = std::move(sig);
  }
  // the continuous places' levels: a column per place, in place order, with its unit and capacity
  if (const net::Fluid* fluid = net.fluid(); levels != nullptr && fluid != nullptr &&
                                             levels->columns.size() == fluid->places.size()) {
    ordered_json lv;
    lv["time"] = levels->time;
    auto& series = lv["places"] = ordered_json::array();
    for (std::size_t c = 0; c < fluid->places.size(); ++c) {
      const auto& fp = fluid->places[c];
      auto column = ordered_json::array();
      for (const auto& row : levels->rows) column.push_back(row[c] ? ordered_json(*row[c]) : ordered_json(nullptr));
      series.push_back({{"name", net.placeName(fp.place)},
                        {"unit", fp.unit},
                        {"capacity", fp.capacity == net::kNoBound ? ordered_json(nullptr) : ordered_json(fp.capacity)},
                        {"values", std::move(column)}});
    }
    run["levels"] = std::move(lv);
  }
  return run.dump();
}

std::optional<std::string> htmlReport(const model::Report& report, const net::Net& net,
                                      const net::Timeline& timeline, const model::SignalTable* signals,
                                      std::string& why, const model::SignalTable* levels) {
  return script::callPython(kReportPagePy, "report_page.py", "page", runJson(report, net, timeline, signals, levels),
                            why);
}

}  // namespace gdpn::experiments

#pragma once
/// \file
/// The HTML report of a run (`gdpn run --html`): one self-contained page with the summary
/// tables and plots of tokens over time, transition occurrences (a Gantt chart), throughput,
/// cycle times beside their bounds, every continuous place's level, and every signal, drawn by
/// matplotlib as SVG through the embedded Python.

#include <optional>
#include <string>

#include "gdpn/model/report.h"
#include "gdpn/model/signals.h"
#include "gdpn/net/timeline.h"

namespace gdpn::experiments {

/// The run as the page's Python receives it (JSON text): the report's JSON, the parameters
/// with their units (`param_table`), the timeline in seconds, the signals as columns, and the
/// continuous places' levels (`levels`: Simulation::levels(), with each place's unit and capacity).
std::string runJson(const model::Report& report, const net::Net& net, const net::Timeline& timeline,
                    const model::SignalTable* signals, const model::SignalTable* levels = nullptr);

/// The page: nullopt with `why` (Python's traceback) when it cannot be drawn, as when
/// matplotlib is missing.
std::optional<std::string> htmlReport(const model::Report& report, const net::Net& net,
                                      const net::Timeline& timeline, const model::SignalTable* signals,
                                      std::string& why, const model::SignalTable* levels = nullptr);

}  // namespace gdpn::experiments

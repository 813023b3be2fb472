#pragma once
/// \file
/// A run as every face asks for one: what it collects from its start (the report's figures,
/// the circuits of tokens with alternatives, a timeline). Its defaults are the defaults of
/// `gdpn run` showing its report, of `gdpn.load(...).run(...)` and of the IDE; a Session
/// applies it to each run it makes (at creation, reset and rebuild).

#include "gdpn/model/report.h"

namespace gdpn::session {

/// What each run of a session collects from its start.
struct RunRequest {
  /// Collect the report's figures (statistics) and watch the round trips of every token with
  /// alternative circuits, so that the report shows each circuit's measured cycle. Off: no
  /// statistics are collected (the run's report is never made) and no cycles worked out.
  bool report = true;
  /// Keep every occurrence and change of tokens, up to the timeline's budget, and every
  /// continuous place's amount after each step (the plots of `gdpn run --html`);
  /// Session::timeline() and Simulation::levels() give them.
  bool timeline = false;
  /// Echo each `sim.log` line on stderr (`[t=...] ...`), the globals script's too; off
  /// (`-q`): the lines go to the trace alone.
  bool echo_log = true;
  /// Wall-clock time the cycle bounds may take, for the circuits watched and the report,
  /// seconds.
  double cycle_seconds = model::kCycleBoundSeconds;
};

}  // namespace gdpn::session

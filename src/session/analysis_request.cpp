#include "gdpn/session/analysis_request.h"

#include <algorithm>
#include <cstdio>

#include "gdpn/core/memory.h"
#include "gdpn/net/coloured_search.h"
#include "gdpn/net/compile.h"
#include "gdpn/net/unfold.h"

namespace gdpn::session {

namespace {

/// The limits with the deadline of the time limit, for a single search.
net::ExploreOptions withDeadline(const AnalysisRequest& request) {
  net::ExploreOptions limits = request.limits();
  if (request.time_limit_s > 0.0) limits.deadline = net::deadlineAfter(request.time_limit_s);
  return limits;
}

}  // namespace

net::ExploreOptions AnalysisRequest::limits() const {
  net::ExploreOptions o;
  o.max_states = max_states;
  o.max_bytes = static_cast<std::uint64_t>(max_memory_mib * 1024.0 * 1024.0);
  if (guarded()) {
    o.max_bytes = core::availableMemory() / 4 * 3;
    o.max_bytes_guard = true;
  }
  o.threads = threads;
  o.shortest_path = shortest_path;
  o.reduction = reduction;
  return o;
}

bool AnalysisAnswer::stoppedAtGuard() const {
  const auto stopped = model::stoppedPhases(analysis);
  return guard && std::any_of(stopped.begin(), stopped.end(),
                              [](const auto& p) { return p.second == net::ExploreStop::MaxMemory; });
}

std::string AnalysisAnswer::guardNote(std::string_view option) const {
  char mib[32];
  std::snprintf(mib, sizeof mib, "%.0f", static_cast<double>(max_bytes) / (1024.0 * 1024.0));
  return "stopped at the default " + std::string(option) + ", 3/4 of the memory available at the start (" + mib + " MiB)";
}

std::optional<AnalysedNet> analysedNet(const net::NetSpec& spec, core::Diagnostics& diags, ColourSearch how) {
  AnalysedNet out;
  if (!net::coloured(spec)) {
    out.net = net::compile(spec, diags);
    if (!out.net) return std::nullopt;
    return out;
  }
  std::optional<core::Diagnostic> why_not;
  if (how != ColourSearch::Native) {
    // Auto: unfolding's refusal kept aside, a note where the native search takes over
    core::Diagnostics unfolding;
    auto unfolded = net::unfold(spec, how == ColourSearch::Unfold ? diags : unfolding);
    if (unfolded) {
      out.net = net::compile(unfolded->net, diags);
      out.names = std::move(unfolded->names);
      if (!out.net) return std::nullopt;
      core::Diagnostics quiet;  // what it could say, the unfolding said
      out.coloured = net::compile(spec, quiet);
      return out;
    }
    if (how == ColourSearch::Unfold) return std::nullopt;
    for (const auto& d : unfolding.all()) {
      if (d.severity == core::Severity::Error && !why_not) why_not = d;
    }
  }
  out.net = net::compile(spec, diags);
  if (!out.net) return std::nullopt;
  if (const std::string refusal = net::colouredRefusal(*out.net); !refusal.empty()) {
    diags.error(spec.pages.empty() ? core::SourceLoc{} : spec.pages.front().loc,
                "the coloured net cannot be searched without unfolding: " + refusal);
    return std::nullopt;
  }
  out.native = true;
  out.coloured = out.net;
  if (why_not) {
    diags.note(why_not->loc, "analysed over markings with values, without unfolding: " + why_not->message);
  }
  return out;
}

AnalysisAnswer analyze(const AnalysedNet& analysed, std::string path, const AnalysisRequest& request) {
  const net::Net& net = *analysed.net;
  model::AnalysisOptions options;
  options.coloured = analysed.coloured.get();
  options.explore = request.limits();
  options.explore.progress = request.progress;
  options.dt = request.dt;
  options.time_limit_s = request.time_limit_s;
  options.progress = request.phase_progress;
  AnalysisAnswer answer;
  answer.max_bytes = options.explore.max_bytes;
  answer.guard = options.explore.max_bytes_guard;
  answer.analysis = model::analyze(net, std::move(path), options);
  return answer;
}

std::vector<net::QueryAnswer> answerQueries(const net::Net& net, const std::vector<net::Formula>& formulas,
                                            const AnalysisRequest& request) {
  return net::answerQueries(net, formulas, withDeadline(request));
}

net::ExploreStop writeStateGraph(const net::Net& net, net::GraphFormat format, std::ostream& out,
                                 const AnalysisRequest& request) {
  return net::writeStateGraph(net, format, out, withDeadline(request));
}

}  // namespace gdpn::session

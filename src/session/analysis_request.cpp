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
  if (net::hybrid(spec)) {
    // a hybrid net: its discrete part, with a note of what that leaves out
    net::DiscretePart left;
    const net::NetSpec discrete = net::discretePart(spec, &left);
    // the hybrid net must compile as it is: its mistakes are the user's, whatever is analysed
    if (!net::compile(spec, diags)) return std::nullopt;
    auto out = analysedNet(discrete, diags, how);
    if (!out) return out;
    const auto counted = [](std::size_t n, const char* what) {
      return std::to_string(n) + " " + what + (n == 1 ? "" : "s");
    };
    out->notes.push_back("the continuous part (" + counted(left.places, "continuous place") + ", " +
                         counted(left.transitions, "continuous transition") + ", " + counted(left.arcs, "arc") +
                         ") is left out: thresholds on amounts count as met and amounts move no tokens, so the state "
                         "space, bounds, deadlocks, liveness, invariants and cycle times are the discrete net's, every "
                         "run of the hybrid net among its runs (a deadlock found may not happen; none found holds)");
    return out;
  }
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
  answer.analysis.notes.insert(answer.analysis.notes.begin(), analysed.notes.begin(), analysed.notes.end());
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

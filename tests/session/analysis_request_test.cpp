// The request of an analysis: its defaults are gdpn analyze's, the memory guard among them,
// for every face (the CLI and Model.analyze() alike).

#include <gtest/gtest.h>

#include <algorithm>

#include "gdpn/core/memory.h"
#include "gdpn/session/analysis_request.h"

namespace gdpn::session {
namespace {

TEST(AnalysisRequest, WithoutAMemoryLimitTheGuardIsThreeQuartersOfTheAvailableMemory) {
  const AnalysisRequest request;
  EXPECT_EQ(request.max_states, 20'000'000u);
  EXPECT_TRUE(request.guarded());
  const std::uint64_t before = core::availableMemory() / 4 * 3;
  const net::ExploreOptions limits = request.limits();
  const std::uint64_t after = core::availableMemory() / 4 * 3;
  EXPECT_TRUE(limits.max_bytes_guard);
  EXPECT_EQ(limits.max_states, 20'000'000u);
  // the memory available moves a little between the readings (other processes)
  const std::uint64_t slack = 256ull << 20;
  EXPECT_GE(limits.max_bytes + slack, std::min(before, after));
  EXPECT_LE(limits.max_bytes, std::max(before, after) + slack);
}

TEST(AnalysisRequest, AMemoryLimitGivenIsALimitNotAGuard) {
  AnalysisRequest request;
  request.max_memory_mib = 64;
  request.threads = 2;
  request.reduction = false;
  const auto limits = request.limits();
  EXPECT_FALSE(limits.max_bytes_guard);
  EXPECT_EQ(limits.max_bytes, 64u << 20);
  EXPECT_EQ(limits.threads, 2u);
  EXPECT_FALSE(limits.reduction);
}

TEST(AnalysisRequest, TheGuardNoteSaysWhichLimitStoppedIt) {
  AnalysisAnswer answer;
  answer.max_bytes = 3u << 20;
  answer.guard = true;
  EXPECT_EQ(answer.guardNote("--max-memory"),
            "stopped at the default --max-memory, 3/4 of the memory available at the start (3 MiB)");
  EXPECT_FALSE(answer.stoppedAtGuard());  // a complete analysis
  answer.analysis.space.stop = net::ExploreStop::MaxMemory;
  answer.analysis.space.complete = false;
  EXPECT_TRUE(answer.stoppedAtGuard());
  answer.guard = false;  // a limit asked for: no note
  EXPECT_FALSE(answer.stoppedAtGuard());
}

}  // namespace
}  // namespace gdpn::session

// The random generator: fixed sequences for a seed, and distributions with the right moments.

#include "gdpn/core/random.h"

#include <gtest/gtest.h>

#include <cmath>

namespace gdpn::core {
namespace {

TEST(Random, SameSeedSameSequenceAcrossReseeds) {
  Random a(42), b(7);
  b.reseed(42);
  for (int i = 0; i < 100; ++i) EXPECT_EQ(a.next(), b.next());
}

TEST(Random, KnownFirstOutputsPinTheAlgorithm) {
  // xoshiro256** seeded through splitmix64(0): a change here changes every stochastic run
  Random r(0);
  EXPECT_EQ(r.next(), 0x99ec5f36cb75f2b4ULL);
  EXPECT_EQ(r.next(), 0xbf6e1f784956452aULL);
}

template <class F>
std::pair<double, double> moments(F draw, int n) {
  double sum = 0, sq = 0;
  for (int i = 0; i < n; ++i) {
    const double x = draw();
    sum += x;
    sq += x * x;
  }
  const double mean = sum / n;
  return {mean, sq / n - mean * mean};
}

TEST(Random, DistributionsHaveTheirMoments) {
  Random r(3);
  const int n = 200000;
  auto [um, uv] = moments([&] { return r.uniform(2.0, 4.0); }, n);
  EXPECT_NEAR(um, 3.0, 0.01);
  EXPECT_NEAR(uv, 4.0 / 12.0, 0.01);
  auto [nm, nv] = moments([&] { return r.normal(5.0, 2.0); }, n);
  EXPECT_NEAR(nm, 5.0, 0.02);
  EXPECT_NEAR(nv, 4.0, 0.05);
  auto [em, ev] = moments([&] { return r.exponential(3.0); }, n);
  EXPECT_NEAR(em, 3.0, 0.03);
  EXPECT_NEAR(ev, 9.0, 0.2);
}

TEST(Random, Uniform01StaysInItsInterval) {
  Random r(11);
  for (int i = 0; i < 100000; ++i) {
    const double u = r.uniform01();
    ASSERT_GE(u, 0.0);
    ASSERT_LT(u, 1.0);
  }
}

TEST(Random, BelowIsUnbiasedAndInRange) {
  Random r(5);
  int counts[3] = {0, 0, 0};
  for (int i = 0; i < 30000; ++i) {
    const auto k = r.below(3);
    ASSERT_LT(k, 3u);
    ++counts[k];
  }
  for (int c : counts) EXPECT_NEAR(c, 10000, 500);
}

}  // namespace
}  // namespace gdpn::core

// The broad phase: the tree and the sweep find exactly the overlapping pairs that checking
// every pair finds, for boxes of mixed sizes that move and come and go.

#include "gdpn/core/broad_phase.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <utility>

#include "gdpn/core/random.h"

namespace gdpn::core {
namespace {

Aabb randomBox(Random& r, double world, double largest) {
  const Vec3 c{r.uniform(-world, world), r.uniform(-world, world), r.uniform(0, world / 4)};
  // mostly small boxes, some long ones (belts, walls), some flat
  const double sx = r.uniform01() < 0.1 ? r.uniform(0, largest) : r.uniform(0, largest / 20);
  const double sy = r.uniform(0, largest / 20), sz = r.uniform01() < 0.2 ? 0.0 : r.uniform(0, largest / 20);
  return {c - Vec3{sx, sy, sz} * 0.5, c + Vec3{sx, sy, sz} * 0.5};
}

std::set<std::size_t> bruteForce(const std::vector<Aabb>& boxes, const Aabb& q) {
  std::set<std::size_t> hits;
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    if (overlaps(boxes[i], q)) hits.insert(i);
  }
  return hits;
}

TEST(BroadPhase, OverlapCountsTouchingFacesAndNotGaps) {
  const Aabb a{{0, 0, 0}, {1, 1, 1}};
  EXPECT_TRUE(overlaps(a, Aabb{{1, 0, 0}, {2, 1, 1}}));          // a shared face
  EXPECT_FALSE(overlaps(a, Aabb{{1.001, 0, 0}, {2, 1, 1}}));     // a gap along x
  EXPECT_FALSE(overlaps(a, Aabb{{0, 0, 1.5}, {1, 1, 2}}));       // above
  EXPECT_TRUE(overlaps(a, Aabb{{0.5, 0.5, 0.5}, {0.5, 0.5, 0.5}}));  // a point inside
}

TEST(BroadPhase, TreeQueriesFindWhatCheckingEveryBoxFinds) {
  Random r(3);
  for (const std::size_t n : {0u, 1u, 4u, 5u, 37u, 500u}) {
    std::vector<Aabb> boxes;
    for (std::size_t i = 0; i < n; ++i) boxes.push_back(randomBox(r, 20, 12));
    AabbTree tree;
    tree.build(boxes);
    EXPECT_EQ(tree.size(), n);
    for (int k = 0; k < 200; ++k) {
      const Aabb q = randomBox(r, 22, 6);
      std::set<std::size_t> found;
      std::size_t calls = 0;
      tree.query(q, [&](std::size_t i) {
        found.insert(i);
        ++calls;
      });
      EXPECT_EQ(calls, found.size()) << "each box is reported once";
      EXPECT_EQ(found, bruteForce(boxes, q)) << n << " boxes, query " << k;
    }
  }
}

TEST(BroadPhase, TreeHandlesBoxesAllInOnePlace) {
  // identical boxes cannot be split by their centres: the tree still holds and finds them all
  std::vector<Aabb> boxes(100, Aabb{{0, 0, 0}, {1, 1, 1}});
  AabbTree tree;
  tree.build(boxes);
  std::size_t found = 0;
  tree.query(Aabb{{0.5, 0.5, 0.5}, {0.6, 0.6, 0.6}}, [&](std::size_t) { ++found; });
  EXPECT_EQ(found, 100u);
  tree.query(Aabb{{2, 2, 2}, {3, 3, 3}}, [&](std::size_t) { ADD_FAILURE() << "nothing is there"; });
}

TEST(BroadPhase, TreeReportsInTheSameOrderEveryBuild) {
  Random r(9);
  std::vector<Aabb> boxes;
  for (int i = 0; i < 200; ++i) boxes.push_back(randomBox(r, 10, 8));
  AabbTree a, b;
  a.build(boxes);
  b.build(boxes);
  const Aabb q{{-5, -5, 0}, {5, 5, 3}};
  std::vector<std::size_t> ra, rb;
  a.query(q, [&](std::size_t i) { ra.push_back(i); });
  b.query(q, [&](std::size_t i) { rb.push_back(i); });
  EXPECT_FALSE(ra.empty());
  EXPECT_EQ(ra, rb);
}

TEST(BroadPhase, SweepFindsEveryOverlappingPairOnceAsBoxesMoveAndComeAndGo) {
  Random r(5);
  std::vector<Aabb> boxes;
  for (int i = 0; i < 60; ++i) boxes.push_back(randomBox(r, 3, 10));
  SweepAndPrune sweep;
  for (int step = 0; step < 50; ++step) {
    // everything drifts; now and then one box leaves and another arrives
    for (auto& b : boxes) {
      const Vec3 d{r.uniform(-0.2, 0.2), r.uniform(-0.2, 0.2), r.uniform(-0.05, 0.05)};
      b = {b.lo + d, b.hi + d};
    }
    if (step % 7 == 3) boxes.erase(boxes.begin() + static_cast<long>(r.below(boxes.size())));
    if (step % 5 == 1) boxes.push_back(randomBox(r, 3, 10));
    std::set<std::pair<std::size_t, std::size_t>> expected, found;
    for (std::size_t i = 0; i < boxes.size(); ++i) {
      for (std::size_t j = i + 1; j < boxes.size(); ++j) {
        if (overlaps(boxes[i], boxes[j])) expected.insert({i, j});
      }
    }
    std::size_t calls = 0;
    sweep.pairs(boxes, [&](std::size_t i, std::size_t j) {
      EXPECT_NE(i, j);
      found.insert(std::minmax(i, j));
      ++calls;
    });
    EXPECT_EQ(calls, found.size()) << "step " << step << ": a pair reported twice";
    EXPECT_EQ(found, expected) << "step " << step;
    EXPECT_FALSE(expected.empty());
  }
}

}  // namespace
}  // namespace gdpn::core

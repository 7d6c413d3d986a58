// The link classifier behind D1/D2 (refine/link_shape.h): known shapes, and the small and the
// sorted implementations agreeing on many random graphs, large ones included.
#include <doctest/doctest.h>

#include <algorithm>
#include <random>
#include <vector>

#include <delpsc/refine/link_shape.h>

using namespace delpsc;
using refine::LinkShape;
using Edge = std::array<delaunay::PointId, 2>;

namespace {

LinkShape both(const std::vector<Edge>& link) {
  const LinkShape sorted = refine::link_shape_sorted(link);
  if (link.size() <= refine::kSmallLink) {
    const LinkShape small = refine::link_shape_small(link);
    CHECK(small.simple == sorted.simple);
    if (sorted.simple) CHECK(small.vertices == sorted.vertices);
  }
  const LinkShape chosen = refine::link_shape(link);
  CHECK(chosen.simple == sorted.simple);
  return sorted;
}

std::vector<Edge> cycle(delaunay::PointId first, std::size_t n) {
  std::vector<Edge> e;
  for (std::size_t i = 0; i < n; ++i)
    e.push_back({first + static_cast<delaunay::PointId>(i), first + static_cast<delaunay::PointId>((i + 1) % n)});
  return e;
}

}  // namespace

TEST_CASE("known link shapes") {
  for (std::size_t n : {3u, 6u, 16u, 17u, 40u}) {
    std::vector<Edge> c = cycle(100, n);
    std::shuffle(c.begin(), c.end(), std::mt19937(7));
    const LinkShape s = both(c);
    CHECK(s.simple);
    CHECK(s.vertices == c.size());  // a cycle: E == V
    c.pop_back();                    // a path: E == V - 1
    const LinkShape p = both(c);
    CHECK(p.simple);
    CHECK(p.vertices == c.size() + 1);
  }
  // Two disjoint triangles: degrees fine, not connected.
  std::vector<Edge> two = cycle(0, 3);
  for (const Edge& e : cycle(10, 3)) two.push_back(e);
  CHECK_FALSE(both(two).simple);
  // A vertex of degree 3 (a pinched umbrella).
  std::vector<Edge> star = {{0, 1}, {0, 2}, {0, 3}};
  CHECK_FALSE(both(star).simple);
  // A cycle with a tail.
  std::vector<Edge> tail = cycle(0, 4);
  tail.push_back({2, 9});
  CHECK_FALSE(both(tail).simple);
  // A single edge is a path.
  CHECK(both({{5, 8}}).simple);
}

TEST_CASE("small and sorted classifiers agree on random graphs") {
  std::mt19937 engine(12345);
  auto rng = [&] { return static_cast<delaunay::PointId>(engine()); };
  std::size_t simple = 0, total = 0;
  for (int round = 0; round < 20000; ++round) {
    const std::size_t k = 1 + rng() % 24;
    const delaunay::PointId range = static_cast<delaunay::PointId>(2 + rng() % (k + 3));
    std::vector<Edge> link;
    for (std::size_t i = 0; i < k; ++i) {
      delaunay::PointId a = rng() % range, b = rng() % range;
      if (a == b) continue;
      const Edge e = {std::min(a, b), std::max(a, b)};
      if (std::find(link.begin(), link.end(), e) != link.end()) continue;
      link.push_back(e);
    }
    if (link.empty()) continue;
    // Sometimes a path or cycle in disguise: relabelled and shuffled.
    if (round % 3 == 0) {
      link = cycle(rng() % 1000, 3 + rng() % 20);
      if (round % 2 == 0) link.pop_back();
      std::shuffle(link.begin(), link.end(), engine);
    }
    simple += both(link).simple;
    ++total;
  }
  MESSAGE(simple << " simple links of " << total);
  CHECK(simple > total / 5);  // the generator does produce both answers
  CHECK(simple < total);
}

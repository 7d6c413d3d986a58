// The link classifier behind D1/D2 (refine/link_shape.h): known shapes, and the small and the
// large implementations agreeing with a plain oracle (degrees in a map, connectivity by a
// search) on many random graphs, large ones included.
#include <doctest/doctest.h>

#include <algorithm>
#include <map>
#include <random>
#include <set>
#include <vector>

#include <delpsc/refine/link_shape.h>

using namespace delpsc;
using refine::LinkShape;
using Edge = std::array<delaunay::PointId, 2>;

namespace {

// Whether the graph is connected with every degree <= 2, and its vertex count: by a map of
// degrees and a depth-first search, nothing shared with the classifiers.
LinkShape oracle(const std::vector<Edge>& link) {
  std::map<delaunay::PointId, std::vector<delaunay::PointId>> adjacent;
  for (const Edge& e : link) {
    adjacent[e[0]].push_back(e[1]);
    adjacent[e[1]].push_back(e[0]);
  }
  bool low_degree = true;
  for (const auto& [v, next] : adjacent) low_degree = low_degree && next.size() <= 2;
  std::set<delaunay::PointId> seen;
  std::vector<delaunay::PointId> todo{adjacent.begin()->first};
  while (!todo.empty()) {
    const delaunay::PointId v = todo.back();
    todo.pop_back();
    if (!seen.insert(v).second) continue;
    for (const delaunay::PointId w : adjacent[v]) todo.push_back(w);
  }
  return {low_degree && seen.size() == adjacent.size(), adjacent.size()};
}

LinkShape both(const std::vector<Edge>& link) {
  const LinkShape expected = oracle(link);
  const LinkShape large = refine::link_shape_large(link);
  CHECK(large.simple == expected.simple);
  if (expected.simple) CHECK(large.vertices == expected.vertices);
  if (link.size() <= refine::kSmallLink) {
    const LinkShape small = refine::link_shape_small(link);
    CHECK(small.simple == expected.simple);
    if (expected.simple) CHECK(small.vertices == expected.vertices);
  }
  const LinkShape chosen = refine::link_shape(link);
  CHECK(chosen.simple == expected.simple);
  return expected;
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

TEST_CASE("small and large classifiers agree with the oracle on random graphs") {
  std::mt19937 engine(12345);
  auto rng = [&] { return static_cast<delaunay::PointId>(engine()); };
  std::size_t simple = 0, total = 0;
  for (int round = 0; round < 20000; ++round) {
    // Mostly around the small classifier's limit; one round in 8 up to 400 edges, with ids
    // spread over all 31 bits (the large one's hash table, its probing and growth).
    const std::size_t k = round % 8 == 0 ? 1 + rng() % 400 : 1 + rng() % 24;
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
    if (round % 8 == 0) {
      // Ids scattered over 31 bits (consecutive ones hash without collisions).
      std::map<delaunay::PointId, delaunay::PointId> id;
      std::set<delaunay::PointId> used;
      for (const Edge& e : link)
        for (const delaunay::PointId v : e) {
          if (id.count(v) != 0) continue;
          delaunay::PointId fresh = rng() & 0x7fffffffu;
          while (!used.insert(fresh).second) fresh = rng() & 0x7fffffffu;
          id[v] = fresh;
        }
      for (Edge& e : link)
        for (delaunay::PointId& v : e) v = id.at(v);
    }
    // Sometimes a path or cycle in disguise: relabelled and shuffled.
    if (round % 3 == 0) {
      link = cycle(round % 8 == 0 ? rng() % 0x7fff0000u : rng() % 1000, round % 8 == 0 ? 3 + rng() % 400 : 3 + rng() % 20);
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

// ---- links at a pinch (link_pieces, pieces_match_fans) --------------------------------------

TEST_CASE("link pieces: paths with their ends, cycles, and a vertex of degree 3") {
  std::vector<refine::LinkPiece> pieces;
  // Two paths (a pinch of two open fans): 1-2-3 and 7-8.
  std::vector<Edge> two_paths = {{2, 3}, {7, 8}, {1, 2}};
  REQUIRE(refine::link_pieces(two_paths, pieces));
  REQUIRE(pieces.size() == 2);
  std::vector<std::array<delaunay::PointId, 2>> ends;
  for (const auto& p : pieces) {
    CHECK_FALSE(p.cycle);
    ends.push_back({std::min(p.ends[0], p.ends[1]), std::max(p.ends[0], p.ends[1])});
  }
  std::sort(ends.begin(), ends.end());
  CHECK(ends == std::vector<std::array<delaunay::PointId, 2>>{{1, 3}, {7, 8}});
  // A cycle and a path.
  std::vector<Edge> mixed = cycle(10, 4);
  mixed.push_back({30, 31});
  REQUIRE(refine::link_pieces(mixed, pieces));
  REQUIRE(pieces.size() == 2);
  CHECK(std::count_if(pieces.begin(), pieces.end(), [](const auto& p) { return p.cycle; }) == 1);
  // One simple path is one piece, as link_shape says.
  REQUIRE(refine::link_pieces(std::vector<Edge>{{4, 5}, {5, 6}}, pieces));
  CHECK(pieces.size() == 1);
  // Degree 3: no pieces.
  CHECK_FALSE(refine::link_pieces(std::vector<Edge>{{0, 1}, {0, 2}, {0, 3}}, pieces));
}

TEST_CASE("link pieces match a pinch's fans one to one, by kind and by curves") {
  // Vertices 1..4 lie on curves 11..14 (vertex v on curve 10 + v); 5 on none.
  const auto on_curve = [](delaunay::PointId v, std::uint32_t c) { return v >= 1 && v <= 4 && c == 10 + v; };
  constexpr std::uint32_t kClosed = 0xffffffffu;
  const std::vector<std::array<std::uint32_t, 2>> wedges = {{11, 12}, {13, 14}};
  std::vector<refine::LinkPiece> pieces;
  const auto match = [&](const std::vector<Edge>& link, const std::vector<std::array<std::uint32_t, 2>>& fans) {
    return refine::link_pieces(link, pieces) && refine::pieces_match_fans(pieces, fans, on_curve);
  };
  CHECK(match({{1, 6}, {6, 2}, {3, 7}, {7, 4}}, wedges));   // each path between its fan's curves
  CHECK(match({{4, 7}, {7, 3}, {2, 6}, {6, 1}}, wedges));   // in any order and direction
  CHECK_FALSE(match({{1, 6}, {6, 3}, {2, 7}, {7, 4}}, wedges));  // paths joining the wrong curves
  CHECK_FALSE(match({{1, 6}, {6, 2}, {2, 7}, {7, 1}}, wedges));  // one piece for two fans (a cycle)
  CHECK_FALSE(match({{1, 6}, {6, 2}}, wedges));                  // a fan missing
  CHECK_FALSE(match({{1, 6}, {6, 5}, {3, 7}, {7, 4}}, wedges));  // an end on no curve
  // A closed fan and an open one: a cycle and a path.
  const std::vector<std::array<std::uint32_t, 2>> closed_and_open = {{kClosed, kClosed}, {11, 12}};
  std::vector<Edge> ring = cycle(20, 5);
  std::vector<Edge> with_path = ring;
  with_path.push_back({1, 2});
  CHECK(match(with_path, closed_and_open));
  std::vector<Edge> two_paths = {{1, 2}, {3, 4}};
  CHECK_FALSE(match(two_paths, closed_and_open));
}

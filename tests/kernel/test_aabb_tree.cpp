// The AABB tree against brute force: every query answered by the tree must be exactly the answer
// of testing all triangles one by one, on random soups and on grids where segments pass exactly
// through shared edges and vertices (where a careless box test would lose triangles).
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <set>
#include <span>
#include <stdexcept>
#include <vector>

#include <delpsc/kernel/aabb_tree.h>
#include <delpsc/kernel/constructions.h>

using namespace delpsc;
using namespace delpsc::kernel;

namespace {

struct Soup {
  std::vector<Vec3> vertices;
  std::vector<std::array<std::uint32_t, 3>> triangles;
};

Soup random_soup(std::mt19937_64& rng, int n, double size) {
  std::uniform_real_distribution<double> u(0, 1), small(-size, size);
  Soup s;
  for (int i = 0; i < n; ++i) {
    const Vec3 c(u(rng), u(rng), u(rng));
    const auto base = static_cast<std::uint32_t>(s.vertices.size());
    for (int k = 0; k < 3; ++k) s.vertices.push_back(c + Vec3(small(rng), small(rng), small(rng)));
    s.triangles.push_back({base, base + 1, base + 2});
  }
  return s;
}

// An n x n grid of unit squares in the plane z = 0, each split along its diagonal.
Soup grid_soup(int n) {
  Soup s;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) s.vertices.emplace_back(i, j, 0);
  auto id = [n](int i, int j) { return static_cast<std::uint32_t>(j * (n + 1) + i); };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      s.triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      s.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  return s;
}

std::vector<std::uint32_t> brute_segment(const Soup& s, const Vec3& a, const Vec3& b) {
  std::vector<std::uint32_t> ids;
  for (std::uint32_t t = 0; t < s.triangles.size(); ++t) {
    const auto& tri = s.triangles[t];
    if (intersect_segment_triangle(a, b, s.vertices[tri[0]], s.vertices[tri[1]], s.vertices[tri[2]]))
      ids.push_back(t);
  }
  return ids;
}

std::vector<std::uint32_t> brute_ray(const Soup& s, const Vec3& o, const Vec3& d) {
  std::vector<std::uint32_t> ids;
  for (std::uint32_t t = 0; t < s.triangles.size(); ++t) {
    const auto& tri = s.triangles[t];
    if (intersect_ray_triangle(o, d, s.vertices[tri[0]], s.vertices[tri[1]], s.vertices[tri[2]]))
      ids.push_back(t);
  }
  return ids;
}

std::vector<std::uint32_t> ids_of(std::vector<TriangleIntersection> hits) {
  std::vector<std::uint32_t> ids;
  for (const auto& h : hits) ids.push_back(h.triangle);
  std::sort(ids.begin(), ids.end());
  return ids;
}

}  // namespace

TEST_CASE("empty tree answers nothing") {
  AabbTree tree;
  std::vector<TriangleIntersection> hits;
  tree.intersect_segment(Vec3(0, 0, 0), Vec3(1, 1, 1), hits);
  CHECK(hits.empty());
  CHECK_FALSE(tree.closest_point(Vec3(0, 0, 0)).has_value());
  CHECK(tree.bounds().empty());
}

TEST_CASE("segment and ray queries equal brute force on random soups") {
  std::mt19937_64 rng(12345);
  const Soup s = random_soup(rng, 3000, 0.05);
  const AabbTree tree(s.vertices, s.triangles);
  REQUIRE(tree.size() == s.triangles.size());
  CHECK(tree.depth() <= AabbTree::kSahDepth + 11);  // ceil(log2(3000 / 4)) + 1 = 11 median levels
  std::uniform_real_distribution<double> u(-0.2, 1.2);
  std::size_t total = 0;
  for (int q = 0; q < 300; ++q) {
    const Vec3 a(u(rng), u(rng), u(rng)), b(u(rng), u(rng), u(rng));
    std::vector<TriangleIntersection> hits;
    tree.intersect_segment(a, b, hits);
    const auto got = ids_of(hits);
    CHECK(got == brute_segment(s, a, b));
    total += got.size();
    hits.clear();
    tree.intersect_ray(a, b - a, hits);
    CHECK(ids_of(hits) == brute_ray(s, a, b - a));
  }
  CHECK(total > 300);  // the segments do meet triangles: the comparison is not vacuous
}

// Small trees: a single leaf at the root, and wide nodes with unused lanes (their NaN bounds must
// pass no test, and no lane may be lost).
TEST_CASE("trees of one to twelve triangles answer as brute force") {
  std::mt19937_64 rng(99);
  std::uniform_real_distribution<double> u(-0.2, 1.2);
  for (int n = 1; n <= 12; ++n) {
    const Soup s = random_soup(rng, n, 0.3);
    const AabbTree tree(s.vertices, s.triangles);
    REQUIRE(tree.size() == static_cast<std::size_t>(n));
    std::size_t total = 0;
    for (int q = 0; q < 400; ++q) {
      const Vec3 a(u(rng), u(rng), u(rng)), b(u(rng), u(rng), u(rng));
      std::vector<TriangleIntersection> hits;
      tree.intersect_segment(a, b, hits);
      CHECK(ids_of(hits) == brute_segment(s, a, b));
      total += hits.size();
      hits.clear();
      tree.intersect_ray(a, b - a, hits);
      CHECK(ids_of(hits) == brute_ray(s, a, b - a));
    }
    CHECK(total > 0);
  }
}

// Pieces of at most 1/16 of the tree's diagonal, like the mesher's dual-edge windows: around points
// of the triangles, in every direction, down to pieces far below a triangle's size, they must
// find exactly what brute force finds.
TEST_CASE("short segments around the triangles equal brute force") {
  std::mt19937_64 rng(2024);
  const Soup s = random_soup(rng, 3000, 0.05);
  const AabbTree tree(s.vertices, s.triangles);
  const double limit = tree.bounds().diagonal() / 16;
  std::uniform_real_distribution<double> u(0, 1), dir(-1, 1), scale(-8, 0);
  std::uniform_int_distribution<std::uint32_t> pick(0, static_cast<std::uint32_t>(s.triangles.size() - 1));
  std::size_t total = 0;
  for (int q = 0; q < 2000; ++q) {
    const auto& tri = s.triangles[pick(rng)];
    const double r = u(rng), t = u(rng) * (1 - r);
    const Vec3 on = s.vertices[tri[0]] + r * (s.vertices[tri[1]] - s.vertices[tri[0]]) +
                    t * (s.vertices[tri[2]] - s.vertices[tri[0]]);
    const Vec3 d = Vec3(dir(rng), dir(rng), dir(rng)).normalized() * (limit * std::exp2(scale(rng)));
    const Vec3 a = on - u(rng) * d, b = a + d;
    REQUIRE((b - a).norm() <= limit);
    std::vector<TriangleIntersection> hits;
    tree.intersect_segment(a, b, hits);
    const auto got = ids_of(hits);
    CHECK(got == brute_segment(s, a, b));
    total += got.size();
  }
  CHECK(total >= 2000);  // each piece crosses the triangle it was drawn through, most of them more
}

// Triangles at x = 2^-k, each 2^-k across, all around the x axis: every SAH cut peels a few off
// the far end, so the tree would get as deep as the soup is long without the median fallback
// below kSahDepth (the traversal stack is fixed-size).
TEST_CASE("a geometrically graded soup keeps the depth bound and the brute-force answers") {
  Soup s;
  const int n = 120;  // 2^-120 is still a normal float: the centroids stay distinct
  for (int k = 0; k < n; ++k) {
    const double x = std::ldexp(1.0, -k);
    const auto base = static_cast<std::uint32_t>(s.vertices.size());
    s.vertices.emplace_back(x, -x, -x);
    s.vertices.emplace_back(x, 2 * x, -x);
    s.vertices.emplace_back(x, -x, 2 * x);
    s.triangles.push_back({base, base + 1, base + 2});
  }
  const AabbTree tree(s.vertices, s.triangles);
  CHECK(tree.depth() > 12);  // deeper than a median split: SAH did cut unevenly
  CHECK(tree.depth() <= AabbTree::kSahDepth + 6 + 1);  // ceil(log2(120 / 4)) = 5 median levels
  std::vector<TriangleIntersection> hits;
  tree.intersect_segment(Vec3(-1, 0, 0), Vec3(2, 0, 0), hits);
  CHECK(ids_of(hits).size() == static_cast<std::size_t>(n));
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> off(-1e-6, 1e-6);
  for (int q = 0; q < 100; ++q) {
    const Vec3 a(-1, off(rng), off(rng)), b(2, off(rng), off(rng));
    hits.clear();
    tree.intersect_segment(a, b, hits);
    CHECK(ids_of(hits) == brute_segment(s, a, b));
  }
}

TEST_CASE("segments exactly through grid edges and vertices lose no triangle") {
  const Soup s = grid_soup(16);
  const AabbTree tree(s.vertices, s.triangles);
  std::mt19937_64 rng(7);
  std::uniform_int_distribution<int> cell(0, 16);
  for (int q = 0; q < 200; ++q) {
    // Vertical segments through a grid vertex, through the middle of a grid edge, along a
    // diagonal edge; and a segment lying in the plane along a grid line.
    const double x = cell(rng), y = cell(rng);
    for (const Vec3& p : {Vec3(x, y, 0), Vec3(x + 0.5, y, 0), Vec3(x + 0.25, y + 0.25, 0)}) {
      std::vector<TriangleIntersection> hits;
      tree.intersect_segment(p + Vec3(0, 0, -1), p + Vec3(0, 0, 2), hits);
      CHECK(ids_of(hits) == brute_segment(s, p + Vec3(0, 0, -1), p + Vec3(0, 0, 2)));
      if (p.x() <= 16 && p.y() <= 16) CHECK_FALSE(hits.empty());
      // Axis-parallel rays: two directions are 0, so the box test rests on its infinities.
      hits.clear();
      tree.intersect_ray(p + Vec3(0, 0, 1), Vec3(0, 0, -1), hits);
      CHECK(ids_of(hits) == brute_ray(s, p + Vec3(0, 0, 1), Vec3(0, 0, -1)));
      if (p.x() <= 16 && p.y() <= 16) CHECK_FALSE(hits.empty());
    }
    // Along the grid's edge x = 0 from x = +0 to x = -0: b - a is -0 there (1 / -0 = -inf).
    const Vec3 a(0.0, y + 0.5, -1), b(-0.0, y + 0.5, 2);
    std::vector<TriangleIntersection> edge_hits;
    tree.intersect_segment(a, b, edge_hits);
    CHECK(ids_of(edge_hits) == brute_segment(s, a, b));
    if (y < 16) CHECK_FALSE(edge_hits.empty());
    std::vector<TriangleIntersection> hits;
    tree.intersect_segment(Vec3(-1, y, 0), Vec3(17, y, 0), hits);
    CHECK(ids_of(hits) == brute_segment(s, Vec3(-1, y, 0), Vec3(17, y, 0)));
  }
  // Through the interior vertex (8, 8): the six triangles around it all report kind vertex.
  std::vector<TriangleIntersection> hits;
  tree.intersect_segment(Vec3(8, 8, -1), Vec3(8, 8, 1), hits);
  CHECK(hits.size() == 6);
  for (const auto& h : hits) CHECK(h.hit.feature.kind == FeatureKind::vertex);
}

// The plane filter of the tree's leaves rejects a triangle when both ends of the segment are
// clearly on one side of its plane. Segments ending on the triangle (within the rounding of a
// barycentric point), or with both ends a few ulps off its plane on the same side, are where a
// filter with too small an error bound would lose a hit: far from the origin, at small scale
// (not below 2^-280, where the exact predicates' own products underflow, predicates.h).
TEST_CASE("the plane filter loses no triangle a segment touches, however close to its plane") {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(0, 1), w(-1, 1);
  std::size_t total = 0;
  for (const double offset : {0.0, 1e6, -3e9})
    for (const double scale : {1.0, 1e-3, 1e-40}) {
      Soup s;
      for (int i = 0; i < 40; ++i) {
        const Vec3 c = Vec3::Constant(offset) + scale * Vec3(u(rng), u(rng), u(rng));
        const auto base = static_cast<std::uint32_t>(s.vertices.size());
        if (i % 2 == 0) {
          for (int k = 0; k < 3; ++k) s.vertices.push_back(c + 0.5 * scale * Vec3(w(rng), w(rng), w(rng)));
        } else {
          // A needle: |u x v| far below |u| |v|, where the error of the normal (the 4 U V term
          // of the bound) dominates that of the dot products.
          const Vec3 d = scale * Vec3(w(rng), w(rng), w(rng));
          const double thin = std::ldexp(1.0, -10 - static_cast<int>(rng() % 30));
          s.vertices.push_back(c);
          s.vertices.push_back(c + d);
          s.vertices.push_back(c + u(rng) * d + thin * scale * Vec3(w(rng), w(rng), w(rng)));
        }
        s.triangles.push_back({base, base + 1, base + 2});
      }
      const AabbTree tree(s.vertices, s.triangles);
      for (int q = 0; q < 300; ++q) {
        const auto& t = s.triangles[static_cast<std::size_t>(rng() % s.triangles.size())];
        const Vec3 &p0 = s.vertices[t[0]], &p1 = s.vertices[t[1]], &p2 = s.vertices[t[2]];
        const double l0 = u(rng), l1 = u(rng) * (1 - l0);
        const Vec3 on = p0 + l0 * (p1 - p0) + l1 * (p2 - p0);  // on the triangle up to rounding
        const Vec3 n = (p1 - p0).cross(p2 - p0).normalized();
        if (!n.allFinite()) continue;
        const Vec3 d = scale * Vec3(w(rng), w(rng), w(rng));
        const double ulps = std::abs(on.cwiseAbs().maxCoeff()) * 0x1p-50;
        const std::array<std::pair<Vec3, Vec3>, 4> segments{{
            {on, on + d},                                  // one end on it
            {on - d, on + d},                              // through it
            {on + ulps * n, on + 3 * ulps * n + 1e-3 * d},  // both a few ulps off, one side
            {on - 2 * ulps * n, on + 2 * ulps * n},        // a few ulps either side
        }};
        for (const auto& [a, b] : segments) {
          std::vector<TriangleIntersection> hits;
          tree.intersect_segment(a, b, hits);
          const auto got = ids_of(hits);
          const auto want = brute_segment(s, a, b);
          CHECK(got == want);
          total += got.size();
        }
      }
    }
  CHECK(total > 3000);  // most of these segments do touch their triangle: not vacuous
}

TEST_CASE("segments touching a triangle only at a vertex find it, whatever the float rounding of the boxes") {
  // Node bounds and each query's reach are rounded outwards to floats; a segment that leaves a
  // triangle's vertex away from the triangle shares exactly one coordinate value with the
  // triangle's box on each axis, so a rounding one float too far inwards, on either box, loses
  // the triangle. Coordinates of every sign and scale, most of them not floats, some beyond the
  // float range or near its smallest normal.
  std::mt19937_64 rng(29);
  std::uniform_real_distribution<double> u(0.5, 1), w(-1, 1);
  std::size_t total = 0;
  for (const double scale : {1.0, 1e-3, 3e-38, 1e12, 1e39, 1e-45})
    for (const double sign : {1.0, -1.0}) {
      Soup s;
      std::vector<Vec3> tips;  // per triangle: its vertex 0 and the outward direction there
      std::vector<Vec3> outward;
      for (int i = 0; i < 60; ++i) {
        const Vec3 v = sign * scale * Vec3(u(rng), u(rng), u(rng));
        // The triangle lies in the box's negative octant from v: v is its largest corner on
        // every axis, so the segment from v into the positive octant touches it at v alone.
        const auto base = static_cast<std::uint32_t>(s.vertices.size());
        s.vertices.push_back(v);
        s.vertices.push_back(v - scale * Vec3(u(rng), 0.1 * u(rng), 0.2 * u(rng)));
        s.vertices.push_back(v - scale * Vec3(0.1 * u(rng), u(rng), 0.3 * u(rng)));
        s.triangles.push_back({base, base + 1, base + 2});
        tips.push_back(v);
        outward.push_back(scale * Vec3(u(rng), u(rng), u(rng)));
      }
      const AabbTree tree(s.vertices, s.triangles);
      for (std::size_t t = 0; t < tips.size(); ++t) {
        const Vec3& a = tips[t];
        const Vec3 b = a + outward[t];
        std::vector<TriangleIntersection> hits;
        tree.intersect_segment(a, b, hits);
        const auto got = ids_of(hits);
        CHECK(got == brute_segment(s, a, b));
        CHECK(std::binary_search(got.begin(), got.end(), static_cast<std::uint32_t>(t)));
        hits.clear();
        tree.intersect_ray(a, outward[t], hits);
        CHECK(ids_of(hits) == brute_ray(s, a, outward[t]));
        total += got.size();
      }
    }
  CHECK(total >= 12 * 60);  // every segment touches at least its own triangle
}

TEST_CASE("closest point equals brute force") {
  std::mt19937_64 rng(99);
  const Soup s = random_soup(rng, 2000, 0.03);
  const AabbTree tree(s.vertices, s.triangles);
  std::uniform_real_distribution<double> u(-0.5, 1.5);
  for (int q = 0; q < 300; ++q) {
    const Vec3 p(u(rng), u(rng), u(rng));
    double best = std::numeric_limits<double>::infinity();
    for (const auto& tri : s.triangles) {
      const auto c = closest_point_on_triangle(p, s.vertices[tri[0]], s.vertices[tri[1]], s.vertices[tri[2]]);
      best = std::min(best, (c.point - p).squaredNorm());
    }
    const auto got = tree.closest_point(p);
    REQUIRE(got.has_value());
    CHECK(got->squared_distance == doctest::Approx(best).epsilon(1e-12));
    CHECK((got->point - p).squaredNorm() == doctest::Approx(got->squared_distance).epsilon(1e-12));
    // A bound above the distance changes nothing; one at or below it leaves no triangle.
    const auto bounded = tree.closest_point(p, 1.01 * got->squared_distance + 1e-300);
    REQUIRE(bounded.has_value());
    CHECK(bounded->triangle == got->triangle);
    CHECK(bounded->squared_distance == got->squared_distance);
    CHECK_FALSE(tree.closest_point(p, 0.99 * got->squared_distance).has_value());
    CHECK_FALSE(tree.closest_point(p, got->squared_distance).has_value());
  }
}

// Fans of needles around a point (the caps of a finely tessellated cylinder) and loose needles:
// every triangle thin, so every query goes through the edge planes. Planes tilted so that no
// coordinate is exact, at scales from 1e-3 to 1e3 (|n| far from 1 both ways); segments through
// the needles' corners, across their edges and from a corner outwards (an end on the edge
// planes through it, up to rounding); points on the fans, where the best distance is ~0 and the
// edge planes skip nearly all of the boxes' triangles. The answers must be the brute force's and,
// to the triangle, those of the same tree without the edge planes.
TEST_CASE("fans and needles: the edge planes lose no triangle and change no closest point") {
  for (const double scale : {1.0, 1e-3, 1e3}) {
    std::mt19937_64 rng(31);
    std::uniform_real_distribution<double> u(0, 1), s(-1, 1);
    Soup soup;
    const auto add_fan = [&](const Vec3& centre, const Vec3& e1, const Vec3& e2, int n) {
      const auto c = static_cast<std::uint32_t>(soup.vertices.size());
      soup.vertices.push_back(centre);
      for (int i = 0; i < n; ++i) {
        const double a = 2 * M_PI * i / n;
        soup.vertices.push_back(centre + std::cos(a) * e1 + std::sin(a) * e2);
      }
      for (int i = 0; i < n; ++i)
        soup.triangles.push_back({c, c + 1 + static_cast<std::uint32_t>(i), c + 1 + static_cast<std::uint32_t>((i + 1) % n)});
    };
    const Vec3 e1 = Vec3(1, 0.3, 0.2).normalized() * 0.4 * scale;
    const Vec3 e2 = Vec3(-0.3, 1, 0.1).cross(e1).cross(e1).normalized() * -0.4 * scale;
    add_fan(Vec3(0.5, 0.5, 0.5) * scale, e1, e2, 1500);
    add_fan(Vec3(0.45, 0.55, 0.52) * scale, Vec3(0.1, 0.2, 0.35) * scale, Vec3(0.3, -0.25, 0.05) * scale, 700);
    for (int i = 0; i < 500; ++i) {
      const Vec3 p = Vec3(u(rng), u(rng), u(rng)) * scale, d = Vec3(s(rng), s(rng), s(rng)).normalized() * 0.3 * scale;
      const Vec3 w = d.cross(Vec3(s(rng), s(rng), s(rng))).normalized() * std::exp2(-4 - 50 * u(rng) * u(rng)) * 0.3 * scale;
      const auto b = static_cast<std::uint32_t>(soup.vertices.size());
      soup.vertices.insert(soup.vertices.end(), {p, p + d, p + 0.5 * d + w});
      soup.triangles.push_back({b, b + 1, b + 2});
    }
    const AabbTree tree(soup.vertices, soup.triangles);
    const AabbTree plain(soup.vertices, soup.triangles, false);
    std::uniform_int_distribution<std::size_t> pick(0, soup.triangles.size() - 1);
    std::size_t total = 0;
    for (int q = 0; q < 2500; ++q) {
      const auto& t = soup.triangles[pick(rng)];
      const Vec3 &p0 = soup.vertices[t[0]], &p1 = soup.vertices[t[1]], &p2 = soup.vertices[t[2]];
      const Vec3 normal = (p1 - p0).cross(p2 - p0).normalized();
      Vec3 on;
      switch (q % 5) {
        case 0: case 4: on = p1; break;              // a corner, exactly
        case 1: on = 0.5 * (p1 + p2); break;         // an edge's midpoint, rounded
        case 2: on = p0 + u(rng) * (p1 - p0) + 0.001 * u(rng) * (p2 - p0); break;  // along the needle
        default: on = p0 + Vec3(s(rng), s(rng), s(rng)) * 0.01 * scale; break;    // near it
      }
      const Vec3 d = (normal + 0.3 * Vec3(s(rng), s(rng), s(rng))) * (0.001 + 0.05 * u(rng)) * scale;
      Vec3 a = on + d, b = on - u(rng) * d;
      if (q % 5 == 4) a = on, b = on + (p1 - 0.5 * (p0 + p2)) * u(rng) + 0.1 * d;  // from the corner, outwards
      std::vector<TriangleIntersection> hits, plain_hits;
      tree.intersect_segment(a, b, hits);
      plain.intersect_segment(a, b, plain_hits);
      const auto got = ids_of(hits);
      CHECK(got == brute_segment(soup, a, b));
      CHECK(got == ids_of(plain_hits));
      total += got.size();
      const Vec3 p = q % 2 == 0 ? on : a;
      double best = std::numeric_limits<double>::infinity();
      for (const auto& tri : soup.triangles) {
        const auto c = closest_point_on_triangle(p, soup.vertices[tri[0]], soup.vertices[tri[1]], soup.vertices[tri[2]]);
        best = std::min(best, (c.point - p).squaredNorm());
      }
      const auto closest = tree.closest_point(p), plain_closest = plain.closest_point(p);
      REQUIRE(closest.has_value());
      REQUIRE(plain_closest.has_value());
      CHECK(closest->squared_distance == best);
      CHECK(closest->triangle == plain_closest->triangle);
    }
    CHECK(total >= 1500);  // most segments cross the needle they were drawn at, many several
  }
}

TEST_CASE("box query equals brute force on bounding boxes") {
  std::mt19937_64 rng(5);
  const Soup s = random_soup(rng, 2000, 0.04);
  const AabbTree tree(s.vertices, s.triangles);
  std::uniform_real_distribution<double> u(0, 1), w(0, 0.3);
  for (int q = 0; q < 100; ++q) {
    Box3 box;
    box.extend(Vec3(u(rng), u(rng), u(rng)));
    box.extend(box.lo + Vec3(w(rng), w(rng), w(rng)));
    std::vector<std::uint32_t> got;
    tree.triangles_in_box(box, got);
    std::sort(got.begin(), got.end());
    std::vector<std::uint32_t> want;
    for (std::uint32_t t = 0; t < s.triangles.size(); ++t) {
      Box3 tb;
      for (auto v : s.triangles[t]) tb.extend(s.vertices[v]);
      if (tb.overlaps(box)) want.push_back(t);
    }
    CHECK(got == want);
  }
}

TEST_CASE("overlapping pairs equal brute force, each pair once") {
  // margin: each box grown by it (the brute force grows them the same way, in double). group:
  // pairs within one group (not kNoGroup) left out, on both sides, and every pair of a triangle
  // of kLeaveOut.
  const auto check = [](const Soup& s, double margin = 0, std::span<const std::uint32_t> group = {}) {
    const AabbTree tree(s.vertices, s.triangles);
    std::vector<std::array<std::uint32_t, 2>> got;
    tree.for_each_overlapping_pair(
        [&](std::uint32_t a, std::uint32_t b) {
          CHECK(a != b);
          got.push_back({std::min(a, b), std::max(a, b)});
        },
        margin, group);
    const std::size_t reported = got.size();
    std::sort(got.begin(), got.end());
    got.erase(std::unique(got.begin(), got.end()), got.end());
    CHECK(got.size() == reported);  // no pair twice
    std::vector<Box3> boxes(s.triangles.size());
    for (std::size_t t = 0; t < s.triangles.size(); ++t) {
      for (auto v : s.triangles[t]) boxes[t].extend(s.vertices[v]);
      boxes[t].lo -= Vec3::Constant(margin);
      boxes[t].hi += Vec3::Constant(margin);
    }
    std::vector<std::array<std::uint32_t, 2>> want;
    for (std::uint32_t a = 0; a < boxes.size(); ++a)
      for (std::uint32_t b = a + 1; b < boxes.size(); ++b)
        if (boxes[a].overlaps(boxes[b]) &&
            (group.empty() || ((group[a] == AabbTree::kNoGroup || group[a] != group[b]) &&
                               group[a] != AabbTree::kLeaveOut && group[b] != AabbTree::kLeaveOut)))
          want.push_back({a, b});
    CHECK(got == want);
    return want.size();
  };
  std::mt19937_64 rng(9);
  CHECK(check(random_soup(rng, 1500, 0.05)) > 500);
  CHECK(check(random_soup(rng, 3, 0.5)) <= 3);
  CHECK(check(grid_soup(20)) > 0);  // boxes touching along grid lines count: closed boxes
  const Soup one = random_soup(rng, 1, 0.1);
  CHECK(check(one) == 0);
  // Grown boxes pair triangles up to twice the margin apart: more pairs, still exactly those.
  const Soup spread = random_soup(rng, 1500, 0.02);
  const std::size_t touching = check(spread);
  CHECK(check(spread, 0.01) > touching + 100);
  CHECK(check(grid_soup(20), 0.6) > check(grid_soup(20)));  // the next ring, 1 apart
  // Groups: spatial ones (whole subtrees of one group are skipped), scattered ones (only leaf
  // pairs), and kNoGroup mixed in; every triangle in one group leaves no pair at all.
  const Soup dense = random_soup(rng, 1500, 0.05);
  std::vector<std::uint32_t> by_region(dense.triangles.size()), scattered(dense.triangles.size()),
      single(dense.triangles.size(), 7);
  for (std::uint32_t t = 0; t < dense.triangles.size(); ++t) {
    by_region[t] = dense.vertices[dense.triangles[t][0]].x() < 0.5 ? 1 : AabbTree::kNoGroup;
    scattered[t] = t % 3 == 0 ? AabbTree::kNoGroup : t % 5;
  }
  const std::size_t all = check(dense);
  CHECK(check(dense, 0, by_region) < all);
  CHECK(check(dense, 0, scattered) < all);
  CHECK(check(dense, 0, single) == 0);
  // Left out: a region (whole subtrees), scattered triangles among groups, all of them.
  std::vector<std::uint32_t> region_out(by_region), scattered_out(scattered),
      all_out(dense.triangles.size(), AabbTree::kLeaveOut);
  for (std::uint32_t t = 0; t < dense.triangles.size(); ++t) {
    if (region_out[t] == 1) region_out[t] = AabbTree::kLeaveOut;
    if (t % 7 == 0) scattered_out[t] = AabbTree::kLeaveOut;
  }
  const std::size_t without_region = check(dense, 0, region_out);
  CHECK(without_region > 0);
  CHECK(without_region < check(dense, 0, by_region));
  CHECK(check(dense, 0, scattered_out) < check(dense, 0, scattered));
  CHECK(check(dense, 0, all_out) == 0);
  CHECK_THROWS_AS(AabbTree(dense.vertices, dense.triangles).for_each_overlapping_pair(
                      [](std::uint32_t, std::uint32_t) {}, 0, std::span<const std::uint32_t>(single).first(10)),
                  std::invalid_argument);
  // A negative or NaN margin counts as 0: no overlapping pair is dropped.
  const AabbTree tree(spread.vertices, spread.triangles);
  for (const double bad : {-0.01, std::numeric_limits<double>::quiet_NaN()}) {
    std::size_t n = 0;
    tree.for_each_overlapping_pair([&](std::uint32_t, std::uint32_t) { ++n; }, bad);
    CHECK(n == touching);
  }
}

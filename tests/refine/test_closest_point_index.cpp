// ClosestPointIndex: fans of thin triangles searched by angle must give the distance the AABB
// tree over all triangles gives, for points anywhere - on the surface, just off it, on a fan's
// axis, at its centre, far away - and on fans of every shape the index may take: flat, conical,
// pleated, wound inconsistently, a saddle, fans sharing triangles, a triangle with a vertex on
// the axis. Without fans it is the tree itself.
#include <doctest/doctest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include <delpsc/kernel/aabb_tree.h>
#include <delpsc/kernel/constructions.h>
#include <delpsc/refine/closest_point_index.h>

using namespace delpsc;
using refine::ClosestPointIndex;
using Triangle = ClosestPointIndex::Triangle;

namespace {

constexpr double kPi = std::numbers::pi;

struct Shape {
  std::vector<Vec3> vertices;
  std::vector<Triangle> triangles;
  std::uint32_t add(const Vec3& p) {
    vertices.push_back(p);
    return static_cast<std::uint32_t>(vertices.size() - 1);
  }
};

// A fan of n triangles around `centre` through the rim points rim(i), i = 0..n-1, closed when
// `closed`; `reverse(i)` flips triangle i's winding.
template <class Rim, class Reverse>
void add_fan(Shape& s, const Vec3& centre, int n, Rim rim, Reverse reverse, bool closed = true) {
  const std::uint32_t c = s.add(centre);
  const std::uint32_t first = static_cast<std::uint32_t>(s.vertices.size());
  for (int i = 0; i < n; ++i) s.add(rim(i));
  for (int i = 0; i + (closed ? 0 : 1) < n; ++i) {
    const std::uint32_t a = first + static_cast<std::uint32_t>(i), b = first + static_cast<std::uint32_t>((i + 1) % n);
    s.triangles.push_back(reverse(i) ? Triangle{c, b, a} : Triangle{c, a, b});
  }
}

Vec3 on_circle(int i, int n, double radius, double z) {
  const double t = 2 * kPi * i / n;
  return {radius * std::cos(t), radius * std::sin(t), z};
}

// The distance each way, and that the index's triangle and point agree with its distance.
void check_against_tree(const Shape& s, std::size_t min_fans, std::uint32_t seed) {
  const kernel::AabbTree tree(s.vertices, s.triangles);
  const ClosestPointIndex index(s.vertices, s.triangles, tree);
  CHECK(index.fan_count() >= min_fans);
  const kernel::Box3 box = tree.bounds();
  const double diagonal = box.diagonal();
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> unit(0, 1);
  std::vector<Vec3> queries;
  for (int i = 0; i < 3000; ++i) {  // on the surface, and just off it
    const Triangle& t = s.triangles[rng() % s.triangles.size()];
    double a = unit(rng), b = unit(rng);
    if (a + b > 1) a = 1 - a, b = 1 - b;
    const Vec3 on = s.vertices[t[0]] + a * (s.vertices[t[1]] - s.vertices[t[0]]) + b * (s.vertices[t[2]] - s.vertices[t[0]]);
    const double off = diagonal * std::pow(10.0, -1 - 5 * unit(rng));
    queries.push_back(on + off * Vec3(unit(rng) - 0.5, unit(rng) - 0.5, unit(rng) - 0.5));
    if (i % 10 == 0) queries.push_back(on);
  }
  for (int i = 0; i < 1000; ++i) {  // anywhere in a box twice the model's
    const Vec3 r(unit(rng), unit(rng), unit(rng));
    queries.push_back(box.lo - 0.5 * (box.hi - box.lo) + 2 * (box.hi - box.lo).cwiseProduct(r));
  }
  for (const Vec3& v : s.vertices) queries.push_back(v);  // every vertex, the centres among them
  for (int i = 0; i < 200; ++i)                              // on and near the z axis
    queries.push_back(Vec3(1e-9 * (unit(rng) - 0.5), 0, (unit(rng) - 0.5) * 2));
  int wrong = 0, inconsistent = 0, bounded_wrong = 0;
  for (const Vec3& p : queries) {
    const auto expected = tree.closest_point(p);
    const auto got = index.closest_point(p);
    REQUIRE(expected.has_value());
    REQUIRE(got.has_value());
    if (std::abs(std::sqrt(got->squared_distance) - std::sqrt(expected->squared_distance)) > 1e-12 * diagonal) ++wrong;
    // Bounded: only a triangle strictly nearer than the bound counts - none below half the
    // distance, the closest one below twice it (or below a tiny bound for a point on the surface).
    const double d2 = expected->squared_distance;
    if (d2 > 0 && index.closest_point(p, 0.5 * d2)) ++bounded_wrong;
    const auto within = index.closest_point(p, d2 > 0 ? 2 * d2 : 1e-300);
    if (!within || std::abs(std::sqrt(within->squared_distance) - std::sqrt(d2)) > 1e-12 * diagonal) ++bounded_wrong;
    const Triangle& t = s.triangles[got->triangle];
    const auto own = kernel::closest_point_on_triangle(p, s.vertices[t[0]], s.vertices[t[1]], s.vertices[t[2]]);
    if ((own.point - got->point).norm() > 1e-12 * diagonal) ++inconsistent;
  }
  CHECK(wrong == 0);
  CHECK(inconsistent == 0);
  CHECK(bounded_wrong == 0);
}

}  // namespace

TEST_CASE("a closed cylinder with caps fanned from their centres: both caps searched by angle") {
  const int n = 400;
  Shape s;
  const auto none = [](int) { return false; };
  add_fan(s, {0, 0, 0}, n, [&](int i) { return on_circle(n - i, n, 1, 0); }, none);  // facing down
  add_fan(s, {0, 0, 1}, n, [&](int i) { return on_circle(i, n, 1, 1); }, none);
  // The side between the two rims (vertices 1..n and n+2..2n+1).
  for (int i = 0; i < n; ++i) {
    const std::uint32_t a = static_cast<std::uint32_t>(1 + (n - i) % n), b = static_cast<std::uint32_t>(1 + (n - i - 1 + n) % n);
    const std::uint32_t c = static_cast<std::uint32_t>(n + 2 + i), d = static_cast<std::uint32_t>(n + 2 + (i + 1) % n);
    s.triangles.push_back({a, b, d});
    s.triangles.push_back({a, d, c});
  }
  check_against_tree(s, 2, 1);
}

TEST_CASE("fans of other shapes: cones, pleats, mixed windings, a saddle, open fans, two fans sharing a strip") {
  const auto none = [](int) { return false; };
  const auto every_other = [](int i) { return i % 2 == 1; };
  SUBCASE("a steep cone and a shallow one, and a cone wound inconsistently") {
    for (const double height : {5.0, 0.05}) {
      Shape s;
      add_fan(s, {0, 0, height}, 300, [](int i) { return on_circle(i, 300, 1, 0); }, none);
      check_against_tree(s, 1, 2);
      Shape mixed;
      add_fan(mixed, {0, 0, height}, 300, [](int i) { return on_circle(i, 300, 1, 0); }, every_other);
      check_against_tree(mixed, 1, 3);
    }
  }
  SUBCASE("a pleated fan (rim up and down) and a monkey saddle") {
    Shape pleats;
    add_fan(pleats, {0, 0, 0}, 256, [](int i) { return on_circle(i, 256, 1, i % 2 ? 0.2 : -0.2); }, none);
    check_against_tree(pleats, 1, 4);
    Shape saddle;
    add_fan(saddle, {0, 0, 0}, 300, [](int i) { return on_circle(i, 300, 1, std::cos(3 * 2 * kPi * i / 300)); }, none);
    check_against_tree(saddle, 1, 5);
  }
  SUBCASE("an open fan (a half disc), and a flat fan wound every other way") {
    Shape half;
    add_fan(half, {0, 0, 0}, 200, [](int i) { return on_circle(i, 398, 1, 0); }, none, false);
    check_against_tree(half, 1, 6);
    Shape flat;
    add_fan(flat, {0, 0, 0}, 200, [](int i) { return on_circle(i, 200, 1, 0); }, every_other);
    check_against_tree(flat, 1, 7);
  }
  SUBCASE("a fan with a rim point high above its centre, and irregular rim radii") {
    Shape s;
    std::mt19937 rng(8);
    std::uniform_real_distribution<double> radius(0.01, 2);
    add_fan(s, {0, 0, 0}, 300, [&](int i) { return i == 17 ? Vec3(0, 0, 1) : on_circle(i, 300, radius(rng), 0); }, none);
    check_against_tree(s, 1, 9);
  }
  SUBCASE("a flat fan with two fins standing on its axis: the fins' directions give no angle") {
    Shape s;
    add_fan(s, {0, 0, 0}, 300, [](int i) { return on_circle(i, 300, 1, 0); }, none);
    // The fins' unit normals, (0, 1, 0) and (0, -1, 0), cancel exactly: the axis stays z, and
    // their top vertex lies on it.
    const std::uint32_t top = s.add({0, 0, 1});
    s.triangles.push_back({0, top, 1});
    s.triangles.push_back({0, top, 151});
    check_against_tree(s, 1, 12);
  }
  SUBCASE("a cone on a disc fanned from a rim point: two side triangles wedge a quarter turn there") {
    Shape s;
    const int n = 300;
    std::vector<std::uint32_t> rim;
    for (int i = 0; i < n; ++i) rim.push_back(s.add(on_circle(i, n, 1, 0)));
    const std::uint32_t apex = s.add({0, 0, 1});
    for (int i = 1; i + 1 < n; ++i)
      s.triangles.push_back({rim[0], rim[static_cast<std::size_t>(i) + 1], rim[static_cast<std::size_t>(i)]});
    for (int i = 0; i < n; ++i)
      s.triangles.push_back({apex, rim[static_cast<std::size_t>(i)], rim[static_cast<std::size_t>((i + 1) % n)]});
    check_against_tree(s, 2, 13);
  }
  SUBCASE("two fans whose centres share triangles (a strip between them)") {
    Shape s;
    const std::uint32_t a = s.add({0, 0, 0}), b = s.add({3, 0, 0});
    std::vector<std::uint32_t> rim;
    for (int i = 0; i < 200; ++i) rim.push_back(s.add(Vec3(1.5, std::cos(kPi * i / 199), std::sin(kPi * i / 199))));
    for (int i = 0; i + 1 < 200; ++i) {
      s.triangles.push_back({a, rim[static_cast<std::size_t>(i)], rim[static_cast<std::size_t>(i) + 1]});
      s.triangles.push_back({b, rim[static_cast<std::size_t>(i) + 1], rim[static_cast<std::size_t>(i)]});
    }
    s.triangles.push_back({a, b, rim[0]});  // in both fans' lists: searched in one
    check_against_tree(s, 2, 10);
  }
}

TEST_CASE("without a vertex of 64 triangles the index is the tree, triangle for triangle") {
  Shape s;
  const auto none = [](int) { return false; };
  add_fan(s, {0, 0, 0}, 63, [](int i) { return on_circle(i, 63, 1, 0); }, none);
  const kernel::AabbTree tree(s.vertices, s.triangles);
  const ClosestPointIndex index(s.vertices, s.triangles, tree);
  CHECK(index.fan_count() == 0);
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-2, 2);
  for (int i = 0; i < 500; ++i) {
    const Vec3 p(u(rng), u(rng), u(rng));
    CHECK(index.closest_point(p)->triangle == tree.closest_point(p)->triangle);
    // The bound passes through to the tree: nothing strictly below the distance itself.
    const double d2 = tree.closest_point(p)->squared_distance;
    CHECK_FALSE(index.closest_point(p, d2).has_value());
    CHECK(index.closest_point(p, 2 * d2 + 1e-300)->triangle == tree.closest_point(p)->triangle);
  }
}

// The sample part (io/sample_part.h): its complex has the corners, curves and patches derived
// by hand in the header, each patch the expected topology, the incidences consistent with the
// mesh (support/complex_checks.h); the solid is closed and consistently oriented, the fin an
// open sheet, and no two triangles cross.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <map>
#include <stdexcept>

#include <delpsc/io/sample_part.h>
#include <delpsc/protect/complex.h>

#include "support/complex_checks.h"
#include "support/problem_lines.h"

using namespace delpsc;
using Topologies = std::vector<std::pair<int, int>>;

namespace {

// Directed-edge counts: in a closed, consistently oriented surface every directed edge appears
// once and its reverse once.
std::map<std::pair<std::uint32_t, std::uint32_t>, int> directed_edges(const io::TriangleSoup& soup) {
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> count;
  for (const auto& t : soup.triangles)
    for (int k = 0; k < 3; ++k) ++count[{t[k], t[(k + 1) % 3]}];
  return count;
}

bool on_fin(const Vec3& p) { return p.z() > 1; }

}  // namespace

TEST_CASE("sample part: 16 corners, 20 curves, 9 patches with the topology of the header") {
  for (int around : {16, 48}) {
    CAPTURE(around);
    const io::TriangleSoup soup = io::make_sample_part(around);
    const protect::Complex c = protect::build_complex(soup);
    CHECK(c.cleanup.zero_area_triangles.empty());
    CHECK(c.cleanup.welded_vertices == 0);  // welded by the generator already
    const auto problems = test::complex_problems(c);
    CHECK_MESSAGE(problems.empty(), test::problem_lines(problems));
    CHECK(c.corner_count() == 16);
    CHECK(c.curve_count() == 20);
    CHECK(c.closed_curve_count() == 4);
    CHECK(c.patch_count() == 9);
    CHECK(c.patches_without_boundary() == 0);
    CHECK(test::non_manifold_curves(c) == 1);
    CHECK(test::patch_topologies(c) ==
          Topologies{{-2, 4}, {-1, 3}, {0, 2}, {0, 2}, {1, 1}, {1, 1}, {1, 1}, {1, 1}, {1, 1}});
  }
}

TEST_CASE("sample part: the block is closed and oriented, the fin an oriented open sheet") {
  const io::TriangleSoup soup = io::make_sample_part(32);
  CHECK(soup.triangles.size() < 20000);
  io::TriangleSoup solid{soup.vertices, {}}, fin{soup.vertices, {}};
  for (const auto& t : soup.triangles)
    (on_fin(soup.vertices[t[0]]) || on_fin(soup.vertices[t[1]]) || on_fin(soup.vertices[t[2]]) ? fin : solid)
        .triangles.push_back(t);
  CHECK(fin.triangles.size() > 0);
  const auto solid_edges = directed_edges(solid);
  for (const auto& [e, n] : solid_edges) {
    CHECK(n == 1);  // no directed edge twice: orientation consistent
    CHECK(solid_edges.count({e.second, e.first}) == 1);  // closed
  }
  const auto fin_edges = directed_edges(fin);
  std::size_t fin_boundary = 0;
  for (const auto& [e, n] : fin_edges) {
    CHECK(n == 1);
    fin_boundary += fin_edges.count({e.second, e.first}) == 0;
  }
  // The fin is a 4 x 2 grid at this resolution (y from 1/2 to 3/2 in steps of 1/4, height 0.6
  // in lround(0.6 * 4) = 2 layers): its outline has 2 (4 + 2) edges.
  CHECK(fin_boundary == 12);
  // The solid's enclosed volume (divergence theorem) is the block minus the holes, positive:
  // outward orientation.
  double volume = 0;
  for (const auto& t : solid.triangles)
    volume += soup.vertices[t[0]].dot(soup.vertices[t[1]].cross(soup.vertices[t[2]])) / 6;
  // The holes are 32-gons: area 32/2 r^2 sin(2 pi / 32).
  const double hole = 16 * 0.45 * 0.45 * std::sin(2 * std::numbers::pi / 32);
  CHECK(volume == doctest::Approx(8 - 2 * hole).epsilon(1e-5));
}

TEST_CASE("sample part: no two triangles cross (all pairs without a shared vertex, by bounding boxes)") {
  const io::TriangleSoup soup = io::make_sample_part(16);
  // Separating-axis test on triangles: for a generated model with no near-misses, a float test
  // is decisive. Pairs sharing a vertex are adjacent in the mesh and skipped.
  auto crosses = [&](const std::array<std::uint32_t, 3>& s, const std::array<std::uint32_t, 3>& t) {
    const Vec3 p[3] = {soup.vertices[s[0]], soup.vertices[s[1]], soup.vertices[s[2]]};
    const Vec3 q[3] = {soup.vertices[t[0]], soup.vertices[t[1]], soup.vertices[t[2]]};
    std::vector<Vec3> axes{(p[1] - p[0]).cross(p[2] - p[0]), (q[1] - q[0]).cross(q[2] - q[0])};
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) axes.push_back((p[(i + 1) % 3] - p[i]).cross(q[(j + 1) % 3] - q[j]));
    for (const Vec3& axis : axes) {
      if (axis.squaredNorm() < 1e-20) continue;
      double plo = 1e300, phi = -1e300, qlo = 1e300, qhi = -1e300;
      for (int i = 0; i < 3; ++i) {
        plo = std::min(plo, axis.dot(p[i])), phi = std::max(phi, axis.dot(p[i]));
        qlo = std::min(qlo, axis.dot(q[i])), qhi = std::max(qhi, axis.dot(q[i]));
      }
      const double tol = 1e-12 * axis.norm();
      if (phi < qlo + tol || qhi < plo + tol) return false;  // separated (touching counts as apart)
    }
    return true;
  };
  std::size_t crossings = 0;
  for (std::size_t i = 0; i < soup.triangles.size(); ++i)
    for (std::size_t j = i + 1; j < soup.triangles.size(); ++j) {
      const auto &s = soup.triangles[i], &t = soup.triangles[j];
      bool share = false;
      for (auto a : s)
        for (auto b : t) share = share || a == b;
      if (!share && crosses(s, t)) ++crossings;
    }
  CHECK(crossings == 0);
}

TEST_CASE("sample part: resolutions that do not fit are refused") {
  CHECK_THROWS_AS(io::make_sample_part(8), std::invalid_argument);
  CHECK_THROWS_AS(io::make_sample_part(24), std::invalid_argument);
}

// The complex of real models from Debian's libcgal-demo (fandisk, part, anchor, joint,
// elephant), fetched by scripts/get-cgal-data.sh into data/cgal-demo/ (absent: see
// tests/support/cgal_demo_data.h). Checked: incidences consistent with the mesh; counts stable under
// renumbering of vertices and triangles, rotation of each triangle's corners and reversal of the
// orientation; and, with features off, one patch per closed surface whose Euler characteristic
// is V - E + F counted independently here.
#include <doctest/doctest.h>

#include <algorithm>
#include <numeric>
#include <random>
#include <set>
#include <sstream>

#include <delpsc/io/read_model.h>
#include <delpsc/protect/complex.h>

#include "support/complex_checks.h"
#include "support/problem_lines.h"
#include "support/cgal_demo_data.h"

using namespace delpsc;
using protect::build_complex;
using protect::Complex;

namespace {

const char* const kModels[] = {"fandisk", "part", "anchor", "joint", "elephant"};

std::optional<io::TriangleSoup> load(const char* name) { return test::cgal_demo_soup(name); }

struct Summary {
  std::size_t corners, curves, closed, patches, without_boundary;
  std::vector<std::pair<int, int>> topologies;
  std::vector<double> curve_lengths;      // sorted
  std::multiset<std::array<double, 3>> rule_corners;  // positions of corners not chosen on loops
  bool operator==(const Summary& o) const {
    if (std::tie(corners, curves, closed, patches, without_boundary, topologies, rule_corners) !=
        std::tie(o.corners, o.curves, o.closed, o.patches, o.without_boundary, o.topologies, o.rule_corners))
      return false;
    for (std::size_t i = 0; i < curve_lengths.size(); ++i)
      if (std::abs(curve_lengths[i] - o.curve_lengths[i]) > 1e-9 * (1 + curve_lengths[i])) return false;
    return curve_lengths.size() == o.curve_lengths.size();
  }
};

Summary summarize(const Complex& c) {
  Summary s{c.corner_count(), c.curve_count(), c.closed_curve_count(), c.patch_count(),
            c.patches_without_boundary(), test::patch_topologies(c), {}, {}};
  for (const auto& curve : c.curves) s.curve_lengths.push_back(curve.length);
  std::sort(s.curve_lengths.begin(), s.curve_lengths.end());
  for (std::uint32_t k = 0; k < c.corner_count(); ++k)
    if (c.corner_flags[k] != protect::kCornerLoop) {
      const Vec3& p = c.vertices[c.corner_vertex[k]];
      s.rule_corners.insert({p.x(), p.y(), p.z()});
    }
  return s;
}

std::string describe(const Summary& s) {
  std::ostringstream o;
  o << "corners=" << s.corners << " curves=" << s.curves << " closed_curves=" << s.closed << " patches=" << s.patches
    << " patches_without_boundary=" << s.without_boundary << " (chi, loops):";
  for (const auto& [chi, loops] : s.topologies) o << " (" << chi << "," << loops << ")";
  return o.str();
}

// The same surface with vertices and triangles renumbered, each triangle's corners rotated and,
// if `reverse`, every triangle's orientation flipped.
io::TriangleSoup shuffled(const io::TriangleSoup& s, std::uint64_t seed, bool reverse) {
  std::mt19937_64 rng(seed);
  std::vector<std::uint32_t> perm(s.vertices.size());
  std::iota(perm.begin(), perm.end(), 0u);
  std::shuffle(perm.begin(), perm.end(), rng);
  io::TriangleSoup out;
  out.vertices.resize(s.vertices.size());
  for (std::size_t v = 0; v < s.vertices.size(); ++v) out.vertices[perm[v]] = s.vertices[v];
  for (auto t : s.triangles) {
    std::array<std::uint32_t, 3> u = {perm[t[0]], perm[t[1]], perm[t[2]]};
    std::rotate(u.begin(), u.begin() + static_cast<long>(rng() % 3), u.end());
    if (reverse) std::swap(u[1], u[2]);
    out.triangles.push_back(u);
  }
  std::shuffle(out.triangles.begin(), out.triangles.end(), rng);
  return out;
}

}  // namespace

TEST_CASE("libcgal-demo models: consistent incidences, counts stable under renumbering") {
  for (const char* name : kModels) {
    const auto soup = load(name);
    if (!soup) continue;
    const std::string model = name;
    CAPTURE(model);
    const Complex c = build_complex(*soup);
    const auto problems = test::complex_problems(c);
    CHECK_MESSAGE(problems.empty(), test::problem_lines(problems));
    const Summary s = summarize(c);
    MESSAGE(std::string(name) << ": " << describe(s));
    CHECK(s.patches >= 1);
    for (const bool reverse : {false, true}) {
      const Complex again = build_complex(shuffled(*soup, 17, reverse));
      CHECK(test::complex_problems(again).empty());
      const Summary t = summarize(again);
      INFO(describe(t));
      CHECK(t == s);
    }
  }
}

TEST_CASE("libcgal-demo models without features: each is one closed surface of the right genus") {
  protect::ComplexOptions no_features;
  no_features.feature_angle_degrees = 180;
  for (const char* name : kModels) {
    const auto soup = load(name);
    if (!soup) continue;
    const std::string model = name;
    CAPTURE(model);
    // V - E + F counted here, independently of the builder's edge table.
    std::set<std::pair<std::uint32_t, std::uint32_t>> edges;
    std::set<std::uint32_t> used;
    for (const auto& t : soup->triangles)
      for (int k = 0; k < 3; ++k) {
        used.insert(t[k]);
        edges.insert(std::minmax(t[k], t[(k + 1) % 3]));
      }
    const long chi = static_cast<long>(used.size()) - static_cast<long>(edges.size()) +
                     static_cast<long>(soup->triangles.size());
    const Complex c = build_complex(*soup, no_features);
    REQUIRE(c.patch_count() == 1);
    CHECK(c.patches[0].euler_characteristic == chi);
    CHECK(c.patches[0].boundary_loops == 0);
    CHECK(c.curve_count() == 0);
    MESSAGE(std::string(name) << ": genus " << (2 - chi) / 2);
  }
}

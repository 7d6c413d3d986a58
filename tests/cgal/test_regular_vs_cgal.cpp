// Cross-check with CGAL's Regular_triangulation_3 (Epick; point index as vertex info): the same
// finite cells, as quadruples of point indices, and the same hidden points, on generic and
// degenerate inputs, after insertion and after removals. Both use the symbolic perturbation of
// Devillers & Teillaud, so the triangulations must be identical, not just both valid.
//
// One documented difference: CGAL drops a point inserted at a vertex's position with an equal
// weight, where we keep it as hidden. Identical weighted points are therefore compared through a
// canonical index (the smallest among them), and CGAL's hidden points are its non-vertices.
#include <doctest/doctest.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Regular_triangulation_3.h>
#include <CGAL/Regular_triangulation_cell_base_3.h>
#include <CGAL/Regular_triangulation_vertex_base_3.h>
#include <CGAL/Triangulation_data_structure_3.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>

#include <algorithm>
#include <map>
#include <utility>
#include <vector>

#include <delpsc/delaunay/regular_triangulation.h>
#include <delpsc/io/point_generators.h>

#include "support/generators.h"
#include "support/triangulation_checks.h"

using namespace delpsc;
using delaunay::PointId;
using delaunay::PointStatus;
using delaunay::RegularTriangulation;

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Vb = CGAL::Triangulation_vertex_base_with_info_3<std::uint32_t, K,
                                                       CGAL::Regular_triangulation_vertex_base_3<K>>;
using Cb = CGAL::Regular_triangulation_cell_base_3<K>;
using Tds = CGAL::Triangulation_data_structure_3<Vb, Cb>;
using CgalRegular = CGAL::Regular_triangulation_3<K, Tds>;

using Key = std::array<double, 4>;

Key key_of(const K::Weighted_point_3& p) {
  return {p.point().x(), p.point().y(), p.point().z(), p.weight()};
}

// Canonical index of each input point: identical weighted points share the smallest index.
std::map<Key, std::uint32_t> canonical_map(const std::vector<WeightedPoint>& pts) {
  std::map<Key, std::uint32_t> first;
  for (std::uint32_t i = 0; i < pts.size(); ++i) first.emplace(Key{pts[i].x, pts[i].y, pts[i].z, pts[i].w}, i);
  return first;
}

std::vector<std::uint32_t> canonical(const std::vector<WeightedPoint>& pts) {
  const auto first = canonical_map(pts);
  std::vector<std::uint32_t> names(pts.size());
  for (std::uint32_t i = 0; i < pts.size(); ++i) names[i] = first.at(Key{pts[i].x, pts[i].y, pts[i].z, pts[i].w});
  return names;
}

struct Snapshot {
  std::vector<test::Quad> cells;
  std::vector<std::uint32_t> vertices;  // canonical indices, sorted, unique
};

// CGAL vertices are named by their weighted point: a hidden point that CGAL re-inserts after a
// removal comes back as a new vertex without its info.
Snapshot snapshot(const CgalRegular& rt, const std::map<Key, std::uint32_t>& name_of) {
  Snapshot s;
  for (auto c = rt.finite_cells_begin(); c != rt.finite_cells_end(); ++c) {
    test::Quad q;
    for (int i = 0; i < 4; ++i) q[i] = name_of.at(key_of(c->vertex(i)->point()));
    std::sort(q.begin(), q.end());
    s.cells.push_back(q);
  }
  std::sort(s.cells.begin(), s.cells.end());
  for (auto v = rt.finite_vertices_begin(); v != rt.finite_vertices_end(); ++v)
    s.vertices.push_back(name_of.at(key_of(v->point())));
  std::sort(s.vertices.begin(), s.vertices.end());
  return s;
}

// `ids[k]` is our PointId of input point k.
Snapshot snapshot(const RegularTriangulation& t, const std::vector<PointId>& ids,
                  const std::vector<std::uint32_t>& names) {
  std::vector<std::uint32_t> ours(t.number_of_points());
  for (std::uint32_t k = 0; k < ids.size(); ++k) ours[ids[k]] = names[k];
  Snapshot s;
  s.cells = test::finite_cell_quads(t, ours);
  s.vertices = test::points_with_status(t, PointStatus::vertex, ours);
  return s;
}

// Builds both, compares, then removes `removals` random vertices from both and compares again.
void compare_with_cgal(const std::vector<WeightedPoint>& pts, std::size_t removals, const char* what_) {
  const std::string what = what_;
  CAPTURE(what);
  CAPTURE(pts.size());
  const auto names = canonical(pts);
  const auto name_of = canonical_map(pts);

  std::vector<std::pair<K::Weighted_point_3, std::uint32_t>> input;
  for (std::uint32_t i = 0; i < pts.size(); ++i)
    input.emplace_back(K::Weighted_point_3(K::Point_3(pts[i].x, pts[i].y, pts[i].z), pts[i].w), i);
  CgalRegular rt(input.begin(), input.end());
  REQUIRE(rt.is_valid());
  for (auto v = rt.finite_vertices_begin(); v != rt.finite_vertices_end(); ++v)
    REQUIRE(names[v->info()] == name_of.at(key_of(v->point())));

  RegularTriangulation t;
  std::vector<PointId> ids;
  t.insert(pts, &ids);
  std::string why;
  REQUIRE_MESSAGE(t.is_valid(&why), why);
  REQUIRE(t.dimension() == rt.dimension());

  auto ours = snapshot(t, ids, names);
  auto theirs = snapshot(rt, name_of);
  CHECK(ours.cells.size() == theirs.cells.size());
  CHECK(ours.cells == theirs.cells);
  CHECK(ours.vertices == theirs.vertices);
  // Hidden = every live point that is not a vertex, up to identical copies.
  std::size_t cgal_hidden = 0;
  for (auto c = rt.finite_cells_begin(); c != rt.finite_cells_end(); ++c)
    cgal_hidden += static_cast<std::size_t>(std::distance(c->hidden_points_begin(), c->hidden_points_end()));
  std::size_t dropped_copies = 0;
  for (std::uint32_t i = 0; i < pts.size(); ++i) dropped_copies += names[i] != i;
  CHECK(t.number_of_hidden() <= cgal_hidden + dropped_copies);
  CHECK(t.number_of_hidden() >= cgal_hidden);

  // Removals: the same random vertices from both.
  std::map<std::uint32_t, CgalRegular::Vertex_handle> cgal_vertex;
  for (auto v = rt.finite_vertices_begin(); v != rt.finite_vertices_end(); ++v) cgal_vertex[name_of.at(key_of(v->point()))] = v;
  std::map<std::uint32_t, PointId> our_vertex;
  for (std::uint32_t k = 0; k < ids.size(); ++k)
    if (t.status(ids[k]) == PointStatus::vertex) our_vertex[names[k]] = ids[k];
  test::Rng rng(pts.size());
  std::size_t done = 0;
  while (done < removals && our_vertex.size() > 8) {
    auto it = our_vertex.begin();
    std::advance(it, static_cast<std::ptrdiff_t>(rng.index(our_vertex.size())));
    const std::uint32_t name = it->first;
    // CGAL dropped the identical copies of this point; forget ours first (removing the vertex
    // would reveal them).
    for (std::uint32_t k = 0; k < ids.size(); ++k)
      if (names[k] == name && t.status(ids[k]) == PointStatus::hidden) REQUIRE(t.remove(ids[k]));
    REQUIRE(t.remove(it->second));
    rt.remove(cgal_vertex.at(name));
    our_vertex.erase(it);
    cgal_vertex.erase(name);
    ++done;
    // Revealed points are vertices now in both; refresh the maps.
    if (done % 50 == 0 || done == removals) {
      for (auto v = rt.finite_vertices_begin(); v != rt.finite_vertices_end(); ++v) cgal_vertex[name_of.at(key_of(v->point()))] = v;
      for (std::uint32_t k = 0; k < ids.size(); ++k)
        if (t.status(ids[k]) == PointStatus::vertex) our_vertex[names[k]] = ids[k];
      REQUIRE(rt.is_valid());
      REQUIRE_MESSAGE(t.is_valid(&why), why);
      ours = snapshot(t, ids, names);
      theirs = snapshot(rt, name_of);
      CHECK(ours.cells == theirs.cells);
      CHECK(ours.vertices == theirs.vertices);
    }
  }
  CHECK(done == removals);
}

}  // namespace

TEST_CASE("same cells as CGAL: generic inputs") {
  compare_with_cgal(io::uniform_points(20000, 1), 200, "uniform");
  compare_with_cgal(io::weighted_points(20000, 0.01 * 0.01, 2), 200, "weighted");
  test::Rng rng(3);
  // Heavy weights: many hidden points, and removals that reveal them.
  compare_with_cgal(test::uniform_points(rng, 5000, 0, 1, 0, 0.004), 300, "heavy weights");
}

TEST_CASE("same cells as CGAL: degenerate inputs") {
  test::Rng rng(4);
  compare_with_cgal(test::grid_points(20, 20, 20), 200, "grid");
  auto lattice = test::lattice_sphere_points(65025);
  compare_with_cgal(lattice, 200, "lattice sphere");
  lattice.push_back({0, 0, 0, 0});
  compare_with_cgal(lattice, 20, "lattice sphere and centre");
  compare_with_cgal(io::sphere_points(10000, 5), 200, "nearly cospherical");
  auto equal = test::grid_points(12, 12, 12);
  test::set_weights(equal, 0.3);
  compare_with_cgal(equal, 200, "grid, equal weights");
  auto mixed = test::grid_points(12, 12, 12);
  for (auto& p : mixed) p.w = static_cast<double>(rng.integer(0, 8)) / 8;
  compare_with_cgal(mixed, 200, "grid, mixed weights");
  const double centre[3] = {5.5, 5.5, 5.5};
  auto ortho = test::grid_points(12, 12, 12);
  REQUIRE(test::set_orthogonal_weights(ortho, centre, 40.0));
  compare_with_cgal(ortho, 200, "orthogonal weights");
}

TEST_CASE("same cells as CGAL: duplicates") {
  test::Rng rng(5);
  auto pts = test::grid_points(10, 10, 10);
  const std::size_t n = pts.size();
  for (std::size_t k = 0; k < n / 2; ++k) {
    auto p = pts[rng.index(n)];
    p.w = rng.chance(0.5) ? p.w : static_cast<double>(rng.integer(1, 4)) / 8;  // copy or heavier/lighter
    pts.push_back(p);
  }
  std::shuffle(pts.begin(), pts.end(), rng.engine());
  compare_with_cgal(pts, 200, "grid with duplicates");
}

// check_restricted_facets (refine/restricted_facets_check.h): it agrees with RestrictedFacets
// kept up to date by update() after every insertion (boundary facets skipped or carried over),
// and it reports the facets left stale when an insertion is not followed by update().
#include <doctest/doctest.h>

#include <algorithm>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include <delpsc/io/shapes.h>
#include <delpsc/refine/initial_sample.h>
#include <delpsc/refine/polygon_domain.h>
#include <delpsc/refine/restricted_facets.h>
#include <delpsc/refine/restricted_facets_check.h>

#include "support/generators.h"
#include "support/problem_lines.h"

using namespace delpsc;

namespace {

// A point on the unit cube's surface: a random face, a random point of it.
Vec3 on_cube(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(0.02, 0.98);
  Vec3 p(u(rng), u(rng), u(rng));
  const auto axis = static_cast<int>(rng() % 3);
  p[axis] = rng() % 2 == 0 ? 0.0 : 1.0;
  return p;
}

// Far frame points, as the mesher uses (their power cells miss the cube); their ids.
std::vector<delaunay::PointId> insert_frame(delaunay::RegularTriangulation& dt) {
  std::vector<delaunay::PointId> frame;
  for (int i = 0; i < 8; ++i)
    frame.push_back(dt.insert(WeightedPoint::from(Vec3(i & 1 ? 4.0 : -3.0, i & 2 ? 4.0 : -3.0, i & 4 ? 4.0 : -3.0))));
  return frame;
}

// `count` insertions on the cube, each followed by update(); every `check_every` (0: never), the
// records are compared with a fresh scan.
void insert_and_follow(delaunay::RegularTriangulation& dt, const refine::Domain& domain,
                       refine::RestrictedFacets& facets, std::mt19937_64& rng, int count, int check_every) {
  delaunay::ChangeSet changes;
  kernel::LargeVector<delaunay::PointId> touched;
  for (int i = 0; i < count; ++i) {
    const delaunay::PointId id = dt.insert(WeightedPoint::from(on_cube(rng)), &changes);
    if (dt.status(id) != delaunay::PointStatus::vertex) continue;
    touched.clear();
    facets.update(changes, touched, id);
    if (check_every > 0 && i % check_every == 0) {
      const auto problems = refine::check_restricted_facets(dt, domain, facets);
      CHECK_MESSAGE(problems.empty(), test::problem_lines(problems));
    }
  }
}

// The frame, then `count` random points of the unit cube's surface.
void sample_cube(delaunay::RegularTriangulation& dt, std::mt19937_64& rng, int count) {
  insert_frame(dt);
  for (int i = 0; i < count; ++i) dt.insert(WeightedPoint::from(on_cube(rng)));
}

}  // namespace

TEST_CASE("restricted facets kept by update() equal a fresh scan; a missed update is caught") {
  const refine::PolygonDomain domain(io::make_cube(2));
  delaunay::RegularTriangulation dt;
  std::mt19937_64 rng(3);
  sample_cube(dt, rng, 60);  // a coarse sample of the surface
  refine::RestrictedFacets facets(dt, domain);
  kernel::LargeVector<delaunay::PointId> touched;
  facets.rebuild(touched);
  REQUIRE(facets.size() > 0);
  CHECK(refine::check_restricted_facets(dt, domain, facets).empty());

  // Insertions followed by update(): the incremental records stay those of a full scan.
  insert_and_follow(dt, domain, facets, rng, 400, 40);
  CHECK(refine::check_restricted_facets(dt, domain, facets).empty());

  // One insertion the records do not follow: the new point's restricted facets are missing.
  delaunay::ChangeSet changes;
  const delaunay::PointId id = dt.insert(WeightedPoint::from(Vec3(0.5, 0.5, 0.0)), &changes);
  REQUIRE(dt.status(id) == delaunay::PointStatus::vertex);
  CHECK_FALSE(refine::check_restricted_facets(dt, domain, facets).empty());
  // ...and the references of the destroyed cells' slots name records of facets that are gone.
  CHECK_FALSE(facets.refs_consistent().empty());
  touched.clear();
  facets.update(changes, touched, id);
  CHECK(facets.refs_consistent().empty());
  CHECK(refine::check_restricted_facets(dt, domain, facets).empty());
}

TEST_CASE("a kept record whose point or size is not the fresh scan's is reported") {
  // The records of a sample of the unit cube, checked against the same cube moved by 1e-4 along
  // x: the same facets stay restricted (their dual edges are far longer), but on the two faces
  // x = 0 and x = 1 the points of V_t ∩ σ move by 1e-4, far beyond the check's rounding slack.
  const refine::PolygonDomain domain(io::make_cube(2));
  io::TriangleSoup moved = io::make_cube(2);
  for (Vec3& v : moved.vertices) v.x() += 1e-4;
  const refine::PolygonDomain shifted(moved);
  delaunay::RegularTriangulation dt;
  std::mt19937_64 rng(11);
  sample_cube(dt, rng, 300);
  refine::RestrictedFacets facets(dt, domain);
  kernel::LargeVector<delaunay::PointId> touched;
  facets.rebuild(touched);
  REQUIRE(facets.size() > 0);
  CHECK(refine::check_restricted_facets(dt, domain, facets).empty());
  const auto problems = refine::check_restricted_facets(dt, shifted, facets, 1000);
  CHECK(std::any_of(problems.begin(), problems.end(),
                    [](const std::string& p) { return p.find("is kept with point") != std::string::npos; }));
}

TEST_CASE("excluded frame points: no facet through them is examined, and the records still equal a fresh scan") {
  const refine::PolygonDomain domain(io::make_cube(2));
  delaunay::RegularTriangulation dt;
  const std::vector<delaunay::PointId> frame = insert_frame(dt);
  std::mt19937_64 rng(5);
  for (int i = 0; i < 200; ++i) dt.insert(WeightedPoint::from(on_cube(rng)));
  refine::RestrictedFacets facets(dt, domain), all(dt, domain);
  facets.exclude_vertices(frame);
  kernel::LargeVector<delaunay::PointId> touched;
  facets.rebuild(touched);
  all.rebuild(touched);
  REQUIRE(facets.size() > 0);
  // The frame's facets are skipped (every sample point of the cube is a hull point, so there are
  // many), and since the frame's power cells miss the cube that loses nothing.
  CHECK(facets.queries() + 100 < all.queries());
  CHECK(facets.size() == all.size());
  CHECK(refine::check_restricted_facets(dt, domain, facets).empty());
  insert_and_follow(dt, domain, facets, rng, 200, 0);
  CHECK(refine::check_restricted_facets(dt, domain, facets).empty());

  // Excluding a point on the surface does drop its restricted facets, and the check sees it.
  refine::RestrictedFacets wrong(dt, domain);
  const delaunay::PointId on_surface = frame.back() + 1;
  REQUIRE(dt.status(on_surface) == delaunay::PointStatus::vertex);
  const std::vector<delaunay::PointId> one{on_surface};
  wrong.exclude_vertices(one);
  wrong.rebuild(touched);
  CHECK(wrong.incident(on_surface).empty());
  CHECK_FALSE(refine::check_restricted_facets(dt, domain, wrong).empty());

  // A stray id is refused, not taken as a table size.
  const std::vector<delaunay::PointId> stray{delaunay::kNoPoint};
  CHECK_THROWS_AS(wrong.exclude_vertices(stray), std::invalid_argument);
}

TEST_CASE("rebuild with the initial sample's proven cover skips most queries and loses no restricted facet") {
  // The mesher's start: the frame, balls (on the cube's edges, model 2), then the sample chosen
  // from the candidates (lattice, random points, net), whose reach sample_cover_power proves.
  for (const int model : {0, 1, 2}) {
    const refine::PolygonDomain domain(model == 1 ? io::make_sphere(12) : io::make_cube(2));
    CAPTURE(model);
    const double spacing = 0.08, radius = model == 2 ? 0.6 * spacing : 0;
    const std::vector<WeightedPoint> balls =
        model == 2 ? test::unit_cube_edge_balls(spacing, radius) : std::vector<WeightedPoint>{};
    kernel::LargeVector<Vec3> points;
    kernel::LargeVector<std::uint32_t> patches;
    const refine::CandidateParts parts = domain.surface_candidates(spacing, 1u << 30, points, patches);
    bool decided = false;
    const auto chosen = refine::select_sample(points, parts, balls, {}, spacing, {}, &decided);
    REQUIRE(decided);
    delaunay::RegularTriangulation dt;
    const std::vector<delaunay::PointId> frame = insert_frame(dt);
    std::vector<WeightedPoint> sample(balls);
    for (const std::uint32_t i : chosen) sample.push_back(WeightedPoint::from(points[i]));
    dt.insert(sample);
    const double bound =
        refine::sample_cover_power(refine::kGapFillSpacing * spacing, parts.net_radius, radius, refine::kBallClearance);
    refine::RestrictedFacets culled(dt, domain), all(dt, domain);
    culled.exclude_vertices(frame);
    all.exclude_vertices(frame);
    kernel::LargeVector<delaunay::PointId> touched;
    culled.rebuild(touched, {}, bound);
    all.rebuild(touched);
    REQUIRE(all.size() > 0);
    CHECK(culled.size() == all.size());
    CHECK(culled.queries() * 5 < all.queries() * 4);  // ~27% fewer on these small models, ~75% on the CGAL demo models
    for (const auto& p : refine::check_restricted_facets(dt, domain, culled)) FAIL_CHECK(p);
    // The records stay right as points are added (carried-over outcomes included), and the
    // updates go on skipping by the bound: insertions only bring every point nearer a vertex.
    std::mt19937_64 rng(7);
    const std::size_t skipped_by_rebuild = culled.skipped();
    if (model == 0) {
      insert_and_follow(dt, domain, culled, rng, 100, 0);
      CHECK(culled.skipped() > skipped_by_rebuild);
    }
    for (const auto& p : refine::check_restricted_facets(dt, domain, culled)) FAIL_CHECK(p);
    if (model == 0) {
      // Removing the sample points of a corner opens a hole the bound does not cover: from the
      // first removal on, update() queries without it, and no restricted facet is lost.
      delaunay::ChangeSet changes;
      const std::size_t skipped_before = culled.skipped();
      int removed = 0;
      for (delaunay::PointId v = frame.back() + 1; v < dt.number_of_points(); ++v) {
        if (dt.status(v) != delaunay::PointStatus::vertex || (dt.point(v).point() - Vec3(1, 1, 1)).norm() > 0.5) continue;
        REQUIRE(dt.remove(v, &changes));
        touched.clear();
        culled.update(changes, touched, delaunay::kNoPoint);
        const std::string refs = culled.refs_consistent();  // no stale reference left for the next update
        CHECK_MESSAGE(refs.empty(), refs);
        ++removed;
      }
      REQUIRE(removed > 20);
      CHECK(culled.skipped() == skipped_before);
      for (const auto& p : refine::check_restricted_facets(dt, domain, culled)) FAIL_CHECK(p);
      insert_and_follow(dt, domain, culled, rng, 50, 0);
      CHECK(culled.skipped() == skipped_before);
      for (const auto& p : refine::check_restricted_facets(dt, domain, culled)) FAIL_CHECK(p);
    }

    // A bound below what the sample reaches drops restricted facets, and the check sees it.
    refine::RestrictedFacets wrong(dt, domain);
    wrong.exclude_vertices(frame);
    wrong.rebuild(touched, {}, 0.3 * spacing * spacing);
    CHECK_FALSE(refine::check_restricted_facets(dt, domain, wrong).empty());
  }
}

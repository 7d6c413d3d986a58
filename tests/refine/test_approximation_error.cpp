// The sampled distances between an output mesh and its input (refine/approximation_error.h), on
// outputs whose distance is known: the input itself (0), the input moved by a known vector, a
// cube with a face missing (the face's centre is half a side from the rest), a feature curve
// moved off its place, lost or mislabelled; the bracket d_s <= d <= d_s + h; bad arguments; and
// meshes made by the mesher, whose distances the size λ bounds.
#include <doctest/doctest.h>

#include <random>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <span>
#include <stdexcept>

#include <delpsc/io/shapes.h>
#include <delpsc/kernel/constructions.h>
#include <delpsc/protect/protect.h>
#include <delpsc/refine/approximation_error.h>
#include <delpsc/refine/mesher.h>
#include <delpsc/refine/polygon_domain.h>
#include <delpsc/refine/protected_balls.h>
#include <delpsc/refine/triangle_samples.h>

using namespace delpsc;
using refine::ApproximationError;
using refine::PolygonDomain;

namespace {

constexpr double kTiny = 1e-12;  // rounding of closest points on unit-sized models

/// The input's own triangles, patches, feature edges (labelled by curve) and corners, as the
/// mesher would write them: the output that approximates the input perfectly.
io::SurfaceMesh mesh_of(const protect::Complex& c) {
  io::SurfaceMesh m;
  m.vertices.assign(c.vertices.begin(), c.vertices.end());
  m.triangles.assign(c.triangles.begin(), c.triangles.end());
  for (const auto p : c.triangle_patch) m.triangle_patch.push_back(static_cast<std::int32_t>(p));
  for (std::size_t e = 0; e < c.edges.size(); ++e)
    if (c.edge_curve[e] != protect::kNoIndex) {
      m.edges.push_back(c.edges[e]);
      m.edge_curve.push_back(static_cast<std::int32_t>(c.edge_curve[e]));
    }
  m.corners.assign(c.corner_vertex.begin(), c.corner_vertex.end());
  return m;
}

ApproximationError measure(const io::SurfaceMesh& out, const PolygonDomain& in, double h) {
  refine::ApproximationOptions o;
  o.sample_spacing = h;
  return refine::measure_approximation(out, in, o);
}

/// Moves every vertex of `m` by d (a fresh copy of the vertices; indices unchanged).
io::SurfaceMesh translated(io::SurfaceMesh m, const Vec3& d) {
  for (auto& v : m.vertices) v += d;
  return m;
}

}  // namespace

TEST_CASE("the input itself is at distance 0, surface and features") {
  const PolygonDomain cube(io::make_cube(4));
  const ApproximationError e = measure(mesh_of(cube.complex()), cube, 0.05);
  CHECK(e.hausdorff() <= kTiny);
  CHECK(e.feature_distance() <= kTiny);
  CHECK(e.diagonal == doctest::Approx(std::sqrt(3.0)));
  CHECK(e.curves.size() == 12);
  for (const auto& c : e.curves) CHECK(c.output_edges == 4);
  CHECK(e.unlabelled_edges == 0);
  // Spacing 0.05 on 1 x 1 faces: hundreds of samples per face, each way.
  CHECK(e.output_to_input.samples > 6 * 200);
  CHECK(e.input_to_output.samples == e.output_to_input.samples);
}

TEST_CASE("a sheet moved along its normal by d is at distance |d| both ways") {
  const PolygonDomain sheet(io::make_square_sheet(4));
  const double d = 0.03;
  const ApproximationError e = measure(translated(mesh_of(sheet.complex()), Vec3(0, 0, d)), sheet, 0.1);
  CHECK(e.output_to_input.distance == doctest::Approx(d).epsilon(kTiny));
  CHECK(e.input_to_output.distance == doctest::Approx(d).epsilon(kTiny));
  CHECK(e.hausdorff() == doctest::Approx(d).epsilon(kTiny));
  CHECK(e.relative(e.hausdorff()) == doctest::Approx(d / std::sqrt(2.0)).epsilon(kTiny));
  // The boundary curves moved with it.
  CHECK(e.feature_distance() == doctest::Approx(d).epsilon(kTiny));
}

TEST_CASE("a sheet moved within its plane: the part that left is as far as the move") {
  const PolygonDomain sheet(io::make_square_sheet(4));
  const ApproximationError e = measure(translated(mesh_of(sheet.complex()), Vec3(0.1, 0, 0)), sheet, 0.02);
  CHECK(e.output_to_input.distance == doctest::Approx(0.1).epsilon(kTiny));
  CHECK(e.input_to_output.distance == doctest::Approx(0.1).epsilon(kTiny));
  // The two curves along the move slide along themselves: only their ends stick out, by 0.1. The
  // two across it move by 0.1 sideways.
  CHECK(e.feature_distance() == doctest::Approx(0.1).epsilon(kTiny));
}

TEST_CASE("a cube without its top face: input to output half a side, output to input 0") {
  const PolygonDomain cube(io::make_cube(4));
  io::SurfaceMesh open = mesh_of(cube.complex());
  io::SurfaceMesh kept = open;
  kept.triangles.clear();
  kept.triangle_patch.clear();
  for (std::size_t t = 0; t < open.triangles.size(); ++t) {
    const auto& tri = open.triangles[t];
    const bool top = open.vertices[tri[0]].z() == 1 && open.vertices[tri[1]].z() == 1 && open.vertices[tri[2]].z() == 1;
    if (top) continue;
    kept.triangles.push_back(tri);
    kept.triangle_patch.push_back(open.triangle_patch[t]);
  }
  REQUIRE(kept.triangles.size() == open.triangles.size() - 32);
  const ApproximationError e = measure(kept, cube, 0.05);
  CHECK(e.output_to_input.distance <= kTiny);
  // The centre of the top face (a vertex of make_cube(4), so sampled) is 0.5 from the side faces.
  CHECK(e.input_to_output.distance == doctest::Approx(0.5).epsilon(kTiny));
  CHECK((e.input_to_output.where - Vec3(0.5, 0.5, 1)).norm() <= kTiny);
  CHECK(e.hausdorff() == doctest::Approx(0.5).epsilon(kTiny));
  // The feature edges are all still there.
  CHECK(e.feature_distance() <= kTiny);
}

TEST_CASE("the sampled distance is within h below the true one, and reaches it as h shrinks") {
  // make_cube(1): the top face is two triangles; with h = 0.3 (n = 5 on the diagonal) the face
  // centre is not a sample, with h = 0.25 (n = 6) it is.
  const PolygonDomain cube(io::make_cube(1));
  io::SurfaceMesh m = mesh_of(cube.complex());
  std::erase_if(m.triangles, [&](const auto& t) {
    return m.vertices[t[0]].z() == 1 && m.vertices[t[1]].z() == 1 && m.vertices[t[2]].z() == 1;
  });
  m.triangle_patch.clear();
  for (const double h : {0.7, 0.3, 0.1}) {
    const double d = measure(m, cube, h).input_to_output.distance;
    INFO("h=" << h << " d=" << d);
    CHECK(d <= 0.5 + kTiny);
    CHECK(d >= 0.5 - h);
    CHECK(d < 0.5 - kTiny);
  }
  CHECK(measure(m, cube, 0.25).input_to_output.distance == doctest::Approx(0.5).epsilon(kTiny));
}

TEST_CASE("the farthest point inside a triangle: sampled within h, and by the grid's interior points") {
  // Input: one right triangle. Output: its three corner triangles of the midpoint subdivision,
  // which cover the input's boundary: the farthest input point is the incentre of the middle
  // (medial) triangle, at its inradius r = (1/2 + 1/2 - sqrt(2)/2) / 2 from the output.
  io::TriangleSoup soup;
  soup.vertices = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)};
  soup.triangles = {{0, 1, 2}};
  const PolygonDomain triangle(soup);
  io::SurfaceMesh corners;
  corners.vertices = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0.5, 0, 0), Vec3(0.5, 0.5, 0), Vec3(0, 0.5, 0)};
  corners.triangles = {{0, 3, 5}, {3, 1, 4}, {5, 4, 2}};
  const double r = (1 - std::sqrt(0.5)) / 2;
  for (const double h : {0.3, 0.1, 0.03, 0.01}) {
    const ApproximationError e = measure(corners, triangle, h);
    INFO("h=" << h << " d=" << e.input_to_output.distance);
    CHECK(e.input_to_output.distance <= r + kTiny);
    CHECK(e.input_to_output.distance >= r - h);
    CHECK(e.output_to_input.distance <= kTiny);
  }
  // h = 0.3: rows parallel to the hypotenuse, 3 of them (height sqrt(2)/2 over a step of at most
  // 0.26); row 1, on x + y = 2/3, is cut into 4 pieces whose middle point (1/3, 1/3) lies in the
  // medial triangle at (2/3 - 1/2) / sqrt(2) from its hypotenuse; every other sample is covered.
  CHECK(measure(corners, triangle, 0.3).input_to_output.distance ==
        doctest::Approx((2.0 / 3 - 0.5) / std::sqrt(2.0)).epsilon(kTiny));
  // h = 0.5: two rows; the inner one, x + y = 1/2, lies on the corner triangles' edge: all covered.
  CHECK(measure(corners, triangle, 0.5).input_to_output.distance <= kTiny);
  // h larger than the triangle: the corners alone, covered.
  CHECK(measure(corners, triangle, 2).input_to_output.distance <= kTiny);
}

namespace {

using Triangles = std::span<const std::array<std::uint32_t, 3>>;

/// The documented surface sampling of A (each used vertex, each triangle's triangle_samples),
/// every sample measured against every triangle of B.
double brute_force_distance(std::span<const Vec3> av, Triangles a, std::span<const Vec3> bv,
                            Triangles b, double h) {
  double largest = 0;
  const auto measure_sample = [&](const Vec3& p) {
    double best = std::numeric_limits<double>::infinity();
    for (const auto& t : b)
      best = std::min(best, (kernel::closest_point_on_triangle(p, bv[t[0]], bv[t[1]], bv[t[2]]).point - p).norm());
    largest = std::max(largest, best);
  };
  kernel::LargeVector<Vec3> samples;
  for (const auto& t : a) {
    samples.assign({av[t[0]], av[t[1]], av[t[2]]});
    refine::triangle_samples(av[t[0]], av[t[1]], av[t[2]], h, samples);
    for (const Vec3& p : samples) measure_sample(p);
  }
  return largest;
}

}  // namespace

TEST_CASE("triangle_samples: every point within h of a sample or corner, ~area / h² of them") {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1, 1);
  std::uniform_real_distribution<double> unit(0, 1);
  kernel::LargeVector<Vec3> samples;
  for (int round = 0; round < 300; ++round) {
    Vec3 a(u(rng), u(rng), u(rng)), b(u(rng), u(rng), u(rng)), c(u(rng), u(rng), u(rng));
    if (round % 3 == 0) c = a + (b - a) * unit(rng) + Vec3(u(rng), u(rng), u(rng)) * 1e-3;  // a needle
    const double h = 0.02 + 0.3 * unit(rng);
    samples.assign({a, b, c});
    refine::triangle_samples(a, b, c, h, samples);
    // The count without the points agrees (the initial sample's net budgets with it).
    CHECK(refine::triangle_sample_count(a, b, c, h) == static_cast<double>(samples.size() - 3));
    const double area = 0.5 * (b - a).cross(c - a).norm();
    const double perimeter = (b - a).norm() + (c - b).norm() + (a - c).norm();
    INFO("round " << round << " h=" << h << " area=" << area << " samples=" << samples.size());
    // Rows (sqrt(3)/2) h apart cut into pieces <= h: about 1.15 area / h² inside, plus the ends.
    CHECK(static_cast<double>(samples.size()) <= 1.2 * area / (h * h) + 3 * perimeter / h + 8);
    for (int k = 0; k < 200; ++k) {
      const double s = std::sqrt(unit(rng)), r = unit(rng);
      const Vec3 p = (1 - s) * a + s * (1 - r) * b + s * r * c;
      double nearest = std::numeric_limits<double>::infinity();
      for (const Vec3& q : samples) nearest = std::min(nearest, (q - p).norm());
      CHECK(nearest <= h * (1 + 1e-12));
    }
  }
  samples.clear();
  refine::triangle_samples(Vec3(0, 0, 0), Vec3(0, 0, 0), Vec3(0, 0, 0), 0.1, samples);
  CHECK(samples.empty());
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  refine::triangle_samples(Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, nan, 0), 0.1, samples);
  refine::triangle_samples(Vec3(0, 0, 0), Vec3(inf, 0, 0), Vec3(0, 1, 0), 0.1, samples);
  refine::triangle_samples(Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), nan, samples);
  refine::triangle_samples(Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), inf, samples);
  CHECK(samples.empty());
  CHECK(refine::triangle_sample_count(Vec3(0, 0, 0), Vec3(0, 0, 0), Vec3(0, 0, 0), 0.1) == 0);
  CHECK(refine::triangle_sample_count(Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, nan, 0), 0.1) == 0);
  CHECK(refine::triangle_sample_count(Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), nan) == 0);
  // A needle 1e30 pieces long: counted in one row's time, not made.
  CHECK(refine::triangle_sample_count(Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0.5, 1e-31, 0), 1e-30) ==
        doctest::Approx(1e30).epsilon(1e-9));
}

TEST_CASE("the walk and the tree find what measuring every sample against every triangle finds") {
  // A sphere whose vertices are pushed in or out by a deterministic pseudo-random amount up to
  // 0.03: the largest distances are at scattered places, each way.
  const PolygonDomain sphere(io::make_sphere(4));
  io::SurfaceMesh bumpy = mesh_of(sphere.complex());
  for (std::size_t v = 0; v < bumpy.vertices.size(); ++v) {
    const double bump = 0.03 * std::sin(12.9898 * static_cast<double>(v) + 78.233);
    bumpy.vertices[v] *= 1 + bump;
  }
  for (const double h : {0.3, 0.07}) {
    const ApproximationError e = measure(bumpy, sphere, h);
    const auto& in = sphere.complex();
    const double out_in = brute_force_distance(bumpy.vertices, bumpy.triangles, in.vertices, in.triangles, h);
    const double in_out = brute_force_distance(in.vertices, in.triangles, bumpy.vertices, bumpy.triangles, h);
    INFO("h=" << h << " out->in " << out_in << " in->out " << in_out);
    CHECK(out_in > 0.01);
    CHECK(e.output_to_input.distance == doctest::Approx(out_in).epsilon(kTiny));
    CHECK(e.input_to_output.distance == doctest::Approx(in_out).epsilon(kTiny));
  }
}

TEST_CASE("the walk and the tree agree with every sample measured on a fan of thin triangles") {
  // A disc fanned from its centre into 600 triangles, and a copy whose rim goes up and down by
  // a pseudo-random 0.01: near the centre consecutive samples lie many triangles apart, the
  // walk goes far, and the tree is slow there (all the thin triangles' boxes overlap).
  constexpr std::uint32_t kRim = 600;
  io::TriangleSoup soup;
  soup.vertices.emplace_back(0, 0, 0);
  for (std::uint32_t i = 0; i < kRim; ++i)
    soup.vertices.emplace_back(std::cos(2 * M_PI * i / kRim), std::sin(2 * M_PI * i / kRim), 0);
  for (std::uint32_t i = 0; i < kRim; ++i) soup.triangles.push_back({0, 1 + i, 1 + (i + 1) % kRim});
  const PolygonDomain disc(protect::build_complex(soup));
  io::SurfaceMesh wavy = mesh_of(disc.complex());
  for (std::size_t v = 0; v < wavy.vertices.size(); ++v)
    if (wavy.vertices[v].squaredNorm() > 0.5) wavy.vertices[v].z() = 0.01 * std::sin(12.9898 * static_cast<double>(v) + 78.233);
  const double h = 0.05;
  const ApproximationError e = measure(wavy, disc, h);
  const auto& in = disc.complex();
  const double out_in = brute_force_distance(wavy.vertices, wavy.triangles, in.vertices, in.triangles, h);
  const double in_out = brute_force_distance(in.vertices, in.triangles, wavy.vertices, wavy.triangles, h);
  INFO("out->in " << out_in << " in->out " << in_out);
  CHECK(out_in > 0.005);
  CHECK(e.output_to_input.distance == doctest::Approx(out_in).epsilon(kTiny));
  CHECK(e.input_to_output.distance == doctest::Approx(in_out).epsilon(kTiny));
}

TEST_CASE("features: chords skipping every other vertex of a polygonal rim") {
  // The capped cylinder's rims are regular 24-gons. Replace one rim's edges by chords A-C over
  // every second vertex B: the input vertex B is the sag s = |B - M| from the chord (M its
  // midpoint), and the chord's midpoint M is s |AM| / |AB| from the polyline (a point inside an
  // edge, found only by sampling the edge's interior).
  const PolygonDomain cylinder(io::make_capped_cylinder(1, 2, 24, 8, 4));
  const protect::Complex& c = cylinder.complex();
  io::SurfaceMesh m = mesh_of(c);
  const std::uint32_t rim = 0;
  const auto polyline = c.curve_polyline(rim);
  REQUIRE(polyline.size() == 25);
  io::SurfaceMesh chords = m;
  chords.edges.clear();
  chords.edge_curve.clear();
  for (std::size_t e = 0; e < m.edges.size(); ++e)
    if (m.edge_curve[e] != static_cast<std::int32_t>(rim)) {
      chords.edges.push_back(m.edges[e]);
      chords.edge_curve.push_back(m.edge_curve[e]);
    }
  for (std::size_t i = 0; i + 2 < polyline.size(); i += 2) {
    chords.edges.push_back({polyline[i], polyline[i + 2]});
    chords.edge_curve.push_back(static_cast<std::int32_t>(rim));
  }
  const Vec3 &a = c.vertices[polyline[0]], &b = c.vertices[polyline[1]], &cc = c.vertices[polyline[2]];
  const Vec3 mid = (a + cc) / 2;
  const double sag = (b - mid).norm();
  const double chord_to_polyline = sag * (mid - a).norm() / (b - a).norm();
  // h = 0.1 cuts each chord (length 2 sin 15°) into 6 pieces: its midpoint is a sample.
  const ApproximationError e = measure(chords, cylinder, 0.1);
  CHECK(e.hausdorff() <= kTiny);
  CHECK(e.curves[rim].input_to_output.distance == doctest::Approx(sag).epsilon(1e-9));
  CHECK(e.curves[rim].output_to_input.distance == doctest::Approx(chord_to_polyline).epsilon(1e-9));
  CHECK(e.curves[rim].output_edges == 12);
  CHECK(e.feature_distance() == doctest::Approx(sag).epsilon(1e-9));
}

TEST_CASE("features: a curve moved sideways, a curve lost, an edge with a foreign label") {
  const PolygonDomain cube(io::make_cube(4));
  const io::SurfaceMesh exact = mesh_of(cube.complex());
  // The curve along x at y = z = 0, moved by (0, -0.02, -0.01): perpendicular to it, so every
  // sample on either side is at exactly that distance from the other.
  std::uint32_t curve = protect::kNoIndex;
  for (std::uint32_t c = 0; c < cube.complex().curve_count(); ++c) {
    const Vec3 mid = cube.complex().point_at(c, 0.5 * cube.complex().curves[c].length);
    if ((mid - Vec3(0.5, 0, 0)).norm() < kTiny) curve = c;
  }
  REQUIRE(curve != protect::kNoIndex);
  const Vec3 offset(0, -0.02, -0.01);

  SUBCASE("moved") {
    io::SurfaceMesh m = exact;
    for (std::size_t e = 0; e < m.edges.size(); ++e) {
      if (m.edge_curve[e] != static_cast<std::int32_t>(curve)) continue;
      for (auto& v : m.edges[e]) {
        m.vertices.push_back(m.vertices[v] + offset);  // a copy: the surface keeps its place
        v = static_cast<std::uint32_t>(m.vertices.size() - 1);
      }
    }
    const ApproximationError e = measure(m, cube, 0.03);
    CHECK(e.hausdorff() <= kTiny);
    CHECK(e.curves[curve].input_to_output.distance == doctest::Approx(offset.norm()).epsilon(kTiny));
    CHECK(e.curves[curve].output_to_input.distance == doctest::Approx(offset.norm()).epsilon(kTiny));
    CHECK(e.feature_distance() == doctest::Approx(offset.norm()).epsilon(kTiny));
    for (const auto& c : e.curves)
      if (c.curve != curve) CHECK(std::max(c.input_to_output.distance, c.output_to_input.distance) <= kTiny);
  }
  SUBCASE("lost") {
    io::SurfaceMesh m;
    m.vertices = exact.vertices;
    m.triangles = exact.triangles;
    for (std::size_t e = 0; e < exact.edges.size(); ++e)
      if (exact.edge_curve[e] != static_cast<std::int32_t>(curve)) {
        m.edges.push_back(exact.edges[e]);
        m.edge_curve.push_back(exact.edge_curve[e]);
      }
    const ApproximationError e = measure(m, cube, 0.03);
    CHECK(e.curves[curve].output_edges == 0);
    CHECK(std::isinf(e.curves[curve].input_to_output.distance));
    CHECK(std::isinf(e.feature_distance()));
    CHECK(e.feature_output_to_input.distance <= kTiny);
  }
  SUBCASE("labelled with a curve the input does not have, or not labelled") {
    io::SurfaceMesh m = exact;
    m.edge_curve[0] = 99;
    ApproximationError e = measure(m, cube, 0.03);
    CHECK(e.unlabelled_edges == 1);
    CHECK(std::isinf(e.feature_output_to_input.distance));
    m.edge_curve.clear();
    e = measure(m, cube, 0.03);
    CHECK(e.unlabelled_edges == m.edges.size());
    CHECK(std::isinf(e.feature_distance()));
  }
}

TEST_CASE("empty sides and bad arguments") {
  const PolygonDomain cube(io::make_cube(2));
  io::SurfaceMesh none;
  ApproximationError e = measure(none, cube, 0.1);
  CHECK(e.output_to_input.samples == 0);
  CHECK(std::isinf(e.input_to_output.distance));
  CHECK(std::isinf(e.feature_distance()));  // every curve lost

  io::SurfaceMesh m = mesh_of(cube.complex());
  CHECK_THROWS_AS(measure(m, cube, 0), std::invalid_argument);
  CHECK_THROWS_AS(measure(m, cube, -1), std::invalid_argument);
  CHECK_THROWS_AS(measure(m, cube, std::numeric_limits<double>::quiet_NaN()), std::invalid_argument);
  CHECK_THROWS_AS(measure(m, cube, std::numeric_limits<double>::infinity()), std::invalid_argument);
  io::SurfaceMesh bad = m;
  bad.triangles[3][1] = static_cast<std::uint32_t>(bad.vertices.size());
  CHECK_THROWS_AS(measure(bad, cube, 0.1), std::invalid_argument);
  bad = m;
  bad.edges[0][0] = 1u << 30;
  CHECK_THROWS_AS(measure(bad, cube, 0.1), std::invalid_argument);
  bad = m;
  bad.edge_curve.pop_back();
  CHECK_THROWS_AS(measure(bad, cube, 0.1), std::invalid_argument);
  bad = m;
  bad.vertices[2].y() = std::numeric_limits<double>::quiet_NaN();
  CHECK_THROWS_AS(measure(bad, cube, 0.1), std::invalid_argument);
}

TEST_CASE("a stop ends the measurement early, on both threads, and never changes a finished one") {
  const PolygonDomain cube(io::make_cube(4));
  const io::SurfaceMesh moved = translated(mesh_of(cube.complex()), Vec3(0, 0, 0.01));
  // ~280,000 samples each way at h = 0.005: dozens of polls on each thread.
  refine::ApproximationOptions o;
  o.sample_spacing = 0.005;
  const ApproximationError full = refine::measure_approximation(moved, cube, o);
  REQUIRE(full.output_to_input.samples > 20 * 4096);
  CHECK_FALSE(full.stopped);

  std::atomic<int> calls{0};
  o.stop = [&calls] {
    ++calls;
    return false;
  };
  const ApproximationError polled = refine::measure_approximation(moved, cube, o);
  CHECK_FALSE(polled.stopped);
  CHECK(calls.load() > 20);
  CHECK(polled.hausdorff() == full.hausdorff());
  CHECK(polled.feature_distance() == full.feature_distance());
  CHECK(polled.input_to_output.samples == full.input_to_output.samples);

  // True once, on the third call, then false: the other thread stops too, without asking again
  // (a poll or two may slip in before the first thread records the stop; without the shared
  // flag the other thread polls to its end, dozens of times).
  calls = 0;
  o.stop = [&calls] { return ++calls == 3; };
  const ApproximationError cut = refine::measure_approximation(moved, cube, o);
  CHECK(cut.stopped);
  CHECK(calls.load() <= 8);
}

namespace {

/// Meshes `soup` at λ = fraction of its diagonal and measures the result with h = λ / 4.
ApproximationError mesh_and_measure(const io::TriangleSoup& soup, double fraction, double* lambda) {
  const PolygonDomain domain(soup);
  *lambda = fraction * domain.bounding_box().diagonal();
  protect::BallSet set = protect::protect(domain.complex(), *lambda);
  refine::ProtectedBalls balls(set);
  refine::MesherOptions options;
  options.facet_size = *lambda;
  options.max_vertices = 20000;
  refine::Mesher mesher(domain, balls, options);
  mesher.run();
  REQUIRE(mesher.failing_vertices().empty());
  return measure(mesher.output(), domain, *lambda / 4);
}

}  // namespace

TEST_CASE("meshes from the mesher are as close as λ allows") {
  double lambda = 0;
  SUBCASE("cube: planar faces and straight curves are reproduced exactly") {
    const ApproximationError e = mesh_and_measure(io::make_cube(4), 0.1, &lambda);
    CHECK(e.hausdorff() <= 1e-9);
    CHECK(e.feature_distance() <= 1e-9);
  }
  SUBCASE("sphere: chords cut inside, within λ; finer is closer") {
    // Every restricted triangle lies in its surface Delaunay ball, centred on the surface, whose
    // vertices are within power distance λ² of the centre (§3, λ-size): each of its points is
    // within sqrt(2) λ of the surface (a ball vertex of radius r <= λ adds r² to the power).
    // The sphere has no ball, so λ itself; a chord of length ~λ on the unit sphere is about
    // λ² / 8 from it, and the polyhedral input adds its own facets' sag.
    const ApproximationError coarse = mesh_and_measure(io::make_sphere(8), 0.08, &lambda);
    const double coarse_lambda = lambda;
    MESSAGE("sphere λ=" << lambda << ": out->in " << coarse.output_to_input.distance << ", in->out "
                        << coarse.input_to_output.distance);
    CHECK(coarse.output_to_input.distance <= lambda);
    CHECK(coarse.input_to_output.distance <= lambda);
    CHECK(coarse.hausdorff() > 1e-4);  // the chords do leave the surface
    const ApproximationError fine = mesh_and_measure(io::make_sphere(8), 0.04, &lambda);
    MESSAGE("sphere λ=" << lambda << ": out->in " << fine.output_to_input.distance << ", in->out "
                        << fine.input_to_output.distance);
    CHECK(fine.hausdorff() < coarse.hausdorff());
    CHECK(fine.hausdorff() <= lambda);
    CHECK(coarse_lambda == doctest::Approx(2 * lambda));
  }
  SUBCASE("capped cylinder: the rims are circles, their chords within λ") {
    const ApproximationError e = mesh_and_measure(io::make_capped_cylinder(1, 2, 24, 8, 4), 0.04, &lambda);
    MESSAGE("cylinder λ=" << lambda << ": hausdorff " << e.hausdorff() << ", features " << e.feature_distance());
    CHECK(e.hausdorff() <= std::sqrt(2.0) * lambda);
    CHECK(e.feature_distance() <= lambda);
    CHECK(e.feature_distance() > 0);
    CHECK(e.unlabelled_edges == 0);
    for (const auto& c : e.curves) CHECK(c.output_edges > 0);
  }
}

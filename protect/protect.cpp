// Protect(D, λ), DelPSC §3 (steps in protect.h), and the Engine shared by its parts.
#include "protect.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

#include <nanoflann.hpp>

#include "folds.h"
#include "protect_engine.h"

namespace delpsc::protect {

namespace detail {

Engine::Engine(BallSet& b, const ProtectOptions& l, ProtectStats& s)
    : balls(b),
      complex(b.complex()),
      options(l),
      stats(s),
      first_new_id_(static_cast<BallId>(b.id_bound())),
      min_radius_(l.min_radius_fraction * b.diagonal()) {}

namespace {

double total_curve_length(const Complex& complex) {
  double length = 0;
  for (const Curve& c : complex.curves) length += c.length;
  return length;
}

}  // namespace

void Engine::fail_caps(double radius, const Vec3& where, std::uint32_t curve) const {
  char message[520];
  if (balls.size() >= options.max_balls)
    std::snprintf(message, sizeof message,
                  "protection stopped: more than %zu balls (the cap), the last at (%.6g, %.6g, %.6g); a size too "
                  "small for the curves (%.3g long in all, and Protect places a few balls per length of the size), or "
                  "curves closer together, or meeting at smaller angles, than the size asked for can resolve?",
                  options.max_balls, where.x(), where.y(), where.z(), total_curve_length(complex));
  else {
    // The nearest other curve (the ball's own does not count; any, for a corner ball), or the
    // ball's own curve coming back near it (a hairpin), whichever is nearer.
    const std::uint32_t own[] = {curve};
    auto near = nearest_curve_except(complex, where, curve == kNoIndex ? std::span<const std::uint32_t>{} : own);
    bool returning = false;
    if (curve != kNoIndex)
      if (const auto back = curve_returning_near(complex, curve, complex.closest_parameter(curve, where));
          back && (!near || back->distance < near->distance))
        near = back, returning = true;
    // A patch the ball's curve (or corner) does not bound, nearer still: a surface nearly
    // touching the curve (a fin's edge hovering over a sheet), not two curves.
    std::span<const std::uint32_t> bounded;
    if (curve != kNoIndex)
      bounded = complex.curve_patch_ids(curve);
    else
      for (std::uint32_t k = 0; k < complex.corner_vertex.size(); ++k)
        if (complex.vertices[complex.corner_vertex[k]] == where) bounded = complex.corner_patch_ids(k);
    const auto patch = nearest_patch_except(complex, where, bounded);
    char gap[200] = "; the surface nearly touching itself there?";
    // Nothing within kNearRadii radii: the balls shrank for the surface at this one place (the
    // mesher refining the ball at a needle's tip whose umbrella it could not make a disk), not for
    // a gap to another curve or patch; calling a curve half the model away "touching" misled.
    constexpr double kNearRadii = 1e4;
    const bool patch_nearer = patch && (!near || patch->distance < near->distance);
    const double nearest = patch_nearer ? patch->distance : near ? near->distance : HUGE_VAL;
    if (nearest < HUGE_VAL && nearest > kNearRadii * radius)
      std::snprintf(gap, sizeof gap, "; no other curve or patch within 10^4 radii of it (the nearest, %s %u, %s %.3g from it)",
                    patch_nearer ? "patch" : "curve", patch_nearer ? patch->patch : near->curve,
                    !patch_nearer && returning ? "itself comes back" : "passes", nearest);
    else if (patch_nearer)
      std::snprintf(gap, sizeof gap, "; the surface nearly touching a %s there (patch %u passes %.3g from it)?",
                    curve != kNoIndex ? "curve" : "corner", patch->patch, patch->distance);
    else if (near)
      std::snprintf(gap, sizeof gap, "; curves touching or crossing there (curve %u %s %.3g from it)?", near->curve,
                    returning ? "itself comes back" : "passes", near->distance);
    std::snprintf(message, sizeof message,
                  "protection stopped: a ball of radius %.3g at (%.6g, %.6g, %.6g), below the cap of %.3g "
                  "(%.3g of the bounding-box diagonal), with %zu balls%s",
                  radius, where.x(), where.y(), where.z(), min_radius_, options.min_radius_fraction, balls.size(), gap);
  }
  throw ProtectionError(message, where, balls.size() >= options.max_balls);
}

void Engine::poll_stop() {
  if (!options.stop || (++work_ & 0xfffu) != 0 || !options.stop()) return;
  throw ProtectionStopped("protection stopped on request with " + std::to_string(balls.size()) + " balls");
}

BallId Engine::set_corner_ball(std::uint32_t corner, double radius) {
  poll_stop();
  if (!within_caps(radius)) fail_caps(radius, complex.vertices[complex.corner_vertex[corner]], kNoIndex);
  const BallId old = balls.corner_ball(corner);
  const BallId id = balls.set_corner_ball(corner, radius);
  if (old != kNoBall && old < first_new_id_) removed_.push_back(old);
  created_.push_back(id);
  return id;
}

BallId Engine::insert_interior(std::uint32_t curve, BallId after, double s, double radius) {
  poll_stop();
  if (!within_caps(radius)) fail_caps(radius, complex.point_at(curve, s), curve);
  const BallId id = balls.insert_interior(curve, after, s, radius);
  created_.push_back(id);
  return id;
}

void Engine::remove_interior(BallId id) {
  balls.remove_interior(id);
  if (id < first_new_id_) removed_.push_back(id);
}

}  // namespace detail

namespace {

// The corners' positions for nanoflann.
struct CornerCloud {
  const Complex& complex;
  std::size_t kdtree_get_point_count() const { return complex.corner_count(); }
  double kdtree_get_pt(std::size_t i, std::size_t dim) const {
    return complex.vertices[complex.corner_vertex[i]][static_cast<Eigen::Index>(dim)];
  }
  template <class Box>
  bool kdtree_get_bbox(Box&) const { return false; }
};

// Distance from each corner to the nearest other one (infinity if there is none). O(n log n).
std::vector<double> nearest_corner_distances(const Complex& complex) {
  const std::size_t n = complex.corner_count();
  std::vector<double> d(n, std::numeric_limits<double>::infinity());
  if (n < 2) return d;
  CornerCloud cloud{complex};
  using Tree = nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<double, CornerCloud>,
                                                   CornerCloud, 3, std::uint32_t>;
  Tree tree(3, cloud, nanoflann::KDTreeSingleIndexAdaptorParams(10));
  tree.buildIndex();
  for (std::uint32_t k = 0; k < n; ++k) {
    const Vec3& p = complex.vertices[complex.corner_vertex[k]];
    std::uint32_t ids[2];
    double d2[2];
    const auto found = tree.knnSearch(p.data(), 2, ids, d2);
    // Corners are distinct vertices of a welded mesh: the nearest is the corner itself.
    for (std::size_t i = 0; i < found; ++i)
      if (ids[i] != k) d[k] = std::min(d[k], std::sqrt(d2[i]));
  }
  return d;
}

// Step 2 grades a curve's first cover when min(r_u, r_v) is below this fraction of λ: the
// paper's uniform α would put more than 16 times the balls of a cover at λ along the whole curve.
constexpr double kGradedFirstCoverBelow = 1.0 / 16;

// Step 1: the vertex ball radius of every corner (protect.h).
double vertex_radius(const BallSet& balls, std::uint32_t corner, double nearest, double lambda) {
  const Complex& complex = balls.complex();
  double r = std::isfinite(nearest) ? nearest / 3 : balls.diagonal() / 3;
  for (const std::uint32_t c : complex.corner_curve_ids(corner))
    if (complex.curves[c].closed) r = std::min(r, complex.curves[c].length / 6);
  while (r > lambda) r /= 2;
  for (const std::uint32_t c : complex.corner_curve_ids(corner)) {
    const Curve& curve = complex.curves[c];
    if (!curve.closed) continue;
    while (true) {
      const CurveInterval seg = complex.segment_in_ball(c, 0, r);
      if (!seg.whole && seg.s1 - seg.s0 <= curve.length / 2) break;
      r /= 2;
    }
  }
  return r;
}

}  // namespace

BallSet protect(const Complex& complex, double lambda, const ProtectOptions& options, ProtectStats* stats) {
  if (!(lambda > 0) || !std::isfinite(lambda))
    throw std::invalid_argument("protect: the size lambda must be positive and finite");
  BallSet balls(complex);
  ProtectStats local;
  detail::Engine engine(balls, options, stats ? *stats : local);

  // 1. Vertex balls.
  const std::vector<double> nearest = nearest_corner_distances(complex);
  for (std::uint32_t k = 0; k < complex.corner_count(); ++k)
    engine.set_corner_ball(k, vertex_radius(balls, k, nearest[k], lambda));

  // 2. Cover each curve between its vertex balls with α = min(r_u, r_v), or graded from each
  //    end up to 6λ/7 where that α is far below λ (protect.h).
  for (std::uint32_t c = 0; c < complex.curve_count(); ++c) {
    const Curve& curve = complex.curves[c];
    const BallOnCurve u{balls.corner_ball(curve.start_corner), 0.0};
    const BallOnCurve v{balls.corner_ball(curve.end_corner), curve.length};
    const double r_u = balls[u.id].radius, r_v = balls[v.id].radius;
    detail::CoverSizes sizes;
    sizes.alpha = std::min(r_u, r_v);
    if (options.graded_cover && sizes.alpha < kGradedFirstCoverBelow * lambda) {
      sizes = detail::graded_cover_sizes(6 * lambda / 7, r_u, r_v);
      ++engine.stats.graded_first_covers;
    }
    detail::cover(engine, c, u, v, sizes);
  }

  // 3. Refine every ball larger than λ (Cover's 7α/6 end game can exceed it), in rounds.
  std::vector<BallId> too_big;
  while (balls.largest() != kNoBall && balls[balls.largest()].radius > lambda) {
    too_big.clear();
    for (const BallId id : balls.live_ids()) {
      engine.poll_stop();
      if (balls[id].radius > lambda) too_big.push_back(id);
    }
    detail::refine_balls(engine, too_big);
  }

  // 4. Separate all balls (and repair any adjacent pair failing C2 / C3.a).
  detail::separate(engine, balls.live_ids());
  return balls;
}

}  // namespace delpsc::protect

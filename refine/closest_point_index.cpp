#include "closest_point_index.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <delpsc/kernel/constructions.h>

namespace delpsc::refine {

namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kTwoPi = 2 * std::numbers::pi;
// Added to both ends of every wedge and to every query's reach: far above the rounding of the
// angles (~1e-16 rad for directions at least 1e-6 of their length off the axis), far below the
// angle between neighbouring triangles of any fan worth searching (2π / 20,000 ~ 3e-4).
constexpr double kMargin = 1e-9;
// A direction closer to the axis than this, relative to its length, gives no reliable angle.
constexpr double kOffAxis = 1e-6;

// Into [0, 2π), for the differences of angles this file makes (within a few turns of 0); std::fmod
// was a third of a query's time.
double wrap(double angle) {
  if (!std::isfinite(angle)) return angle;
  while (angle < 0) angle += kTwoPi;
  while (angle >= kTwoPi) angle -= kTwoPi;
  return angle;
}

}  // namespace

ClosestPointIndex::ClosestPointIndex(std::span<const Vec3> vertices, std::span<const Triangle> triangles,
                                     const kernel::AabbTree& all)
    : vertices_(vertices), triangles_(triangles), all_(&all) {
  std::vector<std::uint32_t> degree(vertices.size(), 0);
  for (const Triangle& t : triangles)
    for (const std::uint32_t v : t) ++degree[v];
  std::vector<std::uint32_t> centres;
  for (std::uint32_t v = 0; v < vertices.size(); ++v)
    if (degree[v] >= kMinFanDegree) centres.push_back(v);
  if (centres.empty()) return;
  // Most triangles first: a triangle with two centres (a strip between two fans) joins the larger.
  std::sort(centres.begin(), centres.end(),
            [&](std::uint32_t a, std::uint32_t b) { return degree[a] != degree[b] ? degree[a] > degree[b] : a < b; });
  constexpr std::uint32_t kNone = 0xffffffffu;
  std::vector<std::uint32_t> rank(vertices.size(), kNone);
  for (std::uint32_t i = 0; i < centres.size(); ++i) rank[centres[i]] = i;
  std::vector<std::vector<std::uint32_t>> members(centres.size());
  for (std::uint32_t t = 0; t < triangles.size(); ++t)
    for (const std::uint32_t v : triangles[t])
      if (rank[v] != kNone) members[rank[v]].push_back(t);
  std::vector<char> taken(triangles.size(), 0);
  std::vector<std::uint32_t> free_members;
  for (std::uint32_t i = 0; i < centres.size(); ++i) {
    free_members.clear();
    for (const std::uint32_t t : members[i])
      if (!taken[t]) free_members.push_back(t);
    if (free_members.size() < kMinFanDegree) continue;
    std::optional<Fan> fan = make_fan(centres[i], free_members);
    if (!fan) continue;
    for (const Entry& e : fan->entries) taken[e.triangle] = 1;
    for (const std::uint32_t t : fan->always) taken[t] = 1;
    fans_.push_back(std::move(*fan));
  }
  if (fans_.empty()) return;
  for (std::uint32_t t = 0; t < triangles.size(); ++t)
    if (!taken[t]) {
      rest_triangles_.push_back(triangles[t]);
      rest_ids_.push_back(t);
    }
  rest_ = kernel::AabbTree(vertices, rest_triangles_);
}

std::size_t ClosestPointIndex::fan_triangles() const {
  std::size_t n = 0;
  for (const Fan& f : fans_) n += f.entries.size() + f.always.size();
  return n;
}

std::optional<ClosestPointIndex::Fan> ClosestPointIndex::make_fan(std::uint32_t centre,
                                                                  std::span<const std::uint32_t> members) const {
  // The two axes of the file comment: the unit normals summed as given, and turned to agree
  // with the first one.
  Vec3 as_given = Vec3::Zero(), agreeing = Vec3::Zero(), first = Vec3::Zero();
  for (const std::uint32_t t : members) {
    const Triangle& tri = triangles_[t];
    const Vec3 n = (vertices_[tri[1]] - vertices_[tri[0]]).cross(vertices_[tri[2]] - vertices_[tri[0]]).normalized();
    if (!n.allFinite()) continue;
    if (first.isZero()) first = n;
    as_given += n;
    agreeing += n.dot(first) < 0 ? Vec3(-n) : n;
  }
  std::optional<Fan> best;
  double best_total = 2 * kTwoPi;  // wedges more than twice around: no fan
  for (const Vec3& axis : {as_given, agreeing}) {
    std::optional<Fan> fan = fan_about(centre, members, axis);
    if (!fan) continue;
    double total = 0;
    for (const Entry& e : fan->entries) total += e.width;
    if (total < best_total) {
      best_total = total;
      best = std::move(fan);
    }
  }
  return best;
}

std::optional<ClosestPointIndex::Fan> ClosestPointIndex::fan_about(std::uint32_t centre,
                                                                   std::span<const std::uint32_t> members,
                                                                   const Vec3& axis) const {
  const Vec3 a = axis.normalized();
  if (!a.allFinite() || axis.isZero()) return std::nullopt;
  Fan fan;
  fan.centre = vertices_[centre];
  fan.axis = a;
  fan.e1 = (std::abs(a.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY()).cross(a).normalized();
  fan.e2 = a.cross(fan.e1);
  for (const std::uint32_t t : members) {
    const Triangle& tri = triangles_[t];
    for (const std::uint32_t v : tri) fan.box.extend(vertices_[v]);
    // The other two vertices, u then v in the triangle's cyclic order after the centre.
    const int k = tri[0] == centre ? 0 : tri[1] == centre ? 1 : 2;
    const Vec3 du = vertices_[tri[(k + 1) % 3]] - fan.centre, dv = vertices_[tri[(k + 2) % 3]] - fan.centre;
    const double xu = du.dot(fan.e1), yu = du.dot(fan.e2), xv = dv.dot(fan.e1), yv = dv.dot(fan.e2);
    if (!(std::hypot(xu, yu) > kOffAxis * du.norm()) || !(std::hypot(xv, yv) > kOffAxis * dv.norm())) {
      fan.always.push_back(t);
      continue;
    }
    const double tu = std::atan2(yu, xu), tv = std::atan2(yv, xv);
    double turn = tv - tu;  // into (-π, π]: the wedge is the shorter way round
    if (turn > kPi) turn -= kTwoPi;
    if (turn <= -kPi) turn += kTwoPi;
    // Near a half turn the wedge is nearly a half-space and its bound says little.
    if (std::abs(turn) > kPi - 1e-6) {
      fan.always.push_back(t);
      continue;
    }
    const double start = turn >= 0 ? tu : tv;
    fan.entries.push_back({wrap(start - kMargin), std::abs(turn) + 2 * kMargin, t});
  }
  // A wedge far wider than the fan's average (a cone's side triangle at a base fanned from a rim
  // corner spans a quarter turn among chords of 1/5,000 of a half turn) would keep every search's
  // backward pass going that far: such triangles are tried every time instead.
  double total = 0;
  for (const Entry& e : fan.entries) total += e.width;
  const double wide = 16 * total / static_cast<double>(std::max<std::size_t>(fan.entries.size(), 1));
  std::erase_if(fan.entries, [&](const Entry& e) {
    if (e.width <= wide) return false;
    fan.always.push_back(e.triangle);
    return true;
  });
  if (fan.always.size() > members.size() / 8) return std::nullopt;
  std::sort(fan.entries.begin(), fan.entries.end(), [](const Entry& x, const Entry& y) {
    return x.start != y.start ? x.start < y.start : x.triangle < y.triangle;
  });
  for (const Entry& e : fan.entries) fan.widest = std::max(fan.widest, e.width);
  return fan;
}

void ClosestPointIndex::try_triangle(std::uint32_t t, const Vec3& p, kernel::ClosestTriangle& best) const {
  const Triangle& tri = triangles_[t];
  const auto q = kernel::closest_point_on_triangle(p, vertices_[tri[0]], vertices_[tri[1]], vertices_[tri[2]]);
  const double d2 = (q.point - p).squaredNorm();
  if (d2 < best.squared_distance) best = {t, q.point, d2};
}

ClosestPointIndex::Aim ClosestPointIndex::aim(const Fan& fan, const Vec3& p) const {
  const Vec3 d = p - fan.centre;
  const double x = d.dot(fan.e1), y = d.dot(fan.e2);
  const double alpha = wrap(std::atan2(y, x));
  // The first entry starting after alpha: the one before it is the wedge that may hold p.
  const auto after = std::upper_bound(fan.entries.begin(), fan.entries.end(), alpha,
                                      [](double a, const Entry& e) { return a < e.start; });
  return {std::hypot(x, y), alpha, static_cast<std::size_t>(after - fan.entries.begin())};
}

void ClosestPointIndex::probe(const Fan& fan, const Aim& at, const Vec3& p, kernel::ClosestTriangle& best) const {
  for (const std::uint32_t t : fan.always) try_triangle(t, p, best);
  const std::size_t n = fan.entries.size();
  if (n == 0) return;
  try_triangle(fan.entries[(at.first_after + n - 1) % n].triangle, p, best);
  try_triangle(fan.entries[at.first_after % n].triangle, p, best);
}

void ClosestPointIndex::search_fan(const Fan& fan, const Aim& at, const Vec3& p, kernel::ClosestTriangle& best) const {
  const std::size_t n = fan.entries.size();
  if (n == 0) return;
  const double rho = at.rho, alpha = at.alpha;
  // The angle from p's direction beyond which no wedge holds a point nearer than the best so
  // far: ρ sin(Δ) >= best there (the bound needs Δ <= π/2; beyond, it is ρ itself). Infinite
  // while p is no farther from the axis than from the best point: every wedge may then be nearer.
  const auto reach = [&] {
    const double b = std::sqrt(best.squared_distance);
    if (!(b < rho)) return HUGE_VAL;
    return std::asin(b / rho) * (1 + 1e-12) + kMargin;
  };
  double r = reach();
  // p nearer the axis than the best point: no angle prunes anything.
  if (r == HUGE_VAL) {
    for (const Entry& e : fan.entries) try_triangle(e.triangle, p, best);
    return;
  }
  // Backwards from the wedge that may hold p, then forwards; each side stops where the angle to
  // the nearest wedge it could still reach passes the reach, which shrinks as the best improves.
  for (std::size_t step = 0; step < n; ++step) {
    const Entry& e = fan.entries[(at.first_after + n - 1 - step) % n];
    const double behind = wrap(alpha - e.start);  // p's angle past the wedge's first direction
    if (behind - fan.widest >= r) break;
    if (behind - e.width < r) {
      const double before = best.squared_distance;
      try_triangle(e.triangle, p, best);
      if (best.squared_distance < before) r = reach();
    }
  }
  for (std::size_t step = 0; step < n; ++step) {
    const Entry& e = fan.entries[(at.first_after + step) % n];
    const double ahead = wrap(e.start - alpha);
    if (ahead >= r) break;
    const double before = best.squared_distance;
    try_triangle(e.triangle, p, best);
    if (best.squared_distance < before) r = reach();
  }
}

std::optional<kernel::ClosestTriangle> ClosestPointIndex::closest_point(const Vec3& p, double below_squared) const {
  if (fans_.empty()) return all_->closest_point(p, below_squared);
  // The bound is the best so far until a triangle beats it (try_triangle keeps strictly nearer).
  kernel::ClosestTriangle best{0, Vec3::Zero(), below_squared};
  // First each fan's wedges at p's direction: cheap, and near a fan they bound the tree query of
  // the rest tightly (on a cylinder's cap its side is far, and finding the nearest of its strips
  // without a bound was most of the query). Without a bound a fan's angular search would reach
  // far too: the best found anywhere comes first.
  for (const Fan& fan : fans_)
    if (fan.box.squared_distance(p) < best.squared_distance) probe(fan, aim(fan, p), p, best);
  if (const auto c = rest_.closest_point(p, best.squared_distance)) {
    best = *c;
    best.triangle = rest_ids_[c->triangle];
  }
  for (const Fan& fan : fans_)
    if (fan.box.squared_distance(p) < best.squared_distance) search_fan(fan, aim(fan, p), p, best);
  if (!(best.squared_distance < below_squared)) return std::nullopt;
  return best;
}

}  // namespace delpsc::refine

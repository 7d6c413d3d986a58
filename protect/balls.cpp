// BallSet (balls.h): the protecting balls with their curve order, heap and spatial index.
#include "balls.h"

#include <algorithm>
#include <cmath>
#include <cassert>
#include <cstdio>
#include <limits>
#include <stdexcept>

#include <delpsc/kernel/constructions.h>
#include <delpsc/kernel/predicates.h>

namespace delpsc::protect {

namespace {

double bounding_box_diagonal(const Complex& complex) {
  if (complex.vertices.empty()) return 0;
  Vec3 lo = complex.vertices.front(), hi = lo;
  for (const Vec3& p : complex.vertices) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  return (hi - lo).norm();
}

// seg_σ of a ball centred at an end of an open curve. Works around a slip in
// Complex::segment_in_ball (curve_geometry.cpp, reported): its walk tests "a full turn inside
// the ball" (|sb - s| >= length) before testing whether the vertex it reached is inside, which
// on an open curve fires when a walk from one end reaches the other end's vertex, and answers
// "whole curve" although that vertex is outside. Only a corner ball can meet it (the test needs
// s at an end); the exit is then on the last polyline segment of the walk.
CurveInterval segment_at_open_end(const Complex& complex, std::uint32_t c, double s, double r,
                                  CurveInterval seg) {
  const Vec3 centre = complex.point_at(c, s);
  const WeightedPoint ball = WeightedPoint::from(centre, r * r);
  const auto poly = complex.curve_polyline(c);
  const auto params = complex.curve_parameters(c);
  const std::size_t n = poly.size();
  const bool from_start = s <= 0;
  const Vec3& far = complex.vertices[from_start ? poly[n - 1] : poly[0]];
  if (kernel::power_distance_sign(far.data(), ball.data()) <= 0) return seg;  // really whole
  // The walk got to the far end with every vertex before it inside: leave on the last piece.
  const std::size_t a = from_start ? n - 2 : 1, b = from_start ? n - 1 : 0;
  const kernel::SphereHits hits =
      kernel::intersect_segment_sphere(complex.vertices[poly[a]], complex.vertices[poly[b]], ball);
  const double t = hits.count > 0 ? hits.t[hits.count - 1] : 0.0;
  const double exit = params[a] + t * (params[b] - params[a]);
  if (from_start) return {0.0, std::max(exit, s), false};
  return {std::min(exit, s), complex.curves[c].length, false};
}

}  // namespace

BallSet::BallSet(const Complex& complex)
    : complex_(&complex),
      diagonal_(bounding_box_diagonal(complex)),
      corner_ball_(complex.corner_count(), kNoBall),
      first_(complex.curve_count(), kNoBall),
      last_(complex.curve_count(), kNoBall),
      interior_count_(complex.curve_count(), 0) {}

std::vector<BallId> BallSet::live_ids() const {
  std::vector<BallId> ids;
  ids.reserve(live_);
  for (BallId id = 0; id < balls_.size(); ++id)
    if (balls_[id].alive) ids.push_back(id);
  return ids;
}

BallOnCurve BallSet::before(BallId interior) const {
  const Ball& b = balls_[interior];
  if (b.prev != kNoBall) return {b.prev, balls_[b.prev].s};
  return {corner_ball_[complex_->curves[b.curve].start_corner], 0.0};
}

BallOnCurve BallSet::after(BallId interior) const {
  const Ball& b = balls_[interior];
  if (b.next != kNoBall) return {b.next, balls_[b.next].s};
  const Curve& curve = complex_->curves[b.curve];
  return {corner_ball_[curve.end_corner], curve.length};
}

std::vector<BallOnCurve> BallSet::curve_sequence(std::uint32_t curve) const {
  const Curve& c = complex_->curves[curve];
  std::vector<BallOnCurve> seq;
  seq.reserve(interior_count_[curve] + 2);
  seq.push_back({corner_ball_[c.start_corner], 0.0});
  for (BallId id = first_[curve]; id != kNoBall; id = balls_[id].next) seq.push_back({id, balls_[id].s});
  seq.push_back({corner_ball_[c.end_corner], c.length});
  return seq;
}

std::vector<BallId> BallSet::neighbours(BallId id) const {
  std::vector<BallId> out;
  const Ball& b = balls_[id];
  if (!b.is_corner()) {
    out.push_back(before(id).id);
    const BallId a = after(id).id;
    if (a != out.front()) out.push_back(a);  // a closed curve whose only other ball is the corner's
    return out;
  }
  for (const std::uint32_t c : complex_->corner_curve_ids(b.corner)) {
    const Curve& curve = complex_->curves[c];
    // The corner may be the curve's start, its end, or both (closed curve, listed twice).
    if (curve.start_corner == b.corner && first_[c] != kNoBall) out.push_back(first_[c]);
    if (curve.end_corner == b.corner && last_[c] != kNoBall) out.push_back(last_[c]);
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

bool BallSet::on_curve(BallId id, std::uint32_t curve) const {
  const Ball& b = balls_[id];
  if (!b.is_corner()) return b.curve == curve;
  const Curve& c = complex_->curves[curve];
  return c.start_corner == b.corner || c.end_corner == b.corner;
}

bool BallSet::share_curve(BallId a, BallId b) const {
  const Ball& A = balls_[a];
  const Ball& B = balls_[b];
  if (!A.is_corner()) return on_curve(b, A.curve);
  if (!B.is_corner()) return on_curve(a, B.curve);
  for (const std::uint32_t c : complex_->corner_curve_ids(A.corner))
    if (on_curve(b, c)) return true;
  return false;
}

CurveInterval BallSet::segment_on(std::uint32_t curve, const BallOnCurve& b) const {
  const Curve& c = complex_->curves[curve];
  CurveInterval seg = complex_->segment_in_ball(curve, b.s, balls_[b.id].radius);
  if (!c.closed && seg.whole) seg = segment_at_open_end(*complex_, curve, b.s, balls_[b.id].radius, seg);
  // A closed curve's end corner stands at `length` in the unrolled view, but segment_in_ball
  // wraps it to 0: shift the answer by one turn.
  if (c.closed && b.s >= c.length && !seg.whole) {
    seg.s0 += c.length;
    seg.s1 += c.length;
  }
  return seg;
}

BallId BallSet::largest() const {
  while (!heap_.empty()) {
    const BallId id = kNoBall - heap_.top().second;
    if (balls_[id].alive) return id;
    heap_.pop();
  }
  return kNoBall;
}

std::pair<double, double> BallSet::radius_range() const {
  if (live_ == 0) return {0, 0};
  double lo = std::numeric_limits<double>::infinity(), hi = 0;
  for (const Ball& b : balls_)
    if (b.alive) {
      lo = std::min(lo, b.radius);
      hi = std::max(hi, b.radius);
    }
  return {lo, hi};
}

void BallSet::balls_meeting(const Vec3& centre, double radius, std::vector<BallId>& out) const {
  grid_.for_each_candidate(centre, radius, [&](std::uint32_t id) {
    const Ball& b = balls_[id];
    if ((b.centre - centre).norm() <= radius + b.radius) out.push_back(id);
  });
}

std::vector<BallId> BallSet::balls_meeting(BallId id) const {
  std::vector<BallId> out;
  balls_meeting(balls_[id].centre, balls_[id].radius, out);
  out.erase(std::remove(out.begin(), out.end(), id), out.end());
  return out;
}

BallId BallSet::new_ball(const Ball& b) {
  if (!(b.radius > 0) || !std::isfinite(b.radius))
    throw std::invalid_argument("BallSet: a ball's radius must be positive and finite");
  if (balls_.size() >= kNoBall) throw std::length_error("BallSet: too many balls for 32-bit ids");
  const auto id = static_cast<BallId>(balls_.size());
  balls_.push_back(b);
  balls_.back().alive = true;
  ++live_;
  grid_.insert(id, b.centre, b.radius);
  heap_.emplace(b.radius, kNoBall - id);
  return id;
}

void BallSet::kill(BallId id) {
  Ball& b = balls_[id];
  assert(b.alive);
  b.alive = false;
  --live_;
  grid_.erase(id, b.centre, b.radius);
}

BallId BallSet::set_corner_ball(std::uint32_t corner, double radius) {
  Ball b;
  b.centre = complex_->vertices[complex_->corner_vertex[corner]];
  b.radius = radius;
  b.corner = corner;
  const BallId id = new_ball(b);
  if (corner_ball_[corner] != kNoBall) kill(corner_ball_[corner]);
  else ++live_corners_;
  corner_ball_[corner] = id;
  return id;
}

BallId BallSet::insert_interior(std::uint32_t curve, BallId after, double s, double radius) {
  Ball b;
  b.centre = complex_->point_at(curve, s);
  b.radius = radius;
  b.s = s;
  b.curve = curve;
  b.prev = after;
  b.next = after == kNoBall ? first_[curve] : balls_[after].next;
  assert(after == kNoBall || (balls_[after].alive && balls_[after].curve == curve));
  const BallId id = new_ball(b);
  if (b.prev != kNoBall) balls_[b.prev].next = id;
  else first_[curve] = id;
  if (b.next != kNoBall) balls_[b.next].prev = id;
  else last_[curve] = id;
  ++interior_count_[curve];
  return id;
}

void BallSet::remove_interior(BallId id) {
  Ball& b = balls_[id];
  assert(b.alive && !b.is_corner());
  if (b.prev != kNoBall) balls_[b.prev].next = b.next;
  else first_[b.curve] = b.next;
  if (b.next != kNoBall) balls_[b.next].prev = b.prev;
  else last_[b.curve] = b.prev;
  --interior_count_[b.curve];
  kill(id);
}

std::string balls_to_text(const BallSet& balls, const Vec3& offset) {
  const Complex& complex = balls.complex();
  std::string out;
  char line[64];
  char numbers[128];  // 4 numbers of at most 24 characters
  auto ball_line = [&](const Ball& b) {
    const Vec3 centre = b.centre + offset;
    std::snprintf(numbers, sizeof numbers, "%.17g %.17g %.17g %.17g\n", centre.x(), centre.y(), centre.z(), b.radius);
    out += numbers;
  };
  for (std::uint32_t k = 0; k < complex.corner_count(); ++k) {
    const BallId id = balls.corner_ball(k);
    if (id == kNoBall) continue;
    std::snprintf(line, sizeof line, "corner %u ", k);
    out += line;
    ball_line(balls[id]);
  }
  for (std::uint32_t c = 0; c < complex.curve_count(); ++c) {
    const Curve& curve = complex.curves[c];
    std::snprintf(line, sizeof line, "curve %u %u %u %zu\n", c, curve.start_corner, curve.end_corner,
                  balls.interior_count(c));
    out += line;
    for (BallId id = balls.first_interior(c); id != kNoBall; id = balls[id].next) ball_line(balls[id]);
  }
  return out;
}

}  // namespace delpsc::protect

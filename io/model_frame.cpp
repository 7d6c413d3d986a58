#include "model_frame.h"

#include <cmath>
#include <limits>

namespace delpsc::io {

Vec3 move_near_origin(std::span<Vec3> points) {
  Vec3 offset = Vec3::Zero();
  if (points.empty()) return offset;
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity());
  Vec3 hi = -lo;
  for (const Vec3& p : points) {
    if (!p.allFinite()) return offset;
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  const double diagonal = (hi - lo).norm();
  for (int k = 0; k < 3; ++k) {
    // Every coordinate on the axis within [bound, 2 bound] (or [2 bound, bound] below zero):
    // x - bound is exact for each of them (Sterbenz's lemma).
    double bound = 0;
    if (lo[k] > 0 && hi[k] <= 2 * lo[k]) bound = lo[k];
    if (hi[k] < 0 && lo[k] >= 2 * hi[k]) bound = hi[k];
    if (std::fabs(bound) >= kFarFromOriginRatio * diagonal) offset[k] = bound;
  }
  if (offset != Vec3::Zero())
    for (Vec3& p : points) p -= offset;
  return offset;
}

void move_by(std::span<Vec3> points, const Vec3& offset) {
  if (offset == Vec3::Zero()) return;
  for (Vec3& p : points) p += offset;
}

}  // namespace delpsc::io

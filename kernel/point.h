// Points and weighted points, the plain data every module passes around.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>  // cross products: every user of Vec3 may need them

namespace delpsc {

/// A point or vector in R^3. Eigen is the natural tool for the constructions (dot, cross, norms).
using Vec3 = Eigen::Vector3d;

/// A weighted point (ball): centre (x, y, z) and weight w = r^2, the squared radius.
/// An ordinary (unweighted) point has w = 0. The power distance of a point q to it is
/// |q - c|^2 - w. 32 bytes, laid out exactly as one record of the binary point-set format
/// (four little-endian doubles x, y, z, w), so a file can be read straight into an array.
struct WeightedPoint {
  double x = 0, y = 0, z = 0, w = 0;

  const double* data() const { return &x; }
  double* data() { return &x; }
  Vec3 point() const { return {x, y, z}; }
  static WeightedPoint from(const Vec3& p, double weight = 0) { return {p.x(), p.y(), p.z(), weight}; }
  friend bool operator==(const WeightedPoint&, const WeightedPoint&) = default;
};
static_assert(sizeof(WeightedPoint) == 4 * sizeof(double), "WeightedPoint must be four packed doubles");

}  // namespace delpsc

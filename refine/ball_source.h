// What the mesher needs from the protecting balls (Dey & Levine 2009, §2.1-2.2, §3 step 2a): the
// live balls as weighted points with the curve or corner each protects, their adjacency along
// the curves (condition D3 and the output's Skl^1), the largest one (d2), and RefineBall, which
// reports the balls it removed and added so the triangulation can follow.
//
// A small interface of our own so that refine/ does not depend on how protect/ stores its balls:
// refine/protected_balls.h adapts protect::BallSet; NoBalls serves domains without features
// (a sphere, a torus), where nothing needs protecting.
#pragma once

#include <cstdint>
#include <vector>

#include <delpsc/kernel/point.h>

namespace delpsc::refine {

using BallKey = std::uint32_t;
inline constexpr BallKey kNoBallKey = 0xffffffffu;
inline constexpr std::uint32_t kNoElement = 0xffffffffu;

/// A protecting ball B(centre, radius) (radius > 0, coordinates' units) centred on a corner or on
/// the interior of a curve.
struct ProtectingBall {
  Vec3 centre = Vec3::Zero();
  double radius = 0;
  std::uint32_t curve = kNoElement;   ///< curve of an interior ball, kNoElement for a corner ball
  std::uint32_t corner = kNoElement;  ///< corner of a corner ball, kNoElement otherwise
  bool is_corner() const { return corner != kNoElement; }
};

/// What one RefineBall changed: keys of the balls that died and of those created (a shrunk
/// corner ball appears in both, under its old and its new key).
struct BallUpdate {
  std::vector<BallKey> removed, added;
};

class BallSource {
 public:
  virtual ~BallSource() = default;
  /// Keys of the live balls.
  virtual std::vector<BallKey> live_balls() const = 0;
  /// A live ball.
  virtual ProtectingBall ball(BallKey key) const = 0;
  /// Whether two live balls are consecutive on some curve (condition C2's adjacency).
  virtual bool adjacent(BallKey a, BallKey b) const = 0;
  /// The curve's balls b_0 .. b_k from its start corner to its end corner (a closed curve: the
  /// corner ball first and last).
  virtual std::vector<BallKey> curve_chain(std::uint32_t curve) const = 0;
  /// A live ball of largest radius, kNoBallKey when there is none.
  virtual BallKey largest() const = 0;
  /// RefineBall(b) (and Separate of what it made); precondition: b alive.
  virtual BallUpdate refine(BallKey b) = 0;
};

/// The balls of a domain without corners or curves: none.
class NoBalls final : public BallSource {
 public:
  std::vector<BallKey> live_balls() const override { return {}; }
  ProtectingBall ball(BallKey) const override { return {}; }
  bool adjacent(BallKey, BallKey) const override { return false; }
  std::vector<BallKey> curve_chain(std::uint32_t) const override { return {}; }
  BallKey largest() const override { return kNoBallKey; }
  BallUpdate refine(BallKey) override { return {}; }
};

}  // namespace delpsc::refine

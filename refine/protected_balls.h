// The mesher's BallSource (ball_source.h) over protect::BallSet: Protect's balls, RefineBall and
// Separate of protect/protect.h.
#pragma once

#include <algorithm>

#include <delpsc/protect/balls.h>
#include <delpsc/protect/protect.h>

#include "ball_source.h"

namespace delpsc::refine {

/// The smallest ball RefineBall may make inside the refinement loop, as a fraction of λ.
/// RefineBall (§3 step 2a) shrinks balls where the disk condition fails near a curve; a ball
/// 10^4 times smaller than λ means the model has features λ cannot see - a sharp edge that is no
/// curve at the chosen feature angle, a surface nearly touching itself - and with protect's own
/// floor (1e-10 of the diagonal) such a run went on for minutes, halving balls, before failing
/// the same way. The acceptance tests mesh every test model with this floor.
inline constexpr double kSmallestRefinedBallOfLambda = 1e-4;

/// ProtectOptions for the balls refined during meshing at size λ of a model whose bounding box
/// has diagonal `diagonal`: `base` with the floor above (never lower than base's own).
inline protect::ProtectOptions refinement_ball_options(double lambda, double diagonal,
                                                       protect::ProtectOptions base = {}) {
  if (diagonal > 0)
    base.min_radius_fraction = std::max(base.min_radius_fraction, kSmallestRefinedBallOfLambda * lambda / diagonal);
  return base;
}

class ProtectedBalls final : public BallSource {
 public:
  /// `balls` must outlive this object; it is edited by refine().
  explicit ProtectedBalls(protect::BallSet& balls, const protect::ProtectOptions& options = {})
      : balls_(&balls), options_(options) {}

  std::vector<BallKey> live_balls() const override { return balls_->live_ids(); }
  ProtectingBall ball(BallKey key) const override {
    const protect::Ball& b = (*balls_)[key];
    return {b.centre, b.radius, b.curve, b.corner};
  }
  bool adjacent(BallKey a, BallKey b) const override {
    const std::vector<protect::BallId> n = balls_->neighbours(a);
    return std::find(n.begin(), n.end(), b) != n.end();
  }
  std::vector<BallKey> curve_chain(std::uint32_t curve) const override {
    std::vector<BallKey> out;
    for (const protect::BallOnCurve& b : balls_->curve_sequence(curve)) out.push_back(b.id);
    return out;
  }
  BallKey largest() const override { return balls_->largest(); }
  BallUpdate refine(BallKey b) override {
    protect::BallChanges c = protect::refine_ball(*balls_, b, options_, &stats_);
    return {std::move(c.removed), std::move(c.added)};
  }
  const protect::ProtectStats& stats() const { return stats_; }

 private:
  protect::BallSet* balls_;
  protect::ProtectOptions options_;
  protect::ProtectStats stats_;
};

}  // namespace delpsc::refine

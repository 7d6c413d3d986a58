// The mesher's BallSource (ball_source.h) over protect::BallSet: Protect's balls, RefineBall and
// Separate of protect/protect.h.
#pragma once

#include <algorithm>

#include <delpsc/protect/balls.h>
#include <delpsc/protect/protect.h>

#include "ball_source.h"

namespace delpsc::refine {

class ProtectedBalls final : public BallSource {
 public:
  /// `balls` must outlive this object; it is edited by refine().
  explicit ProtectedBalls(protect::BallSet& balls, const protect::ProtectOptions& options = {})
      : balls_(&balls), options_(options) {
    options_.stop = nullptr;  // see ProtectOptions::stop: a RefineBall is never cut short
  }

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

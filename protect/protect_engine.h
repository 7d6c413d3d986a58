// Internal to protect/: the state shared by Cover (cover.cpp), RefineBall (refine_ball.cpp) and
// Separate (separate.cpp) while protect() or refine_ball() (protect.h) runs: the ball set, the
// safety caps, the statistics, and the log of what was removed and created, from which
// refine_ball reports its changes.
#pragma once

#include <span>
#include <vector>

#include "cap_envelope.h"
#include "protect.h"

namespace delpsc::protect::detail {

class Engine {
 public:
  Engine(BallSet& balls, const ProtectOptions& options, ProtectStats& stats);

  BallSet& balls;
  const Complex& complex;
  const ProtectOptions& options;
  ProtectStats& stats;

  /// The edits of BallSet, logged and checked against the caps (ProtectionError).
  BallId set_corner_ball(std::uint32_t corner, double radius);
  BallId insert_interior(std::uint32_t curve, BallId after, double s, double radius);
  void remove_interior(BallId id);
  /// Counts a unit of work (a ball edit, a ball scanned by Separate or step 3) and every 4,096
  /// of them asks options.stop (a clock read, typically); throws ProtectionStopped.
  void poll_stop();

  /// Ids created since the engine started, in order (some may be dead again).
  const std::vector<BallId>& created() const { return created_; }
  /// Ids that existed when the engine started and were removed since, in order.
  const std::vector<BallId>& removed() const { return removed_; }

 private:
  /// Whether a new ball of this radius keeps within the caps; if not, fail_caps says which.
  bool within_caps(double radius) const { return balls.size() < options.max_balls && radius >= min_radius_; }

  /// Throws the ProtectionError for a ball failing within_caps; `where`, its centre, is named
  /// (where the model needs balls that small), with the nearest other curve than `curve` (the
  /// ball's, kNoIndex for a corner ball) and how far it passes.
  [[noreturn]] void fail_caps(double radius, const Vec3& where, std::uint32_t curve) const;

  BallId first_new_id_;
  std::size_t work_ = 0;
  double min_radius_;
  std::vector<BallId> created_, removed_;
};

/// The α of a Cover: the paper's one number, or the graded size of protect.h,
/// min(alpha, left_limit + slope (s - x), right_limit + slope (y - s), caps(s)) read where each
/// step starts, caps (if given) the envelope of the refined run's own caps (cap_envelope.h).
struct CoverSizes {
  double alpha = 0;
  bool graded = false;
  double left_limit = 0, right_limit = 0, slope = 0;
  CapEnvelope* caps = nullptr;
};

/// The graded size of protect.h between neighbours of radii r_left and r_right, up to alpha:
/// at most 0.6 of a neighbour's radius next to it, growing by at most 0.1 per unit of curve.
inline CoverSizes graded_cover_sizes(double alpha, double r_left, double r_right) {
  constexpr double kJunctionFraction = 0.6, kGradedSlope = 0.1;
  return {alpha, true, kJunctionFraction * r_left, kJunctionFraction * r_right, kGradedSlope};
}

/// Cover(x, y, α) of §2.2 on `curve` between the adjacent balls `left` and `right` (x the end
/// of seg(left), y the start of seg(right)); returns the ids of the balls it made, in order
/// (at least one).
std::vector<BallId> cover(Engine& engine, std::uint32_t curve, const BallOnCurve& left,
                          const BallOnCurve& right, const CoverSizes& sizes);

/// RefineBall of every live ball in `marked` (duplicates allowed), runs of consecutive interior
/// balls together unless options.refine_runs is false (protect.h). Returns the balls made.
std::vector<BallId> refine_balls(Engine& engine, std::span<const BallId> marked);

/// Separate: refines until no ball meets a ball with which it shares no curve, and no adjacent
/// pair fails C2 or C3.a, given that any such ball is in `candidates` or is made on the way.
void separate(Engine& engine, std::vector<BallId> candidates);

}  // namespace delpsc::protect::detail

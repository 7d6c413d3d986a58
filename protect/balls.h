// The protecting balls of DelPSC (Dey & Levine 2009, §2.1) as a first-class object: one ball per
// corner (the vertex balls b_0 / b_k of condition C1), shared by every curve ending there, and
// for each curve its interior balls in order from its start corner to its end corner. A ball is
// a weighted point with weight w = r^2 for the regular triangulation.
//
// Identity: every ball ever created gets a new BallId (0, 1, 2, ... never reused), so whoever
// follows the set (the mesher's triangulation) can name what was removed and what was added.
// A ball is never edited in place: shrinking a corner ball removes it and adds a new one.
//
// Curve view. A curve σ is seen as the sequence b_0, b_1, ..., b_k: its start corner's ball at
// parameter 0, its interior balls at their arc-length parameters (strictly increasing in
// (0, length)), its end corner's ball at parameter length. A closed curve (start corner == end
// corner) is seen unrolled: the one corner ball stands at both 0 and length. seg_σ(b) is given in
// the same coordinates (segment_on), so on a closed curve the corner ball's segment is
// [length + s0, length] at the end and [0, s1] at the start, unclamped (s0 < 0 at the start or
// s1 > length at the end are pieces past the corner).
//
// Adjacency (C2): two balls are adjacent when they are consecutive in some curve's sequence.
// "On a common curve" (C3.b): an interior ball lies on its curve, a corner ball on every curve
// ending at its corner; two balls share a curve when some curve holds both.
//
// Indexes kept up to date by every edit:
//  - per curve a doubly linked list of its interior balls (O(1) insertion and removal);
//  - a lazy max-heap of radii: largest() is O(1) amortised (dead entries are dropped when met);
//  - a hierarchical hash grid (ball_grid.h: one grid per power of two of the radius, each at a
//    few resolutions): balls_meeting(c, r) costs O(levels * (27 + candidates)), never a scan of
//    all balls unless that is cheaper.
// An edit costs O(log n) for the heap plus O(1) expected for the grid and the lists.
// Memory: 64 bytes per ball ever created (dead balls keep their record, so ids stay valid for
// reading) plus roughly 100 per live ball for the index and the heap.
// Threads: the const members may be called concurrently, except largest() (it drops dead heap
// entries).
#pragma once

#include <cstdint>
#include <queue>
#include <string>
#include <utility>
#include <vector>

#include <delpsc/kernel/point.h>

#include "ball_grid.h"
#include "complex.h"

namespace delpsc::protect {

using BallId = std::uint32_t;
inline constexpr BallId kNoBall = kNoIndex;

/// A protecting ball B(centre, radius), centred on a corner or on a curve.
struct Ball {
  Vec3 centre = Vec3::Zero();
  double radius = 0;
  double s = 0;                     ///< arc-length parameter on `curve` (interior balls; 0 for corner balls)
  std::uint32_t curve = kNoIndex;   ///< curve of an interior ball; kNoIndex for a corner ball
  std::uint32_t corner = kNoIndex;  ///< corner of a corner ball; kNoIndex for an interior ball
  /// Interior balls: the previous / next interior ball on the curve, kNoBall where the
  /// neighbour is the start / end corner's ball.
  BallId prev = kNoBall, next = kNoBall;
  bool alive = true;

  bool is_corner() const { return corner != kNoIndex; }
  /// The ball as a weighted point (weight = squared radius) for the regular triangulation.
  WeightedPoint weighted_point() const { return WeightedPoint::from(centre, radius * radius); }
};

/// A ball as one curve sees it: its id and its parameter in that curve's view (see file comment).
struct BallOnCurve {
  BallId id = kNoBall;
  double s = 0;
};

class BallSet {
 public:
  /// An empty set over `complex`, which must outlive it and not change.
  explicit BallSet(const Complex& complex);

  const Complex& complex() const { return *complex_; }
  /// Diagonal of the bounding box of the complex's vertices (0 for an empty complex).
  double diagonal() const { return diagonal_; }

  // ---- reading ----------------------------------------------------------------------------------
  std::size_t size() const { return live_; }                 ///< live balls
  std::size_t corner_ball_count() const { return live_corners_; }
  std::size_t id_bound() const { return balls_.size(); }     ///< every id ever issued is below
  const Ball& operator[](BallId id) const { return balls_[id]; }
  bool alive(BallId id) const { return id < balls_.size() && balls_[id].alive; }
  /// Ids of the live balls, increasing. O(id_bound).
  std::vector<BallId> live_ids() const;

  /// The ball of a corner, kNoBall before it has one.
  BallId corner_ball(std::uint32_t corner) const { return corner_ball_[corner]; }
  BallId first_interior(std::uint32_t curve) const { return first_[curve]; }  ///< kNoBall if none
  BallId last_interior(std::uint32_t curve) const { return last_[curve]; }    ///< kNoBall if none
  std::size_t interior_count(std::uint32_t curve) const { return interior_count_[curve]; }

  /// The ball before / after an interior ball on its curve (an interior ball or the start / end
  /// corner's ball), with its parameter in the curve's view.
  BallOnCurve before(BallId interior) const;
  BallOnCurve after(BallId interior) const;
  /// The curve's sequence b_0 .. b_k (needs both corner balls). O(k).
  std::vector<BallOnCurve> curve_sequence(std::uint32_t curve) const;
  /// The balls adjacent to `id` (C2), each once. A corner ball has one per curve end (fewer if
  /// some coincide: a closed curve with a single interior ball).
  std::vector<BallId> neighbours(BallId id) const;
  /// Whether some curve holds both balls (see file comment). O(degree of a corner).
  bool share_curve(BallId a, BallId b) const;
  /// Whether the curve holds the ball (its own curve, or a curve ending at its corner).
  bool on_curve(BallId id, std::uint32_t curve) const;

  /// seg_σ(b) of the ball `b.id` seen from `curve` at parameter b.s, in the curve's view.
  /// O(log n + polyline vertices inside the ball).
  CurveInterval segment_on(std::uint32_t curve, const BallOnCurve& b) const;

  /// A live ball of largest radius (the smallest id among equals), kNoBall if the set is empty.
  BallId largest() const;
  /// Smallest and largest live radius ({0, 0} when empty). O(id_bound).
  std::pair<double, double> radius_range() const;

  /// Live balls meeting the closed ball B(centre, radius): |c - c'| <= radius + r' (doubles).
  void balls_meeting(const Vec3& centre, double radius, std::vector<BallId>& out) const;
  /// Live balls other than `id` meeting it.
  std::vector<BallId> balls_meeting(BallId id) const;

  // ---- editing: the primitive steps of Protect / RefineBall (protect.h) -------------------------
  // They keep every index above up to date but check no protection condition.

  /// Gives `corner` a new ball of the given radius (> 0) centred on its vertex; its previous
  /// ball, if any, dies. Returns the new id.
  BallId set_corner_ball(std::uint32_t corner, double radius);
  /// Inserts an interior ball at parameter s (in (0, length), not wrapped) of `curve`, right
  /// after the interior ball `after` (kNoBall: first on the curve). The caller keeps the order
  /// (s between its neighbours' parameters). Returns the new id.
  BallId insert_interior(std::uint32_t curve, BallId after, double s, double radius);
  /// Removes an interior ball from its curve.
  void remove_interior(BallId id);

 private:
  BallId new_ball(const Ball& b);
  void kill(BallId id);

  const Complex* complex_;
  double diagonal_ = 0;
  kernel::LargeVector<Ball> balls_;
  std::size_t live_ = 0, live_corners_ = 0;
  std::vector<BallId> corner_ball_;
  std::vector<BallId> first_, last_;
  std::vector<std::size_t> interior_count_;
  detail::BallGrid grid_;
  mutable std::priority_queue<std::pair<double, BallId>> heap_;  // (radius, ~id): ties by smallest id
};

/// The balls as text, the format of `delpsc protect --balls` (issue 5):
///   corner ID X Y Z R                               one line per corner
///   curve ID START_CORNER_ID END_CORNER_ID N        one block per curve (closed: START == END)
///   X Y Z R                                         N lines, the curve's interior balls in order
/// Numbers in shortest round-trip form (%.17g), so a reader gets the doubles back exactly.
/// `offset` is added to every centre (a model moved near the origin, written in its file's frame;
/// io/model_frame.h); with the default the doubles are written as they are.
std::string balls_to_text(const BallSet& balls, const Vec3& offset = Vec3::Zero());

}  // namespace delpsc::protect

// Internal to protect/: the graded cover's α_max along a run of refined balls (refine_ball.cpp).
//
// Each ball b of the run asks that the balls covering its segment [a_b, b_b] be at most its own
// cap c_b (a quarter of its radius: Lemma 2.5's factor 7/24 after the 7α/6 end game). The run's
// smallest cap everywhere would honour that, but it spreads the smallest ball's size over the
// whole run: along a needle (mpi.off: two curves leaving a corner 0.069° apart, 4 units long)
// every ball meets the other curve, the run is the whole needle, and the cap of the ball at the
// tip made hundreds of thousands of balls where the gap grows linearly. The envelope
//     H(s) = min_b ( c_b + L dist(s, [a_b, b_b]) )
// is the largest L-Lipschitz function at most c_b on every segment, so the derivation of
// protect.h (consecutive radii within 1 + L 4/3 of each other) and Lemma 2.5 both still hold.
#pragma once

#include <cstddef>
#include <functional>
#include <queue>
#include <utility>
#include <vector>

namespace delpsc::protect::detail {

class CapEnvelope {
 public:
  struct Piece {
    double a, b, cap;  ///< a ball's segment [a, b] in curve parameters and its cap
  };

  /// `pieces` in any order, each a <= b; slope L >= 0. O(n log n).
  CapEnvelope(std::vector<Piece> pieces, double slope);

  /// H(s); successive calls must not decrease s. Amortised O(log n).
  double at(double s);

 private:
  double slope_;
  std::vector<Piece> by_start_;        // sorted by a
  std::vector<double> suffix_;         // min over k >= i of cap_k + L a_k (pieces starting later)
  std::size_t next_ = 0;               // first piece of by_start_ with a > the last query
  using Active = std::pair<double, double>;  // (cap, b) of a piece with a <= s
  std::priority_queue<Active, std::vector<Active>, std::greater<>> active_;
  double passed_ = 0;                  // min over pieces with b < s of cap - L b
  bool any_passed_ = false;
  double last_query_ = 0;
  bool queried_ = false;
};

}  // namespace delpsc::protect::detail

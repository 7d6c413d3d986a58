// CapEnvelope (cap_envelope.h): H(s) = min( F(s), G(s) ) with
//   F(s) over pieces already started (a <= s): cap while s <= b, cap + L (s - b) after b;
//   G(s) over pieces not started (a > s): cap + L (a - s), a suffix minimum of cap + L a.
// The started pieces still containing s sit in a min-heap by cap; one found expired at the top
// (b < s) moves into `passed_` as cap - L b, whose term is then passed_ + L s. An expired piece
// below the top costs nothing: its term is at least its cap, so at least the top's.
#include "cap_envelope.h"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace delpsc::protect::detail {

CapEnvelope::CapEnvelope(std::vector<Piece> pieces, double slope) : slope_(slope), by_start_(std::move(pieces)) {
  std::sort(by_start_.begin(), by_start_.end(), [](const Piece& p, const Piece& q) { return p.a < q.a; });
  suffix_.assign(by_start_.size() + 1, HUGE_VAL);
  for (std::size_t i = by_start_.size(); i-- > 0;)
    suffix_[i] = std::min(suffix_[i + 1], by_start_[i].cap + slope_ * by_start_[i].a);
}

double CapEnvelope::at(double s) {
  assert(!queried_ || s >= last_query_);
  queried_ = true;
  last_query_ = s;
  while (next_ < by_start_.size() && by_start_[next_].a <= s) {
    active_.emplace(by_start_[next_].cap, by_start_[next_].b);
    ++next_;
  }
  while (!active_.empty() && active_.top().second < s) {
    const double term = active_.top().first - slope_ * active_.top().second;
    passed_ = any_passed_ ? std::min(passed_, term) : term;
    any_passed_ = true;
    active_.pop();
  }
  double h = suffix_[next_] - slope_ * s;
  if (!active_.empty()) h = std::min(h, active_.top().first);
  if (any_passed_) h = std::min(h, passed_ + slope_ * s);
  return h;
}

}  // namespace delpsc::protect::detail

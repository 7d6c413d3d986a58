// Small adaptors that turn point-set makers into Family generators (oracle_harness.h).
#pragma once

#include <algorithm>
#include <utility>
#include <vector>

#include "oracle_configs.h"
#include "oracle_harness.h"

namespace delpsc::test {

using Points = std::vector<WeightedPoint>;

/// Family generator from a maker Points(Rng&) that never rejects.
template <class Make>
auto always(Make make) {
  return [make](Rng& rng, Case& c) {
    c.set(make(rng));
    return true;
  };
}

/// Family generator from a maker bool(Rng&, Points&) that may reject.
template <class Make>
auto maybe(Make make) {
  return [make](Rng& rng, Case& c) {
    Points p;
    if (!make(rng, p)) return false;
    c.set(p);
    return true;
  };
}

/// The generator's output, moved by configs::nudge_a_little on the axes of axes_mask (bit 3 =
/// weight), among the points from first_point on (e.g. 1 to spare an unweighted query point).
template <class Gen>
auto nudged(Gen gen, unsigned axes_mask, std::size_t first_point = 0) {
  return [gen, axes_mask, first_point](Rng& rng, Case& c) {
    if (!gen(rng, c)) return false;
    Points p(c.pts.begin() + static_cast<std::ptrdiff_t>(first_point), c.pts.begin() + c.n);
    configs::nudge_a_little(rng, p, axes_mask);
    std::copy(p.begin(), p.end(), c.pts.begin() + static_cast<std::ptrdiff_t>(first_point));
    return true;
  };
}

/// The generator's output scaled by a random power of two 2^k in range (weights by 2^2k).
template <class Gen>
auto scaled(Gen gen) {
  return [gen](Rng& rng, Case& c) {
    if (!gen(rng, c)) return false;
    Points p(c.pts.begin(), c.pts.begin() + c.n);
    scale_randomly(rng, p);
    c.set(p);
    return true;
  };
}

/// The generator's output scaled to one end of the range: by 2^kmin or 2^kmax of
/// scale_bounds(), so that its smallest or its largest magnitude touches the range's limit.
template <class Gen>
auto scaled_to_extreme(Gen gen) {
  return [gen](Rng& rng, Case& c) {
    if (!gen(rng, c)) return false;
    Points p(c.pts.begin(), c.pts.begin() + c.n);
    const auto [kmin, kmax] = scale_bounds(p);
    if (kmin > kmax) return false;
    scale_pow2(p, rng.chance(0.5) ? kmin : kmax);
    c.set(p);
    return true;
  };
}

/// k points drawn with replacement from the generator's points: repeated points (equal
/// positions, with equal or, half of the time for the first one, different weights), which the
/// plain predicates allow.
template <class Gen>
auto with_repeats(Gen gen, int k) {
  return [gen, k](Rng& rng, Case& c) {
    if (!gen(rng, c)) return false;
    const Case pool = c;
    for (int i = 0; i < k; ++i) c.pts[static_cast<std::size_t>(i)] = pool.pts[rng.index(static_cast<std::size_t>(pool.n))];
    c.n = k;
    if (rng.chance(0.5)) c.pts[0].w = pool.pts[0].w + 1;  // same place, another weight
    return true;
  };
}

/// The generator's output with its points in a random order (so that the special point of a
/// construction, e.g. the one off the circle, is not always last).
template <class Gen>
auto shuffled(Gen gen) {
  return [gen](Rng& rng, Case& c) {
    if (!gen(rng, c)) return false;
    std::shuffle(c.pts.begin(), c.pts.begin() + c.n, rng.engine());
    return true;
  };
}

}  // namespace delpsc::test

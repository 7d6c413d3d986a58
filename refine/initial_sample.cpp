#include "initial_sample.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <numeric>
#include <utility>

#include <delpsc/kernel/bits.h>

namespace delpsc::refine {

namespace {

// A grid of weighted points, one chain per occupied cell. Every interaction the selection tests
// reaches at most one cell size (see select_separated_points), so the 27 cells around a point
// hold everything that can reject it. Where the candidates' box holds few cells for the points
// (kDenseCellsPerPoint a point: a surface sample at spacing s in a box of side L has ~L²/s²
// points for L³/s³ cells), the chains' heads are a flat array over the box, one cell of margin
// around it: a cell's 26 neighbours are then 9 runs of 3 consecutive heads (the hash lookups
// were half of choosing the sphere's sample at 2%). Elsewhere (fine sizes, mostly empty boxes)
// a hash table with open addressing, sized once for every cell it will hold (it never rehashes,
// so slot positions stay valid). Keys follow the same x-major order of cells in both
// (select_in_parts sorts by them), so both choose the same points.
class PointGrid {
 public:
  static constexpr std::uint32_t kEmpty = 0xffffffffu;
  /// Up to this many cells a point and kDenseCells in all, the flat array (4 bytes a cell,
  /// written once; freed with the grid, before the triangulation is built). At 8 cells a point
  /// the cube and the sphere at 0.46% took the table; at 32, 1.3 and 2.1 million cells, 3-6%
  /// less time for each run (BENCHMARKS.md, session 31).
  static constexpr std::size_t kDenseCellsPerPoint = 32, kDenseCells = std::size_t{1} << 23;

  /// `box`: the candidates' (every key asked of the grid is of a point in it, but added points
  /// may lie anywhere); `points`: how many will be added at most.
  PointGrid(const kernel::Box3& box, double cell, std::size_t points) : origin_(box.lo), inverse_(1 / cell) {
    std::size_t cells = 1;
    for (int a = 0; a < 3; ++a) {
      // Cells 0 .. n - 1 along the axis hold the box (see cell_of), one more on either side.
      const double n = std::floor((box.hi[a] - box.lo[a]) * inverse_) + 3;
      extent_[a] = static_cast<std::int64_t>(std::min(n, double{1 << 21}));
      cells = cells > (std::size_t{1} << 40) ? cells : cells * static_cast<std::size_t>(extent_[a]);
    }
    dense_ = cells <= std::min(kDenseCells, kDenseCellsPerPoint * std::max<std::size_t>(points, 512));
    if (dense_) heads_.assign(cells, kEmpty);
  }

  /// Sizes the hash table for at most `cells` occupied cells (nothing in the flat array) and the
  /// chains for `points` points; before any add. The table is what the lookups miss in cache: it
  /// is sized by cells, not by points.
  void reserve(std::size_t cells, std::size_t points) {
    if (!dense_) {
      std::size_t capacity = 64;
      while (capacity < 2 * cells) capacity *= 2;
      slots_.assign(capacity, Slot{});
      home_used_.assign(capacity / 64, 0);
    }
    points_.reserve(points);
    next_.reserve(points);
  }

  std::array<std::int64_t, 3> cell_of(const Vec3& p) const {
    return {static_cast<std::int64_t>(std::floor((p.x() - origin_.x()) * inverse_)),
            static_cast<std::int64_t>(std::floor((p.y() - origin_.y()) * inverse_)),
            static_cast<std::int64_t>(std::floor((p.z() - origin_.z()) * inverse_))};
  }
  /// The key of a cell of the box (or of its margin), x major in both layouts.
  std::uint64_t key_of(const std::array<std::int64_t, 3>& c) const { return dense_ ? index(c) : pack(c); }
  /// Bits a key of the box takes (for the radix sort).
  int key_bits() const { return dense_ ? static_cast<int>(std::bit_width(heads_.size())) : 63; }

  /// The slot of a cell: where its chain is, or the empty slot where it would start.
  std::size_t slot_of(std::uint64_t key) const { return dense_ ? key : probe(home(key), key); }
  /// The heads of the chains of the 26 cells around cell c (of the box), those with points.
  /// Returns how many.
  std::size_t neighbour_heads(const std::array<std::int64_t, 3>& c, std::array<std::uint32_t, 26>& out) const {
    std::size_t occupied = 0;
    for (std::int64_t dx = -1; dx <= 1; ++dx)
      for (std::int64_t dy = -1; dy <= 1; ++dy)
        for (std::int64_t dz = -1; dz <= 1; ++dz) {
          if (dx == 0 && dy == 0 && dz == 0) continue;
          const std::uint32_t head = head_of({c[0] + dx, c[1] + dy, c[2] + dz});
          if (head != kEmpty) out[occupied++] = head;
        }
    return occupied;
  }
  /// Adds w to the cell `key` whose slot_of is `slot` (no add in between).
  void add_at(std::size_t slot, std::uint64_t key, const WeightedPoint& w) {
    std::uint32_t* head;
    if (dense_) {
      head = &heads_[slot];
    } else {
      const std::size_t h = home(key);
      home_used_[h >> 6] |= std::uint64_t{1} << (h & 63);
      slots_[slot].key = key;
      head = &slots_[slot].head;
    }
    points_.push_back(w);
    next_.push_back(*head);
    *head = static_cast<std::uint32_t>(points_.size() - 1);
  }
  /// Adds w wherever it lies; in the flat array a point beyond the margin is left out (no cell
  /// it could reject a candidate from is there).
  void add(const WeightedPoint& w) {
    const auto c = cell_of(w.point());
    if (dense_ && !in_margin(c)) return;
    const std::uint64_t key = key_of(c);
    add_at(slot_of(key), key, w);
  }

  /// The first point of the chain of `slot` (kEmpty: none).
  std::uint32_t head(std::size_t slot) const { return dense_ ? heads_[slot] : slots_[slot].head; }
  /// Whether a point in the chain that starts at `head` has power distance to x at most `limit`,
  /// or `ball_limit` for a ball (a point of positive weight: protecting balls have positive
  /// radii, the other points weight 0).
  bool chain_within(std::uint32_t head, const Vec3& x, double limit, double ball_limit) const {
    for (std::uint32_t i = head; i != kEmpty; i = next_[i]) {
      const WeightedPoint& w = points_[i];
      if ((w.point() - x).squaredNorm() - w.w <= (w.w > 0 ? ball_limit : limit)) return true;
    }
    return false;
  }

 private:
  struct Slot {
    std::uint64_t key = 0;
    std::uint32_t head = kEmpty;
  };

  /// 21 bits per axis, x major (offset so that cells just below the origin's pack too; cells
  /// farther out alias, which only lengthens a chain: every test is by distance).
  static std::uint64_t pack(const std::array<std::int64_t, 3>& c) {
    const auto u = [](std::int64_t v) { return static_cast<std::uint64_t>(v + (1 << 20)) & 0x1fffff; };
    return u(c[0]) << 42 | u(c[1]) << 21 | u(c[2]);
  }
  bool in_margin(const std::array<std::int64_t, 3>& c) const {
    for (int a = 0; a < 3; ++a)
      if (c[a] < -1 || c[a] + 1 >= extent_[a]) return false;
    return true;
  }
  std::size_t index(const std::array<std::int64_t, 3>& c) const {
    return static_cast<std::size_t>(((c[0] + 1) * extent_[1] + c[1] + 1) * extent_[2] + c[2] + 1);
  }
  /// The first point of cell c's chain (kEmpty: none). Most cells around a surface point are
  /// empty (a surface crosses about a third of a 3 x 3 x 3 block): in the hash table a bit per
  /// home slot, in a table 128 times smaller than the slots, answers most of them without
  /// probing (the probes were half of choosing the cube's sample).
  std::uint32_t head_of(const std::array<std::int64_t, 3>& c) const {
    if (dense_) return heads_[index(c)];
    const std::uint64_t key = pack(c);
    const std::size_t h = home(key);
    if ((home_used_[h >> 6] >> (h & 63) & 1u) == 0) return kEmpty;
    return slots_[probe(h, key)].head;
  }
  // All 64 bits mixed: a multiply keeps x (bits 42 and up of the key) out of the low bits a
  // table of under 2^22 slots uses, and the cells of one (y, z) column then shared a cluster
  // (~40 probes a lookup; 3.4% of the instructions of meshing the cube).
  std::size_t home(std::uint64_t key) const {
    return static_cast<std::size_t>(kernel::mix64(key)) & (slots_.size() - 1);
  }
  std::size_t probe(std::size_t i, std::uint64_t key) const {
    while (slots_[i].head != kEmpty && slots_[i].key != key) i = (i + 1) & (slots_.size() - 1);
    return i;
  }

  Vec3 origin_;
  double inverse_;
  std::array<std::int64_t, 3> extent_{};  // cells along each axis, margin included
  bool dense_ = false;
  kernel::LargeVector<std::uint32_t> heads_;  // flat: a head per cell
  kernel::LargeVector<Slot> slots_;            // hashed
  kernel::LargeVector<std::uint64_t> home_used_;  // bit i: some cell's home slot is i
  kernel::LargeVector<WeightedPoint> points_;
  kernel::LargeVector<std::uint32_t> next_;
};

// Consecutive candidates [from, from + count) tested at scale × spacing (× their local spacing).
struct SelectionPart {
  std::size_t from = 0, count = 0;
  double scale = 1;
};

// select_separated_points over consecutive parts of `candidates`, in one grid: each part's
// candidates, in cell order, against the balls (at ball_clearance times the spacing, in (0, 1]),
// the fixed points and everything chosen before (in earlier parts too). One grid instead of one
// per part spares re-adding every point chosen so far (the net's part costs half as much).
// decided[k] (if given, one per part): whether part k's every candidate was decided. Parts'
// scales in (0, 1].
std::vector<std::uint32_t> select_in_parts(std::span<const Vec3> candidates, std::span<const SelectionPart> parts,
                                           std::span<const WeightedPoint> balls, std::span<const Vec3> fixed,
                                           double spacing, double ball_clearance, std::span<const double> local_spacing,
                                           bool* decided, const std::function<bool()>& stop) {
  std::vector<std::uint32_t> chosen;
  if (decided) std::fill(decided, decided + parts.size(), false);
  const bool local = !local_spacing.empty();
  if (!(spacing > 0) || !std::isfinite(spacing) || candidates.size() > 0xffffffffu ||
      (local && local_spacing.size() != candidates.size()))
    return chosen;
  // A ball B(c, r) rejects x when |x - c|² - r² <= (ball_clearance spacing)², so within
  // sqrt(spacing² + r²); a point within spacing: one cell of that size around x's reaches them
  // all. The relative 1e-9 covers the rounding of a point's cell index (below 2^-33 of a cell at
  // index 2^19).
  double largest_weight = 0;
  for (const WeightedPoint& b : balls) largest_weight = std::max(largest_weight, b.w);
  const double cell = std::sqrt(spacing * spacing + largest_weight) * (1 + 1e-9);
  kernel::Box3 box;
  std::vector<kernel::LargeVector<std::uint32_t>> order(parts.size());
  std::size_t valid = 0;
  for (std::size_t k = 0; k < parts.size(); ++k) {
    order[k].reserve(parts[k].count);
    for (std::size_t i = parts[k].from; i < parts[k].from + parts[k].count; ++i)
      if (candidates[i].allFinite() && (!local || (local_spacing[i] > 0 && local_spacing[i] <= spacing))) {
        box.extend(candidates[i]);
        order[k].push_back(static_cast<std::uint32_t>(i));
      }
    valid += order[k].size();
  }
  // Written to refuse NaN too (a spacing whose square underflows gives a zero cell).
  if (valid == 0 || !(cell > 0) || !((box.hi - box.lo).maxCoeff() / cell <= double{1 << 19})) return chosen;
  if (decided)
    for (std::size_t k = 0; k < parts.size(); ++k) decided[k] = order[k].size() == parts[k].count;
  PointGrid grid(box, cell, balls.size() + fixed.size() + valid);
  // Cell order (then index) within a part: the candidates of a cell are tested one after
  // another against the same 27 chains, found once per cell, and the chosen points pack like a
  // scan line.
  std::vector<kernel::KeyedIndices> keyed(parts.size());
  std::size_t candidate_cells = 0;
  for (std::size_t k = 0; k < parts.size(); ++k) {
    keyed[k].reserve(order[k].size());
    for (const std::uint32_t i : order[k]) keyed[k].emplace_back(grid.key_of(grid.cell_of(candidates[i])), i);
    kernel::radix_sort_by_key(keyed[k], grid.key_bits());  // stable: equal cells keep index order
    for (std::size_t j = 0; j < keyed[k].size(); ++j)
      candidate_cells += j == 0 || keyed[k][j].first != keyed[k][j - 1].first;
  }
  grid.reserve(balls.size() + fixed.size() + candidate_cells, balls.size() + fixed.size() + valid);
  for (const WeightedPoint& b : balls) grid.add(b);
  for (const Vec3& p : fixed) grid.add(WeightedPoint::from(p));
  for (std::size_t k = 0; k < parts.size(); ++k) {
    const double part_spacing = parts[k].scale * spacing;
    std::size_t own = 0;                   // the cell's own slot
    std::array<std::uint32_t, 26> heads{};  // its neighbours' chains with points...
    std::size_t occupied = 0;              // ...heads[0 .. occupied)
    bool neighbours_found = false;         // ...once a candidate of the cell needs them
    std::uint64_t current = 0;
    for (std::size_t j = 0; j < keyed[k].size(); ++j) {
      if ((j & 0xffffu) == 0xffffu && stop && stop()) {
        if (decided) std::fill(decided, decided + parts.size(), false);
        return chosen;
      }
      const auto [key, i] = keyed[k][j];
      const Vec3& x = candidates[i];
      if (j == 0 || key != current) {
        current = key;
        own = grid.slot_of(key);
        neighbours_found = false;
      }
      const double s = local ? parts[k].scale * local_spacing[i] : part_spacing;
      const double limit = s * s, ball_limit = ball_clearance * ball_clearance * limit;
      // The cell's own chain first: most refusals are there (a net point's refuser, often), and
      // they then cost no lookup of the 26 neighbours.
      if (grid.chain_within(grid.head(own), x, limit, ball_limit)) continue;
      if (!neighbours_found) {
        // Once per cell: only this cell gains points until the next one.
        neighbours_found = true;
        occupied = grid.neighbour_heads(grid.cell_of(x), heads);
      }
      if (std::any_of(heads.begin(), heads.begin() + static_cast<std::ptrdiff_t>(occupied),
                      [&](std::uint32_t head) { return grid.chain_within(head, x, limit, ball_limit); }))
        continue;
      grid.add_at(own, key, WeightedPoint::from(x));
      chosen.push_back(i);
    }
  }
  return chosen;
}

}  // namespace

std::vector<std::uint32_t> select_separated_points(std::span<const Vec3> candidates,
                                                   std::span<const WeightedPoint> balls,
                                                   std::span<const Vec3> fixed, double spacing,
                                                   std::span<const double> local_spacing, bool* decided) {
  const SelectionPart whole{0, candidates.size(), 1};
  return select_in_parts(candidates, {&whole, 1}, balls, fixed, spacing, 1, local_spacing, decided, {});
}

std::vector<std::uint32_t> select_sample(std::span<const Vec3> candidates, const CandidateParts& parts,
                                         std::span<const WeightedPoint> balls, std::span<const Vec3> fixed,
                                         double spacing, std::span<const double> local_spacing, bool* net_decided,
                                         double ball_clearance, const std::function<bool()>& stop) {
  if (net_decided) *net_decided = false;
  if (!(ball_clearance > 0 && ball_clearance <= 1)) return {};
  const std::size_t lattice = std::min(parts.lattice, candidates.size());
  const std::size_t net = std::min(parts.net, candidates.size() - lattice);
  const std::array<SelectionPart, 3> three{SelectionPart{0, lattice, 1},
                                           SelectionPart{lattice, candidates.size() - lattice - net, kGapFillSpacing},
                                           SelectionPart{candidates.size() - net, net, kGapFillSpacing}};
  std::array<bool, 3> decided{};
  std::vector<std::uint32_t> chosen =
      select_in_parts(candidates, three, balls, fixed, spacing, ball_clearance, local_spacing, decided.data(), stop);
  if (net_decided) *net_decided = net > 0 && decided[2];
  return chosen;
}

double sample_cover_power(double spacing, double net_radius, double largest_ball_radius, double ball_clearance) {
  const double s = spacing, h = net_radius, r = largest_ball_radius, ks = ball_clearance * spacing;
  const double near_point = (s + h) * (s + h);
  const double near_ball = ks * ks + h * h + 2 * h * std::sqrt(ks * ks + r * r);
  return std::max(near_point, near_ball);
}

}  // namespace delpsc::refine

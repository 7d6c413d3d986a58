#include "disk_condition.h"

#include <algorithm>

#include "link_shape.h"

namespace delpsc::refine {

const char* to_string(DiskFailure f) {
  switch (f) {
    case DiskFailure::none: return "none";
    case DiskFailure::d1: return "D1";
    case DiskFailure::d2: return "D2";
    case DiskFailure::d3: return "D3";
    case DiskFailure::d4: return "D4";
  }
  return "?";
}

DiskCondition::DiskCondition(const Domain& domain, const BallSource& balls,
                             const kernel::LargeVector<VertexPlace>& places)
    : domain_(&domain), balls_(&balls), places_(&places) {}

namespace {

std::size_t count_of(std::span<const std::uint32_t> list, std::uint32_t x) {
  return static_cast<std::size_t>(std::count(list.begin(), list.end(), x));
}

}  // namespace

void DiskCondition::patches_of(PointId p, std::vector<std::pair<std::uint32_t, bool>>& out) const {
  out.clear();
  if (p >= places_->size()) return;
  const VertexPlace& v = (*places_)[p];
  switch (v.kind) {
    case VertexPlace::Kind::outside: return;
    case VertexPlace::Kind::surface: out.emplace_back(v.patch, true); return;
    case VertexPlace::Kind::ball: break;
  }
  if (v.corner == kNoElement) {
    const auto patches = domain_->curve_patches(v.curve);
    for (const std::uint32_t s : patches) {
      if (std::any_of(out.begin(), out.end(), [&](const auto& e) { return e.first == s; })) continue;
      out.emplace_back(s, count_of(patches, s) >= 2);  // σ on both sides of the curve: a slit
    }
    return;
  }
  // A corner is interior to σ when every curve through it that bounds σ has σ on both sides
  // (the end of a slit), or when none does: a corner where separate sheets touch at a vertex
  // and no curve passes (protect::kCornerSheets, two spheres touching) lies inside each sheet,
  // whose umbrella there is a full disk. Otherwise it is on σ's boundary. (Taking such a corner
  // for a boundary point made D2 fail at every scale: the ball halved to the balls' floor.)
  for (const std::uint32_t s : domain_->corner_patches(v.corner)) {
    bool interior = true;
    for (const std::uint32_t c : domain_->corner_curves(v.corner)) {
      const std::size_t k = count_of(domain_->curve_patches(c), s);
      if (k != 0) interior &= k >= 2;
    }
    out.emplace_back(s, interior);
  }
}

bool DiskCondition::on_patch(PointId q, std::uint32_t patch) const {
  if (q >= places_->size()) return false;
  const VertexPlace& v = (*places_)[q];
  switch (v.kind) {
    case VertexPlace::Kind::outside: return false;
    case VertexPlace::Kind::surface: return v.patch == patch;
    case VertexPlace::Kind::ball: break;
  }
  const auto patches = v.corner == kNoElement ? domain_->curve_patches(v.curve) : domain_->corner_patches(v.corner);
  return std::find(patches.begin(), patches.end(), patch) != patches.end();
}

DiskFailure DiskCondition::check_pinched_link(std::span<const std::array<PointId, 2>> link,
                                              std::span<const std::array<std::uint32_t, 2>> fans) const {
  thread_local std::vector<LinkPiece> pieces;
  if (!link_pieces(link, pieces) || pieces.size() != fans.size()) return DiskFailure::d1;
  // A path's end lies on a curve when it is a ball of that curve or at a corner it ends at.
  const auto on_curve = [this](PointId q, std::uint32_t curve) {
    if (q >= places_->size() || (*places_)[q].kind != VertexPlace::Kind::ball) return false;
    const VertexPlace& v = (*places_)[q];
    if (v.corner == kNoElement) return v.curve == curve;
    const auto curves = domain_->corner_curves(v.corner);
    return std::find(curves.begin(), curves.end(), curve) != curves.end();
  };
  return pieces_match_fans(pieces, fans, on_curve) ? DiskFailure::none : DiskFailure::d2;
}

DiskVerdict DiskCondition::check(PointId p, std::span<const Incidence> incident) const {
  thread_local std::vector<std::pair<std::uint32_t, bool>> patches;
  patches_of(p, patches);
  const bool p_is_ball = p < places_->size() && (*places_)[p].kind == VertexPlace::Kind::ball;
  DiskVerdict late;  // first D3/D4 failure, reported if no D1/D2 failure is found
  // Scratch kept between calls: check runs after every insertion for each touched vertex, and
  // five allocations per call showed in profiles (malloc/free ~3% of meshing).
  thread_local std::vector<std::array<PointId, 2>> link;
  thread_local std::vector<std::uint32_t> link_facet;
  for (const auto& [sigma, interior] : patches) {
    link.clear();
    link_facet.clear();
    for (const Incidence& x : incident) {
      if (x.patch != sigma) continue;
      link.push_back(x.link);
      link_facet.push_back(x.slot);
    }
    if (link.empty()) return {DiskFailure::d1, sigma, kNoFacet};
    const auto fans = p_is_ball && (*places_)[p].corner != kNoElement
                          ? domain_->corner_pinch_fans((*places_)[p].corner, sigma)
                          : std::span<const std::array<std::uint32_t, 2>>{};
    if (!fans.empty()) {
      // σ pinched at this corner: one disk per fan of the input (link_shape.h), D1 for the
      // count of disks, D2 for their kinds and the curves each open one runs between.
      if (const DiskFailure f = check_pinched_link(link, fans); f != DiskFailure::none) return {f, sigma, kNoFacet};
    } else {
      const LinkShape shape = link_shape(link);
      if (!shape.simple) return {DiskFailure::d1, sigma, kNoFacet};
      // Connected with degrees <= 2: a cycle when E == V, a path when E == V - 1.
      const bool cycle = link.size() == shape.vertices;
      if (cycle != interior) return {DiskFailure::d2, sigma, kNoFacet};
    }
    if (late.failure != DiskFailure::none) continue;
    for (std::size_t i = 0; i < link.size() && late.failure == DiskFailure::none; ++i) {
      for (const PointId q : link[i]) {
        if (!on_patch(q, sigma)) {
          late = {DiskFailure::d4, sigma, link_facet[i]};
          break;
        }
        if (p_is_ball && (*places_)[q].kind == VertexPlace::Kind::ball &&
            !balls_->adjacent((*places_)[p].ball, (*places_)[q].ball)) {
          late = {DiskFailure::d3, sigma, link_facet[i]};
          break;
        }
      }
    }
  }
  // A triangle restricted to a patch σ that does not contain p: it belongs to no umbrella checked
  // above (those are taken over p's own patches), yet it would put p into Skl²|σ. It is the D4
  // failure of its vertices that lie in σ, if any; reporting it at p too covers a triangle none
  // of whose vertices lie in σ (seen on a rotated box with a fin at 4%).
  if (late.failure == DiskFailure::none)
    for (const Incidence& x : incident) {
      if (std::none_of(patches.begin(), patches.end(), [&](const auto& e) { return e.first == x.patch; }))
        return {DiskFailure::d4, x.patch, x.slot};
    }
  return late;
}

}  // namespace delpsc::refine

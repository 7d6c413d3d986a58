// Disk_Condition(p) of DelPSC (Dey & Levine 2009, §3), checked on the umbrellas
// Umb_σ(p) = the restricted triangles of Skl²|σ incident to p, for every patch σ containing p:
//  (D1) the underlying space of Umb_σ(p) is a 2-disk (here: non-empty, and the link of p - the
//       edges opposite p - is one simple path or one simple cycle; at a corner where σ touches
//       itself, a pinch, one disk per fan of σ there: link_shape.h's link_pieces);
//  (D2) p is inside that disk (cycle) iff p ∈ int σ (an unweighted point, or a ball on a curve
//       with σ on both of its sides, like a slit), on its boundary (path) otherwise; at a pinch,
//       a cycle per closed fan and a path per open one, between the fan's two curves;
//  (D3) a vertex p on a curve or corner is joined in Umb_σ(p) to no ball that is not adjacent to it;
//  (D4) every vertex of Umb_σ(p) lies in σ; here also: no restricted triangle incident to p is
//       restricted to a patch that does not contain p (otherwise a triangle of σ with no vertex
//       in σ would escape every umbrella).
// Once the restricted triangles are known the checks are combinatorial. Cost: O(k^2) for an
// umbrella of k triangles (k is ~6-20); its link's shape in O(k) (link_shape.h; O(k^2) up to 16
// edges).
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include <delpsc/kernel/large_array.h>

#include "ball_source.h"
#include "restricted_facets.h"

namespace delpsc::refine {

/// Where a point of the mesher's triangulation lies in the complex.
struct VertexPlace {
  enum class Kind : std::uint8_t {
    outside,  ///< not on the domain (the far frame points of the mesher)
    surface,  ///< an unweighted point inserted on `patch`
    ball,     ///< the centre of protecting ball `ball`, on `curve` or at `corner`
  };
  Kind kind = Kind::outside;
  std::uint32_t patch = kNoElement;
  BallKey ball = kNoBallKey;
  std::uint32_t curve = kNoElement;
  std::uint32_t corner = kNoElement;
};

enum class DiskFailure : std::uint8_t { none, d1, d2, d3, d4 };
const char* to_string(DiskFailure f);

struct DiskVerdict {
  DiskFailure failure = DiskFailure::none;
  std::uint32_t patch = kNoElement;  ///< the σ of the failing umbrella
  std::uint32_t facet = kNoFacet;    ///< D3/D4: a restricted facet of Umb_σ(p) showing the failure
};

class DiskCondition {
 public:
  /// All three must outlive this object; `places` is indexed by PointId and may grow.
  DiskCondition(const Domain& domain, const BallSource& balls, const kernel::LargeVector<VertexPlace>& places);

  /// The patches containing p, with whether p is interior to each (see D2).
  void patches_of(PointId p, std::vector<std::pair<std::uint32_t, bool>>& out) const;
  /// Whether vertex q lies on patch σ (for D4).
  bool on_patch(PointId q, std::uint32_t patch) const;
  /// The first failure found at p, D1/D2 reported before D3/D4; none for a point outside the
  /// domain. `incident`: every restricted facet with vertex p (RestrictedFacets::incident(p)),
  /// each with its patch and the two other vertices; any order.
  DiskVerdict check(PointId p, std::span<const Incidence> incident) const;
  DiskVerdict check(PointId p, const RestrictedFacets& facets) const { return check(p, facets.incident(p)); }

 private:
  /// D1/D2 at a corner where σ is pinched, for Umb_σ(p)'s link: one piece per fan of the input.
  DiskFailure check_pinched_link(std::span<const std::array<PointId, 2>> link,
                                 std::span<const std::array<std::uint32_t, 2>> fans) const;

  const Domain* domain_;
  const BallSource* balls_;
  const kernel::LargeVector<VertexPlace>* places_;
};

}  // namespace delpsc::refine

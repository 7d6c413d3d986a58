// The criteria step 2(b) of DelPSC refines restricted facets against (Dey & Levine 2009, §3), with
// the names CGAL Mesh_3 users know:
//   facet_size      size(t, σ) ≤ λ, or ≤ sizing(x) with a sizing function - the paper's λ-size
//                   property (§2), measured at x, the point of V_t ∩ σ realising size(t, σ);
//   facet_distance  |c_t - x| ≤ D, c_t the orthocentre of t (its circumcentre when t's vertices
//                   are unweighted): how far the triangle strays from the surface point it stands
//                   for, CGAL's "facet_distance";
//   facet_angle     every angle of t ≥ θ, only for triangles whose three vertices are unweighted -
//                   the quality extension of §5 ("bounded aspect ratio for most triangles except
//                   the ones near non-smooth regions"): triangles with a ball vertex are exempt,
//                   since nothing may be inserted inside a ball to fix them.
//
// Termination. Every point inserted is x of a bad record, the point of V_t power-nearest to t's
// vertices, so its distance to every unweighted vertex is at least size(t, σ), and it lies outside
// every ball. The packing argument of Theorem 3.1 therefore goes through as long as each criterion
// only fires on records whose size is bounded below:
//   - facet_size: size > λ (or > sizing(x) ≥ its positive infimum);
//   - facet_distance: for an unweighted t, size² = |c_t - x|² + R_t² ≥ |c_t - x|² > D², so size > D;
//     for a t with a weighted vertex the orthoradius² can be negative, so we also require size > D;
//   - facet_angle: size ≥ R_t (x on V_t) and a triangle with angle < θ has R_t > ℓ_min/(2 sin θ).
//     With θ ≤ 30° (radius-edge ratio ≥ 1) the inserted point is no closer to the mesh than the
//     shortest edge it removes - Chew's argument, the same bound CGAL documents for its
//     facet_angle. kMaxFacetAngleDegrees is therefore the largest bound accepted.
#pragma once

#include <cstdint>
#include <functional>

#include <delpsc/delaunay/regular_triangulation.h>

#include "restricted_facets.h"

namespace delpsc::refine {

/// The largest facet_angle (degrees) for which refinement is known to terminate (see above).
inline constexpr double kMaxFacetAngleDegrees = 30;

/// Which criterion a record fails worst.
enum class FacetCriterion : std::uint8_t { none, size, distance, angle };
const char* to_string(FacetCriterion c);

struct FacetCriteriaOptions {
  double facet_size = 0;       ///< λ (absolute length); 0: only `sizing` bounds the size
  /// λ as a function of position (absolute length, must be > 0 and finite wherever it is asked);
  /// empty: the constant facet_size. When both are given the smaller one applies.
  std::function<double(const Vec3&)> sizing;
  double facet_distance = 0;   ///< D (absolute length); 0: off
  double facet_angle = 0;      ///< θ in degrees, in [0, kMaxFacetAngleDegrees]; 0: off
};

class FacetCriteria {
 public:
  /// Throws std::invalid_argument for impossible values (negative, NaN, θ > 30°, no size at all).
  explicit FacetCriteria(FacetCriteriaOptions options);

  /// How badly record r fails: the largest of size/λ(x), |c_t - x|/D and sin θ / sin(min angle)
  /// over the criteria that apply (see the file comment); > 1 means r must be refined. Sets
  /// `*which` to the criterion realising it when `which` is non-null. Throws std::domain_error
  /// when the sizing function returns a non-positive or non-finite value. O(1) plus one sizing call.
  double badness(const RestrictedFacet& r, const delaunay::RegularTriangulation& dt,
                 FacetCriterion* which = nullptr) const;

  const FacetCriteriaOptions& options() const { return options_; }
  /// λ at x: the smaller of facet_size and sizing(x) (+inf with neither). Throws as badness().
  double size_bound(const Vec3& x) const;

 private:

  FacetCriteriaOptions options_;
  double sin_angle_ = 0;  // sin θ
};

}  // namespace delpsc::refine

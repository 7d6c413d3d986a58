#include "facet_criteria.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include <delpsc/kernel/constructions.h>

#include "mesh_quality.h"

namespace delpsc::refine {

const char* to_string(FacetCriterion c) {
  switch (c) {
    case FacetCriterion::none: return "none";
    case FacetCriterion::size: return "facet_size";
    case FacetCriterion::distance: return "facet_distance";
    case FacetCriterion::angle: return "facet_angle";
  }
  return "?";
}

namespace {

void require_length(double value, const char* name) {
  if (!(value >= 0) || !std::isfinite(value))
    throw std::invalid_argument(std::string(name) + " must be a finite length >= 0 (got " + std::to_string(value) + ")");
}

}  // namespace

FacetCriteria::FacetCriteria(FacetCriteriaOptions options) : options_(std::move(options)) {
  require_length(options_.facet_size, "facet_size");
  require_length(options_.facet_distance, "facet_distance");
  if (options_.facet_size == 0 && !options_.sizing)
    throw std::invalid_argument("facet_size must be positive (or a sizing function given)");
  if (!(options_.facet_angle >= 0) || !(options_.facet_angle <= kMaxFacetAngleDegrees))
    throw std::invalid_argument("facet_angle must be between 0 and 30 degrees (got " +
                                std::to_string(options_.facet_angle) +
                                "): above 30 degrees refinement is not known to terminate");
  sin_angle_ = std::sin(options_.facet_angle * std::numbers::pi / 180);
}

double FacetCriteria::size_bound(const Vec3& x) const {
  double bound = options_.facet_size > 0 ? options_.facet_size : HUGE_VAL;
  if (options_.sizing) {
    const double s = options_.sizing(x);
    if (!(s > 0) || !std::isfinite(s))
      throw std::domain_error("sizing function returned " + std::to_string(s) + " at (" + std::to_string(x.x()) +
                              ", " + std::to_string(x.y()) + ", " + std::to_string(x.z()) +
                              "): it must be positive and finite on the whole domain");
    bound = std::min(bound, s);
  }
  return bound;
}

double FacetCriteria::badness(const RestrictedFacet& r, const delaunay::RegularTriangulation& dt,
                              FacetCriterion* which) const {
  double worst = r.size / size_bound(r.point);
  FacetCriterion worst_criterion = FacetCriterion::size;
  auto consider = [&](double value, FacetCriterion c) {
    if (value > worst) {
      worst = value;
      worst_criterion = c;
    }
  };
  const WeightedPoint a = dt.point(r.vertices[0]), b = dt.point(r.vertices[1]), c = dt.point(r.vertices[2]);
  const bool unweighted = a.w == 0 && b.w == 0 && c.w == 0;
  if (options_.facet_distance > 0 && (unweighted || r.size > options_.facet_distance)) {
    // A collinear t (no orthocentre) has V_t at infinity in the plane's directions: refine it.
    const auto centre = kernel::orthocentre(a, b, c);
    consider(centre ? (centre->point() - r.point).norm() / options_.facet_distance : HUGE_VAL, FacetCriterion::distance);
  }
  if (sin_angle_ > 0 && unweighted) {
    const double angle = triangle_min_angle(a.point(), b.point(), c.point());
    consider(angle > 0 ? sin_angle_ / std::sin(angle) : HUGE_VAL, FacetCriterion::angle);
  }
  if (which) *which = worst > 1 ? worst_criterion : FacetCriterion::none;
  return worst;
}

}  // namespace delpsc::refine

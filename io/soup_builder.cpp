#include "soup_builder.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdio>
#include <vector>

#include <delpsc/kernel/aabb_tree.h>
#include <delpsc/kernel/predicates.h>

#include "error.h"

namespace delpsc::io::detail {

std::string at_line(std::size_t line) { return "line " + std::to_string(line); }
std::string at_byte(std::size_t offset) { return "byte " + std::to_string(offset); }

std::string quoted(std::string_view token) {
  constexpr std::size_t kMax = 40;
  std::string out = "'";
  for (std::size_t i = 0; i < token.size() && i < kMax; ++i) {
    const auto c = static_cast<unsigned char>(token[i]);
    if (c >= 0x20 && c < 0x7f && c != '\\') {
      out += static_cast<char>(c);
    } else {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\x%02x", c);
      out += buf;
    }
  }
  if (token.size() > kMax) out += "...";
  return out + "'";
}

SoupBuilder::SoupBuilder(std::string name) : name_(std::move(name)), slots_(1024, 0) {}

void SoupBuilder::fail(std::string_view place, std::string_view what) const {
  std::string msg = name_ + ": ";
  if (!place.empty()) msg.append(place).append(": ");
  msg.append(what);
  throw Error(msg);
}

void SoupBuilder::check_count(std::uint64_t count, std::uint64_t min_bytes, std::uint64_t available,
                              std::uint64_t cap, std::string_view what,
                              std::string_view place) const {
  if (count > cap)
    fail(place, "the header announces " + std::to_string(count) + " " + std::string(what) +
                    ", more than the supported " + std::to_string(cap));
  // count * min_bytes <= available, written so that it cannot overflow.
  if (min_bytes > 0 && count > available / min_bytes)
    fail(place, "the header announces " + std::to_string(count) + " " + std::string(what) +
                    " but only " + std::to_string(available) +
                    " bytes follow (each needs at least " + std::to_string(min_bytes) +
                    "): truncated or corrupt file");
}

void SoupBuilder::reserve(std::size_t file_vertices, std::size_t triangles) {
  file_to_merged_.reserve(file_vertices);
  soup_.vertices.reserve(file_vertices);
  soup_.triangles.reserve(triangles);
  std::size_t want = slots_.size();
  while (want < 2 * file_vertices) want *= 2;
  if (want != slots_.size()) rehash(want);
}

namespace {

std::uint64_t mix(std::uint64_t h) {
  // The splitmix64 finaliser (Steele, Lea & Flood 2014): every input bit affects every output bit.
  h ^= h >> 30;
  h *= 0xbf58476d1ce4e5b9ULL;
  h ^= h >> 27;
  h *= 0x94d049bb133111ebULL;
  return h ^ (h >> 31);
}

std::uint64_t coordinate_hash(const Vec3& p) {
  // Adding +0.0 turns -0.0 into +0.0, so equal doubles hash equally.
  const auto bits = [](double v) { return std::bit_cast<std::uint64_t>(v + 0.0); };
  return mix(bits(p.x()) ^ mix(bits(p.y()) ^ mix(bits(p.z()))));
}

}  // namespace

void SoupBuilder::rehash(std::size_t slot_count) {
  slots_.assign(slot_count, 0);
  const std::size_t mask = slots_.size() - 1;
  for (std::uint32_t v = 0; v < soup_.vertices.size(); ++v) {
    std::size_t s = coordinate_hash(soup_.vertices[v]) & mask;
    while (slots_[s] != 0) s = (s + 1) & mask;
    slots_[s] = v + 1;
  }
}

std::uint32_t SoupBuilder::find_or_insert(const Vec3& p) {
  const std::size_t mask = slots_.size() - 1;
  std::size_t s = coordinate_hash(p) & mask;
  while (slots_[s] != 0) {
    const std::uint32_t v = slots_[s] - 1;
    if (soup_.vertices[v] == p) return v;  // == on doubles: -0 == +0, as hashed
    s = (s + 1) & mask;
  }
  const auto v = static_cast<std::uint32_t>(soup_.vertices.size());
  soup_.vertices.push_back(p);
  slots_[s] = v + 1;
  if (2 * soup_.vertices.size() > slots_.size()) rehash(2 * slots_.size());
  return v;
}

bool SoupBuilder::add_vertex(double x, double y, double z) {
  if (!std::isfinite(x) || !std::isfinite(y) || !std::isfinite(z)) return false;
  Vec3 p(x, y, z);
  for (int k = 0; k < 3; ++k) {
    const double m = std::fabs(p[k]);
    if (m != 0 && m < kernel::kMinExactMagnitude) {
      p[k] = 0;
      ++flushed_to_zero_;
      largest_flushed_ = std::max(largest_flushed_, m);
    } else if (m > kernel::kMaxExactMagnitude && first_too_large_ == SIZE_MAX) {
      first_too_large_ = file_to_merged_.size();
    }
  }
  file_to_merged_.push_back(find_or_insert(p));
  return true;
}

namespace {

/// Ear clipping is quadratic or worse: a convex polygon with more corners than this is fanned, a
/// concave one clipped up to kMostCornersClippedConcave corners (~0.1-1 s; its fan would overlap
/// itself: a star-shaped 1,000-gon was refused as a self-intersecting model) and fanned with a
/// warning beyond.
constexpr std::size_t kMostCornersClipped = 500;
constexpr std::size_t kMostCornersClippedConcave = 5000;
/// A triangle below this shape (add_polygon: about a 3° angle in a triangle of otherwise even
/// sides) is a sliver worth a second split, by best ears, of a polygon of at most
/// kMostCornersBestEar corners (O(n^3)).
constexpr double kPoorShape = 0.1;
constexpr std::size_t kMostCornersBestEar = 32;

/// 2D cross product of (b - a) and (c - b): > 0 where the boundary turns left at b.
double turn(const std::array<double, 2>& a, const std::array<double, 2>& b, const std::array<double, 2>& c) {
  return (b[0] - a[0]) * (c[1] - b[1]) - (b[1] - a[1]) * (c[0] - b[0]);
}

}  // namespace

// A convex polygon is fanned (v0 vi vi+1). A concave one's fan overlaps itself - a valid L-shaped
// face starting at its reflex corner was refused as a self-intersecting model - so it is split
// by ear clipping in its plane (projected along the largest component of its Newell normal),
// each ear kept in the polygon's order (orientation). Where clipping finds no ear (a polygon
// that is not simple in projection) the rest is fanned as before.
//
// Either can make slivers where corners are nearly in line: libcgal-demo's mpi.off has an 8-gon
// with four corners on one line within 4e-5 that became triangles of 0.0001° and 0.0006° whose
// computed normals were off by 64° and 79° - sharp edges, so feature curves, that are not in the
// model. So when the split has a triangle worse than kPoorShape, a polygon of at most
// kMostCornersBestEar corners is clipped again taking the best-shaped ear each time, and the
// split whose worst triangle is better is kept (every other polygon is split as before).
void SoupBuilder::add_polygon(std::span<const std::uint32_t> indices) {
  ++report_.polygons;
  const std::size_t n = indices.size();
  std::vector<std::uint32_t> v(n);
  for (std::size_t i = 0; i < n; ++i) v[i] = file_to_merged_[indices[i]];
  using Triangle = std::array<std::uint32_t, 3>;
  const auto fan = [](const std::vector<std::uint32_t>& corners, auto& out) {
    for (std::size_t i = 1; i + 1 < corners.size(); ++i) out.push_back({corners[0], corners[i], corners[i + 1]});
  };
  if (n <= 3) return fan(v, soup_.triangles);
  const auto& V = soup_.vertices;
  Vec3 normal = Vec3::Zero();
  for (std::size_t i = 0; i < n; ++i) normal += V[v[i]].cross(V[v[(i + 1) % n]]);
  int axis = 0;
  for (int k = 1; k < 3; ++k)
    if (std::fabs(normal[k]) > std::fabs(normal[axis])) axis = k;
  // Projected counter-clockwise: the axes after `axis`, swapped when the normal points down it.
  int u = (axis + 1) % 3, w = (axis + 2) % 3;
  if (normal[axis] < 0) std::swap(u, w);
  std::vector<std::array<double, 2>> q(n);
  for (std::size_t i = 0; i < n; ++i) q[i] = {V[v[i]][u], V[v[i]][w]};
  bool convex = true;
  for (std::size_t i = 0; i < n && convex; ++i) convex = turn(q[(i + n - 1) % n], q[i], q[(i + 1) % n]) >= 0;
  if (n > kMostCornersClipped && convex) return fan(v, soup_.triangles);
  if (n > kMostCornersClippedConcave) {
    // Fanned, as every polygon this large was: "not convex" here is a floating-point verdict, and
    // corners along a straight side often turn by -1e-17 (a rotated square of 6,000 corners was
    // refused for it). Where the polygon really is concave the fan overlaps itself, which the
    // self-intersection check then finds exactly; the warning says why.
    if (nonconvex_fanned_++ == 0)
      report_.warnings.push_back("polygon " + std::to_string(report_.polygons) + " has " + std::to_string(n) +
                                 " corners and does not look convex: fanned from its first corner (clipping stops "
                                 "at " + std::to_string(kMostCornersClippedConcave) +
                                 " corners); if the model is then refused as intersecting itself, triangulate "
                                 "it beforehand");
    return fan(v, soup_.triangles);
  }

  // 4√3 area / (sum of squared sides): 1 for an equilateral triangle, 0 for a degenerate one.
  const auto shape = [&](std::size_t a, std::size_t b, std::size_t c) {
    const Vec3 &x = V[v[a]], &y = V[v[b]], &z = V[v[c]];
    const double sides = (y - x).squaredNorm() + (z - y).squaredNorm() + (x - z).squaredNorm();
    return sides > 0 ? 2 * std::sqrt(3.0) * (y - x).cross(z - x).norm() / sides : 0.0;
  };
  const auto inside = [&](const std::array<double, 2>& p, std::size_t a, std::size_t b, std::size_t c) {
    return turn(q[a], q[b], p) >= 0 && turn(q[b], q[c], p) >= 0 && turn(q[c], q[a], p) >= 0;
  };
  // Ear clipping, as positions in v: the first ear found (retrying the previous corner after a
  // cut), or the best-shaped ear each time. Returns the worst shape of the triangles made.
  const auto clip = [&](bool best_ear, std::vector<Triangle>& out) {
    std::vector<std::size_t> ring(n);  // the corners left
    for (std::size_t i = 0; i < n; ++i) ring[i] = i;
    double worst = 1;
    const auto is_ear = [&](std::size_t i) {
      const std::size_t m = ring.size();
      const std::size_t a = ring[(i + m - 1) % m], b = ring[i], c = ring[(i + 1) % m];
      if (!(turn(q[a], q[b], q[c]) > 0)) return false;
      for (const std::size_t r : ring)
        if (r != a && r != b && r != c && q[r] != q[a] && q[r] != q[b] && q[r] != q[c] && inside(q[r], a, b, c))
          return false;
      return true;
    };
    const auto cut = [&](std::size_t i) {
      const std::size_t m = ring.size();
      const std::size_t a = ring[(i + m - 1) % m], b = ring[i], c = ring[(i + 1) % m];
      out.push_back({v[a], v[b], v[c]});
      worst = std::min(worst, shape(a, b, c));
      ring.erase(ring.begin() + static_cast<std::ptrdiff_t>(i));
    };
    if (best_ear) {
      while (ring.size() > 3) {
        std::size_t best = ring.size();
        double best_shape = -1;
        for (std::size_t i = 0; i < ring.size(); ++i) {
          const std::size_t m = ring.size();
          const double s = shape(ring[(i + m - 1) % m], ring[i], ring[(i + 1) % m]);
          if (s > best_shape && is_ear(i)) best = i, best_shape = s;
        }
        if (best == ring.size()) break;
        cut(best);
      }
    } else {
      for (std::size_t misses = 0, i = 0; ring.size() > 3 && misses < ring.size();) {
        i %= ring.size();
        if (!is_ear(i)) {
          i = (i + 1) % ring.size(), ++misses;
          continue;
        }
        cut(i);
        i = (i + ring.size() - 1) % ring.size(), misses = 0;  // retry the previous corner
      }
    }
    std::vector<std::uint32_t> rest;
    for (const std::size_t r : ring) rest.push_back(v[r]);
    for (std::size_t i = 1; i + 1 < ring.size(); ++i) worst = std::min(worst, shape(ring[0], ring[i], ring[i + 1]));
    fan(rest, out);
    return worst;
  };

  std::vector<Triangle> split;
  double worst = 1;
  if (convex) {
    fan(v, split);
    for (std::size_t i = 1; i + 1 < n; ++i) worst = std::min(worst, shape(0, i, i + 1));
  } else {
    worst = clip(false, split);
  }
  if (worst < kPoorShape && n <= kMostCornersBestEar) {
    std::vector<Triangle> better;
    if (clip(true, better) > worst) split.swap(better);
  }
  soup_.triangles.insert(soup_.triangles.end(), split.begin(), split.end());
}

ReadResult SoupBuilder::finish() {
  if (soup_.triangles.empty())
    fail("", report_.polygons == 0 && file_to_merged_.empty()
                 ? "no vertices and no faces: empty model"
                 : "no faces: the model has " + std::to_string(file_to_merged_.size()) +
                       " vertices but no triangles (a point cloud?)");
  report_.file_vertices = file_to_merged_.size();
  report_.merged_vertices = file_to_merged_.size() - soup_.vertices.size();
  // Setting a coordinate below 2^-140 to 0 moves its vertex by less than that: nothing on a model
  // of ordinary size, but a visible distortion of one that small itself (fandisk scaled by 1e-40
  // meshed with 572 coordinates zeroed and its shape changed; by 1e-42 it was refused as having
  // no triangle of non-zero area). Refused when the move exceeds 2^-40 of the model's extent.
  if (flushed_to_zero_ > 0) {
    kernel::Box3 box;
    for (const Vec3& p : soup_.vertices) box.extend(p);
    const double extent = (box.hi - box.lo).cwiseAbs().maxCoeff();
    if (!(largest_flushed_ <= 0x1p-40 * extent)) {
      // The extent is taken after the flush: a model all of whose coordinates are that small is
      // then 0 across, which the message must not print as its size.
      char size[64] = ", and none of the model's is larger";
      if (extent > 0) std::snprintf(size, sizeof size, ", on a model only %.3g across", extent);
      char text[320];
      std::snprintf(text, sizeof text,
                    "%zu coordinate(s) smaller than 2^-140 (about 7e-43) in magnitude, the range of the exact "
                    "predicates, up to %.3g%s: setting them to 0 would change its shape; scale the model up",
                    flushed_to_zero_, largest_flushed_, size);
      fail("", text);
    }
  }

  const auto& V = soup_.vertices;
  for (std::uint32_t t = 0; t < soup_.triangles.size(); ++t) {
    const auto& [a, b, c] = soup_.triangles[t];
    if (a == b || b == c || a == c || kernel::collinear(V[a].data(), V[b].data(), V[c].data()))
      report_.degenerate_triangles.push_back(t);
  }
  if (!report_.degenerate_triangles.empty())
    report_.warnings.push_back(std::to_string(report_.degenerate_triangles.size()) +
                               " zero-area triangle(s) (repeated or collinear vertices), first: "
                               "triangle " + std::to_string(report_.degenerate_triangles[0]));

  // The exact predicates are guaranteed for coordinates 0 or of magnitude in [2^-140, 2^140]
  // (kernel/predicates.h): beyond that a model would fail later, and mysteriously.
  if (first_too_large_ != SIZE_MAX)
    fail("", "vertex " + std::to_string(first_too_large_) +
                 " has a coordinate larger than 2^140 (about 1.4e42) in magnitude, beyond the range where the "
                 "exact predicates are exact: scale the model down");
  if (flushed_to_zero_ > 0)
    report_.warnings.push_back(std::to_string(flushed_to_zero_) +
                               " coordinate(s) smaller than 2^-140 (about 7e-43) in magnitude set to 0, the "
                               "range of the exact predicates");
  if (report_.merged_vertices > 0 && report_.format.rfind("STL", 0) != 0)
    report_.warnings.push_back(std::to_string(report_.merged_vertices) +
                               " duplicated vertex record(s) merged");
  return {std::move(soup_), std::move(report_)};
}

}  // namespace delpsc::io::detail

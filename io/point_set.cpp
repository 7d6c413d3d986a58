#include "point_set.h"

#include <bit>
#include <cmath>
#include <cstdio>
#include <cstdint>
#include <cstring>
#include <sstream>

#include <delpsc/kernel/predicates.h>

#include "error.h"
#include "input_bytes.h"
#include "output_file.h"

namespace delpsc::io {

namespace {

static_assert(std::endian::native == std::endian::little,
              "the binary point format is little-endian; add byte swapping for this platform");

bool has_suffix(const std::string& s, const std::string& suffix) {
  return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

// Finite, and inside the range where the predicates are exact (kernel/predicates.h): a point
// set is the triangulation's exact input, so nothing is rounded to fit - it is refused.
void require_in_exact_range(const WeightedPoint& p, const std::string& path, const std::string& where) {
  const double v[4] = {p.x, p.y, p.z, p.w};
  static const char* names[4] = {"x", "y", "z", "w"};
  for (int k = 0; k < 4; ++k) {
    if (!std::isfinite(v[k])) throw Error(path + ": " + where + ": " + names[k] + " is not a finite number");
    const bool weight = k == 3;
    const double m = std::fabs(v[k]);
    const double lo = weight ? kernel::kMinExactWeight : kernel::kMinExactMagnitude;
    const double hi = weight ? kernel::kMaxExactWeight : kernel::kMaxExactMagnitude;
    if (m == 0 || (lo <= m && m <= hi)) continue;
    char value[32];
    std::snprintf(value, sizeof value, "%.6g", v[k]);
    throw Error(path + ": " + where + ": " + names[k] + " = " + value + " is outside 0 or " +
                (weight ? "[2^-280, 2^280]" : "[2^-140, 2^140]") +
                " in magnitude, the range where the predicates are exact: scale the points");
  }
}

std::vector<WeightedPoint> read_binary(const std::string& path, const kernel::LargeVector<char>& bytes) {
  const std::size_t size = bytes.size();
  if (size % 32 != 0)
    throw Error(path + ": size " + std::to_string(size) +
                " bytes is not a multiple of 32 (records of four doubles x y z w)");
  std::vector<WeightedPoint> points(size / 32);
  if (size > 0) std::memcpy(points.data(), bytes.data(), size);
  for (std::size_t i = 0; i < points.size(); ++i)
    require_in_exact_range(points[i], path, "record " + std::to_string(i) + " (byte " +
                                        std::to_string(i * 32) + ")");
  return points;
}

std::vector<WeightedPoint> read_text(const std::string& path, const kernel::LargeVector<char>& bytes) {
  std::istringstream in(std::string(bytes.data(), bytes.size()));
  std::vector<WeightedPoint> points;
  std::string line;
  std::size_t line_no = 0;
  while (std::getline(in, line)) {
    ++line_no;
    const auto first = line.find_first_not_of(" \t\r");
    if (first == std::string::npos || line[first] == '#') continue;
    std::istringstream fields(line);
    double v[5];
    int n = 0;
    std::string token;
    while (fields >> token) {
      if (n == 4) throw Error(path + ": line " + std::to_string(line_no) +
                              ": more than four numbers (expected x y z [w])");
      char* end = nullptr;
      v[n] = std::strtod(token.c_str(), &end);
      if (end == token.c_str() || *end != '\0')
        throw Error(path + ": line " + std::to_string(line_no) + ": '" + token +
                    "' is not a number");
      ++n;
    }
    if (n < 3)
      throw Error(path + ": line " + std::to_string(line_no) +
                  ": expected x y z [w], found " + std::to_string(n) + " number(s)");
    WeightedPoint p{v[0], v[1], v[2], n == 4 ? v[3] : 0.0};
    require_in_exact_range(p, path, "line " + std::to_string(line_no));
    points.push_back(p);
  }
  return points;
}

}  // namespace

std::vector<WeightedPoint> read_point_set(const std::string& path) {
  // A pipe is waited on for as long as its writer takes (PipeWait's default).
  const kernel::LargeVector<char> bytes = read_input_bytes(path, "point set file");
  return has_suffix(path, ".bin") ? read_binary(path, bytes) : read_text(path, bytes);
}

void write_point_set(const std::string& path, const std::vector<WeightedPoint>& points) {
  if (has_suffix(path, ".bin")) {
    write_output_file(path, std::string_view(reinterpret_cast<const char*>(points.data()),
                                             points.size() * sizeof(WeightedPoint)));
    return;
  }
  std::ostringstream out;
  out.precision(17);
  for (const auto& p : points) out << p.x << ' ' << p.y << ' ' << p.z << ' ' << p.w << '\n';
  write_output_file(path, out.str());
}

}  // namespace delpsc::io

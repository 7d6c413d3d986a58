// The body shared by the libFuzzer targets: parse the input as one model format and check that
// the reader either throws io::Error or returns a soup that keeps every promise of read_model.h.
// Any other exception, a sanitizer report, a leak or a broken promise is a crash for libFuzzer.
#pragma once

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include <delpsc/io/error.h>
#include <delpsc/io/read_model.h>

namespace delpsc::fuzz {

inline void check(bool ok) {
  if (!ok) std::abort();
}

inline int read_one(const std::uint8_t* data, std::size_t size, io::ModelFormat format) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  try {
    const io::ReadResult r = io::read_model_from_memory(bytes, format, "fuzz");
    const auto& s = r.soup;
    check(!s.triangles.empty());
    for (const Vec3& p : s.vertices) check(std::isfinite(p.x()) && std::isfinite(p.y()) && std::isfinite(p.z()));
    for (const auto& t : s.triangles)
      for (const std::uint32_t v : t) check(v < s.vertices.size());
    check(r.report.file_vertices == s.vertices.size() + r.report.merged_vertices);
    for (const std::uint32_t t : r.report.degenerate_triangles) check(t < s.triangles.size());
  } catch (const io::Error&) {
    // The expected outcome for most inputs.
  }
  return 0;
}

}  // namespace delpsc::fuzz

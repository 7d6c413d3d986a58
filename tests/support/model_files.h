// Test helpers for io/ model readers and mesh writers: temporary files, byte strings built
// field by field (binary STL / PLY in either byte order), error capture, and a comparison of
// meshes by geometry rather than by vertex numbering.
#pragma once

#include <array>
#include <bit>
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>
#include <vector>

#include <delpsc/io/error.h>
#include <delpsc/io/read_model.h>

namespace delpsc::test {

/// A path in $TMPDIR (or /tmp) unique to this process.
std::string temp_path(const std::string& name);
void write_file(const std::string& path, std::string_view bytes);
std::string read_file(const std::string& path);

/// Parses `bytes` as `format` under the name "mem.EXT".
io::ReadResult read_bytes(std::string_view bytes, io::ModelFormat format);

/// The message of the io::Error thrown by f(), or "" if it returns normally. Any other exception
/// propagates (and fails the test).
template <class F>
std::string io_error_of(F&& f) {
  try {
    f();
  } catch (const io::Error& e) {
    return e.what();
  }
  return "";
}

/// Binary data assembled value by value in a chosen byte order.
class Bytes {
 public:
  explicit Bytes(std::endian order = std::endian::little) : order_(order) {}
  Bytes& text(std::string_view s) {
    data_.append(s);
    return *this;
  }
  template <class T>
  Bytes& put(T v) {
    char b[sizeof(T)];
    std::memcpy(b, &v, sizeof(T));
    if (order_ != std::endian::native)
      for (std::size_t i = 0; i < sizeof(T) / 2; ++i) std::swap(b[i], b[sizeof(T) - 1 - i]);
    data_.append(b, sizeof(T));
    return *this;
  }
  const std::string& str() const { return data_; }

 private:
  std::endian order_;
  std::string data_;
};

/// A triangle by its corner coordinates.
using CornerTriangle = std::array<std::array<double, 3>, 3>;

/// The triangles of a soup as coordinate triples, each rotated (never reflected, so orientation
/// counts) to start at its lexicographically smallest corner, then sorted: two soups have equal
/// canonical triangles iff they describe the same oriented triangles, however numbered.
std::vector<CornerTriangle> canonical_triangles(const io::TriangleSoup& soup);

/// The same, with every coordinate first rounded to float (what binary STL stores).
std::vector<CornerTriangle> canonical_triangles_as_float(const io::TriangleSoup& soup);

}  // namespace delpsc::test

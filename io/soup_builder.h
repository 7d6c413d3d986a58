// Internal to io/: what every model parser shares — the growing soup with exact-duplicate vertex
// merging, fan triangulation, error messages with a place, and the final checks.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <delpsc/kernel/large_array.h>

#include "read_model.h"

namespace delpsc::io::detail {

/// "line N" / "byte N": the PLACE part of an error message.
std::string at_line(std::size_t line);
std::string at_byte(std::size_t offset);

/// A token from an untrusted file, fit for a message: quoted, control and non-ASCII bytes as
/// \xNN, cut after 40 characters.
std::string quoted(std::string_view token);

class SoupBuilder {
 public:
  explicit SoupBuilder(std::string name);

  const std::string& name() const { return name_; }
  ReadReport& report() { return report_; }

  /// Throws io::Error "NAME: PLACE: WHAT" (or "NAME: WHAT" when place is empty).
  [[noreturn]] void fail(std::string_view place, std::string_view what) const;

  /// Fails unless `count` records of at least `min_bytes` each fit into `available` bytes and
  /// count <= `cap`; call it before reserving anything from a count read in a header.
  void check_count(std::uint64_t count, std::uint64_t min_bytes, std::uint64_t available,
                   std::uint64_t cap, std::string_view what, std::string_view place) const;

  /// Capacity hints (call only with counts validated by check_count).
  void reserve(std::size_t file_vertices, std::size_t triangles);

  /// Adds the next vertex of the file and returns false, adding nothing, if a coordinate is NaN
  /// or infinite (the caller reports it with its place). Amortised O(1). The exact predicates
  /// cover coordinates 0 or of magnitude in [2^-140, 2^140] (kernel/predicates.h): a smaller one
  /// is set to 0 (a move below 1e-42, reported as a warning), a larger one makes finish() fail.
  bool add_vertex(double x, double y, double z);
  std::size_t file_vertex_count() const { return file_to_merged_.size(); }

  /// Adds a face by file vertex indices. Preconditions (checked by the parser, which knows the
  /// place): indices.size() >= 3, every index < file_vertex_count().
  void add_polygon(std::span<const std::uint32_t> indices);

  /// Checks the model is not empty, finds the zero-area triangles and completes the report.
  ReadResult finish();

 private:
  std::uint32_t find_or_insert(const Vec3& p);
  void rehash(std::size_t slot_count);  // slot_count: a power of two

  std::string name_;
  ReadReport report_;
  TriangleSoup soup_;
  kernel::LargeVector<std::uint32_t> file_to_merged_;
  std::size_t flushed_to_zero_ = 0;        // coordinates below 2^-140 set to 0
  double largest_flushed_ = 0;             // the largest magnitude among them
  std::size_t nonconvex_fanned_ = 0;       // polygons fanned though they look concave
  std::size_t first_too_large_ = SIZE_MAX;  // file index of the first vertex beyond 2^140
  // Open addressing, linear probing: slot = merged vertex index + 1, 0 = empty. Kept at most half
  // full. Flat arrays beat std::unordered_map by several times on millions of STL corners.
  kernel::LargeVector<std::uint32_t> slots_;
};

}  // namespace delpsc::io::detail

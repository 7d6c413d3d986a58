// Reading polygon models: OFF, OBJ, STL (ASCII and binary) and PLY (ASCII, binary little- and
// big-endian) into a TriangleSoup, with input validation good enough to face files from anywhere.
//
// Every reader
//  - fan-triangulates convex polygons (v0 vi vi+1) and ear-clips concave ones in their plane,
//    keeping the file's vertex order (orientation);
//  - merges exactly duplicated vertices (equal x, y and z as doubles; -0 equals +0) through a hash
//    on the coordinates, keeping the first occurrence: STL lists every triangle's corners
//    separately and needs it, the indexed formats get it too so that no format reaches the complex
//    builder with two copies of a point. Vertices no triangle uses stay (the commands drop them:
//    unused_vertices.h);
//  - keeps zero-area triangles (a repeated vertex after merging, or three exactly collinear
//    vertices, decided by the exact kernel predicate) but lists them in ReadReport, because
//    whether and how to drop them is the complex builder's decision;
//  - throws io::Error on bad input with a message "FILE: PLACE: PROBLEM", PLACE being
//    "line N" for text and "byte N" (offset from the start of the file) for binary data: missing
//    or unreadable file, unknown extension, truncated file, garbage, face index out of range,
//    faces with fewer than 3 vertices, NaN or infinite coordinates, header counts the file cannot
//    possibly hold (checked against the file size before anything is allocated from them), more
//    than 2^32 - 1 vertices, a model without triangles.
//
// Format notes (what is accepted beyond the letter of each format):
//  - OFF and OBJ: a UTF-8 byte-order mark at the start is skipped; lines may end in LF, CRLF or
//    a lone CR (classic Mac OS), mixed.
//  - OFF: header keyword [ST][C][N]OFF or none at all (Geomview allows it), counts on the same
//    line or the next; anything after a vertex's 3 coordinates or a face's indices on the same
//    line (normals, colours) is ignored; '#' comments. Binary OFF, 4OFF and nOFF are refused.
//  - OBJ: "v x y z ..." and "f" with i, i/t, i/t/n, i//n index forms, negative (relative)
//    indices; indices must refer to vertices already defined; other statements are ignored.
//  - STL: binary if the size is exactly 84 + 50 n for the count n in the header, even when the
//    header starts with "solid" (many exporters write that); otherwise ASCII if it starts with
//    "solid" and has no NUL byte in its first kilobyte; otherwise binary (and then truncated or
//    padded). ASCII keywords are case-insensitive; several solids per file are read. Normals are
//    ignored: the vertex order gives the orientation.
//  - PLY: x, y, z of any numeric type among other vertex properties in any order; faces from the
//    list "vertex_indices" or "vertex_index" (any integer count and index types); every other
//    element and property is skipped.
//
// Cost: the file is read into memory once and parsed in a single pass; time and memory O(file
// size). About 1M triangles per few hundred ms in binary formats (BENCHMARKS.md).
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "input_bytes.h"
#include "triangle_soup.h"

namespace delpsc::io {

enum class ModelFormat { off, obj, stl, ply };

/// What the reader saw and did, alongside the soup. Warnings are single human-readable lines for
/// the user (they never repeat the file name); nothing in them is an error.
struct ReadReport {
  /// "OFF", "OBJ", "STL (ASCII)", "STL (binary)", "PLY (ASCII)", "PLY (binary little-endian)"...
  std::string format;
  /// Vertex records in the file (for STL: three per facet).
  std::size_t file_vertices = 0;
  /// Of those, how many were exact duplicates merged into an earlier vertex.
  std::size_t merged_vertices = 0;
  /// Faces (polygons, STL facets) in the file; each gives (corners - 2) triangles.
  std::size_t polygons = 0;
  /// Indices into TriangleSoup::triangles of the zero-area triangles, increasing.
  std::vector<std::uint32_t> degenerate_triangles;
  /// Vertices no triangle uses, once dropped (io/unused_vertices.h; the readers keep them and
  /// leave this 0, the commands drop them and count them here).
  std::size_t unused_vertices = 0;
  std::vector<std::string> warnings;
};

struct ReadResult {
  TriangleSoup soup;
  ReadReport report;
};

/// The format named by the extension of `path` (case-insensitive .off .obj .stl .ply), or nullopt.
std::optional<ModelFormat> model_format_from_path(const std::string& path);

/// Reads a model file; the format is chosen by the extension. Throws io::Error (see above), and
/// ReadStopped when `wait.stop` gave up on a pipe without data.
ReadResult read_model(const std::string& path, const PipeWait& wait = {});

/// Parses a model already in memory (the fuzz targets and tests use it); `name` stands for the
/// file name in messages. Throws io::Error.
ReadResult read_model_from_memory(std::string_view bytes, ModelFormat format, const std::string& name);

}  // namespace delpsc::io

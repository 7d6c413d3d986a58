// STL, binary (80-byte header, uint32 count, 50-byte facet records: normal, 3 vertices as float,
// uint16 attribute) and ASCII (solid / facet normal / outer loop / vertex / endloop / endfacet /
// endsolid). Every facet lists its own corners: the SoupBuilder's merging restores the sharing.
#include <algorithm>
#include <string>
#include <vector>

#include "byte_order.h"
#include "model_parsers.h"
#include "text_scanner.h"

namespace delpsc::io::detail {

namespace {

constexpr std::size_t kHeaderBytes = 84;
constexpr std::size_t kFacetBytes = 50;

bool starts_with_solid(std::string_view bytes) {
  const std::size_t first = bytes.find_first_not_of(" \t\r\n");
  return first != std::string_view::npos &&
         equals_ignoring_case(bytes.substr(first, 5), "solid");
}

// Many binary exporters start the free-form header with "solid", so the keyword alone proves
// nothing. A size of exactly 84 + 50 n is near-certain proof of binary; a NUL byte early on
// proves it is not text.
}  // namespace

bool stl_size_proves_binary(std::string_view bytes) {
  if (bytes.size() < kHeaderBytes) return false;
  const auto n = load<std::uint32_t>(bytes.data() + 80, std::endian::little);
  return kHeaderBytes + kFacetBytes * std::uint64_t{n} == bytes.size();
}

namespace {

bool is_binary(std::string_view bytes) {
  if (stl_size_proves_binary(bytes)) return true;
  if (!starts_with_solid(bytes)) return true;
  const std::string_view head = bytes.substr(0, 1024);
  return head.find('\0') != std::string_view::npos;
}

void parse_binary(std::string_view bytes, SoupBuilder& out) {
  out.report().format = "STL (binary)";
  if (bytes.size() < kHeaderBytes)
    out.fail(at_byte(bytes.size()), "truncated: a binary STL starts with an 84-byte header, the file has " +
                                        std::to_string(bytes.size()) + " bytes");
  std::uint64_t n = load<std::uint32_t>(bytes.data() + 80, std::endian::little);
  // Some exporters leave the count at 0 or stale: more whole records than announced, and nothing
  // else, are all read (a file with a zero count was an 'empty model', one with a low count lost
  // its last triangles behind a warning that -q hid).
  const std::uint64_t records = (bytes.size() - kHeaderBytes) / kFacetBytes;
  if (records > n && (bytes.size() - kHeaderBytes) % kFacetBytes == 0) {
    out.report().warnings.push_back("the header announces " + std::to_string(n) + " triangles but the file holds " +
                                    std::to_string(records) + " whole records: all " + std::to_string(records) +
                                    " read");
    n = records;
  }
  // Three file vertices per facet are indexed with uint32.
  out.check_count(n, kFacetBytes, bytes.size() - kHeaderBytes, kMaxVertices / 3, "triangles",
                  at_byte(80));
  const std::uint64_t expected = kHeaderBytes + kFacetBytes * n;
  if (expected < bytes.size())
    out.report().warnings.push_back(std::to_string(bytes.size() - expected) +
                                    " bytes after the last triangle ignored");
  out.reserve(3 * n, n);
  for (std::uint32_t t = 0; t < n; ++t) {
    const std::size_t record = kHeaderBytes + kFacetBytes * t;
    for (std::size_t k = 0; k < 3; ++k) {
      const std::size_t at = record + 12 + 12 * k;  // past the normal
      const char* p = bytes.data() + at;
      const float x = load<float>(p, std::endian::little);
      const float y = load<float>(p + 4, std::endian::little);
      const float z = load<float>(p + 8, std::endian::little);
      if (!out.add_vertex(x, y, z))
        out.fail(at_byte(at), "triangle " + std::to_string(t) + ", vertex " + std::to_string(k) +
                                  ": NaN or infinite coordinate");
    }
    const std::uint32_t corners[3] = {3 * t, 3 * t + 1, 3 * t + 2};
    out.add_polygon(corners);
  }
}

void parse_ascii(std::string_view bytes, SoupBuilder& out) {
  out.report().format = "STL (ASCII)";
  TextScanner in(bytes, '\0');
  const auto expect = [&](std::string_view keyword) {
    const std::string_view tok = in.token();
    if (tok.empty())
      out.fail(at_line(in.line()), "unexpected end of file, expected '" + std::string(keyword) +
                                       "' (truncated?)");
    if (!equals_ignoring_case(tok, keyword))
      out.fail(at_line(in.line()), "expected '" + std::string(keyword) + "', found " + quoted(tok));
  };
  const auto number = [&](std::string_view what) {
    const std::string_view tok = in.token();
    if (tok.empty())
      out.fail(at_line(in.line()), "unexpected end of file in " + std::string(what) + " (truncated?)");
    double v = 0;
    if (!parse_double(tok, v))
      out.fail(at_line(in.line()), std::string(what) + ": " + quoted(tok) + " is not a number");
    return v;
  };

  expect("solid");
  in.next_line();  // the solid's name
  bool closed = false;
  std::vector<std::uint32_t> polygon;
  for (std::string_view tok = in.token(); !tok.empty(); tok = in.token()) {
    if (equals_ignoring_case(tok, "endsolid")) {
      closed = true;
      in.next_line();
    } else if (closed && equals_ignoring_case(tok, "solid")) {  // several solids in one file
      closed = false;
      in.next_line();
    } else if (!closed && equals_ignoring_case(tok, "facet")) {
      expect("normal");
      for (int k = 0; k < 3; ++k) number("facet normal");  // unused: may even be NaN
      expect("outer");
      expect("loop");
      polygon.clear();
      for (;;) {
        const std::string_view word = in.token();
        if (equals_ignoring_case(word, "endloop")) break;
        if (word.empty())
          out.fail(at_line(in.line()), "unexpected end of file inside a facet (truncated?)");
        if (!equals_ignoring_case(word, "vertex"))
          out.fail(at_line(in.line()), "expected 'vertex' or 'endloop', found " + quoted(word));
        const double x = number("vertex"), y = number("vertex"), z = number("vertex");
        if (out.file_vertex_count() >= kMaxVertices)
          out.fail(at_line(in.line()), "more than " + std::to_string(kMaxVertices) + " vertices");
        if (!out.add_vertex(x, y, z))
          out.fail(at_line(in.line()), "vertex has a NaN or infinite coordinate");
        polygon.push_back(static_cast<std::uint32_t>(out.file_vertex_count() - 1));
      }
      if (polygon.size() < 3)
        out.fail(at_line(in.line()), "facet with " + std::to_string(polygon.size()) +
                                         " vertices; at least 3 are needed");
      expect("endfacet");
      out.add_polygon(polygon);
    } else {
      out.fail(at_line(in.line()), std::string("expected ") +
                                       (closed ? "'solid' or the end of the file"
                                               : "'facet' or 'endsolid'") +
                                       ", found " + quoted(tok));
    }
  }
  if (!closed) out.report().warnings.push_back("missing 'endsolid' at the end of the file");
}

}  // namespace

void parse_stl(std::string_view bytes, SoupBuilder& out) {
  if (bytes.empty()) out.fail("", "empty file");
  // A UTF-8 byte-order mark before "solid" (some Windows editors add one): an ASCII file, which
  // otherwise was read as binary and refused for the count its header seemed to announce. A
  // binary file whose size proves it binary is read as such whatever its header holds.
  constexpr std::string_view kBom = "\xEF\xBB\xBF";
  if (bytes.starts_with(kBom) && !stl_size_proves_binary(bytes) && !is_binary(bytes.substr(kBom.size())))
    bytes.remove_prefix(kBom.size());
  if (is_binary(bytes))
    parse_binary(bytes, out);
  else
    parse_ascii(bytes, out);
}

}  // namespace delpsc::io::detail

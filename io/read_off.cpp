// OFF (Geomview Object File Format): "OFF", "nv nf ne", nv lines "x y z ...", nf lines
// "k i1 ... ik ...", 0-based indices.
#include <algorithm>
#include <string>
#include <vector>

#include "model_parsers.h"
#include "text_scanner.h"

namespace delpsc::io::detail {

namespace {

// [ST][C][N]OFF: texture coordinates, colours and normals ride along on the vertex lines after
// x y z, and we ignore the rest of every line anyway. 4OFF (homogeneous) and nOFF (any
// dimension) change what the numbers mean, so they are refused rather than misread.
bool is_supported_keyword(std::string_view k) {
  if (k.starts_with("ST")) k.remove_prefix(2);
  if (k.starts_with("C")) k.remove_prefix(1);
  if (k.starts_with("N")) k.remove_prefix(1);
  return k == "OFF";
}

std::string count_text(std::size_t i, std::size_t n) {
  return std::to_string(i) + " of " + std::to_string(n);
}

}  // namespace

void parse_off(std::string_view bytes, SoupBuilder& out) {
  out.report().format = "OFF";
  TextScanner in(bytes, '#');
  std::string_view tok = in.token();
  if (tok.empty()) out.fail("", "empty file (expected an OFF header)");

  std::int64_t nv = 0, nf = 0;
  if (!parse_int(tok, nv)) {  // the keyword is optional in Geomview's definition
    if (!is_supported_keyword(tok)) {
      if (tok.ends_with("OFF"))
        out.fail(at_line(in.line()), "OFF variant " + quoted(tok) + " is not supported");
      out.fail(at_line(in.line()), "expected the header 'OFF', found " + quoted(tok));
    }
    const std::string_view next = in.token_on_line();
    if (next == "BINARY") out.fail(at_line(in.line()), "binary OFF is not supported");
    tok = next.empty() ? in.token() : next;
    if (tok.empty()) out.fail(at_line(in.line()), "unexpected end of file: no vertex count");
    if (!parse_int(tok, nv))
      out.fail(at_line(in.line()), "expected the vertex count, found " + quoted(tok));
  }
  tok = in.token();
  const std::size_t header_line = in.line();
  if (tok.empty()) out.fail(at_line(in.line()), "unexpected end of file: no face count");
  if (!parse_int(tok, nf))
    out.fail(at_line(in.line()), "expected the face count, found " + quoted(tok));
  if (nv < 0 || nf < 0) out.fail(at_line(header_line), "negative vertex or face count");
  // The edge count, if any, is meaningless and skipped with the rest of the line; but three more
  // numbers there are vertex data written without line breaks, which this line-based reader
  // (extras such as colours ride along on a vertex's line) cannot take apart: say so, rather
  // than that the counts exceed the bytes left.
  {
    in.token_on_line();  // the edge count
    int more = 0;
    while (more < 3 && !in.token_on_line().empty()) ++more;
    if (more == 3)
      out.fail(at_line(in.line()), "more numbers follow the counts on their line: OFF puts each vertex and each "
                                   "face on a line of its own");
  }
  in.next_line();

  // A count is absurd if the rest of the file cannot hold that many records of even 2 bytes;
  // below that, a file merely too short fails naturally at its end, with a line number. Capacity
  // is reserved only for what the file can hold at the smallest real record sizes, "0 0 0\n" and
  // "3 0 1 2\n", so a lying header never makes us allocate more than a few times the file size.
  const std::uint64_t left = bytes.size() - in.offset() + 1;  // the last record needs no '\n'
  out.check_count(static_cast<std::uint64_t>(nv), 2, left, kMaxVertices, "vertices",
                  at_line(header_line));
  out.check_count(static_cast<std::uint64_t>(nf), 2, left - 2 * static_cast<std::uint64_t>(nv),
                  kMaxVertices, "faces", at_line(header_line));
  const auto vertex_count = static_cast<std::size_t>(nv);
  const auto face_count = static_cast<std::size_t>(nf);
  out.reserve(std::min<std::size_t>(vertex_count, left / 6), std::min<std::size_t>(face_count, left / 8));

  for (std::size_t i = 0; i < vertex_count; ++i) {
    double c[3];
    for (double& x : c) {
      tok = in.token();
      if (tok.empty())
        out.fail(at_line(in.line()),
                 "unexpected end of file in vertex " + count_text(i, vertex_count) + " (truncated?)");
      if (!parse_double(tok, x))
        out.fail(at_line(in.line()),
                 "vertex " + std::to_string(i) + ": coordinate " + quoted(tok) + " is not a number");
    }
    if (!out.add_vertex(c[0], c[1], c[2]))
      out.fail(at_line(in.line()),
               "vertex " + std::to_string(i) + " has a NaN or infinite coordinate");
    in.next_line();
  }

  std::vector<std::uint32_t> polygon;
  for (std::size_t f = 0; f < face_count; ++f) {
    tok = in.token();
    if (tok.empty())
      out.fail(at_line(in.line()),
               "unexpected end of file in face " + count_text(f, face_count) + " (truncated?)");
    std::int64_t k = 0;
    if (!parse_int(tok, k))
      out.fail(at_line(in.line()),
               "face " + std::to_string(f) + ": vertex count " + quoted(tok) + " is not an integer");
    if (k < 3)
      out.fail(at_line(in.line()), "face " + std::to_string(f) + " has " + std::to_string(k) +
                                       " vertices; at least 3 are needed");
    // More corners than the model has vertices and than the rest of the file holds indices (two
    // bytes each at least, "0 "): a wrong number, not a truncated file (the loop below would read
    // the next faces as its indices, then report the end of the file).
    if (k > nv && static_cast<std::uint64_t>(k) > (bytes.size() - in.offset()) / 2 + 1)
      out.fail(at_line(in.line()), "face " + std::to_string(f) + " says it has " + std::to_string(k) +
                                       " vertices, more than the model's " + std::to_string(nv) +
                                       " and than the rest of the file can hold");
    polygon.clear();
    for (std::int64_t j = 0; j < k; ++j) {
      tok = in.token();
      std::int64_t index = 0;
      if (tok.empty())
        out.fail(at_line(in.line()),
                 "unexpected end of file in face " + count_text(f, face_count) + " (truncated?)");
      if (!parse_int(tok, index))
        out.fail(at_line(in.line()), "face " + std::to_string(f) + ": vertex index " + quoted(tok) +
                                         " is not an integer");
      if (index < 0 || index >= nv)
        out.fail(at_line(in.line()), "face " + std::to_string(f) + ": vertex index " +
                                         std::to_string(index) + " out of range [0, " +
                                         std::to_string(nv) + ")");
      polygon.push_back(static_cast<std::uint32_t>(index));
    }
    out.add_polygon(polygon);
    in.next_line();
  }
  if (in.skip_to_content())
    out.report().warnings.push_back("text after the last announced face (line " +
                                    std::to_string(in.line()) + ") ignored");
}

}  // namespace delpsc::io::detail

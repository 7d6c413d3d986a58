// Wavefront OBJ: "v x y z [w | r g b]" and "f" statements; every other statement (vt, vn, g, o,
// s, usemtl, mtllib, l, p, free-form geometry...) is skipped, and one OBJ does not define with a
// warning (none of v and f at all: refused, naming the first). Indices count from 1; negative
// ones count back from the last vertex defined so far.
#include <algorithm>
#include <array>
#include <string>
#include <vector>

#include "model_parsers.h"
#include "text_scanner.h"

namespace delpsc::io::detail {

namespace {

/// The vertex index of a face corner "i", "i/t", "i/t/n" or "i//n"; false if malformed.
bool vertex_reference(std::string_view corner, std::int64_t& index) {
  const std::size_t slash = corner.find('/');
  if (!parse_int(corner.substr(0, slash), index)) return false;
  if (slash == std::string_view::npos) return true;
  // The texture and normal parts are unused but must be integers or empty, or the token is
  // garbage rather than a reference.
  std::string_view rest = corner.substr(slash + 1);
  for (int part = 0; part < 2; ++part) {
    const std::size_t next = rest.find('/');
    std::int64_t ignored = 0;
    const std::string_view piece = rest.substr(0, next);
    if (!piece.empty() && !parse_int(piece, ignored)) return false;
    if (next == std::string_view::npos) return true;
    rest = rest.substr(next + 1);
  }
  return false;  // a third '/'
}

bool is_printable_ascii(std::string_view s) {
  for (const char c : s)
    if (static_cast<unsigned char>(c) < 0x21 || static_cast<unsigned char>(c) > 0x7e) return false;
  return true;
}

}  // namespace

namespace {

// The OBJ statements skipped on purpose (texture and normal data, groups, materials, lines,
// points, free-form geometry, display attributes); any other keyword is counted as unknown.
bool known_statement(std::string_view keyword) {
  static constexpr std::array<std::string_view, 38> kKnown = {
      "vt",   "vn",   "vp",    "g",     "o",      "s",       "usemtl", "mtllib", "l",    "p",
      "cstype", "deg", "bmat", "step",  "curv",   "curv2",   "surf",   "parm",   "trim", "hole",
      "scrv", "sp",   "end",   "con",   "mg",     "bevel",   "c_interp", "d_interp", "lod", "maplib",
      "usemap", "shadow_obj", "trace_obj", "ctech", "stech", "call", "csh", "vc"};
  return std::find(kKnown.begin(), kKnown.end(), keyword) != kKnown.end();
}

}  // namespace

void parse_obj(std::string_view bytes, SoupBuilder& out) {
  out.report().format = "OBJ";
  TextScanner in(bytes, '#');
  std::vector<std::uint32_t> polygon;
  std::size_t unknown = 0, first_unknown_line = 0;
  std::string first_unknown;
  while (in.skip_to_content()) {
    const std::string_view keyword = in.token_on_line();
    const std::size_t line = in.line();
    if (keyword == "v") {
      double c[3];
      for (double& x : c) {
        const std::string_view tok = in.token_on_line();
        if (tok.empty()) out.fail(at_line(line), "vertex with fewer than three coordinates");
        if (!parse_double(tok, x))
          out.fail(at_line(line), "vertex coordinate " + quoted(tok) + " is not a number");
      }
      if (out.file_vertex_count() >= kMaxVertices)
        out.fail(at_line(line), "more than " + std::to_string(kMaxVertices) + " vertices");
      if (!out.add_vertex(c[0], c[1], c[2]))
        out.fail(at_line(line), "vertex has a NaN or infinite coordinate");
    } else if (keyword == "f" || keyword == "fo") {  // "fo": the obsolete spelling
      const auto defined = static_cast<std::int64_t>(out.file_vertex_count());
      polygon.clear();
      for (std::string_view tok = in.token_on_line(); !tok.empty(); tok = in.token_on_line()) {
        std::int64_t index = 0;
        if (!vertex_reference(tok, index))
          out.fail(at_line(line), "face corner " + quoted(tok) +
                                      " is not a vertex reference (i, i/t, i/t/n or i//n)");
        if (index == 0) out.fail(at_line(line), "face vertex index 0 (OBJ indices start at 1)");
        const std::int64_t resolved = index > 0 ? index - 1 : defined + index;
        if (resolved < 0 || resolved >= defined)
          out.fail(at_line(line), "face vertex index " + std::to_string(index) +
                                      " out of range: " + std::to_string(defined) +
                                      " vertices defined so far");
        polygon.push_back(static_cast<std::uint32_t>(resolved));
      }
      if (polygon.size() < 3)
        out.fail(at_line(line), "face with " + std::to_string(polygon.size()) +
                                    " vertices; at least 3 are needed");
      out.add_polygon(polygon);
    } else if (!is_printable_ascii(keyword)) {
      out.fail(at_line(line), "not an OBJ statement: " + quoted(keyword) + " (binary data?)");
    } else if (!known_statement(keyword)) {
      if (unknown++ == 0) first_unknown_line = line, first_unknown = quoted(keyword);
    }
    in.next_line();
  }
  // Skipped without a word before: an OFF file named .obj was then "an empty model".
  if (unknown > 0 && out.file_vertex_count() == 0 && out.report().polygons == 0)
    out.fail(at_line(first_unknown_line), "no OBJ 'v' or 'f' statement, and " + first_unknown +
                                              " is no OBJ statement: is this an OBJ file?");
  if (unknown > 0)
    out.report().warnings.push_back(std::to_string(unknown) + " line(s) with a statement OBJ does not know skipped, " +
                                    "the first " + first_unknown + " at line " + std::to_string(first_unknown_line));
}

}  // namespace delpsc::io::detail

// PLY (Turk's Polygon File Format): a text header declaring elements and their properties, then
// the element records in ASCII or binary little/big-endian. We read the vertex element's x, y, z
// and the face element's "vertex_indices" (or "vertex_index") list and skip everything else,
// which only works if every property's size is accounted for: hence the general record walk.
#include <algorithm>
#include <optional>
#include <string>
#include <vector>

#include "byte_order.h"
#include "model_parsers.h"
#include "text_scanner.h"

namespace delpsc::io::detail {

namespace {

enum class PlyType : std::uint8_t { int8, uint8, int16, uint16, int32, uint32, float32, float64 };

std::size_t size_of(PlyType t) {
  static constexpr std::size_t sizes[] = {1, 1, 2, 2, 4, 4, 4, 8};
  return sizes[static_cast<int>(t)];
}

bool is_integer(PlyType t) { return t != PlyType::float32 && t != PlyType::float64; }

std::optional<PlyType> type_named(std::string_view s) {
  static constexpr std::pair<std::string_view, PlyType> names[] = {
      {"char", PlyType::int8},      {"int8", PlyType::int8},       {"uchar", PlyType::uint8},
      {"uint8", PlyType::uint8},    {"short", PlyType::int16},     {"int16", PlyType::int16},
      {"ushort", PlyType::uint16},  {"uint16", PlyType::uint16},   {"int", PlyType::int32},
      {"int32", PlyType::int32},    {"uint", PlyType::uint32},     {"uint32", PlyType::uint32},
      {"float", PlyType::float32},  {"float32", PlyType::float32}, {"double", PlyType::float64},
      {"float64", PlyType::float64}};
  for (const auto& [name, type] : names)
    if (s == name) return type;
  return std::nullopt;
}

/// What a property means to us. Everything not recognised is skipped.
enum class Role : std::uint8_t { skip, x, y, z, face_indices };

struct Property {
  std::string name;
  PlyType type = PlyType::float32;  // the item type, for lists
  bool is_list = false;
  PlyType count_type = PlyType::uint8;
  Role role = Role::skip;
};

struct Element {
  std::string name;
  std::uint64_t count = 0;
  std::vector<Property> properties;
  std::size_t line = 0;  // of its "element" line, for messages
};

struct Header {
  std::optional<std::endian> binary_order;  // nullopt: ASCII
  std::vector<Element> elements;
  std::size_t body_offset = 0;
  std::size_t body_line = 0;
};

Header parse_header(std::string_view bytes, SoupBuilder& out) {
  Header h;
  bool have_format = false;
  TextScanner in(bytes, '\0');
  if (in.token_on_line() != "ply" || !in.at_line_end())
    out.fail(at_line(1), "not a PLY file: the first line must be 'ply'");
  in.next_line();
  for (;;) {
    const std::size_t line = in.line();
    if (in.offset() >= bytes.size())
      out.fail(at_line(line), "the header has no 'end_header' line (truncated, or not a PLY file)");
    const std::string_view keyword = in.token_on_line();
    if (keyword == "end_header") {
      in.next_line();
      h.body_offset = in.offset();
      h.body_line = in.line();
      break;
    }
    if (keyword == "format") {
      const std::string_view encoding = in.token_on_line();
      if (encoding == "ascii")
        h.binary_order.reset();
      else if (encoding == "binary_little_endian")
        h.binary_order = std::endian::little;
      else if (encoding == "binary_big_endian")
        h.binary_order = std::endian::big;
      else
        out.fail(at_line(line), "unknown PLY format " + quoted(encoding));
      have_format = true;
    } else if (keyword == "element") {
      Element e;
      e.name = std::string(in.token_on_line());
      const std::string_view count = in.token_on_line();
      std::int64_t n = 0;
      if (e.name.empty() || !parse_int(count, n) || n < 0)
        out.fail(at_line(line), "expected 'element NAME COUNT' with a count >= 0");
      e.count = static_cast<std::uint64_t>(n);
      e.line = line;
      h.elements.push_back(std::move(e));
    } else if (keyword == "property") {
      if (h.elements.empty()) out.fail(at_line(line), "'property' before any 'element'");
      Property p;
      std::string_view type = in.token_on_line();
      if (type == "list") {
        p.is_list = true;
        const std::string_view count_type = in.token_on_line();
        const auto ct = type_named(count_type);
        if (!ct) out.fail(at_line(line), "unknown property type " + quoted(count_type));
        if (!is_integer(*ct)) out.fail(at_line(line), "a list count must have an integer type");
        p.count_type = *ct;
        type = in.token_on_line();
      }
      const auto t = type_named(type);
      if (!t) out.fail(at_line(line), "unknown property type " + quoted(type));
      p.type = *t;
      p.name = std::string(in.token_on_line());
      if (p.name.empty()) out.fail(at_line(line), "property without a name");
      h.elements.back().properties.push_back(std::move(p));
    } else if (!keyword.empty() && keyword != "comment" && keyword != "obj_info") {
      out.fail(at_line(line), "unexpected header line starting with " + quoted(keyword));
    }
    in.next_line();
  }
  if (!have_format) out.fail("", "the PLY header has no 'format' line");
  return h;
}

/// Marks the properties we read and checks they have usable types. Returns the indices of the
/// vertex and face elements (the face index may be absent: a point cloud, reported later).
std::pair<std::size_t, std::optional<std::size_t>> assign_roles(Header& h, SoupBuilder& out) {
  std::optional<std::size_t> vertex, face;
  for (std::size_t i = 0; i < h.elements.size(); ++i) {
    if (h.elements[i].name == "vertex" && !vertex) vertex = i;
    if (h.elements[i].name == "face" && !face) face = i;
  }
  if (!vertex) out.fail("", "the PLY header declares no 'vertex' element");
  Element& v = h.elements[*vertex];
  const char* axes[3] = {"x", "y", "z"};
  for (int k = 0; k < 3; ++k) {
    const auto it = std::find_if(v.properties.begin(), v.properties.end(),
                                 [&](const Property& p) { return p.name == axes[k]; });
    if (it == v.properties.end())
      out.fail(at_line(v.line), std::string("the vertex element has no property '") + axes[k] + "'");
    if (it->is_list)
      out.fail(at_line(v.line), std::string("vertex property '") + axes[k] + "' is a list");
    it->role = static_cast<Role>(static_cast<int>(Role::x) + k);
  }
  if (v.count > kMaxVertices)
    out.fail(at_line(v.line), "more than " + std::to_string(kMaxVertices) + " vertices");
  if (face) {
    Element& f = h.elements[*face];
    if (*face < *vertex)
      out.fail(at_line(f.line), "the face element comes before the vertex element (not supported)");
    const auto it = std::find_if(f.properties.begin(), f.properties.end(), [](const Property& p) {
      return p.is_list && (p.name == "vertex_indices" || p.name == "vertex_index");
    });
    if (it == f.properties.end())
      out.fail(at_line(f.line), "the face element has no list 'vertex_indices' or 'vertex_index'");
    if (!is_integer(it->type))
      out.fail(at_line(f.line), "face vertex indices must have an integer type");
    it->role = Role::face_indices;
  }
  return {*vertex, face};
}

/// Bounds every element count by what the body can hold before anything is allocated from them:
/// a record needs at least its scalar bytes and list counts (binary) or two characters per
/// property (ASCII: a digit and a separator).
void check_counts(const Header& h, std::uint64_t body_bytes, SoupBuilder& out) {
  std::uint64_t available = body_bytes + (h.binary_order ? 0 : 1);  // the last value needs no separator
  for (const Element& e : h.elements) {
    std::uint64_t min_bytes = 0;
    for (const Property& p : e.properties)
      min_bytes += h.binary_order ? size_of(p.is_list ? p.count_type : p.type) : 2;
    out.check_count(e.count, min_bytes, available, ~std::uint64_t{0},
                    "'" + e.name + "' records", at_line(e.line));
    available -= e.count * min_bytes;
  }
}

/// Where the record walk is, for messages.
struct Position {
  const Element* element = nullptr;
  std::uint64_t record = 0;
  std::string describe() const {
    return "'" + element->name + "' record " + std::to_string(record) + " of " +
           std::to_string(element->count);
  }
};

class BinarySource {
 public:
  BinarySource(std::string_view bytes, std::size_t offset, std::endian order, SoupBuilder& out,
               const Position& at)
      : bytes_(bytes), pos_(offset), order_(order), out_(out), at_(at) {}

  double real(PlyType t) {
    need(size_of(t));
    const char* p = bytes_.data() + pos_;
    last_ = pos_;
    pos_ += size_of(t);
    switch (t) {
      case PlyType::float32: return load<float>(p, order_);
      case PlyType::float64: return load<double>(p, order_);
      default: return static_cast<double>(integer_at(p, t));
    }
  }
  std::int64_t integer(PlyType t) {
    need(size_of(t));
    const std::int64_t v = integer_at(bytes_.data() + pos_, t);
    last_ = pos_;
    pos_ += size_of(t);
    return v;
  }
  void skip(PlyType t) { skip_items(t, 1); }
  void skip_items(PlyType t, std::uint64_t n) {
    need(n * size_of(t));  // n < 2^32 (a list count), no overflow
    pos_ += n * size_of(t);
  }
  /// A cheap bookmark of the value read last (the hot loops must not build strings).
  std::size_t mark() const { return last_; }
  static std::string place(std::size_t mark) { return at_byte(mark); }
  std::string place() const { return place(pos_); }
  std::size_t remaining() const { return bytes_.size() - pos_; }

 private:
  void need(std::uint64_t n) const {
    if (n > bytes_.size() - pos_)
      out_.fail(at_byte(pos_), "unexpected end of file in " + at_.describe() + " (truncated?)");
  }
  std::int64_t integer_at(const char* p, PlyType t) const {
    switch (t) {
      case PlyType::int8: return load<std::int8_t>(p, order_);
      case PlyType::uint8: return load<std::uint8_t>(p, order_);
      case PlyType::int16: return load<std::int16_t>(p, order_);
      case PlyType::uint16: return load<std::uint16_t>(p, order_);
      case PlyType::int32: return load<std::int32_t>(p, order_);
      case PlyType::uint32: return load<std::uint32_t>(p, order_);
      default: return 0;  // float types never reach here (checked in the header)
    }
  }

  std::string_view bytes_;
  std::size_t pos_;
  std::size_t last_ = 0;
  std::endian order_;
  SoupBuilder& out_;
  const Position& at_;
};

class AsciiSource {
 public:
  AsciiSource(std::string_view body, std::size_t first_line, SoupBuilder& out, const Position& at)
      : in_(body, '\0', first_line), out_(out), at_(at) {}

  double real(PlyType) {
    const std::string_view tok = next();
    double v = 0;
    if (!parse_double(tok, v))
      out_.fail(place(), at_.describe() + ": " + quoted(tok) + " is not a number");
    return v;
  }
  std::int64_t integer(PlyType) {
    const std::string_view tok = next();
    std::int64_t v = 0;
    if (!parse_int(tok, v))
      out_.fail(place(), at_.describe() + ": " + quoted(tok) + " is not an integer");
    return v;
  }
  void skip(PlyType) { next(); }
  void skip_items(PlyType, std::uint64_t n) {
    for (std::uint64_t i = 0; i < n; ++i) next();
  }
  std::size_t mark() const { return in_.line(); }  // the line of the token read last
  static std::string place(std::size_t mark) { return at_line(mark); }
  std::string place() const { return place(in_.line()); }
  bool has_more() { return in_.skip_to_content(); }

 private:
  std::string_view next() {
    const std::string_view tok = in_.token();
    if (tok.empty())
      out_.fail(place(), "unexpected end of file in " + at_.describe() + " (truncated?)");
    return tok;
  }

  TextScanner in_;
  SoupBuilder& out_;
  const Position& at_;
};

template <class Source>
void read_records(const Header& h, Source& src, Position& at, SoupBuilder& out) {
  const std::uint64_t vertex_count = [&] {
    for (const Element& e : h.elements)
      if (e.name == "vertex") return e.count;
    return std::uint64_t{0};
  }();
  std::vector<std::uint32_t> polygon;
  for (const Element& e : h.elements) {
    at.element = &e;
    if (e.properties.empty()) continue;  // occupies no bytes, whatever its count
    for (at.record = 0; at.record < e.count; ++at.record) {
      double xyz[3] = {0, 0, 0};
      bool has_vertex = false, has_face = false;
      polygon.clear();
      for (const Property& p : e.properties) {
        if (!p.is_list) {
          if (p.role == Role::skip) {
            src.skip(p.type);
          } else {
            xyz[static_cast<int>(p.role) - static_cast<int>(Role::x)] = src.real(p.type);
            has_vertex = true;
          }
          continue;
        }
        const std::int64_t n = src.integer(p.count_type);
        const std::size_t count_mark = src.mark();
        if (n < 0) out.fail(Source::place(count_mark), at.describe() + ": negative list length");
        if (p.role != Role::face_indices) {
          src.skip_items(p.type, static_cast<std::uint64_t>(n));
          continue;
        }
        if (n < 3)
          out.fail(Source::place(count_mark), at.describe() + ": a face with " + std::to_string(n) +
                                    " vertices; at least 3 are needed");
        has_face = true;
        for (std::int64_t j = 0; j < n; ++j) {
          const std::int64_t index = src.integer(p.type);
          const std::size_t index_mark = src.mark();
          if (index < 0 || static_cast<std::uint64_t>(index) >= vertex_count)
            out.fail(Source::place(index_mark), at.describe() + ": vertex index " + std::to_string(index) +
                                " out of range [0, " + std::to_string(vertex_count) + ")");
          polygon.push_back(static_cast<std::uint32_t>(index));
        }
      }
      if (has_vertex && !out.add_vertex(xyz[0], xyz[1], xyz[2]))
        out.fail(src.place(), at.describe() + ": NaN or infinite coordinate");
      if (has_face) out.add_polygon(polygon);
    }
  }
}

}  // namespace

void parse_ply(std::string_view bytes, SoupBuilder& out) {
  out.report().format = "PLY";
  Header h = parse_header(bytes, out);
  out.report().format = !h.binary_order ? "PLY (ASCII)"
                        : *h.binary_order == std::endian::little ? "PLY (binary little-endian)"
                                                                 : "PLY (binary big-endian)";
  const auto [vertex, face] = assign_roles(h, out);
  check_counts(h, bytes.size() - h.body_offset, out);
  out.reserve(h.elements[vertex].count, face ? h.elements[*face].count : 0);

  Position at;
  if (h.binary_order) {
    BinarySource src(bytes, h.body_offset, *h.binary_order, out, at);
    read_records(h, src, at, out);
    if (src.remaining() > 0)
      out.report().warnings.push_back(std::to_string(src.remaining()) +
                                      " bytes after the last element ignored");
  } else {
    AsciiSource src(bytes.substr(h.body_offset), h.body_line, out, at);
    read_records(h, src, at, out);
    if (src.has_more())
      out.report().warnings.push_back("text after the last element (" + src.place() + ") ignored");
  }
}

}  // namespace delpsc::io::detail

#include "read_model.h"

#include <cstdio>
#include <cstring>
#include <filesystem>
#include <memory>
#include <string>

#include <delpsc/kernel/large_array.h>

#include "error.h"
#include "input_bytes.h"
#include "model_parsers.h"

namespace delpsc::io {

namespace {

std::string lower_extension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  for (char& c : ext)
    if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
  return ext;
}

// A lone '\r' (not followed by '\n') ends a line, as in files from classic Mac OS and some
// exporters that copied its convention: the line-based text formats see '\n' there instead.
// Without this a CR-only OFF file was one long line, refused as a bad header at line 1. CRLF is
// left as it is (the scanners take '\r' for a blank). Empty when there is no lone '\r' (no copy).
std::string with_lone_cr_as_newline(std::string_view text) {
  std::size_t cr = text.find('\r');
  while (cr != std::string_view::npos && cr + 1 < text.size() && text[cr + 1] == '\n') cr = text.find('\r', cr + 2);
  if (cr == std::string_view::npos) return {};
  std::string copy(text);
  for (std::size_t i = cr; i < copy.size(); ++i)
    if (copy[i] == '\r' && (i + 1 == copy.size() || copy[i + 1] != '\n')) copy[i] = '\n';
  return copy;
}

}  // namespace

std::optional<ModelFormat> model_format_from_path(const std::string& path) {
  const std::string ext = lower_extension(path);
  if (ext == ".off") return ModelFormat::off;
  if (ext == ".obj") return ModelFormat::obj;
  if (ext == ".stl") return ModelFormat::stl;
  if (ext == ".ply") return ModelFormat::ply;
  return std::nullopt;
}

ReadResult read_model(const std::string& path, const PipeWait& wait) {
  const auto format = model_format_from_path(path);
  if (!format) {
    const std::string ext = std::filesystem::path(path).extension().string();
    throw Error(path + ": unknown model format " +
                (ext.empty() ? std::string("(no extension)") : "'" + ext + "'") +
                "; expected .off, .obj, .stl or .ply");
  }
  const kernel::LargeVector<char> bytes = read_input_bytes(path, "model file", wait);
  return read_model_from_memory(std::string_view(bytes.data(), bytes.size()), *format, path);
}

ReadResult read_model_from_memory(std::string_view bytes, ModelFormat format, const std::string& name) {
  // Compressed data named like a model: say so, instead of a header or count error about the
  // compressed bytes (a gzipped .stl was refused for the triangle count it seemed to announce).
  // (A binary STL's 80-byte header is free-form: one whose size proves it binary is read.)
  const bool binary_stl = format == ModelFormat::stl && detail::stl_size_proves_binary(bytes);
  if (!binary_stl && bytes.starts_with("\x1f\x8b"))
    throw Error(name + ": gzip-compressed data, not a model file: decompress it first (gunzip)");
  if (!binary_stl && bytes.starts_with("PK\x03\x04"))
    throw Error(name + ": a zip archive, not a model file: extract the model first");
  detail::SoupBuilder builder(name);
  // A UTF-8 byte-order mark, which some Windows editors put before any text: not part of an OFF
  // or OBJ file's content, nor of a PLY header's "ply" (STL decides for itself: a binary STL's
  // header is free-form, parse_stl).
  const bool line_text = format == ModelFormat::off || format == ModelFormat::obj;
  if (bytes.starts_with("\xEF\xBB\xBF") &&
      (line_text || (format == ModelFormat::ply && bytes.substr(3).starts_with("ply"))))
    bytes.remove_prefix(3);
  const std::string normalised = line_text ? with_lone_cr_as_newline(bytes) : std::string();
  if (!normalised.empty()) bytes = normalised;
  switch (format) {
    case ModelFormat::off: detail::parse_off(bytes, builder); break;
    case ModelFormat::obj: detail::parse_obj(bytes, builder); break;
    case ModelFormat::stl: detail::parse_stl(bytes, builder); break;
    case ModelFormat::ply: detail::parse_ply(bytes, builder); break;
  }
  return builder.finish();
}

}  // namespace delpsc::io
